#include "output_paths.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
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

// Why a new entry cannot be made in `folder` ("" when it can).
std::string folderProblem(const fs::path& folder) {
  const std::string name = folder.empty() ? std::string(".") : folder.string();
  struct stat st {};
  if (::stat(name.c_str(), &st) != 0)
    return errno == ENOENT || errno == ENOTDIR
               ? "the folder '" + name + "' does not exist"
               : "cannot reach the folder '" + name + "' (" + std::strerror(errno) + ")";
  if (!S_ISDIR(st.st_mode)) return "'" + name + "' is not a folder";
  if (::access(name.c_str(), W_OK | X_OK) != 0)
    return "cannot write in the folder '" + name + "' (" + std::strerror(errno) + ")";
  return "";
}

[[noreturn]] void refuse(const std::string& what, const std::string& path, const std::string& why) {
  throw InputError(what + " " + path + ": " + why);
}

}  // namespace

void requireWritableFile(const std::string& what, const std::string& path) {
  if (path.empty()) refuse(what, "''", "an empty path");
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) refuse(what, path, "is a directory; name a file to write");
    if (!S_ISREG(st.st_mode))
      refuse(what, path, "exists and is not a regular file (a device, socket or FIFO); refusing to replace it");
  }
  const std::string why = folderProblem(fs::path(path).parent_path());
  if (!why.empty()) refuse(what, path, why);
}

void requireCreatableFolder(const std::string& what, const std::string& path) {
  fs::path t = fs::path(path).lexically_normal();
  if (!t.has_filename()) t = t.parent_path();  // "out/" is "out"
  if (t.empty() || t.filename() == "." || t.filename() == "..")
    refuse(what, path, "name a new or empty folder to create (not . or ..)");
  struct stat st {};
  if (::stat(t.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode)) refuse(what, path, "exists and is not a folder; name a new or empty folder to create");
    std::error_code ec;
    if (!fs::is_empty(t, ec) || ec)
      refuse(what, path,
             "exists and is not an empty folder; nothing is ever deleted or replaced: choose another one or remove it");
  }
  const std::string why = folderProblem(t.parent_path());
  if (!why.empty()) refuse(what, path, why);
}

void refuseUnwritableOutputs(const Args& args, const std::vector<std::string>& file_options,
                             const std::vector<std::string>& folder_options) {
  for (const auto& name : file_options)
    if (const auto path = args.optional(name)) requireWritableFile("--" + name, *path);
  for (const auto& name : folder_options)
    if (const auto path = args.optional(name)) requireCreatableFolder("--" + name, *path);
}

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
