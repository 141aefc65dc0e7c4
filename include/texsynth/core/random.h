#pragma once
// Deterministic, stateless randomness: every random choice is a hash of
// (seed, element, level, pass), so results never depend on thread count or order.
#include <cstdint>

namespace texsynth {

// A strong 64-bit mixer (splitmix64 finalizer).
constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Hash of a random choice's full identity.
constexpr std::uint64_t hashKey(std::uint64_t seed, std::uint64_t element, std::uint64_t level = 0,
                                std::uint64_t pass = 0) {
  std::uint64_t h = mix64(seed);
  h = mix64(h ^ element);
  h = mix64(h ^ (level * 0x100000001b3ull));
  return mix64(h ^ (pass * 0xc2b2ae3d27d4eb4full));
}

// Uniform float in [0,1) from a key.
constexpr float uniform01(std::uint64_t key) {
  return float(key >> 40) * (1.0f / 16777216.0f);
}

// Uniform integer in [0,n) from a key.
constexpr std::uint32_t uniformBelow(std::uint64_t key, std::uint32_t n) {
  return std::uint32_t(((key >> 32) * std::uint64_t(n)) >> 32);
}

// Element id of a 2D/3D lattice point, for use as the `element` of hashKey.
constexpr std::uint64_t latticeId(std::int64_t x, std::int64_t y, std::int64_t z = 0) {
  return mix64(std::uint64_t(x) * 0x9e3779b97f4a7c15ull ^
               mix64(std::uint64_t(y) * 0xc2b2ae3d27d4eb4full ^ mix64(std::uint64_t(z))));
}

// A small sequential generator for places that need a stream (seeded from a key).
class Rng {
 public:
  explicit Rng(std::uint64_t key) : state_(key) {}
  std::uint64_t next() { return mix64(state_++); }
  float uniform() { return uniform01(next()); }
  std::uint32_t below(std::uint32_t n) { return uniformBelow(next(), n); }

 private:
  std::uint64_t state_;
};

}  // namespace texsynth
