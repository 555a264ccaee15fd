// CSV reader with line-numbered errors.
#include "volcomp/tools/csv.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

namespace volcomp::tools {
namespace {

bool IsBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}
bool IsDigit(char c) { return c >= '0' && c <= '9'; }
bool IsAlpha(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool IsWordChar(char c) { return IsAlpha(c) || IsDigit(c) || c == '_'; }

bool IsPadding(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// The field without its leading blanks and trailing blanks or CR (a view into `s`).
std::string_view Trimmed(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t')) ++b;
  while (e > b && IsPadding(s[e - 1])) --e;
  return s.substr(b, e - b);
}

std::string Trim(const std::string& s) { return std::string(Trimmed(s)); }

bool IsSkippable(std::string_view line) {
  const std::string_view t = Trimmed(line);
  return t.empty() || t[0] == '#';
}

bool AllEmpty(const std::vector<std::string>& fields) {
  return std::all_of(fields.begin(), fields.end(), [](const std::string& f) { return f.empty(); });
}

char DetectSeparator(std::string_view header) {
  if (header.find(',') != std::string_view::npos) return ',';
  if (header.find(';') != std::string_view::npos) return ';';
  if (header.find('\t') != std::string_view::npos) return '\t';
  return ',';
}

// Splits one line into `out` (reusing its strings); returns false on an unterminated quote.
// One pass over the line: an unquoted field is a trimmed range of it, a quoted one is built from
// the ranges between its doubled quotes; a quote opens a field only where nothing but blanks
// precedes it in the field.
bool SplitLine(std::string_view line, char sep, std::vector<std::string>* out) {
  std::size_t count = 0;
  auto next_field = [&]() -> std::string& {
    if (count == out->size()) out->emplace_back();
    std::string& f = (*out)[count++];
    f.clear();
    return f;
  };
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (true) {
    std::size_t b = i;
    while (b < n && (line[b] == ' ' || line[b] == '\t')) ++b;
    if (b < n && line[b] == '"') {
      std::string& f = next_field();
      std::size_t j = b + 1;
      while (true) {
        const std::size_t q = line.find('"', j);
        if (q == std::string_view::npos) return false;
        f.append(line.data() + j, q - j);
        if (q + 1 < n && line[q + 1] == '"') {
          f += '"';
          j = q + 2;
        } else {
          j = q + 1;
          break;
        }
      }
      // After the closing quote, text up to the separator belongs to the field as written.
      const std::size_t s = line.find(sep, j);
      const std::size_t end = s == std::string_view::npos ? n : s;
      f.append(line.data() + j, end - j);
      if (s == std::string_view::npos) break;
      i = s + 1;
      continue;
    }
    const std::size_t s = line.find(sep, i);
    const std::size_t end = s == std::string_view::npos ? n : s;
    next_field().assign(Trimmed(line.substr(i, end - i)));
    if (s == std::string_view::npos) break;
    i = s + 1;
  }
  out->resize(count);
  return true;
}

// The first name that appears again later in `names` (the earliest second occurrence), or null.
// Sorted indices, so a header of thousands of columns costs n log n, not n².
const std::string* FirstRepeated(const std::vector<std::string>& names) {
  std::vector<std::size_t> order(names.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return names[a] < names[b]; });
  std::size_t first_second = names.size();
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (names[order[k]] == names[order[k - 1]]) first_second = std::min(first_second, order[k]);
  }
  return first_second < names.size() ? &names[first_second] : nullptr;
}

// A decimal number with `mark` as its decimal separator: \s*[+-]?(\d+M\d*|M\d+)([eE][+-]?\d+)?\s*
// (one pass, no backtracking: the whole field is scanned once).
bool IsDecimalNumber(const std::string& f, char mark) {
  std::size_t i = 0;
  const std::size_t n = f.size();
  while (i < n && IsBlank(f[i])) ++i;
  if (i < n && (f[i] == '+' || f[i] == '-')) ++i;
  std::size_t int_digits = 0, frac_digits = 0;
  while (i < n && IsDigit(f[i])) ++i, ++int_digits;
  if (i >= n || f[i] != mark) return false;
  ++i;
  while (i < n && IsDigit(f[i])) ++i, ++frac_digits;
  if (int_digits == 0 && frac_digits == 0) return false;
  if (i < n && (f[i] == 'e' || f[i] == 'E')) {
    ++i;
    if (i < n && (f[i] == '+' || f[i] == '-')) ++i;
    std::size_t exp_digits = 0;
    while (i < n && IsDigit(f[i])) ++i, ++exp_digits;
    if (exp_digits == 0) return false;
  }
  while (i < n && IsBlank(f[i])) ++i;
  return i == n;
}

// "12,5", "-,5", "1,5e3": a number written with a decimal comma (and no point).
bool IsDecimalCommaNumber(const std::string& field) { return IsDecimalNumber(field, ','); }
bool IsDecimalPointNumber(const std::string& field) { return IsDecimalNumber(field, '.'); }

// `# key: value` before the header: key is a letter, then word characters, then up to four more
// space-separated words; blanks around key and value are dropped.
std::optional<CsvPreambleEntry> PreambleEntry(std::string_view line, std::size_t line_no) {
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i < n && IsBlank(line[i])) ++i;
  if (i >= n || line[i] != '#') return std::nullopt;
  ++i;
  while (i < n && IsBlank(line[i])) ++i;
  if (i >= n || !IsAlpha(line[i])) return std::nullopt;
  const std::size_t key_begin = i;
  while (i < n && IsWordChar(line[i])) ++i;
  for (int words = 0; words < 4 && i + 1 < n && line[i] == ' ' && IsWordChar(line[i + 1]);
       ++words) {
    ++i;
    while (i < n && IsWordChar(line[i])) ++i;
  }
  const std::size_t key_end = i;
  while (i < n && IsBlank(line[i])) ++i;
  if (i >= n || line[i] != ':') return std::nullopt;
  ++i;
  std::size_t e = n;
  while (i < e && IsBlank(line[i])) ++i;
  while (e > i && IsBlank(line[e - 1])) --e;
  return CsvPreambleEntry{std::string(line.substr(key_begin, key_end - key_begin)),
                          std::string(line.substr(i, e - i)), line_no};
}

