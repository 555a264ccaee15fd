// `volcomp export linuxcnc`: LinuxCNC joint compensation files (COMP_FILE_TYPE 0 or 1) from
// positioning test results, with the [JOINT_n] INI lines to paste (see model/linuxcnc_comp.hpp).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/model/axis1d.hpp"
#include "volcomp/model/linuxcnc_comp.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::tools {

namespace {

// Mean deviations per target from either CSV the positioning tools use: the means
// (position_mm, dev_forward_um[, dev_reverse_um], as `build axis`) or the raw readings
// (target_mm, direction, run, deviation_um, as `evaluate positioning`).
model::PositioningData LoadMeans(const std::string& path) {
  const CsvTable csv = CsvTable::ParseFile(path);
  if (csv.find("position_mm") || csv.find("position_deg")) return model::PositioningFromCsv(csv);
  metrology::GroupingOptions g;
  g.allow_few_approaches = true;
  const metrology::PositioningSet set =
      metrology::GroupReadings(metrology::ReadPositioningCsv(csv), g);
  model::PositioningData d;
  d.rotary = set.kind == metrology::AxisKind::kRotary;
  auto mean = [](const metrology::ApproachSeries& s) {
    double sum = 0;
    for (double v : s.deviations) sum += v;
    return sum / static_cast<double>(s.deviations.size());
  };
  for (const metrology::TargetPosition& p : set.positions) {
    d.position.push_back(p.target);
    d.dev_forward.push_back(set.has_up ? mean(p.up) : mean(p.down));
    if (set.has_up && set.has_down) d.dev_reverse.push_back(mean(p.down));
  }
  if (d.position.size() < 2) {
    throw InputError(path + ": a positioning test needs at least 2 target positions");
  }
  return d;
}

}  // namespace

int RunExportLinuxcnc(Args& args) {
  static const std::string kAxes = "XYZABCUVW";
  std::vector<std::pair<char, std::string>> inputs;
  for (char n : kAxes) {
    const std::string opt = std::string("--") + static_cast<char>(n - 'A' + 'a');
    if (auto p = args.value(opt)) inputs.emplace_back(n, *p);
  }
  if (inputs.empty()) throw UsageError("give at least one axis file, e.g. --x x.csv");
  const std::string out_dir = args.required("-o", "--output");
  const long long type = args.integer("--type").value_or(1);
  if (type != 0 && type != 1) throw UsageError("--type must be 0 or 1 (LinuxCNC COMP_FILE_TYPE)");
  std::map<char, int> joint;
  for (std::size_t i = 0; i < kAxes.size(); ++i) joint[kAxes[i]] = static_cast<int>(i);
  if (auto j = args.value("--joints")) {
    for (const auto& [name, value] : image::ParseAxisAssignments(*j, "--joints")) {
      const auto v = ParseDouble(value);
      if (!v || *v < 0 || *v > 15 || *v != static_cast<int>(*v))
        throw UsageError("--joints: joint of " + std::string(1, name) + " must be 0..15");
      joint[name] = static_cast<int>(*v);
    }
  }
  std::map<char, double> spacing;
  if (auto s = args.value("--spacing")) {
    for (const auto& [name, value] : image::ParseAxisAssignments(*s, "--spacing")) {
      const auto v = ParseDouble(value);
      if (!v || !(*v > 0)) throw UsageError("--spacing: " + std::string(1, name) + " must be > 0");
      spacing[name] = *v;
    }
  }
  args.finish();

  std::filesystem::create_directories(out_dir);
  const auto t = static_cast<model::LinuxcncCompType>(type);
  std::string ini;
  std::cout << "volcomp export linuxcnc (COMP_FILE_TYPE " << type << ")\n";
  for (const auto& [name, path] : inputs) {
    const model::PositioningData data = LoadMeans(path);
    model::LinuxcncComp comp;
    try {
      comp = model::BuildLinuxcncComp(data, t, spacing.count(name) ? spacing[name] : 0.0);
    } catch (const std::invalid_argument& e) {
      throw InputError(path + ": " + e.what());
    }
    std::string file = std::string(1, static_cast<char>(name - 'A' + 'a')) + ".comp";
    const std::string full = (std::filesystem::path(out_dir) / file).string();
    std::ofstream(full) << model::FormatLinuxcncComp(comp);
    std::cout << "  axis " << name << ": " << comp.rows.size() << " points from "
              << comp.rows.front().nominal << " to " << comp.rows.back().nominal << ", "
              << (data.dev_reverse.empty() ? "one direction (reverse = forward)" : "bidirectional")
              << ", wrote " << full << "\n";
    ini += "[JOINT_" + std::to_string(joint[name]) +
           "]\nCOMP_FILE = " + std::filesystem::absolute(full).string() +
           "\nCOMP_FILE_TYPE = " + std::to_string(type) + "\n";
  }
  std::ofstream(std::filesystem::path(out_dir) / "joints.ini") << ini;
  std::cout << "\nINI lines (also in " << (std::filesystem::path(out_dir) / "joints.ini").string()
            << "):\n\n"
            << ini;
  return 0;
}

}  // namespace volcomp::tools
