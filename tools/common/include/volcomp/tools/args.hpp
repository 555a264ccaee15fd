// Command-line options for the PC tool: `--name value`, `--name=value`, flags and positionals.
//
// Usage: Args a(argv_vector); auto out = a.value("-o", "--output"); bool json = a.flag("--json");
// a.finish() throws UsageError for anything left unconsumed, so typos are never ignored.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace volcomp::tools {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Args {
 public:
  explicit Args(std::vector<std::string> args) : args_(std::move(args)), used_(args_.size()) {}

  /// True when `name` (or `alias`) is present as a flag; consumes it.
  bool flag(const std::string& name, const std::string& alias = "");
  /// Value of `--name value` or `--name=value`; nullopt when absent; UsageError when the value is
  /// missing. The last occurrence wins.
  std::optional<std::string> value(const std::string& name, const std::string& alias = "");
  /// Every value of a repeatable option, in order.
  std::vector<std::string> values(const std::string& name);
  /// Like value(), but throws UsageError when absent.
  std::string required(const std::string& name, const std::string& alias = "");
  /// Numeric option helpers (UsageError on a bad number).
  std::optional<double> number(const std::string& name);
  std::optional<long long> integer(const std::string& name);
  /// Remaining non-option arguments, in order; consumes them.
  std::vector<std::string> positionals();
  /// Throws UsageError naming the first unconsumed argument.
  void finish() const;

 private:
  std::vector<std::string> args_;
  std::vector<bool> used_;
};

}  // namespace volcomp::tools
