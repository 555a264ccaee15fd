// `volcomp export klipper`: Klipper skew correction (exporters/klipper_skew.hpp) from the
// squareness of a 21-parameter model and/or the --squareness-*-urad options: a SAVE_CONFIG block
// [skew_correction PROFILE] and the SET_SKEW command that gives the same factors.
#include <ostream>
#include <string>

#include "commands.hpp"
#include "hobby_inputs.hpp"
#include "volcomp/exporters/klipper_skew.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

void KlipperText(const JsonValue& d, std::ostream& out) {
  out << "volcomp export klipper: wrote " << d.get("output")->string << " ([skew_correction "
      << d.get("profile")->string << "]" << (d.get("negated")->boolean ? ", NEGATED" : "") << ")\n";
  HobbyInputsText(d, "factor", out);
  out << "  " << d.get("set_skew")->string << "\n";
}

Expected<Output> RunExportKlipper(Args& args, Context& ctx) {
  const std::string out_file = args.Required("-o", "--output");
  exporters::KlipperOptions o;
  o.profile = args.Value("--profile").value_or("volcomp");
  o.square_mm = args.Number("--square-mm").value_or(100);
  o.negate = args.Flag("--negate");
  VOLCOMP_TRY_ASSIGN(const HobbyArgs a, ReadHobbyArgs(args, true, false));
  args.Flag("--json");
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY_ASSIGN(const exporters::HobbySquareness s, LoadSquareness(a, ctx));
  if (!s.any()) {
    return UsageFailure("give the squareness: --model FILE or --squareness-xy-urad ...");
  }
  const Expected<exporters::KlipperSkew> k = exporters::BuildKlipperSkew(s, o);
  if (!k.ok()) return Fail(Error::kInputInvalid, k.error().message);
  VOLCOMP_TRY(tools::WriteTextFile(out_file, k->text));

  std::string set_skew = "SET_SKEW";
  JsonValue lengths = JsonValue::Object();
  const std::optional<exporters::SquareLengths>* planes[] = {&k->xy, &k->xz, &k->yz};
  const char* names[] = {"XY", "XZ", "YZ"};
  for (int i = 0; i < 3; ++i) {
    if (!*planes[i]) continue;
    const exporters::SquareLengths& l = **planes[i];
    lengths.Set(names[i], JsonValue::Numbers({l.ac, l.bd, l.ad}));
    set_skew += std::string(" ") + names[i] + "=" + exporters::FixedDecimals(l.ac, 6) + "," +
                exporters::FixedDecimals(l.bd, 6) + "," + exporters::FixedDecimals(l.ad, 6);
  }
  Output output;
  output.data = JsonValue::Object();
  output.data.Set("firmware", "klipper")
      .Set("output", out_file)
      .Set("profile", o.profile)
      .Set("square_mm", o.square_mm)
      .Set("negated", o.negate)
      .Set("squareness", SquarenessJson(s, k->factors, "factor"))
      .Set("set_skew", set_skew)
      .Set("set_skew_lengths_mm", std::move(lengths));
  output.text = KlipperText;
  return output;
}

}  // namespace

const Command& ExportKlipperCommand() {
  static const Command kCommand{
      "export klipper",
      "Klipper skew correction ([skew_correction] profile and SET_SKEW) from the squareness",
      "",
      Join({{{"--output", "-o", "FILE", nullptr, nullptr,
              "the printer.cfg fragment to write (required)"},
             {"--profile", nullptr, "NAME", nullptr, "volcomp",
              "the profile name: [skew_correction NAME], SKEW_PROFILE LOAD=NAME"},
             {"--square-mm", nullptr, "L", "mm", "100",
              "side of the square whose lengths SET_SKEW is given"},
             {"--negate", nullptr, nullptr, nullptr, nullptr,
              "flip every factor, for a printer that proves to take the other sign"}},
            SquarenessOptions(),
            {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunExportKlipper,
      "Factor = tan(90 deg - angle between the axes): xy = -tan C0Y, xz = tan B0Z,\n"
      "yz = -tan A0Z / cos B0Z (klippy/extras/skew_correction.py). A plane not given is\n"
      "written as 0 in the profile and left out of SET_SKEW. See docs/pc-tool.md,\n"
      "\"Hobby controllers\"."};
  return kCommand;
}

}  // namespace volcomp::cli
