// The command table of `volcomp`.
#include "commands.hpp"

namespace volcomp::tools {

const std::vector<Command>& Commands() {
  static const std::vector<Command> kCommands = {
      {"build grid", "build a table image from corrections at grid nodes (CSV)",
       "--csv FILE -o IMAGE [--resolution-nm X=N,Y=N,Z=N] [--element int16|int32|float32]\n"
       "    [--frac-bits N] [--table-id N] [--info KEY=VALUE]...",
       RunBuildGrid},
      {"inspect", "summarise a table image (--json for machine-readable output)", "IMAGE [--json]",
       RunInspect},
      {"lookup", "correction at points read as CSV on stdin, written as CSV on stdout",
       "IMAGE [--points FILE] < points.csv", RunLookup},
      {"upload", "upload a table image to a board over CAN (block transfer), verify, activate",
       "IMAGE --can SPEC [--node ID] [--activate] [--force] [--retries N] [--quiet] [--log FILE]",
       RunUpload},
      {"verify", "check which table a board has active or staged (--readback compares bytes)",
       "IMAGE --can SPEC [--node ID] [--readback] [--log FILE]", RunVerify},
      {"activate", "activate the staged, verified table (axes referenced and at rest)",
       "--can SPEC [--node ID] [--log FILE]", RunActivate},
      {"deactivate", "deactivate the active table (the correction ramps out)",
       "--can SPEC [--node ID] [--log FILE]", RunDeactivate},
      {"reference", "declare axes referenced over CAN (instead of home switch edges)",
       "--can SPEC [--node ID] [--axes 1,2,3]", RunReference},
      {"status", "a board's identity, state, tables, per-axis diagnostics and counters",
       "--can SPEC [--node ID] [--json] [--log FILE]", RunStatus},
      {"monitor", "follow a board: heartbeat, EMCY and diagnostics every interval",
       "--can SPEC [--node ID] [--interval-ms N] [--duration S]", RunMonitor},
      {"sdo", "read or write one object: sdo read 2104:0, sdo write 2121:0 1",
       "read|write INDEX:SUB [VALUE] --can SPEC [--node ID]", RunSdo},
      {"eds", "write the node's EDS file (CiA 306) generated from the object dictionary",
       "[-o FILE]", RunEds},
      {"evaluate positioning", "GOST 27843-88 / ISO 230-2 positioning test from CSV",
       "FILE|- [--standard gost27843|iso230-2|both] [--sigma formula|range]\n"
       "    [--axis-length-mm L] [--allow-few-runs] [--json] [--report DIR]",
       RunEvaluatePositioning},
      {"evaluate diagonal", "ISO 230-6 body/face diagonal test (E, B, E_d, B_d) from CSV",
       "FILE|- [--allow-few-runs] [--json] [--report DIR]", RunEvaluateDiagonal},
      {"evaluate rotary", "ISO 230-7 error motion (synchronous, asynchronous, tilt, reversal)",
       "FILE|- [--sensitive rotating|fixed] [--fsd-angle-deg A] [--tilt-distance-mm L]\n"
       "    [--face-radius-mm R] [--min-zone] [--reversal FILE2 [--reversal-channel x_um]\n"
       "    [--reversal-procedure P|S]] [--json] [--report DIR]",
       RunEvaluateRotary},
      {"program positioning", "GOST 27843 test program: targets P_j=(N+r)P and G-code cycle",
       "--pitch P --end E [--start S] [--count M] [--seed N] [--fraction-digits D] [--rotary]\n"
       "    [--runs 5] [--cycle linear|pilgrim] [--overrun O] [--axis X] [--feed F]\n"
       "    [--dwell-s S] [-o FILE] [--targets-csv FILE]",
       RunProgramPositioning},
      {"program diagonal", "ISO 230-6 diagonal targets (P1, P2, I_d) and G-code cycle",
       "--p1 X,Y,Z --p2 X,Y,Z --increment-mm I [--name +X+Y+Z] [--runs 5] [--overrun-mm O]\n"
       "    [--feed F] [--dwell-s S] [-o FILE] [--targets-csv FILE]",
       RunProgramDiagonal},
      // Table builders (issue 5); grid options as in docs/table-builders.md.
      {"build model", "GRID3 image from the 21-parameter error model (inverse map)",
       "--model s500|FILE.conf [--order first|exact] [--formulation physical|dissertation]\n"
       "    [--dissertation-case plus|minus] [--angle-scale K] [--tool-offset-mm X,Y,Z]\n"
       "    [--no-squareness] GRID_OPTIONS\n"
       "GRID_OPTIONS: -o IMAGE (--resolution-nm X=N,Y=N,Z=N | --steps-per-unit X=N,Y=N,Z=N)\n"
       "    [--range X=MIN:MAX,...] [--spacing-mm X=S,Y=S,Z=S | --max-interp-error-um E]\n"
       "    [--max-correction-um B] [--element int16|int32|float32] [--frac-bits N]\n"
       "    [--table-id N] [--info KEY=VALUE]... [--json]",
       RunBuildModel},
      {"build tracker", "GRID3 image from laser-tracker axis lines (dissertation ch. 2 methods)",
       "(--points FILE | --builtin s500-315|s500-240)\n"
       "    [--method static|interval|quasi-differential] [--cosines printed|signed|scaled]\n"
       "    [--origin measured|extrapolated] [--static-interval N] [--appendix-form]\n"
       "    [--allow-discontinuous] GRID_OPTIONS (see `volcomp help build model`)",
       RunBuildTracker},
      {"build kmtpp", "GRID3 image by the КМТПП method (dissertation ch. 4)",
       "--model s500|FILE.conf [--tracker FILE | --tracker-builtin s500-315|s500-240]\n"
       "    [--cosines signed|printed] [--calibration-interval N] [--gain K] [--step L]\n"
       "    [--final-step traced|node] [--sum matrix|listing] [--index round|floor]\n"
       "    [--dissertation] [--refine-mm H] [--allow-discontinuous]\n"
       "    GRID_OPTIONS (see `volcomp help build model`)",
       RunBuildKmtpp},
      {"build axis", "AXIS1D image from positioning test results (mean deviations per target)",
       "--x FILE [--y FILE] [--z FILE] [--a FILE] ... -o IMAGE\n"
       "    (--resolution-nm X=N,... | --steps-per-unit X=N,...) [--reverse tables|backlash|mean]\n"
       "    [--spacing X=S,...] [--wrap] [--element int16|int32|float32] [--frac-bits N]\n"
       "    [--table-id N] [--info KEY=VALUE]...",
       RunBuildAxis},
      {"export linuxcnc",
       "LinuxCNC joint compensation files (COMP_FILE_TYPE 0 or 1) from positioning results",
       "--x FILE [--y FILE] [--z FILE] ... -o DIR [--type 0|1] [--joints X=0,Y=1,...]\n"
       "    [--spacing X=S,...]   (FILE: mean deviations as `build axis`, or raw readings as\n"
       "    `evaluate positioning`)",
       RunExportLinuxcnc},
      {"model eval", "forward error (or --inverse command) of a model at points, CSV in/out",
       "--model s500|FILE.conf [model overrides as `build model`] [--inverse] [-o FILE]\n"
       "    [POINTS.csv|-]",
       RunModelEval},
  };
  return kCommands;
}

}  // namespace volcomp::tools
