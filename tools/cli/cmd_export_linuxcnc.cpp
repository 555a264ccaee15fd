// `volcomp export linuxcnc`: LinuxCNC joint compensation files (COMP_FILE_TYPE 0 or 1) from
// positioning test results, with the [JOINT_n] INI lines to merge into the machine's INI file
// (exporters/linuxcnc_comp.hpp). Writes one file per axis and joints.ini into the output
// directory; with --ini merges the lines into that INI file (the old one kept as FILE.bak).
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "export_axes.hpp"
#include "option_groups.hpp"
#include "positioning_input.hpp"
#include "volcomp/exporters/linuxcnc_comp.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

Expected<std::string> AbsolutePath(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::absolute(path, ec);
  if (ec) return Fail(Error::kIoError, path + ": " + ec.message());
  return p.string();
}

void ExportText(const JsonValue& d, std::ostream& out) {
  out << "volcomp export linuxcnc (COMP_FILE_TYPE " << d.get("type")->integer << ", machine units "
      << d.get("linear_units")->string
      << ": [TRAJ] LINEAR_UNITS = " << (d.get("linear_units")->string == "in" ? "inch" : "mm")
      << ")\n";
  for (const JsonValue& a : d.get("axes")->array) {
    out << "  axis " << a.get("axis")->string << ": " << a.get("points")->integer << " points from "
        << a.get("from")->number << " to " << a.get("to")->number << " " << a.get("unit")->string
        << ", "
        << (a.get("bidirectional")->boolean ? "bidirectional" : "one direction (reverse = forward)")
        << ", wrote " << a.get("file")->string << "\n";
  }
  if (const JsonValue* merged = d.get("merged_into")) {
    out << "\nmerged into " << merged->string << " (the file before: " << d.get("backup")->string
        << "):\n\n"
        << d.get("ini")->string;
    return;
  }
  out << "\nINI lines to merge into the [JOINT_n] sections the machine's INI file has (also in "
      << d.get("ini_file")->string << "; --ini FILE merges them):\n\n"
      << d.get("ini")->string;
}

// joints.ini: the lines, under a comment saying how they go in (LinuxCNC INI comments: #).
std::string JointsIniFile(const std::string& ini, exporters::LengthUnit unit) {
  return "# volcomp export linuxcnc: merge these lines into the sections of the same name in the\n"
         "# machine's INI file, do not append them: LinuxCNC reads the first [JOINT_n] section of\n"
         "# a name only and ignores a second one without a message. `volcomp export linuxcnc ...\n"
         "# --ini machine.ini` merges them.\n"
         "# The files are in " +
         std::string(unit == exporters::LengthUnit::kInch ? "inches" : "mm") +
         " (deg on a rotary joint): the machine's [TRAJ] LINEAR_UNITS must be " +
         (unit == exporters::LengthUnit::kInch ? "inch" : "mm") + ".\n" + ini;
}

