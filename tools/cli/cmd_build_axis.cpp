// `volcomp build axis`: AXIS1D tables (forward/reverse or forward + backlash) from positioning test
// results, one CSV per axis (mean deviations per target; see volcomp/model/axis1d.hpp).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/model/axis1d.hpp"
#include "volcomp/model/axis_section.hpp"
#include "volcomp/model/build_cli.hpp"

namespace volcomp::tools {

int RunBuildAxis(Args& args) {
  struct Input {
    char name;
    std::string path;
  };
  std::vector<Input> inputs;
  for (const char* n : {"X", "Y", "Z", "A", "B", "C", "U", "V", "W"}) {
    const std::string opt = std::string("--") + static_cast<char>(n[0] - 'A' + 'a');
    if (auto p = args.value(opt)) inputs.push_back({n[0], *p});
  }
  if (inputs.empty()) throw UsageError("give at least one axis file, e.g. --x x.csv");
  if (inputs.size() > table::kMaxAxes) throw UsageError("at most 6 axes");
  const std::string out_path = args.required("-o", "--output");
  model::Axis1dOptions opt;
  const std::string reverse = args.value("--reverse").value_or("tables");
  if (reverse == "tables") {
    opt.reverse = model::ReverseMode::kTables;
  } else if (reverse == "backlash") {
    opt.reverse = model::ReverseMode::kBacklash;
  } else if (reverse == "mean") {
    opt.reverse = model::ReverseMode::kMean;
  } else {
    throw UsageError("--reverse must be tables, backlash or mean");
  }
  std::vector<double> spacing(inputs.size(), 0.0);
  if (auto s = args.value("--spacing")) {
    for (const auto& [name, value] : image::ParseAxisAssignments(*s, "--spacing")) {
      bool found = false;
      for (std::size_t i = 0; i < inputs.size(); ++i) {
        if (inputs[i].name != name) continue;
        const auto v = ParseDouble(value);
        if (!v || !(*v > 0))
          throw UsageError("--spacing: axis " + std::string(1, name) + " needs a positive number");
        spacing[i] = *v;
        found = true;
      }
      if (!found) throw UsageError("--spacing: no input file for axis " + std::string(1, name));
    }
  }
  const bool wrap = args.flag("--wrap");
  std::vector<char> names;
  for (const Input& in : inputs) names.push_back(in.name);
  image::ImageRequest req;
  req.axes = image::MakeAxisDefs(names, args.value("--resolution-nm").value_or(""),
                                 args.value("--steps-per-unit").value_or(""));
  model::cli::ParseImageOptions(args, &req);
  args.finish();

  std::cout << "volcomp build axis\n";
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const model::PositioningData data = model::LoadPositioningCsv(inputs[i].path);
    for (const auto& w : data.warnings) std::cerr << "warning: " << w << "\n";
    const bool rotary = req.axes[i].kind == table::AxisKind::kRotary;
    model::Axis1dOptions o = opt;
    o.spacing = spacing[i];
    model::AxisSection axis;
    try {
      axis = model::BuildAxisSection(data, o, req.axes[i], static_cast<uint8_t>(i), wrap);
    } catch (const std::invalid_argument& e) {
      throw InputError(inputs[i].path + ": " + e.what());
    }
    const model::Axis1dTable& t = axis.table;
    req.axis_tables.push_back(axis.section);
    req.info.emplace(std::string("source_") + inputs[i].name, inputs[i].path);
    const char* unit = rotary ? "arcsec" : "µm";
    double max_fwd = 0;
    for (double v : t.forward) max_fwd = std::fmax(max_fwd, std::fabs(v));
    char line[256];
    std::snprintf(line, sizeof(line),
                  "  axis %c: %zu nodes from %.6g every %.6g %s, largest forward correction %.3f "
                  "%s, %s, backlash %.3f %s\n",
                  inputs[i].name, t.forward.size(), t.origin, t.spacing, rotary ? "deg" : "mm",
                  max_fwd, unit, t.reverse.empty() ? "no reverse table" : "reverse table",
                  t.backlash, unit);
    std::cout << line;
  }
  req.info.emplace("builder", "volcomp build axis");
  req.info.emplace("reverse", reverse);
  const std::vector<uint8_t> bytes = image::BuildImage(req);
  image::WriteFileBytes(out_path, bytes);
  std::cout << "  wrote " << out_path << " (" << bytes.size() << " bytes)\n";
  return 0;
}

}  // namespace volcomp::tools
