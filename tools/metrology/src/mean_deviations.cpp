// Mean deviations per target from raw positioning readings.
#include "volcomp/metrology/mean_deviations.hpp"

#include <algorithm>
#include <string>

#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/metrology/reading_checks.hpp"
#include "volcomp/metrology/statistics.hpp"

namespace volcomp::metrology {

Expected<MeanDeviations> MeanDeviationsFromCsv(const tools::CsvTable& table,
                                               const GroupingOptions& grouping) {
  VOLCOMP_TRY_ASSIGN(const PositioningData data, ReadPositioningCsv(table));
  return MeanDeviationsFromReadings(data, grouping, table.header_line());
}

Expected<MeanDeviations> MeanDeviationsFromReadings(const PositioningData& data,
                                                    const GroupingOptions& grouping,
                                                    std::size_t whole_line) {
  VOLCOMP_TRY_ASSIGN(const PositioningSet set, GroupReadings(data, grouping));
  if (!set.has_up) {
    return Fail(Error::kInputInvalid,
                data.source + ":" + std::to_string(whole_line) +
                    ": the readings have no ↑ approaches; the forward table needs them");
  }
  MeanDeviations m;
  m.kind = set.kind;
  m.warnings = set.warnings;
  for (const auto& w : CheckReadings(data, set, ReadingCheckOptions{})) m.warnings.push_back(w);
  for (const auto& p : set.positions) {
    m.target.push_back(p.target);
    m.mean_up.push_back(Mean(p.up.deviations));
    if (set.has_down) m.mean_down.push_back(Mean(p.down.deviations));
    m.runs = std::max({m.runs, static_cast<int>(p.up.size()), static_cast<int>(p.down.size())});
  }
  return m;
}

}  // namespace volcomp::metrology
