#include "core/config_file.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace onetip {

struct ConfigNode::Impl {
  std::shared_ptr<const std::string> file;
  YAML::Node node;
  std::string path;  // key path from the root, "" for the root
  int line = 1;
};

namespace {

constexpr std::size_t kMaxConfigValues = 1000000;  // aliases can repeat a subtree without growing the file

[[noreturn]] void failAt(const std::string& file, int line, const std::string& why) {
  throw InputError(file + ":" + std::to_string(std::max(line, 1)) + ": " + why);  // yaml-cpp may not know the line
}

std::string readBounded(const std::string& path) {
  requireInputFile(path);
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path + ": cannot read (" + ec.message() + ")");
  if (bytes > kMaxConfigBytes)
    throw InputError(path + ": " + std::to_string(bytes) + " bytes; a configuration file may hold at most " +
                     std::to_string(kMaxConfigBytes) + " bytes");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open for reading");
  std::ostringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  if (s.size() > kMaxConfigBytes) throw InputError(path + ": grew past the size limit while being read");
  // OpenCV's FileStorage writes "%YAML:1.0", which is not a YAML directive;
  // blank it (keeping the line count) so its files read as YAML 1.2.
  if (s.rfind("%YAML:", 0) == 0) s.replace(0, s.find('\n') == std::string::npos ? s.size() : s.find('\n'), "");
  return s;
}

std::string describe(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a map";
  std::string s = n.Scalar();
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return "\"" + s + "\"";
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Every map key a scalar given once, nesting and size bounded (walked with an
// explicit stack: the document's depth never becomes ours).
void checkStructure(const YAML::Node& root, const std::string& file) {
  std::vector<std::pair<YAML::Node, int>> stack{{root, 0}};
  std::size_t visited = 0;
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    const int line = node.Mark().line + 1;
    if (++visited > kMaxConfigValues)
      failAt(file, line, "more than " + std::to_string(kMaxConfigValues) + " values (aliases repeating a subtree?)");
    if (depth > kMaxConfigDepth)
      failAt(file, line, "nested deeper than " + std::to_string(kMaxConfigDepth) + " levels");
    if (node.IsSequence()) {
      for (const auto& child : node) stack.push_back({child, depth + 1});
    } else if (node.IsMap()) {
      std::set<std::string> seen;
      for (const auto& kv : node) {
        const int key_line = kv.first.Mark().line + 1;
        if (!kv.first.IsScalar() || kv.first.Scalar().empty())
          failAt(file, key_line, "a key must be a plain name, got " + describe(kv.first));
        if (!seen.insert(kv.first.Scalar()).second)
          failAt(file, key_line, "key '" + kv.first.Scalar() + "': given twice in the same map");
        stack.push_back({kv.second, depth + 1});
      }
    }
  }
}

// The line (1-based) of a document marker ("---" or "...") that follows
// content, i.e. starts or ends a second document; 0 when there is none. A
// leading "%YAML" directive and "---" before any content belong to the first.
int secondDocumentLine(const std::string& text) {
  bool content = false;
  int line = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view l(text.data() + start, end - start);
    ++line;
    const bool marker = (l.substr(0, 3) == "---" || l.substr(0, 3) == "...") &&
                        (l.size() == 3 || l[3] == ' ' || l[3] == '\t' || l[3] == '\r');
    if (marker && content) return line;
    const std::size_t first = l.find_first_not_of(" \t\r");
    if (!marker && first != std::string_view::npos && l[first] != '#' && l[first] != '%') content = true;
    start = end + 1;
  }
  return 0;
}

bool parseReal(const std::string& s, double& out) {
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (first != last && *first == '+') ++first;
  const auto r = std::from_chars(first, last, out);
  return r.ec == std::errc() && r.ptr == last && first != last;
}

}  // namespace

ConfigNode::ConfigNode(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

ConfigNode ConfigNode::load(const std::string& path) {
  const std::string text = readBounded(path);
  // One document only. Found from the text: YAML::LoadAll of Debian's
  // yaml-cpp 0.7 never returns on some malformed input (the 2-byte file ",\n"
  // makes it loop and grow without bound; upstream issue 1319), YAML::Load does.
  const int second_document = secondDocumentLine(text);
  if (second_document > 0) failAt(path, second_document, "holds more than one YAML document");
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    const std::string why = dynamic_cast<const YAML::DeepRecursion*>(&e) ? "nested too deeply" : e.msg;
    failAt(path, e.mark.line + 1, "not valid YAML or JSON: " + why);
  }
  if (!root.IsDefined() || root.IsNull()) failAt(path, 1, "the file is empty; expected a map of keys");
  if (!root.IsMap()) failAt(path, root.Mark().line + 1, "expected a map of keys, got " + describe(root));
  checkStructure(root, path);
  return ConfigNode(std::make_shared<const Impl>(Impl{std::make_shared<const std::string>(path), root, "", 1}));
}

bool ConfigNode::present() const { return impl_->node.IsDefined() && !impl_->node.IsNull(); }
bool ConfigNode::isMap() const { return impl_->node.IsMap(); }
bool ConfigNode::isSeq() const { return impl_->node.IsSequence(); }
std::size_t ConfigNode::size() const { return present() ? impl_->node.size() : 0; }
const std::string& ConfigNode::file() const { return *impl_->file; }
const std::string& ConfigNode::keyPath() const { return impl_->path; }
int ConfigNode::line() const { return impl_->line; }

