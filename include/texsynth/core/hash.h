#pragma once
// Content hashing for cache keys: a 64-bit FNV-1a-style streaming hash, strengthened by mix64.
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "texsynth/core/random.h"

namespace texsynth {

class Hasher {
 public:
  Hasher& bytes(const void* data, std::size_t size);
  Hasher& string(std::string_view s) {
    value(std::uint64_t(s.size()));
    return bytes(s.data(), s.size());
  }
  template <typename T>
  Hasher& value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    return bytes(&v, sizeof(T));
  }
  template <typename T>
  Hasher& vector(const std::vector<T>& v) {
    value(std::uint64_t(v.size()));
    return bytes(v.data(), v.size() * sizeof(T));
  }
  std::uint64_t digest() const { return mix64(state_); }
  // 16 hex digits, for file names.
  std::string hex() const;

 private:
  std::uint64_t state_ = 0xcbf29ce484222325ull;
};

}  // namespace texsynth
