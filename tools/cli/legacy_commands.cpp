// TRANSITION: the declarations of the commands not yet converted to the command layer
// (command.hpp). Each moves into its own cmd_*.cpp when it is converted; this file then goes.
#include "commands.hpp"
#include "option_groups.hpp"

namespace volcomp::cli {

using tools::RunBuildGrid;
using tools::RunLookup;
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
using tools::RunBuildModel;
using tools::RunBuildTracker;
using tools::RunBuildKmtpp;
using tools::RunBuildAxis;
using tools::RunExportLinuxcnc;
using tools::RunModelEval;

const Command& BuildGridCommand() {
  static const Command kCommand{"build grid", "build a table image from corrections at grid nodes (CSV)", "",
       Join({{{"--csv", nullptr, "FILE", nullptr, nullptr,
               "corrections at the nodes (required): x_mm|x_steps ..., dx_um|dx_steps ..."},
              {"--output", "-o", "IMAGE", nullptr, nullptr, "image file to write (required)"},
              {"--axes", nullptr, "X,Y,Z", nullptr, "X,Y,Z", "the three grid axes"}},
             ResolutionOptions(),
             ImageOptions()}), nullptr,
                                "",
                                RunBuildGrid};
  return kCommand;
}

const Command& LookupCommand() {
  static const Command kCommand{"lookup",
       "correction at points read as CSV, written as CSV on stdout",
       "IMAGE",
       {{"--points", nullptr, "FILE", nullptr, nullptr,
         "points CSV: x_mm|x_steps ..., optional dir_x (default: standard input)"}}, nullptr,
                                "",
                                RunLookup};
  return kCommand;
}

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

const Command& BuildModelCommand() {
  static const Command kCommand{"build model", "GRID3 image from the 21-parameter error model (inverse map)", "",
       Join({ModelOptions(), GridOptions()}), nullptr,
                                GridNotes(),
                                RunBuildModel};
  return kCommand;
}

const Command& BuildTrackerCommand() {
  static const Command kCommand{"build tracker",
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
             GridOptions()}), nullptr,
                                GridNotes(),
                                RunBuildTracker};
  return kCommand;
}

const Command& BuildKmtppCommand() {
  static const Command kCommand{"build kmtpp", "GRID3 image by the КМТПП method (dissertation ch. 4)", "",
       Join({ModelOptions(),
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
             GridOptions()}), nullptr,
                                GridNotes(),
                                RunBuildKmtpp};
  return kCommand;
}

const Command& BuildAxisCommand() {
  static const Command kCommand{"build axis", "AXIS1D image from positioning tests (raw readings or mean deviations)", "",
       Join({PositioningFileOptions(),
             {{"--output", "-o", "IMAGE", nullptr, nullptr, "image file to write (required)"}},
             ResolutionOptions(),
             {{"--reverse", nullptr, "tables|backlash|mean", nullptr, "tables",
               "negative-direction handling"},
              {"--spacing", nullptr, "X=S,...", "mm (deg for A, B, C)", nullptr,
               "table spacing per axis (default: the test's, or its smallest gap)"},
              {"--wrap", nullptr, nullptr, nullptr, nullptr,
               "rotary table spanning exactly 360° wraps around"}},
             ImageOptions()}), nullptr,
                                PositioningFileNotes(),
                                RunBuildAxis};
  return kCommand;
}

const Command& ExportLinuxcncCommand() {
  static const Command kCommand{"export linuxcnc",
       "LinuxCNC joint compensation files (COMP_FILE_TYPE 0 or 1) from positioning tests", "",
       Join({PositioningFileOptions(),
             {{"--output", "-o", "DIR", nullptr, nullptr,
               "directory for x.comp ... and joints.ini (required)"},
              {"--type", nullptr, "0|1", nullptr, "1",
               "COMP_FILE_TYPE: 1 the file holds the trims, 0 the positions reached"},
              {"--joints", nullptr, "X=N,...", nullptr, nullptr,
               "joint 0..15 of an axis in its [JOINT_n] lines (default: X=0 ... W=8)"},
              {"--spacing", nullptr, "X=S,...", "mm (deg for A, B, C)", nullptr,
               "point spacing per axis (default: the test's, or its smallest gap)"}},
             AllowFewRuns()}), nullptr,
                                "Each FILE is either the raw readings `evaluate positioning` reads (the mean per\n"
       "target and direction is used) or the mean deviations (position_mm, dev_forward_um\n"
       "[, dev_reverse_um]). Writes one file per axis (x.comp, ...) and joints.ini with the\n"
       "INI lines to paste; see docs/linuxcnc.md.",
                                RunExportLinuxcnc};
  return kCommand;
}

const Command& ModelEvalCommand() {
  static const Command kCommand{"model eval", "forward error (or --inverse command) of a model at points, CSV in/out",
       "[POINTS.csv|-]",
       Join({ModelOptions(),
             {{"--inverse", nullptr, nullptr, nullptr, nullptr,
               "the command that lands on each point instead of the error"},
              {"--output", "-o", "FILE", nullptr, nullptr, "CSV to write (default: stdout)"}}}), nullptr,
                                "",
                                RunModelEval};
  return kCommand;
}

}  // namespace volcomp::cli
