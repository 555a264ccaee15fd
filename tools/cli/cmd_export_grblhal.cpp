// `volcomp export grblhal`: grblHAL backlash compensation settings ($160 ...) from positioning
// tests (exporters/grblhal_settings.hpp); grblHAL core has no skew or pitch table.
#include <ostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "hobby_inputs.hpp"
#include "volcomp/exporters/grblhal_settings.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

void GrblhalText(const JsonValue& d, std::ostream& out) {
  out << "volcomp export grblhal: wrote " << d.get("output")->string << "\n";
  HobbyInputsText(d, "", out);
  for (const JsonValue& s : d.get("settings")->array) {
    out << "  $" << s.get("number")->integer << "=" << s.get("text")->string << "\n";
  }
}

Expected<Output> RunExportGrblhal(Args& args, Context& ctx) {
  const std::string out_file = args.Required("-o", "--output");
  VOLCOMP_TRY_ASSIGN(const HobbyArgs a, ReadHobbyArgs(args, false, true));
  args.Flag("--json");
  VOLCOMP_TRY(args.Finish());
  if (a.tests.empty()) return UsageFailure("give at least one axis file, e.g. --x x.csv");
  VOLCOMP_TRY_ASSIGN(const std::vector<exporters::AxisBacklash> b, LoadBacklash(a, ctx));
  const Expected<exporters::GrblhalSettings> g = exporters::BuildGrblhalSettings(b);
  if (!g.ok()) return Fail(Error::kInputInvalid, g.error().message);
  VOLCOMP_TRY(tools::WriteTextFile(out_file, g->text));
  JsonValue settings = JsonValue::Array();
  for (const exporters::GrblhalSetting& s : g->settings) {
    JsonValue j = JsonValue::Object();
    j.Set("axis", std::string(1, s.axis))
        .Set("number", s.number)
        .Set("value", s.value)
        .Set("text", exporters::FixedDecimals(s.value, 5));
    settings.Push(std::move(j));
  }
  Output output;
  output.data = JsonValue::Object();
  output.data.Set("firmware", "grblhal")
      .Set("output", out_file)
      .Set("backlash", BacklashJson(b))
      .Set("settings", std::move(settings));
  output.text = GrblhalText;
  return output;
}

}  // namespace

const Command& ExportGrblhalCommand() {
  static const Command kCommand{
      "export grblhal",
      "grblHAL backlash compensation settings ($160 ...) from positioning tests",
      "",
      Join({{{"--output", "-o", "FILE", nullptr, nullptr, "the settings file to write (required)"}},
            BacklashOptions(),
            {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunExportGrblhal,
      "$160 + axis index (X 0, Y 1, Z 2, A 3, B 4, C 5, U 6, V 7) = the lost motion\n"
      "-(mean reversal) of the axis's two-direction test, mm (deg on a rotary axis), >= 0;\n"
      "needs a grblHAL build with ENABLE_BACKLASH_COMPENSATION. See docs/pc-tool.md,\n"
      "\"Hobby controllers\"."};
  return kCommand;
}

}  // namespace volcomp::cli
