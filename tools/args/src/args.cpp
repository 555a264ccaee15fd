// Command-line option parsing.
#include "volcomp/args/args.hpp"

#include <cerrno>
#include <cstdlib>

#include "volcomp/tools/csv.hpp"  // ParseDouble, ParseInteger

namespace volcomp::args {
namespace {

bool Matches(const std::string& arg, const std::string& name, const std::string& alias) {
  return arg == name || (!alias.empty() && arg == alias);
}

bool IsOptionName(const OptionSpec& o, const std::string& word) {
  return word == o.name || (o.alias != nullptr && word == o.alias);
}

}  // namespace

bool IsNumberWord(const std::string& word) {
  if (tools::ParseDouble(word)) return true;
  // Integers in any base strtoll accepts ("-0x10", "0755"), as `sdo write` values are.
  if (word.empty()) return false;
  errno = 0;
  char* end = nullptr;
  (void)std::strtoll(word.c_str(), &end, 0);
  return end == word.c_str() + word.size() && errno == 0;
}

void Args::Record(Error code, const std::string& message) {
  if (status_.ok()) status_ = Fail(code, message);
}

Args::Args(std::vector<std::string> args) : args_(std::move(args)), used_(args_.size()) {
  for (std::size_t i = 0; i < args_.size(); ++i) {
    if (args_[i] == "--") {
      end_of_options_ = i;
      used_[i] = true;
      break;
    }
  }
}

Args::Args(std::vector<std::string> args, const std::vector<OptionSpec>* spec)
    : args_(std::move(args)), used_(args_.size()), spec_(spec), words_(args_.size()) {
  std::vector<int> count(spec_->size(), 0);
  for (std::size_t i = 0; i < args_.size() && status_.ok(); ++i) {
    const std::string& w = args_[i];
    if (end_of_options_ < i) continue;  // positional after "--"
    if (w == "--") {
      words_[i].kind = Kind::kEndOfOptions;
      end_of_options_ = i;
      used_[i] = true;
      continue;
    }
    if (w.size() < 2 || w[0] != '-' || IsNumberWord(w)) continue;  // positional
    const std::size_t eq = w.rfind("--", 0) == 0 ? w.find('=') : std::string::npos;
    const std::string name = w.substr(0, eq);
    std::size_t k = 0;
    while (k < spec_->size() && !IsOptionName((*spec_)[k], name)) ++k;
    if (k == spec_->size()) {
      Record(Error::kUsage, "unknown option \"" + name + "\"");
      break;
    }
    const OptionSpec& o = (*spec_)[k];
    if (++count[k] > 1 && !o.repeatable) {
      Record(Error::kUsage, std::string("option ") + o.name + " is given twice");
      break;
    }
    words_[i].kind = Kind::kOption;
    words_[i].option = k;
    if (o.value == nullptr) {
      if (eq != std::string::npos)
        Record(Error::kUsage, std::string("option ") + o.name + " takes no value");
      continue;
    }
    if (eq != std::string::npos) {
      words_[i].value = w.substr(eq + 1);
      continue;
    }
    if (i + 1 >= args_.size() || args_[i + 1] == "--") {
      Record(Error::kUsage, std::string("option ") + o.name + " needs a value (" + o.value + ")");
      break;
    }
    words_[i].value = args_[i + 1];
    words_[++i].kind = Kind::kOptionValue;
  }
}

const OptionSpec* Args::Declared(const std::string& name, bool want_value) {
  for (const OptionSpec& o : *spec_) {
    if (!IsOptionName(o, name)) continue;
    if ((o.value != nullptr) != want_value) {
      Record(
          Error::kInvalidArgument,
          "option " + name + (want_value ? " is declared as a flag" : " is declared with a value"));
      return nullptr;
    }
    return &o;
  }
  Record(Error::kInvalidArgument,
         "option " + name + " is not declared in the command's option table");
  return nullptr;
}

std::vector<std::size_t> Args::Occurrences(const OptionSpec& o) const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < words_.size(); ++i) {
    if (words_[i].kind == Kind::kOption && &(*spec_)[words_[i].option] == &o) out.push_back(i);
  }
  return out;
}

