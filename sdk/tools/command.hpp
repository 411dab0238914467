// tools/command.hpp — the `onetip` program's subcommands and their arguments.
//
// Each subcommand lives in its own cmd_<name>.cpp and registers itself with a
// static CommandRegistrar. Arguments are "--key value" (or "--key=value")
// options and "--flag" switches; unknown options, missing values, a value
// given to a switch and missing required options are InputErrors with a
// one-line message naming the option.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace onetip::tools {

struct OptionSpec {
  std::string name;  // without the leading "--"
  std::string help;
  bool is_flag = false;
  bool required = false;
};

class Args {
 public:
  Args(const std::vector<OptionSpec>& specs, const std::vector<std::string>& argv);
  bool has(const std::string& name) const { return values_.count(name) > 0; }
  const std::string& get(const std::string& name) const;  // required option
  std::optional<std::string> optional(const std::string& name) const;
  int getInt(const std::string& name, int fallback) const;
  double getDouble(const std::string& name, double fallback) const;

 private:
  std::map<std::string, std::string> values_;
};

struct Command {
  std::string name;
  std::string summary;
  std::vector<OptionSpec> options;
  std::function<int(const Args&)> run;
};

std::map<std::string, Command>& commandRegistry();

struct CommandRegistrar {
  explicit CommandRegistrar(Command c);
};

std::string usageOf(const Command& c);

}  // namespace onetip::tools
