// Fuzz target: every CSV reader of the PC tool, and the Renishaw .rtl reader and the positioning
// loader that picks between them by content (datasets/positioning_file.hpp). Invariants: malformed
// input is a Failure with a message (kInputInvalid), never an exception, a crash, UB or time/stack
// growing faster than the input (the readers scan each field once: no regular expressions, no
// recursion per character). The fuzz build runs it with inputs of at most 4 KiB and a 128 KiB stack
// (tests/fuzz/CMakeLists.txt): short inputs keep it fast, and the small stack makes recursion per
// character overflow within them (the std::regex reader this replaced overflowed on a 600-digit
// field at 128 KiB: docs/reliability.md, "fuzz_csv").
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "volcomp/builders/node_grid.hpp"
#include "volcomp/datasets/axis_table_csv.hpp"
#include "volcomp/datasets/positioning_csv.hpp"
#include "volcomp/datasets/positioning_file.hpp"
#include "volcomp/datasets/rtl_reader.hpp"
#include "volcomp/datasets/tracker_csv.hpp"
#include "volcomp/metrology/circular.hpp"
#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/rotary_data.hpp"
#include "volcomp/tools/csv.hpp"

namespace {

// A failure must say what is wrong.
template <typename R>
void Check(const R& r) {
  if (!r.ok() && r.error().message.empty()) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace volcomp;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Check(datasets::ParseRtl(text, "fuzz.rtl"));
  Check(datasets::ReadPositioningText(text, "fuzz"));
  const Expected<tools::CsvTable> read = tools::CsvTable::ReadString(text, "fuzz.csv");
  Check(read);
  if (!read.ok()) return 0;
  const tools::CsvTable& csv = *read;
  for (const tools::CsvRow& row : csv.rows()) {
    for (size_t c = 0; c < csv.header().size(); ++c) Check(row.Number(c));
  }
  Check(metrology::ReadPositioningCsv(csv));
  Check(metrology::ReadRotaryCsv(csv));
  Check(metrology::EvaluateDiagonals(csv, metrology::GroupingOptions()));
  Check(datasets::AxisTableFromCsv(csv));
  Check(datasets::TrackerDataFromCsv(csv));
  Check(datasets::TrackerLatticeFromCsv(csv));
  Check(datasets::PositioningFromCsv(csv));
  Check(metrology::ReadCircularCsv(csv, 0.0));
  static const std::vector<image::AxisDef> kXyz = {{'X'}, {'Y'}, {'Z'}};
  Check(builders::NodeGridFromCsv(csv, kXyz));
  return 0;
}
