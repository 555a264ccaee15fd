// Command-line options of the command layers (`volcomp`, tools/cli; `volcomp-sim`, host-sim/app):
// `--name value`, `--name=value`, flags and positionals. No library below them uses it.
//
// Every `volcomp` command declares its options in one table of OptionSpec rows
// (beside its code, tools/cli/cmd_*.cpp). The same rows drive `volcomp help COMMAND` and this
// parser, so the help cannot disagree with what is parsed. With a table, Args classifies the words
// once:
//   - a word naming a declared option is that option; a value option takes the next word as its
//     value whatever it looks like (`--tool-offset-mm -1,2,3`, `--name -X-Y-Z`), or the text
//     after '=' (`--name=-X-Y-Z`); a flag takes no value;
//   - `--` ends the options: every later word is a positional argument;
//   - "-" (standard input) and every word that parses as a number (`-5000`, `-0.5`, `-1e3`,
//     `-0x10`) are positional arguments;
//   - any other word starting with '-' is an unknown option (a kUsage failure naming it);
//   - a non-repeatable option given twice is a kUsage failure;
//   - an absent option with a declared default yields that default, so the default shown by the
//     help is the one in force.
// Asking for an option the table does not declare is a programming error (a kInvalidArgument
// failure naming it). Without a table (`Args(words)`, used by in-process tests) options are
// recognised as they are queried, with the same rules for numbers and `--`.
//
// Errors are sticky, like a stream's fail state: a query that fails (missing value, bad number,
// missing required option) returns an empty value and keeps the first failure (kUsage); Finish()
// returns it, or a failure naming the first word given but not consumed, so typos are never
// ignored. Read every option, then check once:
//   const auto out = args.Value("--output", "-o");
//   const bool json = args.Flag("--json");
//   VOLCOMP_TRY(args.Finish());
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::args {

/// One option of a command, as parsed and as shown by `volcomp help COMMAND`.
struct OptionSpec {
  const char* name;                     // "--pitch"
  const char* alias = nullptr;          // "-o", or nullptr
  const char* value = nullptr;          // value placeholder ("P", "FILE"); nullptr = a flag
  const char* unit = nullptr;           // unit of the value ("mm", "µm", "deg"); nullptr = none
  const char* default_value = nullptr;  // used when absent; nullptr = no default (absent is absent)
  const char* help = "";                // what it does; mention conditional defaults here
  bool repeatable = false;              // may be given more than once (values())
};

class Args {
 public:
  /// Options recognised as they are queried (no table).
  explicit Args(std::vector<std::string> args);
  /// Options classified against `spec` (which must outlive this object); an unknown option, a
  /// missing value, a value given to a flag or a repeated option is the failure status() holds.
  Args(std::vector<std::string> args, const std::vector<OptionSpec>* spec);

  /// True when `name` (or `alias`) is present as a flag; consumes it.
  bool Flag(const std::string& name, const std::string& alias = "");
  /// Value of `--name value` or `--name=value`; the declared default when absent (nullopt when
  /// there is none).
  std::optional<std::string> Value(const std::string& name, const std::string& alias = "");
  /// Every value of a repeatable option, in order.
  std::vector<std::string> Values(const std::string& name);
  /// Like Value(), but absent is a failure ("missing required option --name"); "" then.
  std::string Required(const std::string& name, const std::string& alias = "");
  /// Numeric options (a value that is not a number is a failure; nullopt then).
  std::optional<double> Number(const std::string& name);
  std::optional<long long> Integer(const std::string& name);
  /// Remaining non-option arguments, in order; consumes them.
  std::vector<std::string> Positionals();
  /// The first failure, or one naming the first word given but not consumed, or success.
  Outcome Finish() const;
  /// The first failure so far (classification included), or success.
  const Outcome& status() const { return status_; }

 private:
  enum class Kind { kPositional, kOption, kOptionValue, kEndOfOptions };
  struct Word {
    Kind kind = Kind::kPositional;
    std::size_t option = 0;  // index into spec_ for kOption
    std::string value;       // kOption: its value (value options)
  };
  const OptionSpec* Declared(const std::string& name, bool want_value);
  void Record(Error code, const std::string& message);
  std::vector<std::size_t> Occurrences(const OptionSpec& o) const;
  bool AfterEnd(std::size_t i) const { return i > end_of_options_; }

  std::vector<std::string> args_;
  std::vector<bool> used_;
  const std::vector<OptionSpec>* spec_ = nullptr;
  std::vector<Word> words_;  // with a table: the classification of args_
  std::size_t end_of_options_ = static_cast<std::size_t>(-1);  // index of "--", or none
  Outcome status_;
};

/// True for a word that parses as a number (a value, never an option), e.g. "-5000".
bool IsNumberWord(const std::string& word);

}  // namespace volcomp::args
