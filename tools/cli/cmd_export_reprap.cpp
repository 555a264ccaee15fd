// `volcomp export reprap`: RepRapFirmware axis compensation (M556) from the squareness of a
// 21-parameter model and/or the --squareness-*-urad options, and backlash (M425) from
// positioning tests (exporters/reprap_gcode.hpp).
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "hobby_inputs.hpp"
#include "volcomp/exporters/reprap_gcode.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

void ReprapText(const JsonValue& d, std::ostream& out) {
  out << "volcomp export reprap: wrote " << d.get("output")->string << " (M556 S"
      << d.get("length_mm")->number << (d.get("negated")->boolean ? ", skew NEGATED" : "") << ")\n";
  HobbyInputsText(d, "tangent", out);
}

Expected<Output> RunExportReprap(Args& args, Context& ctx) {
  const std::string out_file = args.Required("-o", "--output");
  const double length_mm = args.Number("--length-mm").value_or(100);
  const bool negate = args.Flag("--negate");
  VOLCOMP_TRY_ASSIGN(const HobbyArgs a, ReadHobbyArgs(args, true, true));
  args.Flag("--json");
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY_ASSIGN(const HobbyInputs in, LoadHobbyInputs(a, ctx));
  const Expected<exporters::ReprapGcode> r =
      exporters::BuildReprapGcode(in.squareness, in.backlash, length_mm, negate);
  if (!r.ok()) return Fail(Error::kInputInvalid, r.error().message);
  VOLCOMP_TRY(tools::WriteTextFile(out_file, r->text));
  JsonValue data = HobbyJson("reprap", out_file, negate, in, r->tangents, "tangent");
  data.Set("length_mm", length_mm);
  return Output(std::move(data), ReprapText);
}

}  // namespace

const Command& ExportReprapCommand() {
  static const Command kCommand{
      "export reprap",
      "RepRapFirmware axis compensation (M556) and backlash (M425) from the squareness and "
      "positioning tests",
      "",
      Join({{{"--output", "-o", "FILE", nullptr, nullptr,
              "the G-code file to write, for config.g (required)"},
             {"--length-mm", nullptr, "S", "mm", "100",
              "M556 S: the length the deviations are given over (> 0)"},
             {"--negate", nullptr, nullptr, nullptr, nullptr,
              "flip every deviation, for a printer that proves to take the other sign"}},
            SquarenessOptions(),
            BacklashOptions(),
            {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunExportReprap,
      "M556 S X Y Z: the tangents XY = tan C0Y, YZ = tan A0Z / cos B0Z, ZX = -tan B0Z\n"
      "(Move.cpp AxisTransform) times S. M425: the lost motion -(mean reversal) in mm, >= 0.\n"
      "See docs/pc-tool.md, \"Hobby controllers\"."};
  return kCommand;
}

}  // namespace volcomp::cli
