// TRANSITION: the declarations of the commands not yet converted to the command layer
// (command.hpp). Each moves into its own cmd_*.cpp when it is converted; this file then goes.
#include "commands.hpp"
#include "option_groups.hpp"

namespace volcomp::cli {

using tools::RunUpload;
using tools::RunVerify;
using tools::RunActivate;
using tools::RunDeactivate;
using tools::RunReference;
using tools::RunStatus;
using tools::RunMonitor;
using tools::RunSdo;
using tools::RunConfigShow;
using tools::RunConfigSave;
using tools::RunConfigApply;
using tools::RunNmt;
using tools::RunEds;
using tools::RunEvaluatePositioning;
using tools::RunEvaluateDiagonal;
using tools::RunEvaluateRotary;
using tools::RunProgramPositioning;
using tools::RunProgramDiagonal;
using tools::RunReportCompare;

const Command& UploadCommand() {
  static const Command kCommand{"upload", "upload a table image to a board over CAN (block transfer), verify, activate",
       "IMAGE",
       Join({CanOptions(),
             {{"--activate", nullptr, nullptr, nullptr, nullptr, "activate it after the upload"},
              {"--allow-clamp", nullptr, nullptr, nullptr, nullptr,
               "upload a table the board would clamp (0x2015) or rate-limit (0x2016); a warning"},
              {"--force", nullptr, nullptr, nullptr, nullptr,
               "upload even when the board already has this table"},
              {"--retries", nullptr, "N", nullptr, "2", "repeat a failed transfer up to N times"},
              {"--json", nullptr, nullptr, nullptr, nullptr,
               "the result as one JSON object on stdout (messages on stderr)"},
              {"--quiet", nullptr, nullptr, nullptr, nullptr, "no progress bar"}}}), nullptr,
                                "Before the transfer the image is checked against the board's installation: axis count,\n"
       "names and units per step (0x2012) must match; a table whose largest correction exceeds\n"
       "the max correction (0x2015), or whose gradient times the fastest input rates (0x201E)\n"
       "exceeds the max correction rate (0x2016), is refused (exit 1, naming the axis, the\n"
       "table's value and the board's limit) unless --allow-clamp.",
                                RunUpload};
  return kCommand;
}

const Command& VerifyCommand() {
  static const Command kCommand{"verify", "check which table a board has active or staged", "IMAGE",
       Join({CanOptions(),
             {{"--readback", nullptr, nullptr, nullptr, nullptr,
               "read the table back (the active one, or the staged one with --staged) and compare "
               "it byte by byte"},
              {"--staged", nullptr, nullptr, nullptr, nullptr,
               "verify the staged table instead of the active one"},
              {"--json", nullptr, nullptr, nullptr, nullptr,
               "the result as one JSON object on stdout (messages on stderr)"}}}), nullptr,
                                "Exit 0 when the board has the image (active, or staged with --staged), 1 when it has\n"
       "another table or none, 3 when the board cannot be reached.",
                                RunVerify};
  return kCommand;
}

const Command& ActivateCommand() {
  static const Command kCommand{"activate", "activate the staged, verified table (axes referenced and at rest)", "",
       Join({CanOptions(),
             {{"--allow-clamp", nullptr, nullptr, nullptr, nullptr,
               "activate a table the board would clamp (0x2015) or rate-limit (0x2016)"},
              {"--json", nullptr, nullptr, nullptr, nullptr,
               "the result as one JSON object on stdout (messages on stderr)"}}}), nullptr,
                                "The staged table is read back and checked against the board's installation first: axis\n"
       "count, names and units per step (0x2012) must match; a table whose largest correction\n"
       "exceeds the max correction (0x2015), or whose gradient times the fastest input rates\n"
       "(0x201E) exceeds the max correction rate (0x2016), is refused unless --allow-clamp.",
                                RunActivate};
  return kCommand;
}

const Command& DeactivateCommand() {
  static const Command kCommand{"deactivate", "deactivate the active table (the correction ramps out)", "",
       Join({CanOptions(),
             {{"--json", nullptr, nullptr, nullptr, nullptr,
               "the result as one JSON object on stdout (messages on stderr)"}}}), nullptr,
                                "",
                                RunDeactivate};
  return kCommand;
}

const Command& ReferenceCommand() {
  static const Command kCommand{"reference", "declare axes referenced over CAN (instead of home switch edges)", "",
       Join({CanOptions(),
             {{"--axes", nullptr, "1,2,3", nullptr, nullptr,
               "axis numbers 1..N of the board's N axes (0x2000:4) to reference (default: all)"}}}), nullptr,
                                "",
                                RunReference};
  return kCommand;
}

const Command& StatusCommand() {
  static const Command kCommand{"status", "a board's identity, state, tables, per-axis positions and corrections, counters",
       "",
       Join({CanOptions(),
             {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}), nullptr,
                                "",
                                RunStatus};
  return kCommand;
}

const Command& MonitorCommand() {
  static const Command kCommand{"monitor", "follow a board: heartbeat, EMCY and diagnostics every interval", "",
       Join({CanOptions(),
             {{"--interval-ms", nullptr, "N", "ms", "1000", "time between lines, at least 50"},
              {"--duration", nullptr, "S", "s", "0", "stop after S seconds (0 = until stopped)"},
              {"--csv", nullptr, nullptr, nullptr, nullptr,
               "CSV for logging: a header, then one row per interval in machine units (mm, µm; "
               "deg, arcsec on rotary axes); heartbeat and EMCY lines on stderr"},
              {"--json", nullptr, nullptr, nullptr, nullptr,
               "one JSON object per interval and line (the axes as in `status --json`); "
               "heartbeat and EMCY lines on stderr"}}}), nullptr,
                                "",
                                RunMonitor};
  return kCommand;
}

const Command& SdoCommand() {
  static const Command kCommand{"sdo", "read or write one object: sdo read 2104:0, sdo write 2018:1 -5000",
       "read|write INDEX:SUB [VALUE]", CanOptions(), nullptr,
                                "INDEX in hex, SUB in decimal or 0x-hex; VALUE an integer (decimal, 0x-hex, negative).\n"
       "A negative VALUE is a value, not an option; `--` before it also works.\n"
       "A write is checked against the object dictionary before anything is sent: the object\n"
       "must be writable and VALUE within its type and limits (exit 2 otherwise). When the\n"
       "board refuses, its reason is printed (for a store, the rule and the axis).",
                                RunSdo};
  return kCommand;
}

const Command& ConfigShowCommand() {
  static const Command kCommand{"config show", "every configuration object of a board: value, value in force, factory value",
       "",
       Join({CanOptions(),
             {{"--all", nullptr, nullptr, nullptr, nullptr,
               "also the objects of the axes beyond the axis count"},
              {"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}), nullptr,
                                "The values are the board's edited copy (what a store saves) beside the configuration in\n"
       "force (0x2124); they differ while settings are pending (edited or stored, applied at NMT\n"
       "reset node). See docs/user-guide.md \"Configuring the board from a file\".",
                                RunConfigShow};
  return kCommand;
}

const Command& ConfigSaveCommand() {
  static const Command kCommand{"config save", "write a board's configuration to an INI file", "FILE|-",
       Join({CanOptions(),
             {{"--force", nullptr, nullptr, nullptr, nullptr, "replace an existing FILE"}}}), nullptr,
                                "[board] and one [axis NAME] section per axis; each key's comment names its object and\n"
       "unit. `config apply` reads the file back.",
                                RunConfigSave};
  return kCommand;
}

const Command& ConfigApplyCommand() {
  static const Command kCommand{"config apply",
       "check an INI file with the board's rules, write it, store it, reset the node, read back",
       "FILE",
       Join({CanOptions(),
             {{"--no-reset", nullptr, nullptr, nullptr, nullptr,
               "store only: in force at the next NMT reset node or power-up"}}}), nullptr,
                                "The file is checked first (unknown keys, values outside the objects' limits, the\n"
       "firmware's consistency rules: refused with its line, nothing written); then the objects\n"
       "that differ are written, stored (1010:1) and the node reset (NMT 0x81); every object is\n"
       "read back and compared. Keys left out take the factory value. A refused write or store\n"
       "undoes the edits written before it.",
                                RunConfigApply};
  return kCommand;
}

const Command& NmtCommand() {
  static const Command kCommand{"nmt", "NMT command to the node, confirmed by its boot-up or heartbeat",
       "reset|reset-comm|start|stop|pre-op",
       Join({CanOptions(),
             {{"--wait-ms", nullptr, "N", "ms", "2500",
               "how long to wait for the boot-up or the heartbeat confirming the command"},
              {"--no-wait", nullptr, nullptr, nullptr, nullptr, "send only"}}}), nullptr,
                                "reset: reset node (the stored settings come into force; positions and references are\n"
       "lost); reset-comm: reset communication; start: operational; stop: stopped (only NMT and\n"
       "heartbeat answered); pre-op: pre-operational. Frame 0x000 [command, node-ID].",
                                RunNmt};
  return kCommand;
}

const Command& EdsCommand() {
  static const Command kCommand{"eds",
       "write the node's EDS file (CiA 306) generated from the object dictionary",
       "",
       {{"--output", "-o", "FILE", nullptr, "-", "file to write (- = stdout)"}}, nullptr,
                                "",
                                RunEds};
  return kCommand;
}

const Command& EvaluatePositioningCommand() {
  static const Command kCommand{"evaluate positioning", "GOST 27843-88 / ISO 230-2 positioning test from CSV", "FILE|-",
       Join({{{"--standard", nullptr, "gost27843|iso230-2|both", nullptr, "gost27843",
               "standard(s) to evaluate"},
              {"--sigma", nullptr, "formula|range", nullptr, "formula",
               "GOST 27843 S by formula (5) or by the range method (6)"},
              {"--axis-length-mm", nullptr, "L", "mm", nullptr,
               "axis travel for the target-count checks (default: the targets' span)"}},
             AllowFewRuns(),
             JsonReport()}), nullptr,
                                "Input: target_mm|target_deg, direction, run, deviation_um|deviation_mm|measured_mm|\n"
       "deviation_arcsec|...; ',' or ';' or TAB separated (decimal comma with ';' or TAB);\n"
       "'# key: value' lines before the header are the test conditions of the report.\n"
       "Non-finite readings are refused; implausible magnitudes and Grubbs outliers (99 %)\n"
       "are warned about with their line. See docs/metrology.md.",
                                RunEvaluatePositioning};
  return kCommand;
}

const Command& EvaluateDiagonalCommand() {
  static const Command kCommand{"evaluate diagonal", "ISO 230-6 body/face diagonal test (E, B, E_d, B_d) from CSV", "FILE|-",
       Join({AllowFewRuns(), JsonReport()}), nullptr,
                                "Input: the positioning long layout with a `diagonal` column naming each row's diagonal.",
                                RunEvaluateDiagonal};
  return kCommand;
}

const Command& EvaluateRotaryCommand() {
  static const Command kCommand{"evaluate rotary", "ISO 230-7 error motion (synchronous, asynchronous, tilt, reversal)",
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
             JsonReport()}), nullptr,
                                "",
                                RunEvaluateRotary};
  return kCommand;
}

const Command& ProgramPositioningCommand() {
  static const Command kCommand{"program positioning", "GOST 27843 test program: targets P_j=(N+r)P and G-code cycle", "",
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
             TemplateOutput()}), nullptr,
                                "The readings template names the axis in its preamble; `evaluate positioning` names the\n"
       "report after it. A template that already holds readings is not overwritten.",
                                RunProgramPositioning};
  return kCommand;
}

const Command& ProgramDiagonalCommand() {
  static const Command kCommand{"program diagonal", "ISO 230-6 diagonal targets and G-code cycle (one diagonal or all four)",
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
             TemplateOutput()}), nullptr,
                                "A diagonal is named by its start corner (ISO 230-6): P1 at the low end of X and Y and\n"
       "the high end of Z is -X-Y+Z. With --box, -o FILE.ngc writes FILE_NNN.ngc, FILE_PNN.ngc,\n"
       "FILE_NPN.ngc and FILE_PPN.ngc (start corners -X-Y-Z, +X-Y-Z, -X+Y-Z, +X+Y-Z) and\n"
       "--targets-csv one template for all four, which `evaluate diagonal` reads.",
                                RunProgramDiagonal};
  return kCommand;
}

const Command& ReportCompareCommand() {
  static const Command kCommand{"report compare",
       "before/after page: positioning and diagonal results with reductions",
       "BEFORE AFTER",
       {{"--output", "-o", "DIR", nullptr, nullptr, "directory for compare.html (required)"}}, nullptr,
                                "BEFORE and AFTER are report directories written by `evaluate ... --report DIR` (or\n"
       "single .json results of it); results are paired by name (axis, diagonals).",
                                RunReportCompare};
  return kCommand;
}

}  // namespace volcomp::cli
