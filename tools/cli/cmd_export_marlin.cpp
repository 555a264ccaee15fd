// `volcomp export marlin`: Marlin skew factors (M852) from the squareness of a 21-parameter model
// and/or the --squareness-*-urad options, and backlash (M425) from positioning tests
// (exporters/marlin_gcode.hpp).
#include <ostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "hobby_inputs.hpp"
#include "volcomp/exporters/marlin_gcode.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

void MarlinText(const JsonValue& d, std::ostream& out) {
  out << "volcomp export marlin: wrote " << d.get("output")->string
      << (d.get("negated")->boolean ? " (skew NEGATED)" : "") << "\n";
  HobbyInputsText(d, "factor", out);
}

Expected<Output> RunExportMarlin(Args& args, Context& ctx) {
  const std::string out_file = args.Required("-o", "--output");
  const bool negate = args.Flag("--negate");
  VOLCOMP_TRY_ASSIGN(const HobbyArgs a, ReadHobbyArgs(args, true, true));
  args.Flag("--json");
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY_ASSIGN(const HobbyInputs in, LoadHobbyInputs(a, ctx));
  const Expected<exporters::MarlinGcode> m =
      exporters::BuildMarlinGcode(in.squareness, in.backlash, negate);
  if (!m.ok()) return Fail(Error::kInputInvalid, m.error().message);
  VOLCOMP_TRY(tools::WriteTextFile(out_file, m->text));
  return Output(HobbyJson("marlin", out_file, negate, in, m->factors, "factor"), MarlinText);
}

}  // namespace

const Command& ExportMarlinCommand() {
  static const Command kCommand{
      "export marlin",
      "Marlin skew factors (M852) and backlash (M425) from the squareness and positioning tests",
      "",
      Join({{{"--output", "-o", "FILE", nullptr, nullptr, "the G-code file to write (required)"},
             {"--negate", nullptr, nullptr, nullptr, nullptr,
              "flip every skew factor, for a printer that proves to take the other sign"}},
            SquarenessOptions(),
            BacklashOptions(),
            {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunExportMarlin,
      "M852 I J K = -tan C0Y, tan B0Z, -tan A0Z / cos B0Z (Marlin planner.h skew()), each\n"
      "within -1..1. M425 F1 X Y Z: the lost motion -(mean reversal) in mm, >= 0, of the\n"
      "two-direction tests of X, Y, Z. See docs/pc-tool.md, \"Hobby controllers\"."};
  return kCommand;
}

}  // namespace volcomp::cli
