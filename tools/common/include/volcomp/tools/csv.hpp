// Plain CSV reading for the PC tool: header-named columns, numbers with line-numbered errors.
//
// Accepted syntax: comma-separated fields (a ';' or TAB separator is detected from the header
// line), optional double quotes around a field ("" for a literal quote), '#' starts a comment line,
// blank lines are skipped, CRLF line ends are accepted. The first non-comment line is the header.
// Every data row must have as many fields as the header. Errors carry the 1-based line number of
// the input and name the column, e.g. `points.csv:12: column "dz_um": "abc" is not a number`.
//
// Decimal comma (Russian/European spreadsheets): in a ';' or TAB separated file, numbers may be
// written "150,71". The file's decimal mark is detected from its data: a file that writes one
// number with a decimal comma must write them all so; a decimal point there is an error naming
// both lines (a ',' separated file cannot hold decimal commas).
//
// Preamble: comment lines before the header of the form `# key: value` (key: a letter, then up to
// four words of letters, digits and '_') are kept in order as the file's preamble, e.g. the test
// conditions of a measurement (`# machine: MILL-7`, `# air temperature C: 20.4`).
//
// Errors are Failures (kInputInvalid; kIoError when a file cannot be read) whose message is the
// whole text, e.g. `points.csv:12: column "dz_um": "abc" is not a number`. The reader runs in time
// and stack linear in the input (no regular expressions, no recursion per character).
#pragma once

#include <array>
#include <cstddef>
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::tools {

class CsvTable;
struct CsvMeta;

/// One data row of a CsvTable.
class CsvRow {
 public:
  /// 1-based line number in the source.
  std::size_t line() const { return line_; }
  /// Every field's raw text, in header order.
  const std::vector<std::string>& fields() const { return fields_; }
  /// Raw text of a named column; a Failure when the header has no such column.
  Expected<std::string> Text(const std::string& column) const;
  /// Field parsed as a finite double (decimal mark of the file); a Failure naming line and column.
  Expected<double> Number(const std::string& column) const;
  Expected<double> Number(std::size_t column) const;
  /// Field parsed as a base-10 integer; a Failure naming line and column.
  Expected<long long> Integer(const std::string& column) const;
  /// Named field as a finite double; nullopt when the column is absent or the field is empty.
  Expected<std::optional<double>> OptionalNumber(const std::string& column) const;

 private:
  friend class CsvTable;
  std::shared_ptr<const CsvMeta> meta_;
  std::size_t line_ = 0;
  std::vector<std::string> fields_;
};

/// One `# key: value` line of the preamble.
struct CsvPreambleEntry {
  std::string key;
  std::string value;
  std::size_t line = 0;
};

/// Source name and header shared by a table and its rows.
struct CsvMeta {
  std::string source;
  std::size_t header_line = 0;
  std::vector<std::string> header;
  char separator = ',';
  bool decimal_comma = false;    // numbers are written "1,5" (';' or TAB separated files only)
  std::size_t decimal_line = 0;  // first line whose numbers show the file's decimal mark
  std::vector<CsvPreambleEntry> preamble;

  std::optional<std::size_t> find(const std::string& column) const;
  /// Index of a column, or a Failure "missing column" at the header line.
  Expected<std::size_t> Require(const std::string& column) const;
  /// Failure{kInputInvalid, "source:line: message"}.
  Failure LineFailure(std::size_t line, const std::string& message) const;
};

/// A whole CSV file in memory.
class CsvTable {
 public:
  /// Reads `in`; `source` names it in error messages (a path, or "<stdin>").
  static Expected<CsvTable> Read(std::istream& in, const std::string& source);
  /// Reads the file at `path` (kIoError when it cannot be opened or read).
  static Expected<CsvTable> ReadFile(const std::string& path);
  static Expected<CsvTable> ReadString(const std::string& text,
                                       const std::string& source = "<string>");

  const std::string& source() const { return meta_->source; }
  const std::vector<std::string>& header() const { return meta_->header; }
  const std::vector<CsvRow>& rows() const { return rows_; }
  std::size_t header_line() const { return meta_->header_line; }
  char separator() const { return meta_->separator; }
  bool decimal_comma() const { return meta_->decimal_comma; }
  const std::vector<CsvPreambleEntry>& preamble() const { return meta_->preamble; }

  /// Index of a column (exact, case-sensitive match after trimming), or nullopt.
  std::optional<std::size_t> find(const std::string& column) const { return meta_->find(column); }
  /// First of several accepted names that is present, or nullopt.
  std::optional<std::string> first_of(const std::vector<std::string>& names) const;

  /// Index of a column, or a Failure "missing column".
  Expected<std::size_t> Require(const std::string& column) const { return meta_->Require(column); }
  /// Failure{kInputInvalid, "source:line: message"}.
  Failure LineFailure(std::size_t line, const std::string& message) const {
    return meta_->LineFailure(line, message);
  }

 private:
  std::shared_ptr<const CsvMeta> meta_;
  std::vector<CsvRow> rows_;
};

/// Reads the fields of one row and remembers the first failure (like a stream's fail state), so a
/// row of many fields is read in a few lines and checked once:
///   CsvFields f(row);
///   const double x = f.Number("x_mm"), dx = f.Number("dx_um");
///   VOLCOMP_TRY(f.status());
/// After a failure every read returns 0 / "" / nullopt and status() keeps the first failure.
class CsvFields {
 public:
  explicit CsvFields(const CsvRow& row) : row_(row) {}
  double Number(const std::string& column);
  double Number(std::size_t column);
  long long Integer(const std::string& column);
  std::optional<double> OptionalNumber(const std::string& column);
  std::string Text(const std::string& column);
  /// The first failure, or success.
  const Outcome& status() const { return status_; }

 private:
  template <typename T>
  T Take(Expected<T> r, T fallback);
  const CsvRow& row_;
  Outcome status_;
};

/// Parses a finite double from the whole of `text` (leading/trailing spaces allowed).
std::optional<double> ParseDouble(const std::string& text);
/// Parses a base-10 integer from the whole of `text` (leading/trailing spaces allowed).
std::optional<long long> ParseInteger(const std::string& text);
/// Parses exactly three comma-separated numbers ("X,Y,Z", each as ParseDouble reads it).
std::optional<std::array<double, 3>> ParseTriple(const std::string& text);

}  // namespace volcomp::tools
