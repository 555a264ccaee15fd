// Fuzz target: every CSV reader of the PC tool. Invariants: malformed input is reported with
// tools::InputError (a clear message), never another exception, a crash or UB.
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "volcomp/datasets/axis_table_csv.hpp"
#include "volcomp/datasets/positioning_csv.hpp"
#include "volcomp/datasets/tracker_csv.hpp"
#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/rotary_data.hpp"
#include "volcomp/tools/csv.hpp"

namespace {
template <class Fn>
void Expect(Fn fn) {
  try {
    fn();
  } catch (const volcomp::tools::InputError&) {
  } catch (const std::invalid_argument&) {  // model validation reports through this type
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace volcomp;
  const std::string text(reinterpret_cast<const char*>(data), size);
  tools::CsvTable csv;
  try {
    csv = tools::CsvTable::ParseString(text, "fuzz.csv");
  } catch (const tools::InputError&) {
    return 0;
  }
  for (const tools::CsvRow& row : csv.rows()) {
    for (size_t c = 0; c < csv.header().size(); ++c) {
      Expect([&] { (void)row.number(c); });
    }
  }
  Expect([&] { (void)metrology::ReadPositioningCsv(csv); });
  Expect([&] { (void)metrology::ReadRotaryCsv(csv); });
  Expect([&] { (void)metrology::EvaluateDiagonals(csv, metrology::GroupingOptions()); });
  Expect([&] { (void)datasets::AxisTableFromCsv(csv); });
  Expect([&] { (void)datasets::TrackerDataFromCsv(csv); });
  Expect([&] { (void)datasets::TrackerLatticeFromCsv(csv); });
  Expect([&] { (void)datasets::PositioningFromCsv(csv); });
  return 0;
}
