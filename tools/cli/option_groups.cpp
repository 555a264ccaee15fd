// Option groups shared by several commands.
#include "option_groups.hpp"

namespace volcomp::cli {

using args::OptionSpec;

Options Join(std::initializer_list<Options> parts) {
  Options out;
  for (const Options& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// --- option groups shared by several commands -------------------------------------------------

const Options& CanOptions() {
  static const Options kOptions = {
      {"--can", nullptr, "SPEC", nullptr, nullptr,
       "CAN adapter (required): socketcan:IFACE, slcan:DEVICE[@BITRATE] or slcan-tcp:HOST:PORT"},
      {"--node", nullptr, "ID", nullptr, "16", "node-ID of the board, 1..127 (16 = 0x10)"},
      {"--log", nullptr, "FILE", nullptr, nullptr, "record every CAN frame sent and received"},
      {"--timeout-ms", nullptr, "N", "ms", "1000",
       "how long to wait for each SDO answer, 10..60000"},
  };
  return kOptions;
}
const Options& ResolutionOptions() {
  static const Options kOptions = {
      {"--resolution-nm", nullptr, "X=N,Y=N,...", "nm per step (µ° per step for A, B, C)", nullptr,
       "step size of each axis, as the board's 0x2012; give this or --steps-per-unit"},
      {"--steps-per-unit", nullptr, "X=N,Y=N,...", "steps per mm (per degree for A, B, C)", nullptr,
       "step size of each axis as steps per unit; give this or --resolution-nm, not both"},
  };
  return kOptions;
}
const Options& ImageOptions() {
  static const Options kOptions = {
      {"--element", nullptr, "int16|int32|float32", nullptr, "int16", "element type of the table"},
      {"--frac-bits", nullptr, "N", "bits", nullptr,
       "fraction bits of int16/int32 elements, 0..8 (default: the most that fit every value)"},
      {"--table-id", nullptr, "N", nullptr, "1",
       "table id the board reports in 0x2103, 1..4294967295 (0 there means no table active)"},
      {"--info", nullptr, "KEY=VALUE", nullptr, nullptr,
       "text for the image's INFO section (machine, operator, ...)", true},
  };
  return kOptions;
}
const Options& BoardFileOptions() {
  static const Options kOptions = {
      {"--board", nullptr, "FILE", nullptr, nullptr,
       "check the image against the board's settings file (`config save`) before writing it: "
       "axes and units per step, clamp and rate limit, the home positions inside the lattice"},
      {"--bank-bytes", nullptr, "N", "bytes", nullptr,
       "with --board: the board's table bank size (0x2108, `volcomp status` shows it): refuse a "
       "larger image"},
      {"--allow-clamp", nullptr, nullptr, nullptr, nullptr,
       "with --board: write an image the board would clamp or rate-limit (warned)"},
  };
  return kOptions;
}
const Options& GridOptions() {
  static const Options kOptions = Join({
      {{"--output", "-o", "IMAGE", nullptr, nullptr, "image file to write (required)"}},
      ResolutionOptions(),
      {{"--range", nullptr, "X=MIN:MAX,...", "mm", nullptr,
        "lattice range per axis (default: the data's extent)"},
       {"--spacing-mm", nullptr, "X=S,Y=S,Z=S|S", "mm", nullptr,
        "node spacing, per axis or one for all (default: the data's own spacing)"},
       {"--max-interp-error-um", nullptr, "E", "µm", nullptr,
        "instead of --spacing-mm: the coarsest spacing whose predicted interpolation error is ≤ E"},
       {"--max-correction-um", nullptr, "B", "µm", "1000",
        "refuse a node correction larger than B (catches wrong units)"}},
      ImageOptions(),
      BoardFileOptions(),
      {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable build report on stdout"}},
  });
  return kOptions;
}
const Options& ModelOptions() {
  static const Options kOptions = {
      {"--model", nullptr, "s500|FILE", nullptr, nullptr,
       "the error model (required): the built-in S500, a model config, an Etalon exchange "
       "file or ISG-CSV (ISO 230-1 parameters)"},
      {"--order", nullptr, "first|exact", nullptr, nullptr,
       "rotation order (default: the model's; exact for the physical formulation)"},
      {"--formulation", nullptr, "physical|dissertation", nullptr, nullptr,
       "model formulation (default: the model's, physical)"},
      {"--dissertation-case", nullptr, "plus|minus", nullptr, nullptr,
       "δ+ or δ− of the dissertation's second order (default: the model's, plus)"},
      {"--angle-scale", nullptr, "K", nullptr, nullptr,
       "scale of the angular errors, the dissertation's k (default: the model's, 1)"},
      {"--tool-offset-mm", nullptr, "X,Y,Z", "mm", nullptr,
       "tool point relative to the measuring point (default: the model's)"},
      {"--no-squareness", nullptr, nullptr, nullptr, nullptr, "drop the squareness errors"},
  };
  return kOptions;
}
const Options& ModelFormatOptions() {
  static const Options kOptions = {
      {"--format", nullptr, "conf|etalon|isg", nullptr, nullptr,
       "the --model file's format: model config, Etalon exchange format or ISG-CSV (default: "
       "recognised by content)"},
  };
  return kOptions;
}
const Options& JsonReport() {
  static const Options kOptions = {
      {"--json", nullptr, nullptr, nullptr, nullptr, "every value as JSON on stdout"},
      {"--report", nullptr, "DIR", nullptr, nullptr,
       "write an HTML report and its JSON, named by the axis or diagonals, into DIR"},
  };
  return kOptions;
}
const Options& PositioningFileOptions() {
  static const Options kOptions = {
      {"--x", nullptr, "FILE", nullptr, nullptr, "positioning test of axis X"},
      {"--y", nullptr, "FILE", nullptr, nullptr, "... of axis Y"},
      {"--z", nullptr, "FILE", nullptr, nullptr, "... of axis Z"},
      {"--a", nullptr, "FILE", nullptr, nullptr, "... of rotary axis A"},
      {"--b", nullptr, "FILE", nullptr, nullptr, "... of rotary axis B"},
      {"--c", nullptr, "FILE", nullptr, nullptr, "... of rotary axis C"},
      {"--u", nullptr, "FILE", nullptr, nullptr, "... of axis U"},
      {"--v", nullptr, "FILE", nullptr, nullptr, "... of axis V"},
      {"--w", nullptr, "FILE", nullptr, nullptr, "... of axis W"},
  };
  return kOptions;
}
const char* PositioningFileNotes() {
  return "Each FILE is either the raw readings `evaluate positioning` reads (target_mm, "
         "direction,\n"
         "run, deviation_um ...; or a Renishaw .rtl; the mean per target and direction is used)\n"
         "or the mean deviations (position_mm, dev_forward_um [, dev_reverse_um]).";
}
const Options& AllowFewRuns() {
  static const Options kOptions = {
      {"--allow-few-runs", nullptr, nullptr, nullptr, nullptr,
       "fewer than 5 approaches per target and direction is a warning, not an error"},
  };
  return kOptions;
}
const Options& TemplateOutput() {
  static const Options kOptions = {
      {"--output", "-o", "FILE", nullptr, "-", "G-code program to write (- = stdout)"},
      {"--targets-csv", nullptr, "FILE", nullptr, nullptr,
       "also write a readings template (test-condition preamble, one row per measured stop)"},
      {"--force", nullptr, nullptr, nullptr, nullptr,
       "overwrite a --targets-csv file that already holds readings"},
      {"--runs", nullptr, "N", nullptr, "5", "approaches per target and direction, 1..100"},
      {"--feed", nullptr, "F", "mm/min (deg/min on a rotary axis)", "1000",
       "feed rate of the moves"},
      {"--dwell-s", nullptr, "S", "s", "2", "pause at each measured stop for the reading"},
  };
  return kOptions;
}
const char* GridNotes() {
  return "The lattice, the inverse at every node and the predicted interpolation error are "
         "reported;\n"
         "see docs/table-builders.md.";
}

}  // namespace volcomp::cli
