// The command list of `volcomp`, in the order `volcomp help` shows it.
#include "commands.hpp"

namespace volcomp::cli {

const std::vector<const Command*>& Commands() {
  static const std::vector<const Command*> kCommands = {
      &BuildGridCommand(),
      &InspectCommand(),
      &LookupCommand(),
      &UploadCommand(),
      &VerifyCommand(),
      &ActivateCommand(),
      &DeactivateCommand(),
      &ReferenceCommand(),
      &StatusCommand(),
      &MonitorCommand(),
      &SdoCommand(),
      &ConfigShowCommand(),
      &ConfigSaveCommand(),
      &ConfigApplyCommand(),
      &NmtCommand(),
      &EdsCommand(),
      &EvaluatePositioningCommand(),
      &EvaluateDiagonalCommand(),
      &EvaluateRotaryCommand(),
      &EvaluateCircularCommand(),
      &EvaluateThermalCommand(),
      &ProgramPositioningCommand(),
      &ProgramDiagonalCommand(),
      &ProgramCircularCommand(),
      &ReportCompareCommand(),
      &ReportCertificateCommand(),
      &ReproduceCommand(),
      &BuildModelCommand(),
      &BuildTrackerCommand(),
      &BuildKmtppCommand(),
      &BuildAxisCommand(),
      &BuildImageCommand(),
      &BuildThermalCommand(),
      &ExportLinuxcncCommand(),
      &ExportSiemensCommand(),
      &ExportHeidenhainCommand(),
      &ExportFanucCommand(),
      &ExportIsgCommand(),
      &ExportKlipperCommand(),
      &ExportMarlinCommand(),
      &ExportReprapCommand(),
      &ExportGrblhalCommand(),
      &ModelEvalCommand(),
      &ModelExportCommand(),
  };
  return kCommands;
}

}  // namespace volcomp::cli
