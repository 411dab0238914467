#include "capture/open_frame_source.hpp"

#include <cctype>
#include <filesystem>
#include <map>
#include <mutex>

#include "capture/folder_source.hpp"
#include "capture/session_source.hpp"
#include "capture/v4l2_source.hpp"
#include "capture/video_source.hpp"
#include "core/error.hpp"

namespace onetip::capture {

namespace {

struct SchemeRegistry {
  std::mutex mutex;
  std::map<std::string, FrameSourceFactory> factories;
};

SchemeRegistry& registry() {
  static SchemeRegistry r;
  return r;
}

// "SCHEME" of "SCHEME:REST" when SCHEME is two or more letters or digits.
std::string schemeOf(const std::string& spec) {
  const size_t colon = spec.find(':');
  if (colon == std::string::npos || colon < 2) return {};
  for (size_t i = 0; i < colon; ++i)
    if (!std::isalnum(static_cast<unsigned char>(spec[i]))) return {};
  return spec.substr(0, colon);
}

}  // namespace

void registerFrameSourceScheme(const std::string& scheme, FrameSourceFactory factory) {
  if (schemeOf(scheme + ":") != scheme)
    throw InputError("frame source scheme '" + scheme + "': must be two or more letters or digits");
  SchemeRegistry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.factories[scheme] = std::move(factory);
}

std::unique_ptr<FrameSource> openFrameSource(const std::string& spec) {
  if (spec.empty()) throw InputError("input: empty frame source specification");
  const std::string scheme = schemeOf(spec);
  if (!scheme.empty()) {
    const std::string rest = spec.substr(scheme.size() + 1);
    if (scheme == "v4l2") return std::make_unique<V4l2Source>(rest);
    FrameSourceFactory factory;
    {
      SchemeRegistry& r = registry();
      std::lock_guard<std::mutex> lock(r.mutex);
      auto it = r.factories.find(scheme);
      if (it != r.factories.end()) factory = it->second;
    }
    if (!factory)
      throw InputError("input '" + spec + "': unknown source type '" + scheme +
                       ":' (not available in this program)");
    return factory(rest);
  }
  std::error_code ec;
  if (std::filesystem::is_directory(spec, ec))
    return isSessionFolder(spec) ? std::unique_ptr<FrameSource>(std::make_unique<SessionSource>(spec))
                                 : std::make_unique<FolderSource>(spec);
  if (std::filesystem::is_regular_file(spec, ec)) return std::make_unique<VideoSource>(spec);
  throw InputError("input '" + spec + "': no such folder, file or device");
}

}  // namespace onetip::capture
