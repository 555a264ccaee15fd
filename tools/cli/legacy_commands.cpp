// TRANSITION: the declarations of the commands not yet converted to the command layer
// (command.hpp). Each moves into its own cmd_*.cpp when it is converted; this file then goes.
#include "commands.hpp"
#include "option_groups.hpp"

namespace volcomp::cli {

using tools::RunBuildGrid;
using tools::RunLookup;
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
