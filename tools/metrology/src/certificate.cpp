// The certificate's content: figures chosen from a comparison, tolerances, JSON and text.
#include "volcomp/metrology/certificate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <set>

#include "json_fields.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::metrology {
namespace {

using tools::JsonValue;

struct FigureSpec {
  const char* symbol;  // as compare.hpp names it
  const char* id;
  const char* meaning;
};

// Per compared table (by its title), the figures the certificate states, in page order.
const std::vector<FigureSpec>& IsoPositioning() {
  static const std::vector<FigureSpec> k = {{"A", "iso230-2.A", "positioning accuracy"},
                                            {"E", "iso230-2.E", "systematic positioning error"},
                                            {"B", "iso230-2.B", "reversal value"},
                                            {"M", "iso230-2.M", "range of mean positioning error"},
                                            {"R", "iso230-2.R", "repeatability"}};
  return k;
}
const std::vector<FigureSpec>& GostPositioning() {
  static const std::vector<FigureSpec> k = {{"A", "gost27843.A", "positioning accuracy"},
                                            {"R_max", "gost27843.R_max", "repeatability, largest"},
                                            {"B_max", "gost27843.B_max", "reversal, largest"}};
  return k;
}
const std::vector<FigureSpec>& Diagonal() {
  static const std::vector<FigureSpec> k = {{"E_d", "iso230-6.E_d", "diagonal displacement"},
                                            {"B_d", "iso230-6.B_d", "diagonal reversal"}};
  return k;
}
const std::vector<FigureSpec>& Circular() {
  static const std::vector<FigureSpec> k = {
      {"G(b)", "iso230-4.G_b", "bidirectional circular deviation"},
      {"G_cw", "iso230-4.G_cw", "circular deviation, CW"},
      {"G_ccw", "iso230-4.G_ccw", "circular deviation, CCW"},
      {"H", "iso230-4.H", "circular hysteresis"}};
  return k;
}

// A scope as an info file can name it: letters, digits and '_' (anything else becomes '_').
std::string ScopeName(std::string text) {
  for (char& ch : text) {
    const bool word = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') ||
                      (ch >= '0' && ch <= '9') || ch == '_';
    if (!word) ch = '_';
  }
  return text;
}

double Stated(double v) { return std::round(v * 100.0) / 100.0; }

std::string Condition(const std::vector<std::pair<std::string, std::string>>& list,
                      const std::string& key) {
  for (const auto& [k, v] : list) {
    if (k == key) return v;
  }
  return std::string();
}

std::string AfterPrefix(const std::string& name, const std::string& prefix) {
  return name.compare(0, prefix.size(), prefix) == 0 ? name.substr(prefix.size()) : name;
}

JsonValue PairsJson(const std::vector<std::pair<std::string, std::string>>& pairs) {
  JsonValue o = JsonValue::Object();
  for (const auto& [k, v] : pairs) o.object.emplace_back(k, v);
  return o;
}

JsonValue Optional(const std::optional<double>& v) { return v ? JsonValue(*v) : JsonValue(); }

JsonValue Verdict(const std::optional<bool>& pass) {
  return pass ? JsonValue(*pass ? "pass" : "fail") : JsonValue();
}

}  // namespace

const char* const kUncertaintyNotEvaluated = "not evaluated";
const char* const kUncertaintyWhereStated = "U (k = 2) where the evaluations state it";

int Certificate::Toleranced() const {
  int n = 0;
  for (const auto& f : figures) n += f.tolerance ? 1 : 0;
  return n;
}

bool Certificate::AnyUncertainty() const {
  for (const auto& f : figures) {
    if (f.u_before || f.u_after) return true;
  }
  return false;
}

int Certificate::FailedAfter() const {
  int n = 0;
  for (const auto& f : figures) n += (f.after_pass && !*f.after_pass) ? 1 : 0;
  return n;
}

