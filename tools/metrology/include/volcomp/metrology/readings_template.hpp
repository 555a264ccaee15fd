// The readings template written by `volcomp program ... --targets-csv FILE`: a preamble that asks
// for the test conditions, then one row per measured stop in program order with an empty
// measurement cell for the operator. A template that already holds readings is never overwritten
// unless asked (`--force`): a measurement is never lost to a re-run of the program command.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/test_program.hpp"

namespace volcomp::metrology {

struct TemplateHeader {
  std::string description;  // first comment line: what the test is and how to fill it in
  std::vector<std::pair<std::string, std::string>> known;  // conditions known already (axis ...)
  std::vector<std::string> omit;  // keys of ConditionKeys() that do not apply (axis of a diagonal)
};

/// The preamble: the description, then `# key: value` for every known condition and
/// `# key:` for every other key of ConditionKeys(), then extra known keys.
std::string TemplatePreamble(const TemplateHeader& header);

/// Rows for `moves` (measured stops only): [diagonal,]target,direction,run, then an empty cell.
/// `diagonal` empty: no diagonal column (the header is written by the caller).
std::string TemplateRows(const std::vector<CycleMove>& moves, const std::string& diagonal);

/// Why `path` must not be overwritten: it holds readings (names the first line with one), or it
/// is not a readings template; nullopt when it does not exist or is an empty template.
std::optional<std::string> ReadingsAtRisk(const std::string& path);

/// A failure (kInputInvalid) saying why and naming --force when ReadingsAtRisk(path) and not
/// `force`; commands call it before they write anything.
Outcome RefuseToOverwriteReadings(const std::string& path, bool force);

/// Writes `text` to the file `path` after RefuseToOverwriteReadings(path, force).
Outcome WriteTemplate(const std::string& text, const std::string& path, bool force);

}  // namespace volcomp::metrology
