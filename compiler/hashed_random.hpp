// Random numbers from a hash of what they are for (a pixel and sample, a piece and fibre),
// not from a generator's running state: every thread draws the same number for the same
// thing, so results are the same for any thread count. SplitMix64's finaliser.
#pragma once

#include <cstdint>

namespace knitc::hashed {

inline std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 33;
  x *= 0xff51afd7ed558ccdULL;
  x ^= x >> 33;
  x *= 0xc4ceb9fe1a85ec53ULL;
  x ^= x >> 33;
  return x;
}

// The `n`th uniform number in [0, 1) of the stream keyed by `key`, with 53 bits.
inline double uniform(std::uint64_t key, std::uint64_t n) {
  return static_cast<double>(mix(key + 0x9e3779b97f4a7c15ULL * (n + 1)) >> 11) * 0x1.0p-53;
}

}  // namespace knitc::hashed
