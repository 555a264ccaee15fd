// Uncertainty options of the positioning and diagonal tests.
#include "uncertainty_options.hpp"

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
  };
  return kOptions;
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

metrology::PositioningUncertaintyInputs ReadLengthUncertainty(args::Args& args) {
  metrology::PositioningUncertaintyInputs in;
  in.instrument_u_um = args.Number("--instrument-u-um");
  in.instrument_ppm = args.Number("--instrument-ppm");
  in.material_temperature_C = args.Number("--material-temperature-c");
  if (const auto v = args.Number("--thermometer-range-k")) in.thermometer_range_K = *v;
  in.expansion_um_per_m_K = args.Number("--expansion");
  if (const auto v = args.Number("--expansion-range")) in.expansion_range_um_per_m_K = *v;
  if (const auto v = args.Number("--misalignment-mm")) in.misalignment_mm = *v;
  in.drift_range_um = args.Number("--drift-range-um");
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

metrology::CircularUncertaintyInputs ReadCircularUncertainty(args::Args& args) {
  metrology::CircularUncertaintyInputs in;
  in.reading = ReadLengthUncertainty(args);
  in.calibrator_u_um = args.Number("--calibrator-u-um");
  return in;
}

metrology::PositioningUncertaintyInputs ReadPositioningUncertainty(args::Args& args) {
  metrology::PositioningUncertaintyInputs in = ReadLengthUncertainty(args);
  in.instrument_u_arcsec = args.Number("--instrument-u-arcsec");
  in.instrument_accuracy_arcsec = args.Number("--instrument-accuracy-arcsec");
  in.drift_range_arcsec = args.Number("--drift-range-arcsec");
  return in;
}

}  // namespace volcomp::cli
