// CSV reader with line-numbered errors.
#include "volcomp/tools/csv.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

namespace volcomp::tools {
namespace {

std::string Trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  return s.substr(b, e - b);
}

bool IsSkippable(const std::string& line) {
  const std::string t = Trim(line);
  return t.empty() || t[0] == '#';
}

char DetectSeparator(const std::string& header) {
  if (header.find(',') != std::string::npos) return ',';
  if (header.find(';') != std::string::npos) return ';';
  if (header.find('\t') != std::string::npos) return '\t';
  return ',';
}

// Splits one line; returns false on an unterminated quote.
bool SplitLine(const std::string& line, char sep, std::vector<std::string>* out) {
  out->clear();
  std::string field;
  bool quoted = false, was_quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"' && Trim(field).empty()) {
      quoted = was_quoted = true;
      field.clear();
    } else if (c == sep) {
      out->push_back(was_quoted ? field : Trim(field));
      field.clear();
      was_quoted = false;
    } else {
      field += c;
    }
  }
  if (quoted) return false;
  out->push_back(was_quoted ? field : Trim(field));
  return true;
}

// "12,5", "-,5", "1,5e3": a number written with a decimal comma (and no point).
bool IsDecimalCommaNumber(const std::string& field) {
  static const std::regex kPattern(R"(\s*[+-]?(\d+,\d*|,\d+)([eE][+-]?\d+)?\s*)");
  return std::regex_match(field, kPattern);
}

bool IsDecimalPointNumber(const std::string& field) {
  static const std::regex kPattern(R"(\s*[+-]?(\d+\.\d*|\.\d+)([eE][+-]?\d+)?\s*)");
  return std::regex_match(field, kPattern);
}

// `# key: value` before the header.
std::optional<CsvPreambleEntry> PreambleEntry(const std::string& line, std::size_t line_no) {
  static const std::regex kPattern(
      R"(\s*#\s*([A-Za-z][A-Za-z0-9_]*(?: [A-Za-z0-9_]+){0,4})\s*:\s*(.*?)\s*)");
  std::smatch m;
  if (!std::regex_match(line, m, kPattern)) return std::nullopt;
  return CsvPreambleEntry{m[1], m[2], line_no};
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

std::optional<long long> ParseInteger(const std::string& text) {
  const std::string t = Trim(text);
  if (t.empty()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(t.c_str(), &end, 10);
  if (end != t.c_str() + t.size() || errno == ERANGE) return std::nullopt;
  return v;
}

const std::string& CsvRow::text(const std::string& column) const {
  return fields_[meta_->require(column)];
}

double CsvRow::number(std::size_t column) const {
  const std::string& field = fields_.at(column);
  std::optional<double> v;
  if (meta_->decimal_comma && IsDecimalPointNumber(field)) {
    throw meta_->error(line_, "column \"" + meta_->header[column] + "\": \"" + field +
                                  "\" has a decimal point, but this file writes decimal commas "
                                  "(line " +
                                  std::to_string(meta_->decimal_line) +
                                  "); use one decimal mark throughout");
  }
  if (meta_->decimal_comma && IsDecimalCommaNumber(field)) {
    std::string dotted = field;
    dotted[dotted.find(',')] = '.';
    v = ParseDouble(dotted);
  } else {
    v = ParseDouble(field);
  }
  if (!v && meta_->separator != ',' && !meta_->decimal_comma && IsDecimalCommaNumber(field)) {
    throw meta_->error(line_, "column \"" + meta_->header[column] + "\": \"" + field +
                                  "\" has a decimal comma, but this file writes decimal points "
                                  "(line " +
                                  std::to_string(meta_->decimal_line) +
                                  "); use one decimal mark throughout");
  }
  if (!v) {
    throw meta_->error(line_, "column \"" + meta_->header[column] + "\": \"" + fields_[column] +
                                  "\" is not a number");
  }
  return *v;
}

double CsvRow::number(const std::string& column) const { return number(meta_->require(column)); }

long long CsvRow::integer(const std::string& column) const {
  const std::size_t c = meta_->require(column);
  const auto v = ParseInteger(fields_[c]);
  if (!v) {
    throw meta_->error(line_,
                       "column \"" + column + "\": \"" + fields_[c] + "\" is not an integer");
  }
  return *v;
}

std::optional<double> CsvRow::optional_number(const std::string& column) const {
  const auto c = meta_->find(column);
  if (!c || Trim(fields_[*c]).empty()) return std::nullopt;
  return number(*c);
}

CsvTable CsvTable::Parse(std::istream& in, const std::string& source) {
  auto meta = std::make_shared<CsvMeta>();
  meta->source = source;
  CsvTable t;
  std::string line;
  std::size_t line_no = 0;
  char sep = ',';
  std::vector<std::string> fields;
  while (std::getline(in, line)) {
    ++line_no;
    if (line_no == 1 && line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) {
      line.erase(0, 3);  // UTF-8 byte-order mark
    }
    if (IsSkippable(line)) {
      if (meta->header.empty()) {
        if (auto e = PreambleEntry(line, line_no)) meta->preamble.push_back(*e);
      }
      continue;
    }
    if (meta->header.empty()) {
      sep = meta->separator = DetectSeparator(line);
      if (!SplitLine(line, sep, &meta->header)) {
        throw meta->error(line_no, "unterminated quote in header");
      }
      meta->header_line = line_no;
      for (std::size_t i = 0; i < meta->header.size(); ++i) {
        if (meta->header[i].empty()) throw meta->error(line_no, "empty column name in header");
        for (std::size_t j = 0; j < i; ++j) {
          if (meta->header[i] == meta->header[j]) {
            throw meta->error(line_no,
                              "column \"" + meta->header[i] + "\" appears twice in header");
          }
        }
      }
      continue;
    }
    if (!SplitLine(line, sep, &fields)) throw meta->error(line_no, "unterminated quote");
    if (fields.size() != meta->header.size()) {
      throw meta->error(line_no, "expected " + std::to_string(meta->header.size()) +
                                     " fields, found " + std::to_string(fields.size()));
    }
    CsvRow row;
    row.meta_ = meta;
    row.line_ = line_no;
    row.fields_ = fields;
    t.rows_.push_back(std::move(row));
  }
  if (in.bad()) throw InputError(source + ": read error");
  if (meta->header.empty()) throw InputError(source + ": no header line (empty input)");
  DetectDecimalMark(meta.get(), t.rows_);
  t.meta_ = meta;
  return t;
}

CsvTable CsvTable::ParseFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(path + ": cannot open");
  return Parse(f, path);
}

CsvTable CsvTable::ParseString(const std::string& text, const std::string& source) {
  std::istringstream s(text);
  return Parse(s, source);
}

std::optional<std::size_t> CsvMeta::find(const std::string& column) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == column) return i;
  }
  return std::nullopt;
}

std::size_t CsvMeta::require(const std::string& column) const {
  const auto c = find(column);
  if (!c) throw error(header_line, "missing column \"" + column + "\"");
  return *c;
}

InputError CsvMeta::error(std::size_t line, const std::string& message) const {
  return InputError(source + ":" + std::to_string(line) + ": " + message);
}

std::optional<std::string> CsvTable::first_of(const std::vector<std::string>& names) const {
  for (const auto& n : names) {
    if (find(n)) return n;
  }
  return std::nullopt;
}

}  // namespace volcomp::tools
