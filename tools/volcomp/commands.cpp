// The command table of `volcomp`: every command with every option it accepts (value, unit,
// default, meaning), the help generated from it, and the dispatch that parses with it.
#include "commands.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>

#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {
namespace {

using Options = std::vector<OptionSpec>;

Options Join(std::initializer_list<Options> parts) {
  Options out;
  for (const Options& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// --- option groups shared by several commands -------------------------------------------------

const Options kCanOptions = {
    {"--can", nullptr, "SPEC", nullptr, nullptr,
     "CAN adapter (required): socketcan:IFACE, slcan:DEVICE[@BITRATE] or slcan-tcp:HOST:PORT"},
    {"--node", nullptr, "ID", nullptr, "16", "node-ID of the board, 1..127 (16 = 0x10)"},
    {"--log", nullptr, "FILE", nullptr, nullptr, "record every CAN frame sent and received"},
    {"--timeout-ms", nullptr, "N", "ms", "1000", "how long to wait for each SDO answer, 10..60000"},
};

const Options kResolutionOptions = {
    {"--resolution-nm", nullptr, "X=N,Y=N,...", "nm per step (µ° per step for A, B, C)", nullptr,
     "step size of each axis, as the board's 0x2012; give this or --steps-per-unit"},
    {"--steps-per-unit", nullptr, "X=N,Y=N,...", "steps per mm (per degree for A, B, C)", nullptr,
     "step size of each axis as steps per unit; give this or --resolution-nm, not both"},
};

const Options kImageOptions = {
    {"--element", nullptr, "int16|int32|float32", nullptr, "int16", "element type of the table"},
    {"--frac-bits", nullptr, "N", "bits", nullptr,
     "fraction bits of int16/int32 elements, 0..8 (default: the most that fit every value)"},
    {"--table-id", nullptr, "N", nullptr, "1",
     "table id the board reports in 0x2103, 1..4294967295 (0 there means no table active)"},
    {"--info", nullptr, "KEY=VALUE", nullptr, nullptr,
     "text for the image's INFO section (machine, operator, ...)", true},
};

const Options kGridOptions = Join({
    {{"--output", "-o", "IMAGE", nullptr, nullptr, "image file to write (required)"}},
    kResolutionOptions,
    {{"--range", nullptr, "X=MIN:MAX,...", "mm", nullptr,
      "lattice range per axis (default: the data's extent)"},
     {"--spacing-mm", nullptr, "X=S,Y=S,Z=S|S", "mm", nullptr,
      "node spacing, per axis or one for all (default: the data's own spacing)"},
     {"--max-interp-error-um", nullptr, "E", "µm", nullptr,
      "instead of --spacing-mm: the coarsest spacing whose predicted interpolation error is ≤ E"},
     {"--max-correction-um", nullptr, "B", "µm", "1000",
      "refuse a node correction larger than B (catches wrong units)"}},
    kImageOptions,
    {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable build report on stdout"}},
});

const Options kModelOptions = {
    {"--model", nullptr, "s500|FILE.conf", nullptr, nullptr,
     "the error model (required): the built-in S500 or a model config"},
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

const Options kJsonReport = {
    {"--json", nullptr, nullptr, nullptr, nullptr, "every value as JSON on stdout"},
    {"--report", nullptr, "DIR", nullptr, nullptr,
     "write an HTML report and its JSON, named by the axis or diagonals, into DIR"},
};

const Options kPositioningFileOptions = {
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

const char* const kPositioningFileNotes =
    "Each FILE is either the raw readings `evaluate positioning` reads (target_mm, direction,\n"
    "run, deviation_um ...; the mean per target and direction is used) or the mean deviations\n"
    "(position_mm, dev_forward_um [, dev_reverse_um]).";

const Options kAllowFewRuns = {
    {"--allow-few-runs", nullptr, nullptr, nullptr, nullptr,
     "fewer than 5 approaches per target and direction is a warning, not an error"},
};

const Options kTemplateOutput = {
    {"--output", "-o", "FILE", nullptr, "-", "G-code program to write (- = stdout)"},
    {"--targets-csv", nullptr, "FILE", nullptr, nullptr,
     "also write a readings template (test-condition preamble, one row per measured stop)"},
    {"--force", nullptr, nullptr, nullptr, nullptr,
     "overwrite a --targets-csv file that already holds readings"},
    {"--runs", nullptr, "N", nullptr, "5", "approaches per target and direction, 1..100"},
    {"--feed", nullptr, "F", "mm/min (deg/min on a rotary axis)", "1000", "feed rate of the moves"},
    {"--dwell-s", nullptr, "S", "s", "2", "pause at each measured stop for the reading"},
};

const char* const kGridNotes =
    "The lattice, the inverse at every node and the predicted interpolation error are reported;\n"
    "see docs/table-builders.md.";

}  // namespace

const std::vector<Command>& Commands() {
  static const std::vector<Command> kCommands = {
      {"build grid", "build a table image from corrections at grid nodes (CSV)", "",
       Join({{{"--csv", nullptr, "FILE", nullptr, nullptr,
               "corrections at the nodes (required): x_mm|x_steps ..., dx_um|dx_steps ..."},
              {"--output", "-o", "IMAGE", nullptr, nullptr, "image file to write (required)"},
              {"--axes", nullptr, "X,Y,Z", nullptr, "X,Y,Z", "the three grid axes"}},
             kResolutionOptions,
             kImageOptions}),
       RunBuildGrid},
      {"inspect",
       "summarise a table image",
       "IMAGE",
       {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}},
       RunInspect},
      {"lookup",
       "correction at points read as CSV, written as CSV on stdout",
       "IMAGE",
       {{"--points", nullptr, "FILE", nullptr, nullptr,
         "points CSV: x_mm|x_steps ..., optional dir_x (default: standard input)"}},
       RunLookup},
      {"upload", "upload a table image to a board over CAN (block transfer), verify, activate",
       "IMAGE",
       Join({kCanOptions,
             {{"--activate", nullptr, nullptr, nullptr, nullptr, "activate it after the upload"},
              {"--allow-clamp", nullptr, nullptr, nullptr, nullptr,
               "upload a table the board would clamp (0x2015) or rate-limit (0x2016); a warning"},
              {"--force", nullptr, nullptr, nullptr, nullptr,
               "upload even when the board already has this table"},
              {"--retries", nullptr, "N", nullptr, "2", "repeat a failed transfer up to N times"},
              {"--json", nullptr, nullptr, nullptr, nullptr,
               "the result as one JSON object on stdout (messages on stderr)"},
              {"--quiet", nullptr, nullptr, nullptr, nullptr, "no progress bar"}}}),
       RunUpload,
       "Before the transfer the image is checked against the board's installation: axis count,\n"
       "names and units per step (0x2012) must match; a table whose largest correction exceeds\n"
       "the max correction (0x2015), or whose gradient times the fastest input rates (0x201E)\n"
       "exceeds the max correction rate (0x2016), is refused (exit 1, naming the axis, the\n"
       "table's value and the board's limit) unless --allow-clamp."},
      {"verify", "check which table a board has active or staged", "IMAGE",
       Join({kCanOptions,
             {{"--readback", nullptr, nullptr, nullptr, nullptr,
               "read the table back (the active one, or the staged one with --staged) and compare "
               "it byte by byte"},
              {"--staged", nullptr, nullptr, nullptr, nullptr,
               "verify the staged table instead of the active one"},
              {"--json", nullptr, nullptr, nullptr, nullptr,
               "the result as one JSON object on stdout (messages on stderr)"}}}),
       RunVerify,
       "Exit 0 when the board has the image (active, or staged with --staged), 1 when it has\n"
       "another table or none, 3 when the board cannot be reached."},
      {"activate", "activate the staged, verified table (axes referenced and at rest)", "",
       Join({kCanOptions,
             {{"--allow-clamp", nullptr, nullptr, nullptr, nullptr,
               "activate a table the board would clamp (0x2015) or rate-limit (0x2016)"},
              {"--json", nullptr, nullptr, nullptr, nullptr,
               "the result as one JSON object on stdout (messages on stderr)"}}}),
       RunActivate,
       "The staged table is read back and checked against the board's installation first: axis\n"
       "count, names and units per step (0x2012) must match; a table whose largest correction\n"
       "exceeds the max correction (0x2015), or whose gradient times the fastest input rates\n"
       "(0x201E) exceeds the max correction rate (0x2016), is refused unless --allow-clamp."},
      {"deactivate", "deactivate the active table (the correction ramps out)", "",
       Join({kCanOptions,
             {{"--json", nullptr, nullptr, nullptr, nullptr,
               "the result as one JSON object on stdout (messages on stderr)"}}}),
       RunDeactivate},
      {"reference", "declare axes referenced over CAN (instead of home switch edges)", "",
       Join({kCanOptions,
             {{"--axes", nullptr, "1,2,3", nullptr, nullptr,
               "axis numbers 1..N of the board's N axes (0x2000:4) to reference (default: all)"}}}),
       RunReference},
      {"status", "a board's identity, state, tables, per-axis positions and corrections, counters",
       "",
       Join({kCanOptions,
             {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
       RunStatus},
      {"monitor", "follow a board: heartbeat, EMCY and diagnostics every interval", "",
       Join({kCanOptions,
             {{"--interval-ms", nullptr, "N", "ms", "1000", "time between lines, at least 50"},
              {"--duration", nullptr, "S", "s", "0", "stop after S seconds (0 = until stopped)"},
              {"--csv", nullptr, nullptr, nullptr, nullptr,
               "CSV for logging: a header, then one row per interval in machine units (mm, µm; "
               "deg, arcsec on rotary axes); heartbeat and EMCY lines on stderr"},
              {"--json", nullptr, nullptr, nullptr, nullptr,
               "one JSON object per interval and line (the axes as in `status --json`); "
               "heartbeat and EMCY lines on stderr"}}}),
       RunMonitor},
      {"sdo", "read or write one object: sdo read 2104:0, sdo write 2018:1 -5000",
       "read|write INDEX:SUB [VALUE]", kCanOptions, RunSdo,
       "INDEX in hex, SUB in decimal or 0x-hex; VALUE an integer (decimal, 0x-hex, negative).\n"
       "A negative VALUE is a value, not an option; `--` before it also works.\n"
       "A write is checked against the object dictionary before anything is sent: the object\n"
       "must be writable and VALUE within its type and limits (exit 2 otherwise). When the\n"
       "board refuses, its reason is printed (for a store, the rule and the axis)."},
      {"config show", "every configuration object of a board: value, value in force, factory value",
       "",
       Join({kCanOptions,
             {{"--all", nullptr, nullptr, nullptr, nullptr,
               "also the objects of the axes beyond the axis count"},
              {"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
       RunConfigShow,
       "The values are the board's edited copy (what a store saves) beside the configuration in\n"
       "force (0x2124); they differ while settings are pending (edited or stored, applied at NMT\n"
       "reset node). See docs/user-guide.md \"Configuring the board from a file\"."},
      {"config save", "write a board's configuration to an INI file", "FILE|-",
       Join({kCanOptions,
             {{"--force", nullptr, nullptr, nullptr, nullptr, "replace an existing FILE"}}}),
       RunConfigSave,
       "[board] and one [axis NAME] section per axis; each key's comment names its object and\n"
       "unit. `config apply` reads the file back."},
      {"config apply",
       "check an INI file with the board's rules, write it, store it, reset the node, read back",
       "FILE",
       Join({kCanOptions,
             {{"--no-reset", nullptr, nullptr, nullptr, nullptr,
               "store only: in force at the next NMT reset node or power-up"}}}),
       RunConfigApply,
       "The file is checked first (unknown keys, values outside the objects' limits, the\n"
       "firmware's consistency rules: refused with its line, nothing written); then the objects\n"
       "that differ are written, stored (1010:1) and the node reset (NMT 0x81); every object is\n"
       "read back and compared. Keys left out take the factory value. A refused write or store\n"
       "undoes the edits written before it."},
      {"nmt", "NMT command to the node, confirmed by its boot-up or heartbeat",
       "reset|reset-comm|start|stop|pre-op",
       Join({kCanOptions,
             {{"--wait-ms", nullptr, "N", "ms", "2500",
               "how long to wait for the boot-up or the heartbeat confirming the command"},
              {"--no-wait", nullptr, nullptr, nullptr, nullptr, "send only"}}}),
       RunNmt,
       "reset: reset node (the stored settings come into force; positions and references are\n"
       "lost); reset-comm: reset communication; start: operational; stop: stopped (only NMT and\n"
       "heartbeat answered); pre-op: pre-operational. Frame 0x000 [command, node-ID]."},
      {"eds",
       "write the node's EDS file (CiA 306) generated from the object dictionary",
       "",
       {{"--output", "-o", "FILE", nullptr, "-", "file to write (- = stdout)"}},
       RunEds},
      {"evaluate positioning", "GOST 27843-88 / ISO 230-2 positioning test from CSV", "FILE|-",
       Join({{{"--standard", nullptr, "gost27843|iso230-2|both", nullptr, "gost27843",
               "standard(s) to evaluate"},
              {"--sigma", nullptr, "formula|range", nullptr, "formula",
               "GOST 27843 S by formula (5) or by the range method (6)"},
              {"--axis-length-mm", nullptr, "L", "mm", nullptr,
               "axis travel for the target-count checks (default: the targets' span)"}},
             kAllowFewRuns,
             kJsonReport}),
       RunEvaluatePositioning,
       "Input: target_mm|target_deg, direction, run, deviation_um|deviation_mm|measured_mm|\n"
       "deviation_arcsec|...; ',' or ';' or TAB separated (decimal comma with ';' or TAB);\n"
       "'# key: value' lines before the header are the test conditions of the report.\n"
       "Non-finite readings are refused; implausible magnitudes and Grubbs outliers (99 %)\n"
       "are warned about with their line. See docs/metrology.md."},
      {"evaluate diagonal", "ISO 230-6 body/face diagonal test (E, B, E_d, B_d) from CSV", "FILE|-",
       Join({kAllowFewRuns, kJsonReport}), RunEvaluateDiagonal,
       "Input: the positioning long layout with a `diagonal` column naming each row's diagonal."},
      {"evaluate rotary", "ISO 230-7 error motion (synchronous, asynchronous, tilt, reversal)",
       "FILE|-",
       Join({{{"--sensitive", nullptr, "rotating|fixed", nullptr, "rotating",
               "sensitive direction of the radial measurement"},
              {"--fsd-angle-deg", nullptr, "A", "deg", nullptr,
               "angle of the fixed sensitive direction (with --sensitive fixed; default 0)"},
              {"--tilt-distance-mm", nullptr, "L", "mm", nullptr,
               "distance of the second radial plane (x2_um, y2_um) for tilt"},
              {"--face-radius-mm", nullptr, "R", "mm", nullptr, "radius of the face sensor"},
              {"--min-zone", nullptr, nullptr, nullptr, nullptr,
               "also evaluate about the minimum-zone centre"},
              {"--reversal", nullptr, "FILE2", nullptr, nullptr,
               "Donaldson reversal: the second (reversed) setup"},
              {"--reversal-channel", nullptr, "COLUMN", nullptr, "x_um",
               "channel used for the reversal"},
              {"--reversal-procedure", nullptr, "P|S", nullptr, "P",
               "reversal procedure (same or reversed sign convention)"}},
             kJsonReport}),
       RunEvaluateRotary},
      {"program positioning", "GOST 27843 test program: targets P_j=(N+r)P and G-code cycle", "",
       Join({{{"--pitch", nullptr, "P", "mm (deg with --rotary)", nullptr,
               "largest repeating step of the axis: screw pitch, scale period (required)"},
              {"--start", nullptr, "S", "mm (deg with --rotary)", "0",
               "first end of the measured travel"},
              {"--end", nullptr, "E", "mm", nullptr,
               "other end of the measured travel (required for a linear axis)"},
              {"--count", nullptr, "M", nullptr, "11", "number of target positions"},
              {"--seed", nullptr, "N", nullptr, "1", "seed of the random fractions r_j"},
              {"--fraction-digits", nullptr, "D", nullptr, "2", "digits of r_j, 1..4"},
              {"--rotary", nullptr, nullptr, nullptr, nullptr,
               "full-turn rotary axis (0°, 90°, 180°, 270° included)"},
              {"--cycle", nullptr, "linear|pilgrim", nullptr, "linear",
               "GOST fig. 1 linear cycle or fig. 2 pseudo-pilgrim"},
              {"--overrun", nullptr, "O", "mm (deg with --rotary)", "5",
               "travel beyond the end targets for the reversal"},
              {"--axis", nullptr, "NAME", nullptr, nullptr,
               "axis word of the G-code and of the template (default: X, C with --rotary)"}},
             kTemplateOutput}),
       RunProgramPositioning,
       "The readings template names the axis in its preamble; `evaluate positioning` names the\n"
       "report after it. A template that already holds readings is not overwritten."},
      {"program diagonal", "ISO 230-6 diagonal targets and G-code cycle (one diagonal or all four)",
       "",
       Join({{{"--p1", nullptr, "X,Y,Z", "mm", nullptr, "start point of one diagonal"},
              {"--p2", nullptr, "X,Y,Z", "mm", nullptr, "end point of that diagonal"},
              {"--box", nullptr, "X0,Y0,Z0:X1,Y1,Z1", "mm", nullptr,
               "instead of --p1/--p2: the four body diagonals of this box"},
              {"--increment-mm", nullptr, "I", "mm", nullptr,
               "target spacing along the diagonal (required)"},
              {"--name", nullptr, "+X+Y-Z", nullptr, nullptr,
               "diagonal name; checked against P1→P2 (default: derived from P1→P2)"},
              {"--overrun-mm", nullptr, "O", "mm", "5", "travel beyond the end targets"}},
             kTemplateOutput}),
       RunProgramDiagonal,
       "A diagonal is named by its start corner (ISO 230-6): P1 at the low end of X and Y and\n"
       "the high end of Z is -X-Y+Z. With --box, -o FILE.ngc writes FILE_NNN.ngc, FILE_PNN.ngc,\n"
       "FILE_NPN.ngc and FILE_PPN.ngc (start corners -X-Y-Z, +X-Y-Z, -X+Y-Z, +X+Y-Z) and\n"
       "--targets-csv one template for all four, which `evaluate diagonal` reads."},
      {"report compare",
       "before/after page: positioning and diagonal results with reductions",
       "BEFORE AFTER",
       {{"--output", "-o", "DIR", nullptr, nullptr, "directory for compare.html (required)"}},
       RunReportCompare,
       "BEFORE and AFTER are report directories written by `evaluate ... --report DIR` (or\n"
       "single .json results of it); results are paired by name (axis, diagonals)."},
      {"build model", "GRID3 image from the 21-parameter error model (inverse map)", "",
       Join({kModelOptions, kGridOptions}), RunBuildModel, kGridNotes},
      {"build tracker",
       "GRID3 image from laser-tracker axis lines or a lattice (dissertation ch. 2 methods)", "",
       Join({{{"--points", nullptr, "FILE", nullptr, nullptr,
               "tracker lines CSV (or --builtin, or --lattice)"},
              {"--builtin", nullptr, "s500-315|s500-240", nullptr, nullptr,
               "the dissertation's tracker lines"},
              {"--lattice", nullptr, "FILE", nullptr, nullptr,
               "tracker readings at every lattice node (x_cmd_mm..z_cmd_mm, x_mm..z_mm)"},
              {"--through", nullptr, "IMAGE", nullptr, nullptr,
               "the table in force while the lattice was measured (composed with it)"},
              {"--method", nullptr, "static|interval|quasi-differential", nullptr,
               "quasi-differential", "correction method"},
              {"--cosines", nullptr, "printed|signed|scaled", nullptr, nullptr,
               "axis vectors (default: scaled for quasi-differential, else signed)"},
              {"--origin", nullptr, "measured|extrapolated", nullptr, nullptr,
               "r01 (default: measured with scaled vectors, else extrapolated)"},
              {"--static-interval", nullptr, "N", nullptr, nullptr,
               "interval of the static calibration matrix (default 1)"},
              {"--appendix-form", nullptr, nullptr, nullptr, nullptr,
               "the printed algorithm instead of the exact inverse"},
              {"--allow-discontinuous", nullptr, nullptr, nullptr, nullptr,
               "allow a method that jumps at cell borders"}},
             kGridOptions}),
       RunBuildTracker, kGridNotes},
      {"build kmtpp", "GRID3 image by the КМТПП method (dissertation ch. 4)", "",
       Join({kModelOptions,
             {{"--tracker", nullptr, "FILE", nullptr, nullptr, "tracker lines for the calibration"},
              {"--tracker-builtin", nullptr, "s500-315|s500-240", nullptr, "s500-315",
               "built-in tracker lines (without --tracker)"},
              {"--cosines", nullptr, "signed|printed", nullptr, "signed", "calibration vectors"},
              {"--calibration-interval", nullptr, "N", nullptr, "1", "calibration interval"},
              {"--gain", nullptr, "K", nullptr, nullptr, "K (default 1.5); K·l in (0, 2)"},
              {"--step", nullptr, "L", nullptr, nullptr, "l, model-time step (default 0.1)"},
              {"--final-step", nullptr, "traced|node", nullptr, nullptr,
               "final step base (default traced; node with --dissertation)"},
              {"--sum", nullptr, "matrix|listing", nullptr, nullptr,
               "S update (default matrix; listing with --dissertation)"},
              {"--index", nullptr, "round|floor", nullptr, nullptr,
               "table row rule (default round)"},
              {"--dissertation", nullptr, nullptr, nullptr, nullptr, "the printed variant"},
              {"--refine-mm", nullptr, "H", "mm", nullptr, "resample the tables every H"},
              {"--allow-discontinuous", nullptr, nullptr, nullptr, nullptr,
               "allow the printed final step, which jumps"}},
             kGridOptions}),
       RunBuildKmtpp, kGridNotes},
      {"build axis", "AXIS1D image from positioning tests (raw readings or mean deviations)", "",
       Join({kPositioningFileOptions,
             {{"--output", "-o", "IMAGE", nullptr, nullptr, "image file to write (required)"}},
             kResolutionOptions,
             {{"--reverse", nullptr, "tables|backlash|mean", nullptr, "tables",
               "negative-direction handling"},
              {"--spacing", nullptr, "X=S,...", "mm (deg for A, B, C)", nullptr,
               "table spacing per axis (default: the test's, or its smallest gap)"},
              {"--wrap", nullptr, nullptr, nullptr, nullptr,
               "rotary table spanning exactly 360° wraps around"}},
             kImageOptions}),
       RunBuildAxis, kPositioningFileNotes},
      {"export linuxcnc",
       "LinuxCNC joint compensation files (COMP_FILE_TYPE 0 or 1) from positioning tests", "",
       Join({kPositioningFileOptions,
             {{"--output", "-o", "DIR", nullptr, nullptr,
               "directory for x.comp ... and joints.ini (required)"},
              {"--type", nullptr, "0|1", nullptr, "1",
               "COMP_FILE_TYPE: 1 the file holds the trims, 0 the positions reached"},
              {"--joints", nullptr, "X=N,...", nullptr, nullptr,
               "joint 0..15 of an axis in its [JOINT_n] lines (default: X=0 ... W=8)"},
              {"--spacing", nullptr, "X=S,...", "mm (deg for A, B, C)", nullptr,
               "point spacing per axis (default: the test's, or its smallest gap)"}},
             kAllowFewRuns}),
       RunExportLinuxcnc,
       "Each FILE is either the raw readings `evaluate positioning` reads (the mean per\n"
       "target and direction is used) or the mean deviations (position_mm, dev_forward_um\n"
       "[, dev_reverse_um]). Writes one file per axis (x.comp, ...) and joints.ini with the\n"
       "INI lines to paste; see docs/linuxcnc.md."},
      {"model eval", "forward error (or --inverse command) of a model at points, CSV in/out",
       "[POINTS.csv|-]",
       Join({kModelOptions,
             {{"--inverse", nullptr, nullptr, nullptr, nullptr,
               "the command that lands on each point instead of the error"},
              {"--output", "-o", "FILE", nullptr, nullptr, "CSV to write (default: stdout)"}}}),
       RunModelEval},
  };
  return kCommands;
}

const Command* FindCommand(const std::vector<std::string>& words, std::size_t* consumed) {
  const Command* best = nullptr;
  std::size_t best_words = 0;
  for (const Command& c : Commands()) {
    std::istringstream name(c.name);
    std::vector<std::string> parts;
    for (std::string p; name >> p;) parts.push_back(p);
    if (parts.size() > words.size() || parts.size() <= best_words) continue;
    bool match = true;
    for (std::size_t i = 0; i < parts.size(); ++i) match = match && parts[i] == words[i];
    if (match) {
      best = &c;
      best_words = parts.size();
    }
  }
  *consumed = best_words;
  return best;
}

const Command* FindCommand(int (*run)(Args&)) {
  for (const Command& c : Commands()) {
    if (c.run == run) return &c;
  }
  return nullptr;
}

std::string CommandHelp(const Command& c) {
  std::ostringstream s;
  s << "usage: volcomp " << c.name;
  if (*c.arguments != '\0') s << " " << c.arguments;
  if (!c.options.empty()) s << " [options]";
  s << "\n" << c.summary << "\n";
  if (!c.options.empty()) s << "\noptions:\n";
  for (const OptionSpec& o : c.options) {
    s << "  ";
    if (o.alias != nullptr) s << o.alias << ", ";
    s << o.name;
    if (o.value != nullptr) s << " " << o.value;
    s << "\n      " << o.help;
    if (o.unit != nullptr) s << "; unit: " << o.unit;
    if (o.default_value != nullptr) s << "; default: " << o.default_value;
    if (o.repeatable) s << "; repeatable";
    s << "\n";
  }
  if (*c.notes != '\0') s << "\n" << c.notes << "\n";
  s << "\nexit codes: 0 ok, 1 refused or failed, 2 usage, 3 communication\n";
  return s.str();
}

std::string ToolHelp() {
  std::ostringstream s;
  s << "volcomp: volumetric error compensation PC tool\n\n"
       "usage: volcomp COMMAND [options]\n\ncommands:\n";
  for (const Command& c : Commands()) {
    std::string name = c.name;
    name.resize(24, ' ');
    s << "  " << name << c.summary << "\n";
  }
  s << "\n`volcomp help COMMAND` shows a command's options with units and defaults.\n"
       "A word that is a number (-5000) is a value, not an option; `--` ends the options.\n"
       "exit codes: 0 ok, 1 refused or failed (bad input names file and line), 2 usage,\n"
       "3 communication (no board, bus error, timeout)\n";
  return s.str();
}

// With --json (for the commands that declare it), a failure is a JSON object on stdout too, so a
// script reads one object whatever happened: {"command", "exit_code", "error"}.
void JsonFailure(const Command& cmd,
                 const std::vector<std::string>& words,
                 int code,
                 const std::string& message) {
  bool declared = false;
  for (const OptionSpec& o : cmd.options) declared = declared || std::string(o.name) == "--json";
  if (!declared || std::find(words.begin(), std::find(words.begin(), words.end(), "--"),
                             "--json") == words.end()) {
    return;
  }
  JsonWriter w(std::cout);
  w.begin_object();
  w.key("command").value(cmd.name);
  w.key("exit_code").value(code);
  w.key("error").value(message);
  w.end_object();
  std::cout << "\n";
}

int RunCommand(const Command& cmd, const std::vector<std::string>& words) {
  auto fail = [&](int code, const std::string& message) {
    JsonFailure(cmd, words, code, message);
    return code;
  };
  try {
    Args args(words, &cmd.options);
    return cmd.run(args);
  } catch (const UsageError& e) {
    std::cerr << "volcomp " << cmd.name << ": " << e.what() << "\n(`volcomp help " << cmd.name
              << "` lists the options)\n";
    return fail(kExitUsage, e.what());
  } catch (const CommunicationError& e) {
    std::cerr << "volcomp " << cmd.name << ": error: " << e.what() << "\n";
    return fail(kExitCommunication, e.what());
  } catch (const std::exception& e) {
    std::cerr << "volcomp " << cmd.name << ": error: " << e.what() << "\n";
    return fail(kExitFailed, e.what());
  }
}

int RunCommandLine(const std::vector<std::string>& input) {
  std::vector<std::string> words = input;
  if (words.empty() || words[0] == "--help" || words[0] == "-h" ||
      (words[0] == "help" && words.size() == 1)) {
    std::cout << ToolHelp();
    return words.empty() ? kExitUsage : kExitOk;
  }
  const bool help = words[0] == "help";
  if (help) words.erase(words.begin());
  std::size_t consumed = 0;
  const Command* cmd = FindCommand(words, &consumed);
  if (cmd == nullptr) {
    std::cerr << "volcomp: unknown command \"" << words[0] << "\" (try `volcomp help`)\n";
    return kExitUsage;
  }
  bool help_option = false;
  for (std::size_t i = consumed; i < words.size() && words[i] != "--"; ++i) {
    help_option = help_option || words[i] == "--help" || words[i] == "-h";
  }
  if (help || help_option) {
    std::cout << CommandHelp(*cmd);
    return kExitOk;
  }
  return RunCommand(
      *cmd, std::vector<std::string>(words.begin() + static_cast<long>(consumed), words.end()));
}

}  // namespace volcomp::tools
