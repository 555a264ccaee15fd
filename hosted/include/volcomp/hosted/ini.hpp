// INI text with line numbers: the one reader and writer of the board's configuration files (the
// PC tool's board file, `volcomp config`, and volcomp-fw-linux's configuration file).
//
//   [section] or [section ARG]   section names case-insensitive; ARG (an axis name) too
//   key = value                  keys case-insensitive; values trimmed, kept as written
//   '#' or ';' at the start of a line or after white space starts a comment
//
// Errors are IniError: the source (file name), the 1-based line (0: about the file as a whole)
// and the message, "source:line: message" as text. Messages name the key and quote the value:
// "node_id = 200: above the highest value 127", "feedback: expected sync | latest, got 'x'",
// "unknown key 'nod_id' in [board] (known: ...)". Every check is made before anything is used,
// so a refused file changes nothing. Not thread-safe (plain values).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::hosted {

/// Why an INI text was refused, and where.
struct IniError {
  std::string source;  // the file (or the name given to the parser)
  int line = 0;        // 1-based; 0 when the problem is not on one line
  std::string message;
  Error code = Error::kInputInvalid;  // kIoError when the file could not be read
  /// "source:line: message", or "source: message" without a line.
  std::string ToString() const;
  Failure ToFailure() const { return Failure{code, ToString()}; }
};

template <typename T>
using IniExpected = Expected<T, IniError>;
using IniOutcome = Expected<void, IniError>;

struct IniEntry {
  std::string key;  // lower case
  std::string value;
  int line = 0;
};

struct IniSection {
  std::string name;  // lower case: "axis"
  std::string arg;   // as written: "X" (empty for [board])
  int line = 0;
  std::vector<IniEntry> entries;  // in file order, each key once

  /// "[axis X]", "[board]".
  std::string Title() const;
  /// The entry of `key` (any case: keys are compared in lower case), or null.
  const IniEntry* Find(const std::string& key) const;
};

class IniDocument {
 public:
  /// Splits `text` (named `source` in errors) into sections of entries: refuses a line that is
  /// neither, a key outside a section, a section or a key given twice.
  static IniExpected<IniDocument> Parse(const std::string& text, const std::string& source);
  /// Reads and parses a file ("PATH: cannot read the configuration file", kIoError).
  static IniExpected<IniDocument> ReadFile(const std::string& path);

  const std::string& source() const { return source_; }
  const std::vector<IniSection>& sections() const { return sections_; }
  /// The section [name arg] (arg compared case-insensitively), or null.
  const IniSection* Find(const std::string& name, const std::string& arg = "") const;

  /// Refuses a section not in `known`: "board" for [board], "axis NAME" for [axis ARG].
  IniOutcome CheckSections(const std::vector<std::string>& known) const;

  /// An error at `line` (0: the file), or at an entry: "KEY: what".
  Unexpected<IniError> FailAt(int line, const std::string& message) const;
  Unexpected<IniError> FailKey(const IniEntry& e, const std::string& what) const {
    return FailAt(e.line, e.key + ": " + what);
  }

 private:
  std::string source_;
  std::vector<IniSection> sections_;
};

/// One key a reader understands in a section, and what it does with the entry.
struct IniKey {
  std::string key;
  std::function<IniOutcome(const IniEntry&)> read;
};

/// Runs each entry of `section` (null: nothing to do) through its key's reader (keys in any case),
/// in file order; an unknown key is refused with the known ones (in `keys` order).
IniOutcome ReadKeys(const IniDocument& doc,
                    const IniSection* section,
                    const std::vector<IniKey>& keys);

// ---- Values. Each refusal names the entry; `of` (optional) says whose limit it is.

/// An integer: decimal or 0x hex, negative with '-'; within [low, high]
/// ("KEY = V: above the highest value H" + of).
IniExpected<int64_t> ReadInteger(const IniDocument& doc,
                                 const IniEntry& e,
                                 int64_t low,
                                 int64_t high,
                                 const std::string& of = "");
/// A decimal (negative with '-') with up to `decimals` decimals (0..9) as an exact integer
/// x 10^decimals ("-20.5" with 2 -> -2050), within [low, high] of that integer
/// ("KEY = V: below the lowest value L (x 1e-2)" + of).
IniExpected<int64_t> ReadDecimal(const IniDocument& doc,
                                 const IniEntry& e,
                                 int decimals,
                                 int64_t low,
                                 int64_t high,
                                 const std::string& of = "");
/// ReadDecimal with 9 decimals: "0.0005" -> 500000.
IniExpected<int64_t> ReadDecimalE9(const IniDocument& doc,
                                   const IniEntry& e,
                                   int64_t low,
                                   int64_t high,
                                   const std::string& of = "");
/// true/yes/on/1 or false/no/off/0 (any case).
IniExpected<bool> ReadBool(const IniDocument& doc, const IniEntry& e);
/// The position of the value (any case) in `names` ("KEY: expected a | b, got 'V'").
IniExpected<size_t> ReadChoice(const IniDocument& doc,
                               const IniEntry& e,
                               const std::vector<std::string>& names);
/// Why `v` is outside [low, high] ("above the highest value 127"), or "".
std::string RangeViolation(int64_t v, int64_t low, int64_t high);
/// `s` without leading and trailing white space.
std::string Trim(const std::string& s);

/// An INI text: comments, sections, `key = value` lines (with a comment aligned after them).
class IniWriter {
 public:
  void Comment(const std::string& text);
  /// A blank line (except at the start), then "[title]".
  void Section(const std::string& title);
  void Key(const std::string& key, const std::string& value, const std::string& comment = "");
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

/// "0.0005" for 500000: an integer x 1e9 as the shortest exact decimal.
std::string FormatDecimalE9(int64_t value);
/// "0x080": a number in hex with at least `digits` digits.
std::string FormatHex(uint32_t value, int digits);

}  // namespace volcomp::hosted
