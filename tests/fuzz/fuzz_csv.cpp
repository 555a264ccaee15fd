// Fuzz target: every CSV reader of the PC tool, and the Renishaw .rtl reader and the positioning
// loader that picks between them by content (datasets/positioning_file.hpp). Invariants: malformed
// input is a Failure with a message (kInputInvalid), never an exception, a crash, UB or time/stack
// growing faster than the input (the readers scan each field once: no regular expressions, no
// recursion per character). The fuzz build runs it with inputs of at most 4 KiB and a 128 KiB stack
// (tests/fuzz/CMakeLists.txt): short inputs keep it fast, and the small stack makes recursion per
// character overflow within them (the std::regex reader this replaced overflowed on a 600-digit
// field at 128 KiB: docs/reliability.md, "fuzz_csv").
//
// Input layout while fuzzing: the first byte chooses one of kReaders readers (byte % kReaders; the
// seeds are the checked-in files with each prefix '0'..';', made by the build: seeds_csv/), the
// rest is the text. One reader per input runs 2.7x more inputs per CPU second than all of them,
// with more coverage (docs/reliability.md). The replay test (VOLCOMP_FUZZ_REPLAY) runs each file
// both ways: the whole file through every reader (the checked-in seeds and regression inputs are
// plain files) and the rest through the reader its first byte chooses (a crash file as libFuzzer
// wrote it).
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

using namespace volcomp;

constexpr unsigned kReaders = 12;

// A failure must say what is wrong.
template <typename R>
void Check(const R& r) {
  if (!r.ok() && r.error().message.empty()) std::abort();
}

// Reader `reader` (0 .. kReaders-1) on `text`: 0 the .rtl reader, 1 the positioning loader, 2 the
// CSV table and every cell as a number, 3.. one of the table readers on the parsed table.
void RunReader(unsigned reader, const std::string& text) {
  if (reader == 0) return Check(datasets::ParseRtl(text, "fuzz.rtl"));
  if (reader == 1) return Check(datasets::ReadPositioningText(text, "fuzz"));
  const Expected<tools::CsvTable> read = tools::CsvTable::ReadString(text, "fuzz.csv");
  Check(read);
  if (!read.ok()) return;
  const tools::CsvTable& csv = *read;
  static const std::vector<image::AxisDef> kXyz = {{'X'}, {'Y'}, {'Z'}};
  switch (reader) {
    case 2:
      for (const tools::CsvRow& row : csv.rows()) {
        for (size_t c = 0; c < csv.header().size(); ++c) Check(row.Number(c));
      }
      return;
    case 3:
      return Check(metrology::ReadPositioningCsv(csv));
    case 4:
      return Check(metrology::ReadRotaryCsv(csv));
    case 5:
      return Check(metrology::EvaluateDiagonals(csv, metrology::GroupingOptions()));
    case 6:
      return Check(datasets::AxisTableFromCsv(csv));
    case 7:
      return Check(datasets::TrackerDataFromCsv(csv));
    case 8:
      return Check(datasets::TrackerLatticeFromCsv(csv));
    case 9:
      return Check(datasets::PositioningFromCsv(csv));
    case 10:
      return Check(metrology::ReadCircularCsv(csv, 0.0));
    default:
      return Check(builders::NodeGridFromCsv(csv, kXyz));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const char* chars = reinterpret_cast<const char*>(data);
#ifdef VOLCOMP_FUZZ_REPLAY
  const std::string whole(chars, size);
  for (unsigned r = 0; r < kReaders; ++r) RunReader(r, whole);
#endif
  if (size == 0) return 0;
  RunReader(data[0] % kReaders, std::string(chars + 1, size - 1));
  return 0;
}
