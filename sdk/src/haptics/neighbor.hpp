// haptics/neighbor.hpp — what a k-nearest-neighbour search returns, and the
// one distance and ordering every search in the SDK uses.
//
// Points are float vectors in the standardised space (channel_scaling.hpp).
// The squared distance is accumulated in float in eight lanes (channel i in
// lane i mod 8, lanes summed in a fixed order: vectorisable and about 30 %
// faster than a double loop), returned as double; the k-d tree and the
// brute-force reference call this one function, so they compute bit-equal
// values. Its relative rounding error is below 2e-6 for up to ~100 channels. Neighbours are ordered by (squared distance, row id): equal
// distances (duplicated rows, symmetric grids) resolve to the smaller id, so
// every search returns the same ids for the same data.
#pragma once

#include <cstdint>

namespace onetip::haptics {

struct Neighbor {
  std::uint32_t id = 0;       // dataset row
  double distance_sq = 0.0;   // squared standardised distance
};

inline bool closerThan(const Neighbor& a, const Neighbor& b) noexcept {
  return a.distance_sq < b.distance_sq || (a.distance_sq == b.distance_sq && a.id < b.id);
}

inline double squaredDistance(const float* a, const float* b, int dims) noexcept {
  // Eight float partial sums in a fixed order (vectorisable, deterministic).
  float lane[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  int i = 0;
  for (; i + 8 <= dims; i += 8)
    for (int l = 0; l < 8; ++l) {
      const float d = a[i + l] - b[i + l];
      lane[l] += d * d;
    }
  for (int l = 0; i < dims; ++i, ++l) {
    const float d = a[i] - b[i];
    lane[l] += d * d;
  }
  return static_cast<double>(((lane[0] + lane[4]) + (lane[1] + lane[5])) + ((lane[2] + lane[6]) + (lane[3] + lane[7])));
}

}  // namespace onetip::haptics
