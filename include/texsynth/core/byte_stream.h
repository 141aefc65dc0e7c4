#pragma once
// Little helpers to write and bounds-check-read flat binary records (the host's byte order;
// the cache envelope's magic and checksum reject files from another kind of machine).
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace texsynth {

struct ByteWriter {
  std::string bytes;

  template <typename T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  // Element count (u64) followed by the elements.
  template <typename T>
  void array(const std::vector<T>& values) {
    value(std::uint64_t(values.size()));
    if (!values.empty()) bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
};

// Every read returns false instead of reading past the end, and never allocates more than
// the bytes that remain could hold.
class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}

  std::size_t remaining() const { return bytes_.size() - position_; }
  bool atEnd() const { return position_ == bytes_.size(); }

  bool raw(std::size_t size, std::string_view& out) {
    if (size > remaining()) return false;
    out = bytes_.substr(position_, size);
    position_ += size;
    return true;
  }
  template <typename T>
  bool value(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    std::string_view data;
    if (!raw(sizeof(T), data)) return false;
    std::memcpy(&v, data.data(), sizeof(T));
    return true;
  }
  template <typename T>
  bool array(std::vector<T>& values) {
    std::uint64_t count = 0;
    if (!value(count) || count > remaining() / sizeof(T)) return false;
    std::string_view data;
    if (!raw(count * sizeof(T), data)) return false;
    values.resize(count);
    if (count == 0) return true;  // an empty vector's data() may be null, which memcpy must not get
    std::memcpy(static_cast<void*>(values.data()), data.data(), data.size());  // also fixed-size Eigen vectors
    return true;
  }

 private:
  std::string_view bytes_;
  std::size_t position_ = 0;
};

}  // namespace texsynth
