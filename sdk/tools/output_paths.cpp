#include "output_paths.hpp"

#include <filesystem>

#include "core/error.hpp"

namespace onetip::tools {
namespace {

namespace fs = std::filesystem;

bool samePath(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
  const fs::path pa = fs::weakly_canonical(fs::absolute(a, ec), ec);
  const fs::path pb = fs::weakly_canonical(fs::absolute(b, ec), ec);
  return pa == pb;
}

}  // namespace

void refuseOutputClashes(const Args& args, const std::vector<std::string>& output_options,
                         const std::vector<std::string>& input_options) {
  for (size_t i = 0; i < output_options.size(); ++i) {
    const auto out = args.optional(output_options[i]);
    if (!out) continue;
    std::vector<std::string> others(output_options.begin() + static_cast<long>(i) + 1, output_options.end());
    others.insert(others.end(), input_options.begin(), input_options.end());
    for (const auto& other : others) {
      const auto path = args.optional(other);
      if (path && samePath(*out, *path))
        throw InputError("option '--" + output_options[i] + "' and '--" + other + "' name the same file (" + *out +
                         "); an output never replaces an input or another output");
    }
  }
}

}  // namespace onetip::tools
