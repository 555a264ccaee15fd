// `volcomp evaluate circular FILE|-`: ISO 230-4 circular test (metrology/circular.hpp) from a
// ballbar's readings in both directions, as text or JSON, a polar plot (SVG) and an HTML report.
#include <ostream>

#include "commands.hpp"
#include "file_arguments.hpp"
#include "metrology_report.hpp"
#include "option_groups.hpp"
#include "uncertainty_options.hpp"
#include "volcomp/metrology/circular.hpp"
#include "volcomp/metrology/circular_report.hpp"
#include "volcomp/metrology/report_files.hpp"
#include "volcomp/metrology/test_conditions.hpp"

namespace volcomp::cli {
namespace {

namespace m = volcomp::metrology;

void EvaluateCircularText(const JsonValue& data, std::ostream& out) {
  m::WriteCircularText(out, data);
}

Expected<Output> RunEvaluateCircular(Args& args, Context& ctx) {
  args.Flag("--json");  // the command layer prints the data as JSON
  const auto report_dir = args.Value("--report");
  const auto svg = args.Value("--svg");
  const auto radius = args.Number("--radius");
  VOLCOMP_TRY_ASSIGN(const m::CircularUncertaintyInputs uncertainty,
                     ReadCircularUncertainty(args, ctx));
  const auto files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (files.size() != 1) return UsageFailure("give exactly one data file (or - for stdin)");
  if (radius && !(*radius > 0.0)) return UsageFailure("--radius must be positive");
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable table, ReadCsvArgument(files[0], ctx));
  m::CircularEvaluation ev;
  VOLCOMP_TRY_ASSIGN(ev.data, m::ReadCircularCsv(table, radius.value_or(0.0)));
  VOLCOMP_TRY_ASSIGN(ev.result, m::EvaluateCircular(ev.data));
  ev.conditions = m::ConditionsFromPreamble(table);
  VOLCOMP_TRY_ASSIGN(const auto u_in, m::CompleteFromPreamble(uncertainty, ev.conditions));
  VOLCOMP_TRY_ASSIGN(const auto preamble_radius, ev.conditions.Number("nominal_radius_mm"));
  const double u_radius =
      ev.data.nominal_radius_mm > 0.0 ? ev.data.nominal_radius_mm : preamble_radius.value_or(0.0);
  VOLCOMP_TRY_ASSIGN(ev.uncertainty, m::CircularU(u_in, u_radius, &ev.result.warnings));
  Output output{m::CircularJson(ev), EvaluateCircularText, ev.result.warnings};
  if (svg) VOLCOMP_TRY(WriteTextArgument(m::CircularPolarSvg(ev), *svg, ctx));
  if (report_dir) {
    VOLCOMP_TRY(WriteMetrologyReport(m::CircularPage(ev), output.data, *report_dir,
                                     "circular_" + m::SourceStem(ev.data.source), ctx));
  }
  return output;
}

}  // namespace

const Command& EvaluateCircularCommand() {
  static const Command kCommand{
      "evaluate circular",
      "ISO 230-4 circular test (G, G(b), H, F, centre offset) from ballbar readings",
      "FILE|-",
      Join({{{"--radius", nullptr, "R", "mm", nullptr,
              "nominal radius: the file gives measured radii in a radius_mm column"},
             {"--svg", nullptr, "FILE", nullptr, nullptr,
              "write the polar plot (both directions, deviation magnified) as SVG"}},
            CircularUncertaintyOptions(),
            JsonReport()}),
      RunEvaluateCircular,
      "Input: columns direction (cw|ccw), angle_deg (counter-clockwise from the plane's first\n"
      "axis) and deviation_um (measured - nominal radius), or radius_mm with --radius. Where the\n"
      "two directions are read at different angles, H compares each reading with the other\n"
      "path interpolated linearly between its neighbouring readings."};
  return kCommand;
}

}  // namespace volcomp::cli