Expected<Output> RunExportLinuxcnc(Args& args, Context& ctx) {
  VOLCOMP_TRY_ASSIGN(std::vector<AxisInput> inputs, PositioningInputs(args, /*model_axes=*/true));
  const std::string out_dir = args.Required("-o", "--output");
  const long long type = args.Integer("--type").value_or(1);
  VOLCOMP_TRY(args.status());
  if (type != 0 && type != 1) {
    return UsageFailure("--type must be 0 or 1 (LinuxCNC COMP_FILE_TYPE)");
  }
  VOLCOMP_TRY_ASSIGN(auto joint,
                     ParseAxisNumberMap(args.Value("--joints"), "--joints", "joint", 0, 0, 15));
  VOLCOMP_TRY_ASSIGN(auto spacing, ParseAxisNumbers(args.Value("--spacing"), "--spacing", true));
  const std::optional<std::string> merge_ini = args.Value("--ini");
  VOLCOMP_TRY_ASSIGN(const exporters::LengthUnit unit, ParseMachineUnits(args));
  metrology::GroupingOptions grouping;
  grouping.allow_few_approaches = args.Flag("--allow-few-runs");
  args.Flag("--json");  // the command layer prints the data as JSON
  VOLCOMP_TRY_ASSIGN(const datasets::PositioningReadOptions read,
                     ParsePositioningReadOptions(args));
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY(LoadModels(&inputs, ctx));
  const char* unit_name = exporters::UnitName(unit, false);
  // The INI's machine unit must be the files': read it before anything is written.
  std::optional<std::string> ini_before;
  if (merge_ini) {
    VOLCOMP_TRY_ASSIGN(ini_before, tools::ReadTextFile(*merge_ini));
    const auto in_ini = exporters::LinuxcncLinearUnits(*ini_before, *merge_ini);
    if (!in_ini.ok()) return Fail(Error::kInputInvalid, in_ini.error().message);
    if (*in_ini && **in_ini != unit) {
      const char* ini_unit = exporters::UnitName(**in_ini, false);
      return Fail(Error::kInputInvalid,
                  *merge_ini + ": [TRAJ] LINEAR_UNITS is " +
                      (**in_ini == exporters::LengthUnit::kInch ? "inch" : "mm") +
                      ", the tables would be in " + unit_name + " (--units " + unit_name +
                      "): give --units " + ini_unit + " (nothing was written)");
    }
  }

  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) return Fail(Error::kIoError, out_dir + ": cannot create the directory: " + ec.message());
  const auto comp_type = static_cast<exporters::LinuxcncCompType>(type);
  Output output;
  JsonValue axes = JsonValue::Array();
  std::string ini;
  std::vector<exporters::LinuxcncJointComp> joint_comps;
  std::map<int, char> axis_of_joint;
  for (const AxisInput& in : inputs) {
    const char name = in.axis;
    const std::string& path = in.path;
    const auto [other, added] = axis_of_joint.emplace(joint[name], name);
    if (!added) {
      return UsageFailure("--joints: " + std::string(1, other->second) + " and " +
                          std::string(1, name) + " both on joint " + std::to_string(joint[name]));
    }
    datasets::PositioningFormat format = datasets::PositioningFormat::kCsv;
    VOLCOMP_TRY_ASSIGN(const model::PositioningData data,
                       LoadAxisTest(in, read, grouping, ctx, &format));
    const auto s = spacing.find(name);
    const Expected<exporters::LinuxcncComp> comp =
        exporters::BuildLinuxcncComp(data, comp_type, s != spacing.end() ? s->second : 0.0, unit);
    if (!comp.ok()) return Fail(Error::kInputInvalid, path + ": " + comp.error().message);
    const std::string file = std::string(1, static_cast<char>(name - 'A' + 'a')) + ".comp";
    const std::string full = (std::filesystem::path(out_dir) / file).string();
    VOLCOMP_TRY(tools::WriteTextFile(full, exporters::FormatLinuxcncComp(*comp)));
    VOLCOMP_TRY_ASSIGN(const std::string absolute, AbsolutePath(full));
    ini += exporters::LinuxcncJointIni(joint[name], absolute, comp_type);
    joint_comps.push_back({joint[name], absolute, comp_type});
    JsonValue a = JsonValue::Object();
    a.Set("axis", std::string(1, name))
        .Set("joint", joint[name])
        .Set("source", path)
        .Set("format", in.from_model ? "model" : datasets::PositioningFormatName(format))
        .Set("unit", exporters::UnitName(unit, data.rotary))
        .Set("points", uint64_t{comp->rows.size()})
        .Set("from", comp->rows.front().nominal)
        .Set("to", comp->rows.back().nominal)
        .Set("bidirectional", !data.dev_reverse.empty())
        .Set("max_residual", comp->max_residual)
        .Set("file", full);
    axes.Push(std::move(a));
  }
  const std::string ini_path = (std::filesystem::path(out_dir) / "joints.ini").string();
  VOLCOMP_TRY(tools::WriteTextFile(ini_path, JointsIniFile(ini, unit)));
  output.data = JsonValue::Object();
  if (merge_ini) {
    const std::string& before = *ini_before;
    const exporters::LinuxcncIniMerge merged =
        exporters::MergeLinuxcncJointIni(before, joint_comps, *merge_ini);
    const std::string backup = *merge_ini + ".bak";
    VOLCOMP_TRY(tools::WriteTextFile(backup, before));
    VOLCOMP_TRY(tools::WriteTextFile(*merge_ini, merged.text));
    JsonValue warnings = JsonValue::Array();
    for (const std::string& w : merged.warnings) {
      output.warnings.push_back(w);
      warnings.Push(w);
    }
    output.data.Set("merged_into", *merge_ini)
        .Set("backup", backup)
        .Set("merge_warnings", std::move(warnings));
  }
  output.data.Set("type", type)
      .Set("linear_units", unit_name)
      .Set("output", out_dir)
      .Set("axes", std::move(axes))
      .Set("ini_file", ini_path)
      .Set("ini", ini);
  output.text = ExportText;
  return output;
}

}  // namespace

const Command& ExportLinuxcncCommand() {
  static const Command kCommand{
      "export linuxcnc",
      "LinuxCNC joint compensation files (COMP_FILE_TYPE 0 or 1) from positioning tests",
      "",
      Join({PositioningFileOptions(),
            {ModelAxesOption(),
             {"--output", "-o", "DIR", nullptr, nullptr,
              "directory for x.comp ... and joints.ini (required)"},
             {"--type", nullptr, "0|1", nullptr, "1",
              "COMP_FILE_TYPE: 1 the file holds the trims, 0 the positions reached"},
             {"--joints", nullptr, "X=N,...", nullptr, nullptr,
              "joint 0..15 of an axis in its [JOINT_n] lines (default: X=0 ... W=8)"},
             MachineUnitsOption(),
             {"--spacing", nullptr, "X=S,...", "mm or in (deg for A, B, C)", nullptr,
              "point spacing per axis (default: the test's, or its smallest gap)"},
             {"--ini", nullptr, "FILE", nullptr, nullptr,
              "merge the lines into this LinuxCNC INI file's [JOINT_n] sections (old: FILE.bak); "
              "its [TRAJ] LINEAR_UNITS must be --units"}},
            AllowFewRuns(),
            PositioningFormatOptions(),
            {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunExportLinuxcnc,
      "Each FILE is either the raw readings `evaluate positioning` reads (CSV or a Renishaw\n"
      ".rtl; the mean per target and direction is used) or the mean deviations (position_mm, "
      "dev_forward_um\n"
      "[, dev_reverse_um]). Writes one file per axis (x.comp, ...), ending at the last\n"
      "tested position, and joints.ini with the INI lines to merge into the machine's\n"
      "[JOINT_n] sections (--ini FILE merges them); see docs/linuxcnc.md."};
  return kCommand;
}

}  // namespace volcomp::cli
