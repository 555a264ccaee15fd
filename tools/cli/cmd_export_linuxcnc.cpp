// `volcomp export linuxcnc`: LinuxCNC joint compensation files (COMP_FILE_TYPE 0 or 1) from
// positioning test results, with the [JOINT_n] INI lines to paste (see model/linuxcnc_comp.hpp).
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/model/axis1d.hpp"
#include "volcomp/model/linuxcnc_comp.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::tools {
namespace {

// H3: metrology's WriteTextOutput is gone (files: tools::WriteTextFile); this legacy command still
// reports failures by throwing.
void WriteOrThrow(const std::string& path, const std::string& text) {
  const Outcome written = WriteTextFile(path, text);
  if (!written.ok()) throw InputError(written.error().message);
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
  metrology::GroupingOptions grouping;
  grouping.allow_few_approaches = args.flag("--allow-few-runs");
  args.finish();

  std::filesystem::create_directories(out_dir);
  const auto t = static_cast<model::LinuxcncCompType>(type);
  std::string ini;
  std::cout << "volcomp export linuxcnc (COMP_FILE_TYPE " << type << ")\n";
  for (const auto& [name, path] : inputs) {
    const model::PositioningData data = model::LoadPositioningCsv(path, grouping);
    for (const auto& w : data.warnings) std::cerr << "warning: " << w << "\n";
    model::LinuxcncComp comp;
    try {
      comp = model::BuildLinuxcncComp(data, t, spacing.count(name) ? spacing[name] : 0.0);
    } catch (const std::invalid_argument& e) {
      throw InputError(path + ": " + e.what());
    }
    std::string file = std::string(1, static_cast<char>(name - 'A' + 'a')) + ".comp";
    const std::string full = (std::filesystem::path(out_dir) / file).string();
    WriteOrThrow(full, model::FormatLinuxcncComp(comp));
    std::cout << "  axis " << name << ": " << comp.rows.size() << " points from "
              << comp.rows.front().nominal << " to " << comp.rows.back().nominal << ", "
              << (data.dev_reverse.empty() ? "one direction (reverse = forward)" : "bidirectional")
              << ", wrote " << full << "\n";
    ini += "[JOINT_" + std::to_string(joint[name]) +
           "]\nCOMP_FILE = " + std::filesystem::absolute(full).string() +
           "\nCOMP_FILE_TYPE = " + std::to_string(type) + "\n";
  }
  const std::string ini_path = (std::filesystem::path(out_dir) / "joints.ini").string();
  WriteOrThrow(ini_path, ini);
  std::cout << "\nINI lines (also in " << ini_path << "):\n\n" << ini;
  return 0;
}

}  // namespace volcomp::tools
