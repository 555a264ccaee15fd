// lcnc_evaluate: turns the rest points LinuxCNC's run recorded (lcnc_run.py) into the figures of
// the integration test (docs/linuxcnc.md §4).
//
//   lcnc_evaluate --rest rest.csv --step-mm S --out DIR
//                 [--positioning PROGRAM.ngc=TARGETS.csv]... [--diagonal
//                 PROGRAM.ngc=TARGETS.csv]...
//
// TARGETS.csv are the templates `volcomp program ... --targets-csv` wrote: one row per measured
// stop in program order, matched with the program's recorded stops in order. For each stop the
// reading a laser aligned with the move would give is (tool point - commanded point) . u in um,
// u the unit vector of the program's line (from its first to its farthest stop), the commanded
// point being LinuxCNC's joint position (machine coordinates) and the tool point that of the
// simulated machine with its axes at the drives' counts since power-on minus LinuxCNC's motor
// offset: the machine frame as LinuxCNC homed it, the frame a table is measured in (homing's own
// precision against the switch is checked apart, check_machine_position.py), for three
// machines: `before` (the drives at LinuxCNC's commanded counts: the uncompensated machine),
// `board` (the drives behind the volcomp board) and `native` (the step generators behind the
// native component); for a run of volcomp-comp.hal (columns pos_cmd_mm_*) one machine, `comp1d`
// (LinuxCNC's own joint compensation, the commanded point being the nominal joint position). Writes
// DIR/{before,board,native}/PROGRAM.csv (positioning, the layout of `volcomp evaluate positioning`)
// and DIR/*/diagonals.csv (`volcomp evaluate diagonal`), and DIR/checks.json with the step audit at
// every rest point and the board-versus-native comparison.
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "machine_tool_point.hpp"
#include "volcomp/tools/csv.hpp"