ConfigNode ConfigNode::child(const YAML::Node& node, std::string path) const {
  // Copy-constructed, never assigned: assigning a yaml-cpp Node writes through it.
  const int line = node.IsDefined() && node.Mark().line >= 0 ? node.Mark().line + 1 : impl_->line;
  return ConfigNode(std::make_shared<const Impl>(Impl{impl_->file, node, std::move(path), line}));
}

ConfigNode ConfigNode::operator[](const std::string& key) const {
  const YAML::Node& self = impl_->node;
  const YAML::Node found = self.IsMap() ? self[key] : YAML::Node(YAML::NodeType::Undefined);
  // A missing key comes back as an invalid "zombie" Node that throws when asked its type.
  return child(found.IsDefined() ? found : YAML::Node(YAML::NodeType::Undefined),
               impl_->path.empty() ? key : impl_->path + "." + key);
}

ConfigNode ConfigNode::operator[](std::size_t index) const {
  const YAML::Node& self = impl_->node;
  return child(self.IsSequence() && index < self.size() ? self[index] : YAML::Node(YAML::NodeType::Undefined),
               impl_->path + "[" + std::to_string(index) + "]");
}

std::vector<std::string> ConfigNode::keys() const {
  std::vector<std::string> out;
  if (impl_->node.IsMap())
    for (const auto& kv : impl_->node) out.push_back(kv.first.Scalar());
  return out;
}

void ConfigNode::requireMap() const {
  if (present() && !isMap()) fail("expected a map of keys, got " + describe(impl_->node));
}

void ConfigNode::allowOnly(const std::set<std::string>& known) const {
  requireMap();
  for (const auto& k : keys())
    if (!known.count(k)) (*this)[k].fail("unknown key");
}

void ConfigNode::fail(const std::string& why) const {
  failAt(*impl_->file, impl_->line, impl_->path.empty() ? why : "key '" + impl_->path + "': " + why);
}

double ConfigNode::real(double lo, double hi) const {
  const std::string expected = "expected a number in [" + number(lo) + ", " + number(hi) + "]";
  if (!present()) fail("missing, " + expected);
  const YAML::Node& n = impl_->node;
  double v = 0;
  if (!n.IsScalar() || n.Tag() == "!" || !parseReal(n.Scalar(), v) || !std::isfinite(v) || v < lo || v > hi)
    fail(expected + ", got " + describe(n));
  return v;
}

int ConfigNode::integer(int lo, int hi) const {
  const std::string expected = "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!present()) fail("missing, " + expected);
  const YAML::Node& n = impl_->node;
  if (!n.IsScalar() || n.Tag() == "!") fail(expected + ", got " + describe(n));
  const std::string& s = n.Scalar();
  const char* first = s.data() + (!s.empty() && s[0] == '+' ? 1 : 0);
  long long v = 0;
  const auto r = std::from_chars(first, s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) {
    double d = 0;  // an integral number written as a real ("6.0") is accepted; anything else is not
    if (!parseReal(s, d) || !(std::abs(d) < 9e15) || d != std::floor(d)) fail(expected + ", got " + describe(n));
    v = static_cast<long long>(d);
  }
  if (v < lo || v > hi) fail(expected + ", got " + describe(n));
  return static_cast<int>(v);
}

bool ConfigNode::flag() const {
  const std::string expected = "expected 0 or 1 (or true / false)";
  if (!present()) fail("missing, " + expected);
  const YAML::Node& n = impl_->node;
  if (n.IsScalar() && n.Tag() != "!") {
    const std::string& s = n.Scalar();
    if (s == "1" || s == "true" || s == "True" || s == "TRUE") return true;
    if (s == "0" || s == "false" || s == "False" || s == "FALSE") return false;
  }
  fail(expected + ", got " + describe(n));
}

std::string ConfigNode::text() const {
  if (!present()) fail("missing, expected a text value");
  if (!impl_->node.IsScalar()) fail("expected a text value, got " + describe(impl_->node));
  return impl_->node.Scalar();
}

std::vector<double> ConfigNode::reals(std::size_t count, double lo, double hi) const {
  if (!isSeq() || size() != count)
    fail("expected a list of " + std::to_string(count) + " numbers, got " + describe(impl_->node));
  std::vector<double> v;
  for (std::size_t i = 0; i < count; ++i) v.push_back((*this)[i].real(lo, hi));
  return v;
}

double ConfigNode::real(const std::string& key, double fallback, double lo, double hi) const {
  const ConfigNode n = (*this)[key];
  return n.present() ? n.real(lo, hi) : fallback;
}

int ConfigNode::integer(const std::string& key, int fallback, int lo, int hi) const {
  const ConfigNode n = (*this)[key];
  return n.present() ? n.integer(lo, hi) : fallback;
}

bool ConfigNode::flag(const std::string& key, bool fallback) const {
  const ConfigNode n = (*this)[key];
  return n.present() ? n.flag() : fallback;
}

std::string ConfigNode::text(const std::string& key, const std::string& fallback) const {
  const ConfigNode n = (*this)[key];
  return n.present() ? n.text() : fallback;
}

}  // namespace onetip
