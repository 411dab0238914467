// core/config_file.hpp — configuration files (pattern, calibration, options,
// scenario) read as plain YAML 1.2 by yaml-cpp; JSON is YAML too, and OpenCV's
// "%YAML:1.0" first line is accepted, so files cv::FileStorage wrote still read.
//
// Input is bounded before and while it is parsed: at most kMaxConfigBytes,
// nesting at most kMaxConfigDepth levels, every map key a plain scalar given
// once, numbers finite and inside the range the reader asks for (an integer
// that does not fit is refused, never wrapped). Every error is an InputError
//   "<file>:<line>: key '<key path>': <what was expected>, got <what was there>"
// e.g. `pattern.yaml:3: key 'rows': expected an integer in [2, 1000], got "abc"`
// (lines counted from 1; the key path names nested keys as pad.rows or
// indenters[0].keyframes[2].t).
//
// yaml-cpp stays inside config_file.cpp: ConfigNode is an opaque, immutable,
// cheaply copied view into the parsed document.
#pragma once

#include <cstddef>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace YAML {
class Node;
}

namespace onetip {

inline constexpr std::size_t kMaxConfigBytes = 1 << 20;  // 1 MiB
inline constexpr int kMaxConfigDepth = 32;

class ConfigNode {
 public:
  // Reads and parses `path`; its root must be a map. Throws InputError.
  static ConfigNode load(const std::string& path);

  bool present() const;  // the key exists and is not null (`key:` or `key: ~`)
  bool isMap() const;
  bool isSeq() const;
  std::size_t size() const;  // entries of a list or map

  // A child by key or list index; absent children can be asked present().
  ConfigNode operator[](const std::string& key) const;
  ConfigNode operator[](std::size_t index) const;
  std::vector<std::string> keys() const;  // a map's keys in file order

  // Throws if this map holds a key outside `known` ("unknown key").
  void allowOnly(const std::set<std::string>& known) const;
  // Throws unless this is a map (an absent node counts as an empty map).
  void requireMap() const;

  // Scalar conversions; each throws the message above when the value is absent,
  // not of that type or outside [lo, hi].
  double real(double lo, double hi) const;
  int integer(int lo, int hi) const;
  bool flag() const;  // 0 / 1 or true / false
  std::string text() const;
  std::vector<double> reals(std::size_t count, double lo, double hi) const;  // a list of `count` numbers

  // Optional keys: the fallback when absent.
  double real(const std::string& key, double fallback, double lo, double hi) const;
  int integer(const std::string& key, int fallback, int lo, int hi) const;
  bool flag(const std::string& key, bool fallback) const;
  std::string text(const std::string& key, const std::string& fallback) const;

  // "<file>:<line>: key '<path>': why" as an InputError.
  [[noreturn]] void fail(const std::string& why) const;
  const std::string& file() const;
  const std::string& keyPath() const;
  int line() const;  // 1-based; an absent key reports its parent's line

 private:
  struct Impl;
  explicit ConfigNode(std::shared_ptr<const Impl> impl);
  ConfigNode child(const YAML::Node& node, std::string path) const;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace onetip
