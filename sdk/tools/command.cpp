#include "command.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace onetip::tools {

Args::Args(const std::vector<OptionSpec>& specs, const std::vector<std::string>& argv) {
  std::map<std::string, const OptionSpec*> by_name;
  for (const auto& s : specs) by_name[s.name] = &s;
  for (size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a.rfind("--", 0) != 0) throw InputError("unexpected argument '" + a + "'");
    // "--key=value" is "--key value"; only the first '=' splits, so a value may hold more.
    const size_t eq = a.find('=');
    const std::string name = a.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
    auto it = by_name.find(name);
    if (it == by_name.end()) throw InputError("unknown option '--" + name + "'");
    if (it->second->is_flag) {
      if (eq != std::string::npos)
        throw InputError("option '--" + name + "' is a switch and takes no value ('" + a + "')");
      values_[name] = "1";
    } else if (eq != std::string::npos) {
      values_[name] = a.substr(eq + 1);
    } else {
      if (i + 1 >= argv.size()) throw InputError("option '--" + name + "' needs a value");
      values_[name] = argv[++i];
    }
  }
  for (const auto& s : specs)
    if (s.required && !has(s.name)) throw InputError("missing required option '--" + s.name + "'");
}

const std::string& Args::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw InputError("missing required option '--" + name + "'");
  return it->second;
}

std::optional<std::string> Args::optional(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

int Args::getInt(const std::string& name, int fallback) const {
  auto v = optional(name);
  if (!v) return fallback;
  char* end = nullptr;
  const long x = std::strtol(v->c_str(), &end, 10);
  if (v->empty() || *end != '\0' || x < -2147483647L || x > 2147483647L)
    throw InputError("option '--" + name + "': '" + *v + "' is not an integer");
  return static_cast<int>(x);
}

double Args::getDouble(const std::string& name, double fallback) const {
  auto v = optional(name);
  if (!v) return fallback;
  char* end = nullptr;
  const double x = std::strtod(v->c_str(), &end);
  if (v->empty() || *end != '\0' || !std::isfinite(x))
    throw InputError("option '--" + name + "': '" + *v + "' is not a number");
  return x;
}

std::map<std::string, Command>& commandRegistry() {
  static std::map<std::string, Command> registry;
  return registry;
}

CommandRegistrar::CommandRegistrar(Command c) {
  const std::string name = c.name;
  commandRegistry().emplace(name, std::move(c));
}

std::string usageOf(const Command& c) {
  std::ostringstream out;
  out << "usage: onetip " << c.name;
  for (const auto& o : c.options)
    out << (o.required ? " " : " [") << "--" << o.name << (o.is_flag ? "" : " VALUE")
        << (o.required ? "" : "]");
  out << "\n\n" << c.summary << "\n\noptions (--name VALUE or --name=VALUE):\n";
  for (const auto& o : c.options) out << "  --" << o.name << "\n      " << o.help << "\n";
  return out.str();
}

}  // namespace onetip::tools
