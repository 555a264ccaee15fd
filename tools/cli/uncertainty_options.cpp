// Uncertainty options of the positioning and diagonal tests.
#include "uncertainty_options.hpp"

#include <string>

#include "file_arguments.hpp"
#include "volcomp/metrology/drift_test.hpp"
#include "volcomp/report/format.hpp"

namespace volcomp::cli {

const Options& LengthUncertaintyOptions() {
  static const Options kOptions = {
      {"--instrument-u-um", nullptr, "U", "um", nullptr,
       "the instrument's calibration U at k = 2 (or preamble instrument_u_um)"},
      {"--instrument-ppm", nullptr, "A", "ppm", nullptr,
       "the instrument's stated accuracy ±A ppm of the length (or preamble instrument_ppm)"},
      {"--material-temperature-c", nullptr, "T", "C", nullptr,
       "mean material temperature (or preamble \"material temperature C\")"},
      {"--thermometer-range-k", nullptr, "R", "K", "0.2",
       "full error range of the material thermometer"},
      {"--expansion", nullptr, "ALPHA", "um/(m K)", nullptr,
       "expansion coefficient of the scale or screw (or preamble expansion_um_per_m_K, or an "
       ".rtl's own; none: 11.5, steel, with a note)"},
      {"--expansion-range", nullptr, "R", "um/(m K)", "2",
       "full plausible range of the expansion coefficient"},
      {"--misalignment-mm", nullptr, "D", "mm", "0",
       "lateral beam walk-off over the measured length (cosine error)"},
      {"--drift-range-um", nullptr, "E", "um", nullptr,
       "range E_VE of a drift test (or preamble drift_range_um)"},
      DriftTestOption(),
  };
  return kOptions;
}

args::OptionSpec DriftTestOption() {
  return {"--drift-test",
          nullptr,
          "FILE",
          nullptr,
          nullptr,
          "E_VE from a drift-test file (evaluate thermal's layout): its largest range of one "
          "point's readings; not with --drift-range-um"};
}

Expected<void> ReadDriftTest(args::Args& args,
                             Context& ctx,
                             std::optional<double>* range_um,
                             std::string* source) {
  const auto path = args.Value("--drift-test");
  if (!path) return {};
  if (*range_um) return UsageFailure("give --drift-range-um or --drift-test, not both");
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable table, ReadCsvArgument(*path, ctx));
  VOLCOMP_TRY_ASSIGN(const metrology::DriftRecord record, metrology::ReadDriftCsv(table));
  const auto e = metrology::LargestDriftRange(metrology::EvaluateDrift(record));
  if (!e) return Fail(Error::kInputInvalid, *path + ": no point is read twice");
  *range_um = e->range_um;
  *source = "drift test " + *path + ": " + std::string(1, e->axis) + " at " +
            report::FormatNumber(e->position_mm) + " mm over " +
            report::FormatNumber(e->duration_s / 3600.0) + " h";
  return {};
}

const Options& AngleUncertaintyOptions() {
  static const Options kOptions = {
      {"--instrument-u-arcsec", nullptr, "U", "arcsec", nullptr,
       "rotary axis: the angle reference's calibration U at k = 2 (or preamble "
       "instrument_u_arcsec)"},
      {"--instrument-accuracy-arcsec", nullptr, "A", "arcsec", nullptr,
       "rotary axis: the angle reference's stated accuracy ±A (or preamble "
       "instrument_accuracy_arcsec)"},
      {"--drift-range-arcsec", nullptr, "E", "arcsec", nullptr,
       "rotary axis: range E_VE of a drift test of the angle (or preamble drift_range_arcsec)"},
  };
  return kOptions;
}

Expected<metrology::PositioningUncertaintyInputs> ReadLengthUncertainty(args::Args& args,
                                                                        Context& ctx) {
  metrology::PositioningUncertaintyInputs in;
  in.instrument_u_um = args.Number("--instrument-u-um");
  in.instrument_ppm = args.Number("--instrument-ppm");
  in.material_temperature_C = args.Number("--material-temperature-c");
  if (const auto v = args.Number("--thermometer-range-k")) in.thermometer_range_K = *v;
  in.expansion_um_per_m_K = args.Number("--expansion");
  if (const auto v = args.Number("--expansion-range")) in.expansion_range_um_per_m_K = *v;
  if (const auto v = args.Number("--misalignment-mm")) in.misalignment_mm = *v;
  in.drift_range_um = args.Number("--drift-range-um");
  VOLCOMP_TRY(ReadDriftTest(args, ctx, &in.drift_range_um, &in.drift_source));
  return in;
}

const Options& CircularUncertaintyOptions() {
  static const Options kOptions =
      Join({LengthUncertaintyOptions(),
            {{"--calibrator-u-um", nullptr, "U", "um", nullptr,
              "circular test: U at k = 2 of the calibrator's length, enters F only (or preamble "
              "calibrator_u_um); --instrument-u-um is then the U of one radial reading"}}});
  return kOptions;
}

Expected<metrology::CircularUncertaintyInputs> ReadCircularUncertainty(args::Args& args,
                                                                       Context& ctx) {
  metrology::CircularUncertaintyInputs in;
  VOLCOMP_TRY_ASSIGN(in.reading, ReadLengthUncertainty(args, ctx));
  in.calibrator_u_um = args.Number("--calibrator-u-um");
  return in;
}

Expected<metrology::PositioningUncertaintyInputs> ReadPositioningUncertainty(args::Args& args,
                                                                             Context& ctx) {
  VOLCOMP_TRY_ASSIGN(metrology::PositioningUncertaintyInputs in, ReadLengthUncertainty(args, ctx));
  in.instrument_u_arcsec = args.Number("--instrument-u-arcsec");
  in.instrument_accuracy_arcsec = args.Number("--instrument-accuracy-arcsec");
  in.drift_range_arcsec = args.Number("--drift-range-arcsec");
  return in;
}

}  // namespace volcomp::cli
