// Command-line option parsing.
#include "volcomp/tools/args.hpp"

#include "volcomp/tools/csv.hpp"

namespace volcomp::tools {
namespace {
bool Matches(const std::string& arg, const std::string& name, const std::string& alias) {
  return arg == name || (!alias.empty() && arg == alias);
}
}  // namespace

bool Args::flag(const std::string& name, const std::string& alias) {
  bool found = false;
  for (std::size_t i = 0; i < args_.size(); ++i) {
    if (!used_[i] && Matches(args_[i], name, alias)) used_[i] = found = true;
  }
  return found;
}

std::optional<std::string> Args::value(const std::string& name, const std::string& alias) {
  std::optional<std::string> result;
  for (std::size_t i = 0; i < args_.size(); ++i) {
    if (used_[i]) continue;
    const std::string& a = args_[i];
    if (Matches(a, name, alias)) {
      if (i + 1 >= args_.size()) throw UsageError("option " + a + " needs a value");
      used_[i] = used_[i + 1] = true;
      result = args_[++i];
    } else if (a.rfind(name + "=", 0) == 0) {
      used_[i] = true;
      result = a.substr(name.size() + 1);
    } else if (!alias.empty() && a.rfind(alias + "=", 0) == 0) {
      used_[i] = true;
      result = a.substr(alias.size() + 1);
    }
  }
  return result;
}

std::vector<std::string> Args::values(const std::string& name) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < args_.size(); ++i) {
    if (used_[i]) continue;
    if (args_[i] == name) {
      if (i + 1 >= args_.size()) throw UsageError("option " + name + " needs a value");
      used_[i] = used_[i + 1] = true;
      out.push_back(args_[++i]);
    } else if (args_[i].rfind(name + "=", 0) == 0) {
      used_[i] = true;
      out.push_back(args_[i].substr(name.size() + 1));
    }
  }
  return out;
}

std::string Args::required(const std::string& name, const std::string& alias) {
  auto v = value(name, alias);
  if (!v) throw UsageError("missing required option " + name);
  return *v;
}

std::optional<double> Args::number(const std::string& name) {
  auto v = value(name);
  if (!v) return std::nullopt;
  auto d = ParseDouble(*v);
  if (!d) throw UsageError("option " + name + ": \"" + *v + "\" is not a number");
  return d;
}

std::optional<long long> Args::integer(const std::string& name) {
  auto v = value(name);
  if (!v) return std::nullopt;
  auto d = ParseInteger(*v);
  if (!d) throw UsageError("option " + name + ": \"" + *v + "\" is not an integer");
  return d;
}

std::vector<std::string> Args::positionals() {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < args_.size(); ++i) {
    if (used_[i]) continue;
    if (args_[i].size() > 1 && args_[i][0] == '-') continue;
    used_[i] = true;
    out.push_back(args_[i]);
  }
  return out;
}

void Args::finish() const {
  for (std::size_t i = 0; i < args_.size(); ++i) {
    if (!used_[i]) throw UsageError("unexpected argument \"" + args_[i] + "\"");
  }
}

}  // namespace volcomp::tools
