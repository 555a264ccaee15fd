// Helpers for the metrology tests: the shared ones of tests/support under metrology::testing, and
// CSV tables from text.
#pragma once

#include <string>

#include "expected_value.hpp"
#include "sample_path.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology::testing {

using volcomp::testing::ExpectFailure;
using volcomp::testing::SamplePath;
using volcomp::testing::SourcePath;
using volcomp::testing::ValueOf;

/// The CSV table of `text`, named `source` in messages.
inline tools::CsvTable Csv(const std::string& text, const std::string& source) {
  return ValueOf(tools::CsvTable::ReadString(text, source));
}

}  // namespace volcomp::metrology::testing
