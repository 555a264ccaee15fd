// The commands of the `volcomp` tool. Each command is declared in its own cmd_*.cpp beside its
// code: `const Command& FooCommand()` returns its name, summary, options (option_groups.hpp for
// the shared ones), run function and notes; commands.cpp lists them in the order of `volcomp help`.
//
// To add a command: write cmd_foo.cpp with `Expected<Output> RunFoo(Args&, Context&)` and
// `const Command& FooCommand()` (command.hpp), declare FooCommand here and add it to commands.cpp.
#pragma once

#include "command.hpp"

namespace volcomp::cli {

const Command& BuildGridCommand();
const Command& InspectCommand();
const Command& LookupCommand();
const Command& UploadCommand();
const Command& VerifyCommand();
const Command& ActivateCommand();
const Command& DeactivateCommand();
const Command& ReferenceCommand();
const Command& StatusCommand();
const Command& MonitorCommand();
const Command& SdoCommand();
const Command& ConfigShowCommand();
const Command& ConfigSaveCommand();
const Command& ConfigApplyCommand();
const Command& NmtCommand();
const Command& EdsCommand();
const Command& EvaluatePositioningCommand();
const Command& EvaluateDiagonalCommand();
const Command& EvaluateRotaryCommand();
const Command& EvaluateCircularCommand();
const Command& EvaluateThermalCommand();
const Command& ProgramPositioningCommand();
const Command& ProgramDiagonalCommand();
const Command& ProgramCircularCommand();
const Command& ReportCompareCommand();
const Command& ReportCertificateCommand();
const Command& ReproduceCommand();
const Command& BuildModelCommand();
const Command& BuildTrackerCommand();
const Command& BuildKmtppCommand();
const Command& BuildAxisCommand();
const Command& BuildImageCommand();
const Command& BuildThermalCommand();
const Command& ExportLinuxcncCommand();
const Command& ExportSiemensCommand();
const Command& ExportHeidenhainCommand();
const Command& ExportFanucCommand();
const Command& ExportIsgCommand();
const Command& ExportKlipperCommand();
const Command& ExportMarlinCommand();
const Command& ExportReprapCommand();
const Command& ExportGrblhalCommand();
const Command& ModelEvalCommand();
const Command& ModelExportCommand();

}  // namespace volcomp::cli
