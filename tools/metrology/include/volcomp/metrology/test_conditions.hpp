// Test conditions of a measurement, carried from the readings file into the reports.
//
// A readings file may start with `# key: value` lines before its header (csv.hpp "preamble");
// the templates written by `volcomp program` ask for the keys of kConditionKeys. Every entry with
// a value is a test condition; the reports list them (text, JSON "conditions", HTML table), so a
// report says on which machine, axis, date, by whom, with which instrument and at which air and
// material temperature the readings were taken. `axis` also names the report.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::metrology {

/// The keys a readings template asks for, in order.
const std::vector<std::string>& ConditionKeys();

struct TestConditions {
  std::vector<std::pair<std::string, std::string>> entries;  // key, value (non-empty), file order

  /// Value of `key` (case-insensitive, '_' = ' '), or nullopt.
  std::optional<std::string> Find(const std::string& key) const;
  /// Find() as a number: decimal comma allowed ("20,3"), a reading of the .rtl reader ("20.2 at
  /// start, 20.3 at end") gives the mean of the two; absent: nullopt; not a number: kInputInvalid
  /// naming the key and its text.
  Expected<std::optional<double>> Number(const std::string& key) const;
  bool empty() const { return entries.empty(); }
};

/// The preamble entries of `table` that have a value.
TestConditions ConditionsFromPreamble(const tools::CsvTable& table);

/// The JSON object {key: value, ...} of the entries, in file order.
tools::JsonValue ConditionsJson(const TestConditions& conditions);

/// "machine MILL-7; axis X; ..." from ConditionsJson()'s object (empty when there are none).
std::string ConditionsText(const tools::JsonValue& conditions);

/// A "Test conditions" table, or a paragraph saying that the file gives none and how to add them.
void AddConditionsSection(report::HtmlPage* page, const TestConditions& conditions);

}  // namespace volcomp::metrology
