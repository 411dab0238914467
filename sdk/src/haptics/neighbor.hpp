// haptics/neighbor.hpp — what a k-nearest-neighbour search returns, and the
// one distance and ordering every search in the SDK uses.
//
// Points are float vectors in the standardised space (channel_scaling.hpp).
// The squared distance is accumulated in double, channel by channel in index
// order, so that the k-d tree and the brute-force reference compute bit-equal
// values. Neighbours are ordered by (squared distance, row id): equal
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
