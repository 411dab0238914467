#include "haptics/dataset_binary.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace onetip::haptics {

namespace {

constexpr std::array<char, 8> kMagic = {'O', 'T', 'H', 'A', 'P', 'D', 'S', '\0'};
constexpr size_t kHeaderBytes = 24;
constexpr size_t kChecksumBytes = 8;
constexpr auto kMaxChannels = static_cast<std::uint32_t>(kMaxDatasetChannels);
constexpr std::uint64_t kMaxFileBytes = 1ULL << 30;  // 1 GiB: 13 million rows of 20 channels

static_assert(sizeof(float) == 4, "float32 expected");

template <typename T>
void put(std::vector<char>& out, T v) {
  const char* p = reinterpret_cast<const char*>(&v);  // the SDK targets little-endian hosts
  out.insert(out.end(), p, p + sizeof(T));
}

template <typename T>
T get(const std::vector<char>& in, size_t offset) {
  T v;
  std::memcpy(&v, in.data() + offset, sizeof(T));
  return v;
}

}  // namespace

std::uint64_t fnv1a64(const void* data, size_t bytes, std::uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) {
    hash ^= p[i];
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

bool isBinaryDataset(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 8> head{};
  return in.read(head.data(), head.size()) && head == kMagic;
}

TactileDataset readDatasetBinary(const std::string& path) {
  requireInputFile(path);  // a folder would open and report 2^63 - 1 bytes
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(path + ": cannot open");
  const auto length = static_cast<size_t>(in.tellg());
  if (length > kMaxFileBytes)
    throw InputError(path + ": " + std::to_string(length) + " bytes, more than the " + std::to_string(kMaxFileBytes) +
                     "-byte bound of a binary dataset");
  in.seekg(0);
  std::vector<char> bytes(length);
  if (!in.read(bytes.data(), static_cast<std::streamsize>(length))) throw InputError(path + ": read failed");
  if (length < kHeaderBytes) throw InputError(path + ": truncated binary dataset (no complete header)");
  if (std::memcmp(bytes.data(), kMagic.data(), kMagic.size()) != 0)
    throw InputError(path + ": not a binary tactile dataset (bad magic)");
  const auto version = get<std::uint32_t>(bytes, 8);
  if (version != kDatasetBinaryVersion)
    throw InputError(path + ": binary dataset version " + std::to_string(version) + " is not supported (expected " +
                     std::to_string(kDatasetBinaryVersion) + ")");
  const auto channels = get<std::uint32_t>(bytes, 12);
  const auto rows = get<std::uint64_t>(bytes, 16);
  if (channels == 0 || channels > kMaxChannels)
    throw InputError(path + ": channels = " + std::to_string(channels) + " is out of range 1.." +
                     std::to_string(kMaxChannels));
  const std::uint64_t per_row = 4ULL * (3ULL + channels);
  if (rows == 0 || rows > (length / per_row))
    throw InputError(path + ": truncated binary dataset (header says " + std::to_string(rows) + " rows, file has " +
                     std::to_string(length) + " bytes)");
  const size_t expected = kHeaderBytes + static_cast<size_t>(rows * per_row) + kChecksumBytes;
  if (length != expected)
    throw InputError(path + ": " + std::string(length < expected ? "truncated" : "trailing bytes in") +
                     " binary dataset (" + std::to_string(length) + " bytes, expected " + std::to_string(expected) + ")");
  const auto stored = get<std::uint64_t>(bytes, length - kChecksumBytes);
  if (fnv1a64(bytes.data(), length - kChecksumBytes) != stored)
    throw InputError(path + ": corrupt binary dataset (checksum mismatch)");

  TactileDataset d;
  d.channels = static_cast<int>(channels);
  d.commands.resize(3 * rows);
  d.sensed.resize(channels * rows);
  const char* p = bytes.data() + kHeaderBytes;
  for (size_t r = 0; r < rows; ++r) {
    std::memcpy(d.commands.data() + 3 * r, p, 12);
    std::memcpy(d.sensed.data() + channels * r, p + 12, 4 * channels);
    p += per_row;
    for (std::uint32_t c = 0; c < 3 + channels; ++c) {  // a valid checksum does not make the values usable
      const float v = c < 3 ? d.commands[3 * r + c] : d.sensed[channels * r + c - 3];
      if (!std::isfinite(v))
        throw InputError(path + ": row " + std::to_string(r + 1) + ", column " +
                         (c < 3 ? "m" + std::to_string(c + 1) : "s" + std::to_string(c - 2)) + ": not a finite number");
    }
  }
  return d;
}

void writeDatasetBinary(const TactileDataset& dataset, const std::string& path) {
  if (dataset.channels <= 0 || static_cast<std::uint32_t>(dataset.channels) > kMaxChannels || dataset.size() == 0)
    throw InputError(path + ": refusing to write an empty dataset or one with " +
                     std::to_string(dataset.channels) + " channels");
  std::vector<char> bytes;
  bytes.reserve(kHeaderBytes + 4 * dataset.size() * (3 + static_cast<size_t>(dataset.channels)) + kChecksumBytes);
  bytes.insert(bytes.end(), kMagic.begin(), kMagic.end());
  put<std::uint32_t>(bytes, kDatasetBinaryVersion);
  put<std::uint32_t>(bytes, static_cast<std::uint32_t>(dataset.channels));
  put<std::uint64_t>(bytes, dataset.size());
  for (size_t r = 0; r < dataset.size(); ++r) {
    for (int c = 0; c < 3; ++c) put<float>(bytes, dataset.command(r)[c]);
    for (int c = 0; c < dataset.channels; ++c) put<float>(bytes, dataset.sensedRow(r)[c]);
  }
  put<std::uint64_t>(bytes, fnv1a64(bytes.data(), bytes.size()));
  AtomicFile file(path);
  file.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  file.commit();
}

}  // namespace onetip::haptics
