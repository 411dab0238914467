#include "core/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "core/error.hpp"

namespace onetip {

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), temp_(path_ + ".tmp." + std::to_string(::getpid())) {
  out_.open(temp_, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!out_) throw InputError(path_ + ": cannot open for writing");
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
  }
}

void AtomicFile::commit() {
  if (out_.is_open()) {
    out_.flush();
    if (!out_) throw InputError(path_ + ": write failed");
    out_.close();
  }
  std::error_code ec;
  if (!std::filesystem::exists(temp_, ec))
    throw InputError(path_ + ": nothing was written");
  std::filesystem::rename(temp_, path_, ec);
  if (ec) throw InputError(path_ + ": cannot move into place: " + ec.message());
  committed_ = true;
}

}  // namespace onetip