Certificate BuildCertificate(const Comparison& comparison,
                             CertificateInfo info,
                             CertificateTable table,
                             std::string tool_version,
                             std::string date) {
  Certificate c;
  c.tool_version = std::move(tool_version);
  c.date = std::move(date);
  c.info = std::move(info);
  c.table = std::move(table);
  c.warnings = comparison.warnings;
  std::set<const ToleranceEntry*> used;
  for (const ComparedResult& r : comparison.results) {
    CertificateTest t;
    t.name = r.name;
    t.kind = r.kind;
    t.before_source = r.before_source;
    t.after_source = r.after_source;
    t.conditions_before = r.conditions_before;
    t.conditions_after = r.conditions_after;
    std::string axis = Condition(r.conditions_after, "axis");
    if (axis.empty()) axis = Condition(r.conditions_before, "axis");
    bool rotary = false;
    for (const ComparedTable& table_of : r.tables) rotary = rotary || table_of.unit != "µm";
    if (r.kind == "positioning") {
      if (axis.empty()) axis = AfterPrefix(r.name, "positioning_");
      t.title = "Positioning accuracy, " + axis + " axis" + (rotary ? " (rotary)" : "");
      t.label = axis + " axis";
    } else if (r.kind == "diagonal") {
      t.title = "Diagonal displacement (ISO 230-6), volumetric";
      t.label = "diagonals";
    } else {
      if (axis.empty()) axis = AfterPrefix(r.name, "circular_");
      t.title = "Circular test, " + axis + " plane (ISO 230-4)";
      t.label = axis + " circle";
    }
    for (const ComparedTable& tb : r.tables) {
      const std::vector<FigureSpec>* specs = nullptr;
      std::string scope = axis;
      std::string standard = tb.title;
      if (r.kind == "positioning") {
        if (tb.title.rfind("ISO 230-2", 0) == 0) specs = &IsoPositioning();
        if (tb.title.rfind("GOST 27843", 0) == 0) specs = &GostPositioning();
      } else if (r.kind == "diagonal") {
        standard = "ISO 230-6";
        if (tb.title == "body diagonals") {
          specs = &Diagonal();
          scope = "body";
        } else if (tb.title.rfind("face ", 0) == 0) {
          specs = &Diagonal();
          scope = ScopeName(tb.title.substr(5));  // "XY Z200" -> "XY_Z200"
        }
      } else {
        standard = "ISO 230-4";
        specs = &Circular();
      }
      if (specs == nullptr) continue;
      for (const FigureSpec& s : *specs) {
        for (const ComparedValue& v : tb.values) {
          if (v.symbol != s.symbol) continue;
          CertificateFigure f;
          f.test = r.name;
          f.id = s.id;
          f.scope = scope;
          f.standard = standard;
          f.symbol = v.symbol;
          f.meaning = r.kind == "diagonal" && scope != "body"
                          ? std::string(s.meaning) + ", " + tb.title  // ", face XY Z200"
                          : std::string(s.meaning);
          f.unit = tb.unit;
          f.before = Stated(v.before);
          f.after = Stated(v.after);
          f.u_before = v.u_before;
          f.u_after = v.u_after;
          const ToleranceEntry* tol = c.info.Tolerance(s.id, scope);
          // An unscoped tolerance is for the linear axes (µm): a rotary axis (arc-seconds) needs
          // its own, FIGURE.AXIS.
          if (tol != nullptr && tol->scope.empty() && tb.unit != "µm") tol = nullptr;
          if (tol != nullptr) {
            used.insert(tol);
            f.tolerance = tol->value;
            f.tolerance_from = tol->where;
            f.before_pass = f.before <= tol->value;
            f.after_pass = f.after <= tol->value;
          }
          c.figures.push_back(f);
        }
      }
    }
    c.tests.push_back(std::move(t));
  }
  // Positioning first, then the diagonals and the circular tests (the order of the page).
  auto rank = [](const std::string& kind) {
    return kind == "positioning" ? 0 : kind == "diagonal" ? 1 : 2;
  };
  std::stable_sort(c.tests.begin(), c.tests.end(),
                   [&](const CertificateTest& a, const CertificateTest& b) {
                     return rank(a.kind) < rank(b.kind);
                   });
  auto position = [&](const CertificateFigure& f) {
    for (std::size_t i = 0; i < c.tests.size(); ++i) {
      if (c.tests[i].name == f.test) return i;
    }
    return c.tests.size();
  };
  std::stable_sort(c.figures.begin(), c.figures.end(),
                   [&](const CertificateFigure& a, const CertificateFigure& b) {
                     return position(a) < position(b);
                   });
  for (const ToleranceEntry& tol : c.info.tolerances) {
    if (used.count(&tol) == 0) {
      c.warnings.push_back("tolerance " + tol.figure + (tol.scope.empty() ? "" : "." + tol.scope) +
                           " (" + tol.where + ") applies to no figure of the results");
    }
  }
  return c;
}

