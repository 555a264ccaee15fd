// Test conditions from the readings file's preamble.
#include "volcomp/metrology/test_conditions.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>

namespace volcomp::metrology {
namespace {

std::string Normalized(const std::string& key) {
  std::string out;
  for (char c : key) {
    out += c == '_' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

}  // namespace

const std::vector<std::string>& ConditionKeys() {
  static const std::vector<std::string> kKeys = {"machine",
                                                 "axis",
                                                 "date",
                                                 "operator",
                                                 "instrument",
                                                 "air temperature C",
                                                 "material temperature C"};
  return kKeys;
}

namespace {

// "20.2 at start, 20.3 at end" (the .rtl reader's reading of a sensor): the mean of the two.
std::optional<double> StartEndMean(const std::string& text) {
  const std::size_t a = text.find(" at start, "), b = text.rfind(" at end");
  if (a == std::string::npos || b == std::string::npos || b + 7 != text.size() || b < a) {
    return std::nullopt;
  }
  const auto start = tools::ParseDouble(text.substr(0, a));
  const auto end = tools::ParseDouble(text.substr(a + 11, b - a - 11));
  if (!start || !end) return std::nullopt;
  return (*start + *end) / 2.0;
}

}  // namespace

Expected<std::optional<double>> TestConditions::Number(const std::string& key) const {
  auto text = Find(key);
  if (!text) return std::optional<double>();
  if (const auto mean = StartEndMean(*text)) return std::optional<double>(*mean);
  std::replace(text->begin(), text->end(), ',', '.');
  const auto v = tools::ParseDouble(*text);
  if (!v) {
    return Fail(Error::kInputInvalid,
                "preamble \"" + key + ": " + *Find(key) + "\" is not a number");
  }
  return std::optional<double>(*v);
}

std::optional<std::string> TestConditions::Find(const std::string& key) const {
  for (const auto& [k, v] : entries) {
    if (Normalized(k) == Normalized(key)) return v;
  }
  return std::nullopt;
}

TestConditions ConditionsFromPreamble(const tools::CsvTable& table) {
  TestConditions c;
  for (const auto& e : table.preamble()) {
    if (!e.value.empty()) c.entries.emplace_back(e.key, e.value);
  }
  return c;
}

tools::JsonValue ConditionsJson(const TestConditions& conditions) {
  tools::JsonValue o = tools::JsonValue::Object();
  // Appended, not Set(): a key the file repeats is reported as often as it is given.
  for (const auto& [k, v] : conditions.entries) o.object.emplace_back(k, v);
  return o;
}

std::string ConditionsText(const tools::JsonValue& conditions) {
  std::string s;
  for (const auto& [k, v] : conditions.object) {
    s += (s.empty() ? "" : "; ") + k + " " + v.string;
  }
  return s;
}

void AddConditionsSection(report::HtmlPage* page, const TestConditions& conditions) {
  page->Heading(2, "Test conditions");
  if (conditions.empty()) {
    page->Paragraph(
        "The readings file gives no test conditions. Write them as `# key: value` lines before "
        "its header (machine, axis, date, operator, instrument, air temperature C, material "
        "temperature C); the templates of `volcomp program` ask for them.");
    return;
  }
  std::vector<std::vector<std::string>> rows;
  for (const auto& [k, v] : conditions.entries) rows.push_back({k, v});
  page->Table({"condition", "value"}, rows);
}

}  // namespace volcomp::metrology