// Decides the decimal mark of a ';' or TAB separated file from its numbers.
void DetectDecimalMark(CsvMeta* meta, const std::vector<CsvRow>& rows) {
  if (meta->separator == ',') return;
  for (const CsvRow& row : rows) {
    for (std::size_t c = 0; c < row.fields().size(); ++c) {
      if (IsDecimalCommaNumber(row.fields()[c])) {
        meta->decimal_comma = true;
        meta->decimal_line = row.line();
        return;
      }
      if (IsDecimalPointNumber(row.fields()[c])) {
        meta->decimal_line = row.line();
        return;
      }
    }
  }
}

}  // namespace

std::optional<double> ParseDouble(const std::string& text) {
  const std::string t = Trim(text);
  if (t.empty()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<std::array<double, 3>> ParseTriple(const std::string& text) {
  std::array<double, 3> v{};
  size_t from = 0;
  for (size_t i = 0; i < 3; ++i) {
    const size_t comma = i < 2 ? text.find(',', from) : text.size();
    if (comma == std::string::npos) return std::nullopt;
    const auto d = ParseDouble(text.substr(from, comma - from));
    if (!d) return std::nullopt;
    v[i] = *d;
    from = comma + 1;
  }
  return v;
}

std::optional<long long> ParseInteger(const std::string& text) {
  const std::string t = Trim(text);
  if (t.empty()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(t.c_str(), &end, 10);
  if (end != t.c_str() + t.size() || errno == ERANGE) return std::nullopt;
  return v;
}

Expected<std::string> CsvRow::Text(const std::string& column) const {
  VOLCOMP_TRY_ASSIGN(const std::size_t c, meta_->Require(column));
  return fields_[c];
}

Expected<double> CsvRow::Number(std::size_t column) const {
  if (column >= fields_.size()) return Fail(Error::kInvalidArgument, "CSV column out of range");
  const std::string& field = fields_[column];
  const std::string& name = meta_->header[column];
  std::optional<double> v;
  if (meta_->decimal_comma && IsDecimalPointNumber(field)) {
    return Fail(meta_->LineFailure(
        line_, "column \"" + name + "\": \"" + field +
                   "\" has a decimal point, but this file writes decimal "
                   "commas (line " +
                   std::to_string(meta_->decimal_line) + "); use one decimal mark throughout"));
  }
  if (meta_->decimal_comma && IsDecimalCommaNumber(field)) {
    std::string dotted = field;
    dotted[dotted.find(',')] = '.';
    v = ParseDouble(dotted);
  } else {
    v = ParseDouble(field);
  }
  if (!v && meta_->separator != ',' && !meta_->decimal_comma && IsDecimalCommaNumber(field)) {
    return Fail(meta_->LineFailure(
        line_, "column \"" + name + "\": \"" + field +
                   "\" has a decimal comma, but this file writes decimal "
                   "points (line " +
                   std::to_string(meta_->decimal_line) + "); use one decimal mark throughout"));
  }
  if (!v) {
    return Fail(
        meta_->LineFailure(line_, "column \"" + name + "\": \"" + field + "\" is not a number"));
  }
  return *v;
}

Expected<double> CsvRow::Number(const std::string& column) const {
  VOLCOMP_TRY_ASSIGN(const std::size_t c, meta_->Require(column));
  return Number(c);
}

Expected<long long> CsvRow::Integer(const std::string& column) const {
  VOLCOMP_TRY_ASSIGN(const std::size_t c, meta_->Require(column));
  const auto v = ParseInteger(fields_[c]);
  if (!v) {
    return Fail(meta_->LineFailure(
        line_, "column \"" + column + "\": \"" + fields_[c] + "\" is not an integer"));
  }
  return *v;
}

Expected<std::optional<double>> CsvRow::OptionalNumber(const std::string& column) const {
  const auto c = meta_->find(column);
  if (!c || Trimmed(fields_[*c]).empty()) return std::optional<double>();
  VOLCOMP_TRY_ASSIGN(const double v, Number(*c));
  return std::optional<double>(v);
}

template <typename T>
T CsvFields::Take(Expected<T> r, T fallback) {
  if (!status_.ok()) return fallback;
  if (!r.ok()) {
    status_ = Fail(r.error());
    return fallback;
  }
  return std::move(r).value();
}

double CsvFields::Number(const std::string& column) { return Take(row_.Number(column), 0.0); }
double CsvFields::Number(std::size_t column) { return Take(row_.Number(column), 0.0); }
long long CsvFields::Integer(const std::string& column) { return Take(row_.Integer(column), 0LL); }
std::optional<double> CsvFields::OptionalNumber(const std::string& column) {
  return Take(row_.OptionalNumber(column), std::optional<double>());
}
std::string CsvFields::Text(const std::string& column) {
  return Take(row_.Text(column), std::string());
}

Expected<CsvTable> CsvTable::Read(std::istream& in, const std::string& source) {
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return Fail(Error::kIoError, source + ": read error");
  return ReadString(text.str(), source);
}

Expected<CsvTable> CsvTable::ReadString(const std::string& text, const std::string& source) {
  auto meta = std::make_shared<CsvMeta>();
  meta->source = source;
  CsvTable t;
  std::size_t line_no = 0;
  char sep = ',';
  std::vector<std::string> fields;
  std::string_view rest(text);
  if (rest.substr(0, 3) == "\xEF\xBB\xBF") rest.remove_prefix(3);  // UTF-8 byte-order mark
  while (!rest.empty()) {
    const std::size_t nl = rest.find('\n');
    std::string_view line = rest.substr(0, nl);
    rest.remove_prefix(nl == std::string_view::npos ? rest.size() : nl + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++line_no;
    if (IsSkippable(line)) {
      if (meta->header.empty()) {
        if (auto e = PreambleEntry(line, line_no)) meta->preamble.push_back(*e);
      }
      continue;
    }
    if (meta->header.empty()) {
      sep = meta->separator = DetectSeparator(line);
      if (!SplitLine(line, sep, &meta->header)) {
        return Fail(meta->LineFailure(line_no, "unterminated quote in header"));
      }
      if (AllEmpty(meta->header)) {  // a spreadsheet's empty row (";;;") above the header
        meta->header.clear();
        continue;
      }
      meta->header_line = line_no;
      // A spreadsheet pads every row to its widest: empty names after the last column go.
      const std::size_t width = meta->header.size();
      while (meta->header.size() > 1 && meta->header.back().empty()) meta->header.pop_back();
      if (meta->header.size() == 1 && width > 1) {
        return Fail(meta->LineFailure(
            line_no, "\"" + meta->header[0] +
                         "\" looks like a title row (one cell, the rest of the row empty), not "
                         "the header: delete it or start it with #"));
      }
      for (const std::string& name : meta->header) {
        if (name.empty()) return Fail(meta->LineFailure(line_no, "empty column name in header"));
      }
      if (const std::string* twice = FirstRepeated(meta->header)) {
        return Fail(
            meta->LineFailure(line_no, "column \"" + *twice + "\" appears twice in header"));
      }
      continue;
    }
    if (!SplitLine(line, sep, &fields))
      return Fail(meta->LineFailure(line_no, "unterminated quote"));
    // A spreadsheet's padding: empty cells after the last column, rows of empty cells only.
    while (fields.size() > meta->header.size() && fields.back().empty()) fields.pop_back();
    if (AllEmpty(fields)) continue;
    if (fields.size() != meta->header.size()) {
      return Fail(meta->LineFailure(line_no, "expected " + std::to_string(meta->header.size()) +
                                                 " fields, found " +
                                                 std::to_string(fields.size())));
    }
    CsvRow& row = t.rows_.emplace_back();
    row.meta_ = meta;
    row.line_ = line_no;
    row.fields_ = fields;
  }
  if (meta->header.empty()) {
    return Fail(Error::kInputInvalid, source + ": no header line (empty input)");
  }
  DetectDecimalMark(meta.get(), t.rows_);
  t.meta_ = meta;
  return t;
}

Expected<CsvTable> CsvTable::ReadFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return Fail(Error::kIoError, path + ": cannot open");
  return Read(f, path);
}

std::optional<std::size_t> CsvMeta::find(const std::string& column) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == column) return i;
  }
  return std::nullopt;
}

Expected<std::size_t> CsvMeta::Require(const std::string& column) const {
  const auto c = find(column);
  if (!c) return Fail(LineFailure(header_line, "missing column \"" + column + "\""));
  return *c;
}

Failure CsvMeta::LineFailure(std::size_t line, const std::string& message) const {
  return Failure{Error::kInputInvalid, source + ":" + std::to_string(line) + ": " + message};
}

std::optional<std::string> CsvTable::first_of(const std::vector<std::string>& names) const {
  for (const auto& n : names) {
    if (find(n)) return n;
  }
  return std::nullopt;
}

}  // namespace volcomp::tools