Outcome CheckCertificateDate(const std::string& date) {
  int y = 0, m = 0, d = 0;
  char tail = 0;
  const bool shape = date.size() == 10 && date[4] == '-' && date[7] == '-' &&
                     std::sscanf(date.c_str(), "%4d-%2d-%2d%c", &y, &m, &d, &tail) == 3;
  static const int kDays[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
  if (!shape || y < 1900 || m < 1 || m > 12 || d < 1 || d > kDays[m - 1] ||
      (m == 2 && d == 29 && !leap)) {
    return Fail(Error::kInputInvalid,
                "--date '" + date + "': expected a calendar date as YYYY-MM-DD (2026-11-28)");
  }
  return Outcome::Ok();
}

JsonValue CertificateJson(const Certificate& c) {
  JsonValue j = JsonValue::Object();
  j.Set("command", "report certificate");
  j.Set("tool_version", c.tool_version);
  j.Set("date", c.date);
  j.Set("info_file", c.info.source.empty() ? JsonValue() : JsonValue(c.info.source));
  JsonValue fields = JsonValue::Object();
  for (const auto& [section, keys] : CertificateFieldKeys()) {
    JsonValue s = JsonValue::Object();
    for (const std::string& k : keys) {
      const std::string v = c.info.Field(section, k);
      s.Set(k, v.empty() ? JsonValue() : JsonValue(v));
    }
    fields.Set(section, std::move(s));
  }
  j.Set("fields", std::move(fields));
  JsonValue table = JsonValue::Object();
  table.Set("source", c.table.source.empty() ? JsonValue() : JsonValue(c.table.source));
  table.Set("origin", c.table.origin.empty() ? JsonValue() : JsonValue(c.table.origin));
  table.Set("table_id", c.table.table_id ? JsonValue(uint64_t{*c.table.table_id}) : JsonValue());
  table.Set("crc32", c.table.crc32 ? JsonValue(tools::Hex32(*c.table.crc32)) : JsonValue());
  table.Set("same_as_image",
            c.table.same_as_image.empty() ? JsonValue() : JsonValue(c.table.same_as_image));
  j.Set("table", std::move(table));
  JsonValue tests = JsonValue::Array();
  for (const CertificateTest& t : c.tests) {
    JsonValue o = JsonValue::Object();
    o.Set("name", t.name);
    o.Set("kind", t.kind);
    o.Set("title", t.title);
    o.Set("label", t.label);
    o.Set("before_source", t.before_source);
    o.Set("after_source", t.after_source);
    o.Set("conditions_before", PairsJson(t.conditions_before));
    o.Set("conditions_after", PairsJson(t.conditions_after));
    tests.Push(std::move(o));
  }
  j.Set("tests", std::move(tests));
  JsonValue figures = JsonValue::Array();
  for (const CertificateFigure& f : c.figures) {
    JsonValue o = JsonValue::Object();
    o.Set("test", f.test);
    o.Set("id", f.id);
    o.Set("scope", f.scope);
    o.Set("standard", f.standard);
    o.Set("symbol", f.symbol);
    o.Set("meaning", f.meaning);
    o.Set("unit", f.unit);
    o.Set("before", f.before);
    o.Set("after", f.after);
    o.Set("tolerance", Optional(f.tolerance));
    o.Set("tolerance_from", f.tolerance_from.empty() ? JsonValue() : JsonValue(f.tolerance_from));
    o.Set("before_result", Verdict(f.before_pass));
    o.Set("after_result", Verdict(f.after_pass));
    if (f.u_before || f.u_after) {
      JsonValue u = JsonValue::Object();
      u.Set("k", 2);
      u.Set("before", Optional(f.u_before));
      u.Set("after", Optional(f.u_after));
      o.Set("uncertainty", std::move(u));
    } else {
      o.Set("uncertainty", JsonValue());
    }
    figures.Push(std::move(o));
  }
  j.Set("figures", std::move(figures));
  j.Set("uncertainty", c.AnyUncertainty() ? kUncertaintyWhereStated : kUncertaintyNotEvaluated);
  j.Set("toleranced", c.Toleranced());
  j.Set("failed_after", c.FailedAfter());
  j.Set("verdict",
        c.Toleranced() == 0 ? JsonValue() : JsonValue(c.FailedAfter() == 0 ? "pass" : "fail"));
  JsonValue warnings = JsonValue::Array();
  for (const std::string& w : c.warnings) warnings.Push(w);
  j.Set("warnings", std::move(warnings));
  return j;
}

void WriteCertificateText(std::ostream& out, const JsonValue& c) {
  const JsonValue& m = json::At(json::At(c, "fields"), "machine");
  std::string machine;
  for (const char* k : {"maker", "model", "serial"}) {
    const std::string& v = json::Text(m, k);
    if (!v.empty()) machine += (machine.empty() ? "" : " ") + v;
  }
  out << "certificate of " << (machine.empty() ? "(machine not named)" : machine) << ", "
      << json::Text(c, "date") << ", volcomp " << json::Text(c, "tool_version") << "\n";
  const JsonValue& table = json::At(c, "table");
  if (json::At(table, "table_id").is_null()) {
    out << "table: not given (a line to fill in)\n";
  } else {
    out << "table: id " << json::Integer(table, "table_id") << ", CRC-32 "
        << json::Text(table, "crc32") << " (" << json::Text(table, "origin") << " "
        << json::Text(table, "source") << ")\n";
  }
  for (const JsonValue& t : json::At(c, "tests").array) {
    out << json::Text(t, "title") << " (" << json::Text(t, "name") << ")\n";
    for (const JsonValue& f : json::At(c, "figures").array) {
      if (json::Text(f, "test") != json::Text(t, "name")) continue;
      const JsonValue& tol = json::At(f, "tolerance");
      auto verdict = [&](const char* key) {
        const JsonValue& v = json::At(f, key);
        return v.is_null() ? std::string("-") : v.string;
      };
      char line[200];
      std::snprintf(line, sizeof line, "  %-16s %-6s %8s -> %8s %-3s tolerance %6s: %s -> %s",
                    json::Text(f, "id").c_str(), json::Text(f, "scope").c_str(),
                    report::FormatFixed(json::Number(f, "before"), 2).c_str(),
                    report::FormatFixed(json::Number(f, "after"), 2).c_str(),
                    json::Text(f, "unit").c_str(),
                    tol.is_null() ? "-" : report::FormatNumber(tol.number, 6).c_str(),
                    verdict("before_result").c_str(), verdict("after_result").c_str());
      out << line << "\n";
    }
  }
  const JsonValue& v = json::At(c, "verdict");
  out << "verdict: "
      << (v.is_null() ? std::string("none (no tolerances given)")
                      : v.string + " (" + std::to_string(json::Integer(c, "failed_after")) +
                            " of " + std::to_string(json::Integer(c, "toleranced")) +
                            " toleranced figures out of tolerance after)")
      << "; uncertainty " << json::Text(c, "uncertainty") << "\n";
}

}  // namespace volcomp::metrology
