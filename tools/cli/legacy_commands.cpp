// TRANSITION: the declarations of the commands not yet converted to the command layer
// (command.hpp). Each moves into its own cmd_*.cpp when it is converted; this file then goes.
#include "commands.hpp"
#include "option_groups.hpp"

namespace volcomp::cli {

using tools::RunBuildGrid;
using tools::RunLookup;
using tools::RunEvaluatePositioning;
using tools::RunEvaluateDiagonal;
using tools::RunEvaluateRotary;
using tools::RunProgramPositioning;
using tools::RunProgramDiagonal;
using tools::RunReportCompare;
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