namespace {

using volcomp::Expected;
using volcomp::Fail;
using volcomp::Failure;
using volcomp::Outcome;
using volcomp::model::Vec3;
using volcomp::tools::CsvFields;
using volcomp::tools::CsvTable;
using Steps = std::array<int64_t, 3>;

struct Rest {
  std::string program;
  Vec3 cmd_mm;
  Steps lcnc, board_in, board_corr, board_out, backlog, drive, native;
  Vec3 machine[3];  // axis positions (mm, machine frame) of the evaluated cases
  Vec3 ferror_mm;   // LinuxCNC's joint following errors
};

Steps ReadSteps(CsvFields& f, const std::string& prefix) {
  return {f.Integer(prefix + "0"), f.Integer(prefix + "1"), f.Integer(prefix + "2")};
}

// Axis positions in the machine frame: `counts` steps since power-on, minus the motor offset.
Vec3 Machine_mm(const Steps& counts, double step_mm, const Vec3& motor_offset_mm) {
  return Vec3{static_cast<double>(counts[0]) * step_mm, static_cast<double>(counts[1]) * step_mm,
              static_cast<double>(counts[2]) * step_mm} -
         motor_offset_mm;
}

Failure Usage(const std::string& m) { return Failure{volcomp::Error::kUsage, m}; }

std::string Fixed(double v, int decimals) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

using volcomp::model::Dot;
using volcomp::model::Norm;

struct Spec {
  std::string program, targets;
  bool diagonal;
};

Outcome Run(int argc, char** argv) {
  std::string rest_path, out;
  double step_mm = 0;
  std::vector<Spec> specs;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--rest") {
      rest_path = v;
    } else if (k == "--step-mm") {
      step_mm = volcomp::tools::ParseDouble(v).value_or(0);
    } else if (k == "--out") {
      out = v;
    } else if (k == "--positioning" || k == "--diagonal") {
      const auto eq = v.find('=');
      if (eq == std::string::npos) return Fail(Usage(k + " needs PROGRAM=TARGETS"));
      specs.push_back({v.substr(0, eq), v.substr(eq + 1), k == "--diagonal"});
    } else {
      return Fail(Usage("unknown option " + k));
    }
  }
  if (rest_path.empty() || out.empty() || !(step_mm > 0)) {
    return Fail(Usage("usage: lcnc_evaluate --rest FILE --step-mm S --out DIR ..."));
  }
  VOLCOMP_TRY_ASSIGN(const CsvTable table, CsvTable::ReadFile(rest_path));
  // The board run (volcomp-sim.hal) or the joint compensation run (volcomp-comp.hal: the
  // nominal joint command and the drives only).
  const bool comp_run = table.find("pos_cmd_mm_0").has_value();
  std::vector<const char*> cases = {"before", "board", "native"};
  if (comp_run) cases = {"comp1d"};
  std::vector<Rest> rests;
  for (const auto& r : table.rows()) {
    CsvFields f(r);
    Rest x;
    x.program = f.Text("program");
    const std::string cmd = comp_run ? "pos_cmd_mm_" : "cmd_mm_";
    x.cmd_mm = {f.Number(cmd + "0"), f.Number(cmd + "1"), f.Number(cmd + "2")};
    x.drive = ReadSteps(f, "drive_counts_");
    x.ferror_mm = {f.Number("ferror_mm_0"), f.Number("ferror_mm_1"), f.Number("ferror_mm_2")};
    const Vec3 offset{f.Number("motor_offset_mm_0"), f.Number("motor_offset_mm_1"),
                      f.Number("motor_offset_mm_2")};
    if (comp_run) {
      x.machine[0] = Machine_mm(x.drive, step_mm, offset);
    } else {
      x.lcnc = ReadSteps(f, "lcnc_counts_");
      x.board_in = ReadSteps(f, "board_in_");
      x.board_corr = ReadSteps(f, "board_corr_");
      x.board_out = ReadSteps(f, "board_out_");
      x.backlog = ReadSteps(f, "board_backlog_");
      x.native = ReadSteps(f, "native_counts_");
      x.machine[0] = Machine_mm(x.lcnc, step_mm, offset);
      x.machine[1] = Machine_mm(x.drive, step_mm, offset);
      x.machine[2] = Machine_mm(x.native, step_mm, offset);
    }
    VOLCOMP_TRY(f.status());
    rests.push_back(x);
  }

  // Step audit at every rest point, and the two compensation paths side by side.
  int lost = 0, input_mismatch = 0, output_mismatch = 0, owed = 0;
  int64_t max_native_board_steps = 0;
  double max_native_board_um = 0;
  // The following error LinuxCNC sees at rest: the command against the feedback of the loop it
  // closes (the native component's, which takes its correction out again; LinuxCNC's own joint
  // compensation in the comp run). At rest the step generators stand within a step of the command.
  double max_rest_ferror_steps = 0;
  for (const Rest& r : rests) {
    for (int a = 0; a < 3; ++a) {
      max_rest_ferror_steps = std::max(max_rest_ferror_steps, std::fabs(r.ferror_mm[a]) / step_mm);
    }
  }
  for (const Rest& r : rests) {
    if (comp_run) break;
    for (int a = 0; a < 3; ++a) {
      lost += r.drive[a] != r.lcnc[a] + r.board_corr[a];
      input_mismatch += r.board_in[a] != r.lcnc[a];
      output_mismatch += r.board_out[a] != r.drive[a];
      owed += r.backlog[a] != 0;
      max_native_board_steps =
          std::max<int64_t>(max_native_board_steps, std::llabs(r.native[a] - r.drive[a]));
    }
    const Vec3 d = volcomp::lcnc_test::ToolPoint_mm(r.machine[2]) -
                   volcomp::lcnc_test::ToolPoint_mm(r.machine[1]);
    max_native_board_um = std::max(max_native_board_um, 1000.0 * Norm(d));
  }

  const int n_cases = static_cast<int>(cases.size());
  std::map<std::string, double> max_error_um;
  std::string diag_csv[3];
  for (int c = 0; c < n_cases; ++c) {
    std::filesystem::create_directories(out + "/" + cases[c]);
    diag_csv[c] = "diagonal,target_mm,direction,run,deviation_um\n";
  }
  for (const Spec& s : specs) {
    VOLCOMP_TRY_ASSIGN(const CsvTable targets, CsvTable::ReadFile(s.targets));
    std::vector<const Rest*> stops;
    for (const Rest& r : rests) {
      if (r.program == s.program) stops.push_back(&r);
    }
    if (stops.size() != targets.rows().size()) {
      return Fail(volcomp::Error::kInputInvalid,
                  s.program + ": " + std::to_string(stops.size()) + " recorded stops for " +
                      std::to_string(targets.rows().size()) + " measured stops in " + s.targets);
    }
    // The line's direction: from the first stop to the stop farthest from it.
    Vec3 u{0, 0, 0};
    for (const Rest* r : stops) {
      const Vec3 d = r->cmd_mm - stops.front()->cmd_mm;
      if (Norm(d) > Norm(u)) u = d;
    }
    u = (1.0 / Norm(u)) * u;
    std::string pos_csv[3];
    for (int c = 0; c < n_cases; ++c) pos_csv[c] = "target_mm,direction,run,deviation_um\n";
    for (size_t i = 0; i < stops.size(); ++i) {
      const Rest& r = *stops[i];
      CsvFields t(targets.rows()[i]);
      const std::string head =
          t.Text("target_mm") + "," + t.Text("direction") + "," + t.Text("run") + ",";
      const std::string diagonal = s.diagonal ? t.Text("diagonal") : "";
      VOLCOMP_TRY(t.status());
      for (int c = 0; c < n_cases; ++c) {
        const Vec3 e = volcomp::lcnc_test::ToolPoint_mm(r.machine[c]) - r.cmd_mm;
        max_error_um[cases[c]] = std::max(max_error_um[cases[c]], 1000.0 * Norm(e));
        const std::string row = head + Fixed(1000.0 * Dot(e, u), 4) + "\n";
        if (s.diagonal) {
          diag_csv[c] += "\"" + diagonal + "\"," + row;
        } else {
          pos_csv[c] += row;
        }
      }
    }
    if (!s.diagonal) {
      const std::string base = std::filesystem::path(s.program).stem().string();
      for (int c = 0; c < n_cases; ++c) {
        std::ofstream(out + "/" + cases[c] + "/" + base + ".csv") << pos_csv[c];
      }
    }
  }
  for (int c = 0; c < n_cases; ++c) {
    std::ofstream(out + "/" + cases[c] + "/diagonals.csv") << diag_csv[c];
  }

  std::ofstream j(out + "/checks.json");
  j << "{\n \"rest_points\": " << rests.size() << ",\n \"lost_steps\": " << lost
    << ",\n \"input_mismatches\": " << input_mismatch
    << ",\n \"output_mismatches\": " << output_mismatch << ",\n \"owed_steps\": " << owed
    << ",\n \"native_vs_board_max_steps\": " << max_native_board_steps
    << ",\n \"native_vs_board_max_um\": " << Fixed(max_native_board_um, 4)
    << ",\n \"max_rest_ferror_steps\": " << Fixed(max_rest_ferror_steps, 4);
  for (int c = 0; c < n_cases; ++c) {
    j << ",\n \"max_tool_point_error_um_" << cases[c] << "\": " << Fixed(max_error_um[cases[c]], 4);
  }
  j << "\n}\n";
  std::cout << "lcnc_evaluate: " << rests.size() << " rest points, lost steps " << lost
            << ", native vs board max " << max_native_board_steps << " steps ("
            << Fixed(max_native_board_um, 3) << " um at the tool)\n";
  return Outcome::Ok();
}

}  // namespace

int main(int argc, char** argv) {
  const Outcome r = Run(argc, argv);
  if (r.ok()) return 0;
  std::cerr << "lcnc_evaluate: " << r.error().message << "\n";
  return r.error().code == volcomp::Error::kUsage ? 2 : 1;
}
