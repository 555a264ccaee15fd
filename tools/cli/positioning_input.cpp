// Positioning-test input: format options and the one loader.
#include "positioning_input.hpp"

#include <sstream>

#include "choice_option.hpp"

namespace volcomp::cli {

const Options& PositioningFormatOptions() {
  static const Options kOptions = {
      {"--format", nullptr, "auto|csv|rtl", nullptr, "auto",
       "positioning file format: auto recognises a Renishaw .rtl by its content (HEADER:: ...)"},
      {"--rtl-runs", nullptr, "alternate|forward|reverse", nullptr, "alternate",
       ".rtl runs: odd runs forward and even runs reverse, or every run in one direction "
       "(unidirectional test)"},
      {"--rtl-negate", nullptr, nullptr, nullptr, nullptr,
       ".rtl deviations are nominal − actual (laser set up the other way): flip their sign"},
      {"--rtl-units", nullptr, "mm|in", nullptr, "mm",
       ".rtl written in mm and µm, or (laser software in imperial units) in inches and µin: "
       "converted to mm and µm"},
      {"--rtl-expansion-per", nullptr, "auto|C|F", nullptr, "auto",
       ".rtl expansion coefficient in ppm/°C or ppm/°F (auto: ppm/°F when the file's "
       "temperatures are °F)"},
      {"--accept-units", nullptr, nullptr, nullptr, nullptr,
       "accept a µm (or µin) deviation column whose values are all below 0.1 µm (refused by "
       "default as mm typed as µm, or inches typed as µin)"},
  };
  return kOptions;
}

Expected<datasets::PositioningReadOptions> ParsePositioningReadOptions(Args& args) {
  using datasets::PositioningFormat;
  using datasets::RtlRuns;
  datasets::PositioningReadOptions o;
  VOLCOMP_TRY_ASSIGN(
      o.format, ParseChoice<PositioningFormat>("--format", args.Value("--format").value_or("auto"),
                                               {{"auto", PositioningFormat::kAuto},
                                                {"csv", PositioningFormat::kCsv},
                                                {"rtl", PositioningFormat::kRtl}}));
  VOLCOMP_TRY_ASSIGN(
      o.rtl.runs, ParseChoice<RtlRuns>("--rtl-runs", args.Value("--rtl-runs").value_or("alternate"),
                                       {{"alternate", RtlRuns::kAlternate},
                                        {"forward", RtlRuns::kForward},
                                        {"reverse", RtlRuns::kReverse}}));
  o.rtl.negate = args.Flag("--rtl-negate");
  VOLCOMP_TRY_ASSIGN(o.rtl.units,
                     ParseChoice<datasets::RtlUnits>(
                         "--rtl-units", args.Value("--rtl-units").value_or("mm"),
                         {{"mm", datasets::RtlUnits::kMm}, {"in", datasets::RtlUnits::kIn}}));
  using datasets::RtlExpansionPer;
  VOLCOMP_TRY_ASSIGN(o.rtl.expansion_per,
                     ParseChoice<RtlExpansionPer>(
                         "--rtl-expansion-per", args.Value("--rtl-expansion-per").value_or("auto"),
                         {{"auto", RtlExpansionPer::kAuto},
                          {"C", RtlExpansionPer::kCelsius},
                          {"F", RtlExpansionPer::kFahrenheit},
                          {"c", RtlExpansionPer::kCelsius, false},
                          {"f", RtlExpansionPer::kFahrenheit, false}}));
  o.accept_units = args.Flag("--accept-units");
  return o;
}

Expected<datasets::PositioningFile> ReadPositioningArgument(
    const std::string& path, const datasets::PositioningReadOptions& options, Context& ctx) {
  if (path != "-") return datasets::ReadPositioningFile(path, options);
  std::ostringstream text;
  text << ctx.in.rdbuf();
  return datasets::ReadPositioningText(text.str(), "<stdin>", options);
}

}  // namespace volcomp::cli