bool Args::Flag(const std::string& name, const std::string& alias) {
  if (spec_ != nullptr) {
    const OptionSpec* o = Declared(name, false);
    if (o == nullptr) return false;
    const auto occ = Occurrences(*o);
    for (std::size_t i : occ) used_[i] = true;
    return !occ.empty();
  }
  bool found = false;
  for (std::size_t i = 0; i < args_.size() && !AfterEnd(i); ++i) {
    if (!used_[i] && Matches(args_[i], name, alias)) used_[i] = found = true;
  }
  return found;
}

std::optional<std::string> Args::Value(const std::string& name, const std::string& alias) {
  if (spec_ != nullptr) {
    const OptionSpec* o = Declared(name, true);
    if (o == nullptr) return std::nullopt;
    std::optional<std::string> result;
    for (std::size_t i : Occurrences(*o)) {
      used_[i] = true;
      if (i + 1 < words_.size() && words_[i + 1].kind == Kind::kOptionValue) used_[i + 1] = true;
      result = words_[i].value;
    }
    if (!result && o->default_value != nullptr) result = o->default_value;
    return result;
  }
  std::optional<std::string> result;
  for (std::size_t i = 0; i < args_.size() && !AfterEnd(i); ++i) {
    if (used_[i]) continue;
    const std::string& a = args_[i];
    if (Matches(a, name, alias)) {
      if (i + 1 >= args_.size() || i + 1 == end_of_options_) {
        Record(Error::kUsage, "option " + a + " needs a value");
        return std::nullopt;
      }
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

std::vector<std::string> Args::Values(const std::string& name) {
  std::vector<std::string> out;
  if (spec_ != nullptr) {
    const OptionSpec* o = Declared(name, true);
    if (o == nullptr) return out;
    for (std::size_t i : Occurrences(*o)) {
      used_[i] = true;
      if (i + 1 < words_.size() && words_[i + 1].kind == Kind::kOptionValue) used_[i + 1] = true;
      out.push_back(words_[i].value);
    }
    return out;
  }
  for (std::size_t i = 0; i < args_.size() && !AfterEnd(i); ++i) {
    if (used_[i]) continue;
    if (args_[i] == name) {
      if (i + 1 >= args_.size() || i + 1 == end_of_options_) {
        Record(Error::kUsage, "option " + name + " needs a value");
        return out;
      }
      used_[i] = used_[i + 1] = true;
      out.push_back(args_[++i]);
    } else if (args_[i].rfind(name + "=", 0) == 0) {
      used_[i] = true;
      out.push_back(args_[i].substr(name.size() + 1));
    }
  }
  return out;
}

std::string Args::Required(const std::string& name, const std::string& alias) {
  auto v = Value(name, alias);
  if (!v) {
    Record(Error::kUsage, "missing required option " + name);
    return std::string();
  }
  return *v;
}

std::optional<double> Args::Number(const std::string& name) {
  auto v = Value(name);
  if (!v) return std::nullopt;
  auto d = tools::ParseDouble(*v);
  if (!d) Record(Error::kUsage, "option " + name + ": \"" + *v + "\" is not a number");
  return d;
}

std::optional<long long> Args::Integer(const std::string& name) {
  auto v = Value(name);
  if (!v) return std::nullopt;
  auto d = tools::ParseInteger(*v);
  if (!d) Record(Error::kUsage, "option " + name + ": \"" + *v + "\" is not an integer");
  return d;
}

std::vector<std::string> Args::Positionals() {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < args_.size(); ++i) {
    if (used_[i]) continue;
    const std::string& w = args_[i];
    const bool positional = spec_ != nullptr
                                ? words_[i].kind == Kind::kPositional
                                : AfterEnd(i) || w.size() < 2 || w[0] != '-' || IsNumberWord(w);
    if (!positional) continue;
    used_[i] = true;
    out.push_back(w);
  }
  return out;
}

Outcome Args::Finish() const {
  if (!status_.ok()) return status_;
  for (std::size_t i = 0; i < args_.size(); ++i) {
    if (used_[i]) continue;
    if (spec_ != nullptr && words_[i].kind == Kind::kOptionValue) continue;
    if (spec_ != nullptr && words_[i].kind == Kind::kOption) {
      return Fail(Error::kUsage, "option " + args_[i] + " does not apply here");
    }
    return Fail(Error::kUsage, "unexpected argument \"" + args_[i] + "\"");
  }
  return Outcome::Ok();
}

}  // namespace volcomp::args
