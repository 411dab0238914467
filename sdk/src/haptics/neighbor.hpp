// haptics/neighbor.hpp — what a k-nearest-neighbour search returns, and the
// one distance and ordering every search in the SDK uses.
//
// Points are float vectors in the standardised space (channel_scaling.hpp).
// The squared distance is accumulated in float in eight lanes (channel i in
// lane i mod 8, lanes summed in a fixed order: explicitly vectorised, about
// 2x faster than a double loop), returned as double; the k-d tree and the
// brute-force reference call this one function, so they compute bit-equal
// values. Its relative rounding error is below 2e-6 for up to ~100 channels.
// Neighbours are ordered by (squared distance, row id): equal
// distances (duplicated rows, symmetric grids) resolve to the smaller id, so
// every search returns the same ids for the same data.
#pragma once

#include <cstdint>
#include <cstring>

namespace onetip::haptics {

struct Neighbor {
  std::uint32_t id = 0;       // dataset row
  double distance_sq = 0.0;   // squared standardised distance
};

inline bool closerThan(const Neighbor& a, const Neighbor& b) noexcept {
  return a.distance_sq < b.distance_sq || (a.distance_sq == b.distance_sq && a.id < b.id);
}

namespace detail {
// Four floats as one value (GCC/Clang vector extension: SSE on x86-64, NEON on
// arm64). Each lane is plain IEEE float arithmetic, so results do not depend
// on the instruction set.
using Float4 = float __attribute__((vector_size(16)));

inline Float4 load4(const float* p) noexcept {
  Float4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
}  // namespace detail

// Eight float lanes (channel i in lane i mod 8) held as two Float4, combined in
// one fixed order; a last partial block is padded with zero differences, which
// leave those lanes unchanged.
inline double squaredDistance(const float* a, const float* b, int dims) noexcept {
  using detail::Float4;
  using detail::load4;
  Float4 lo = {0, 0, 0, 0}, hi = {0, 0, 0, 0};  // lanes 0-3 and 4-7
  int i = 0;
  for (; i + 8 <= dims; i += 8) {
    const Float4 d_lo = load4(a + i) - load4(b + i), d_hi = load4(a + i + 4) - load4(b + i + 4);
    lo += d_lo * d_lo;
    hi += d_hi * d_hi;
  }
  if (i < dims) {
    float d[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    for (int l = 0; i + l < dims; ++l) d[l] = a[i + l] - b[i + l];
    const Float4 d_lo = load4(d), d_hi = load4(d + 4);
    lo += d_lo * d_lo;
    hi += d_hi * d_hi;
  }
  const Float4 s = lo + hi;  // (l0 + l4, l1 + l5, l2 + l6, l3 + l7)
  return static_cast<double>((s[0] + s[1]) + (s[2] + s[3]));
}

}  // namespace onetip::haptics
