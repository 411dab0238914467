#include "capture/folder_source.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include "capture/image_file.hpp"
#include "core/error.hpp"

namespace onetip::capture {

namespace fs = std::filesystem;

namespace {
bool isImageFile(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp" || ext == ".tif" ||
         ext == ".tiff";
}
}  // namespace

void FolderSourceOptions::validate() const {
  if (!(nominal_rate_hz > 0.0) || !std::isfinite(nominal_rate_hz))
    throw InputError("folder source: nominal_rate_hz: must be a positive number");
  check.validate();
}

FolderSource::FolderSource(const std::string& folder, FolderSourceOptions options)
    : folder_(folder), options_(options), checker_(options.check) {
  options_.validate();
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw InputError("input '" + folder + "': no such folder");
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (entry.is_regular_file(ec) && isImageFile(entry.path()))
      files_.push_back(entry.path().string());
  if (ec) throw InputError("input '" + folder + "': cannot list the folder: " + ec.message());
  if (files_.empty()) throw InputError("input '" + folder + "': the folder holds no image frames");
  std::sort(files_.begin(), files_.end());
}

Frame FolderSource::next() {
  Frame f;
  if (position_ >= files_.size()) return f;  // end
  const std::string& file = files_[position_];
  f.index = static_cast<std::int64_t>(position_);
  f.timestamp_s = static_cast<double>(position_) / options_.nominal_rate_hz;
  ++position_;
  ImageLimits limits;
  limits.expected = checker_.streamSize();
  GreyImage image = readGreyImage(file, limits);
  const auto problem = image.problem ? image.problem : checker_.problem(image.grey);
  return deliver(std::move(f), std::move(image.grey), problem, fs::path(file).filename().string());
}

}  // namespace onetip::capture
