// haptics/dataset_binary.hpp — the compact binary form of a TactileDataset.
//
// Layout (little-endian):
//   offset 0   8 bytes  magic "OTHAPDS\0"
//   offset 8   u32      version (kDatasetBinaryVersion)
//   offset 12  u32      channels N (1..kMaxDatasetChannels = 1024)
//   offset 16  u64      rows R
//   offset 24  R * (3 + N) float32: per row m1 m2 m3 (degrees) then s1..sN
//   end        u64      FNV-1a 64 checksum of every byte before it
// A reader checks the magic, the version, that the file length is exactly
// 24 + 4 R (3 + N) + 8 (else "truncated"), and the checksum (else "corrupt"),
// then that every value is finite (a NaN with a recomputed checksum is refused
// naming its row and column); files over 1 GiB are refused before reading.
// 166,375 rows of 20 channels take 15.3 MB (the CSV is about twice that).
#pragma once

#include <cstdint>
#include <string>

#include "haptics/tactile_dataset.hpp"

namespace onetip::haptics {

constexpr std::uint32_t kDatasetBinaryVersion = 1;

// True when the file starts with the binary magic.
bool isBinaryDataset(const std::string& path);
TactileDataset readDatasetBinary(const std::string& path);
void writeDatasetBinary(const TactileDataset& dataset, const std::string& path);

// FNV-1a 64 over bytes, continuing from `hash` (start with the offset basis).
constexpr std::uint64_t kFnv1a64Basis = 0xcbf29ce484222325ULL;
std::uint64_t fnv1a64(const void* data, size_t bytes, std::uint64_t hash = kFnv1a64Basis);

}  // namespace onetip::haptics
