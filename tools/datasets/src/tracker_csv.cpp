// Tracker lines and lattices from CSV (see tracker_csv.hpp for the formats).
#include "volcomp/datasets/tracker_csv.hpp"

#include <cmath>
#include <set>
#include <unordered_map>
#include <vector>

#include "trim.hpp"

namespace volcomp::datasets {
namespace {

using model::GridAxes;
using model::GridAxis;
using tools::CsvTable;

// "source:line: message" (line 0: "source: message").
Failure At(const std::string& source, std::size_t line, const std::string& message) {
  return Failure{Error::kInputInvalid,
                 source + (line ? ":" + std::to_string(line) : std::string()) + ": " + message};
}

// Equally spaced node values of one lattice axis, from the set of values the readings give.
Expected<GridAxis> AxisOf(const std::string& source,
                          std::size_t line,
                          const std::set<double>& values,
                          char axis) {
  const std::string name(1, axis);
  if (values.size() < 2) {
    return Fail(At(source, line, "the lattice needs at least 2 nodes along " + name));
  }
  const std::vector<double> v(values.begin(), values.end());
  const double h = (v.back() - v.front()) / static_cast<double>(v.size() - 1);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (std::fabs(v[i] - (v.front() + h * static_cast<double>(i))) > 1e-6) {
      return Fail(
          At(source, line,
             "the " + name + " nodes are not equally spaced (" + std::to_string(v[i]) + " mm)"));
    }
  }
  return GridAxis{v.front(), h, static_cast<uint32_t>(v.size())};
}

uint32_t NodeIndex(const GridAxis& g, double value) {
  return static_cast<uint32_t>(std::lround((value - g.origin_mm) / g.spacing_mm));
}

}  // namespace

Expected<model::TrackerData> TrackerDataFromCsv(const CsvTable& csv) {
  static const char* kCmd[3] = {"x_cmd_mm", "y_cmd_mm", "z_cmd_mm"};
  static const char* kPos[3] = {"x_mm", "y_mm", "z_mm"};
  VOLCOMP_TRY(csv.Require("axis"));
  for (int a = 0; a < 3; ++a) {
    VOLCOMP_TRY(csv.Require(kCmd[a]));
    VOLCOMP_TRY(csv.Require(kPos[a]));
  }
  const int cos_columns =
      (csv.find("cos_x") ? 1 : 0) + (csv.find("cos_y") ? 1 : 0) + (csv.find("cos_z") ? 1 : 0);
  if (cos_columns != 0 && cos_columns != 3) {
    return Fail(csv.LineFailure(csv.header_line(), "give all of cos_x, cos_y, cos_z or none"));
  }
  model::TrackerData d;
  d.name = csv.source();
  d.has_printed_cosines = cos_columns == 3;
  for (const tools::CsvRow& r : csv.rows()) {
    VOLCOMP_TRY_ASSIGN(const std::string axis_text, r.Text("axis"));
    const std::string axis = Trim(axis_text);
    const int a = axis == "X" || axis == "x"   ? 0
                  : axis == "Y" || axis == "y" ? 1
                  : axis == "Z" || axis == "z" ? 2
                                               : -1;
    if (a < 0)
      return Fail(csv.LineFailure(r.line(), "axis must be X, Y or Z, got \"" + axis + "\""));
    const std::string line_name = std::string("the ") + "XYZ"[a] + " line";
    model::TrackerNode n;
    for (int b = 0; b < 3; ++b) {
      VOLCOMP_TRY_ASSIGN(const double c, r.Number(kCmd[b]));
      if (b == a) {
        n.q_mm = c;
      } else if (c != 0.0) {
        return Fail(csv.LineFailure(r.line(), line_name + " must keep " + kCmd[b] +
                                                  " at 0 (the lines run through a common origin)"));
      }
      VOLCOMP_TRY_ASSIGN(n.p_mm[b], r.Number(kPos[b]));
    }
    if (d.has_printed_cosines) {
      tools::CsvFields f(r);
      n.printed_cos = {f.Number("cos_x"), f.Number("cos_y"), f.Number("cos_z")};
      VOLCOMP_TRY(f.status());
    }
    auto& line = d.lines[static_cast<std::size_t>(a)];
    if (line.empty() && n.q_mm != 0.0) {
      return Fail(
          csv.LineFailure(r.line(), line_name + " must start at its origin node (commanded 0)"));
    }
    if (!line.empty()) {
      const double h = line.size() >= 2 ? line[1].q_mm - line[0].q_mm : n.q_mm - line[0].q_mm;
      if (!(n.q_mm > line.back().q_mm)) {
        return Fail(csv.LineFailure(r.line(), line_name + " must increase"));
      }
      if (std::fabs(n.q_mm - line.back().q_mm - h) > 1e-9) {
        return Fail(csv.LineFailure(
            r.line(), line_name + " must be equally spaced (step " + std::to_string(h) + " mm)"));
      }
    }
    line.push_back(n);
  }
  if (const Outcome valid = model::ValidateTrackerData(d); !valid.ok()) {
    return Fail(Error::kInputInvalid, csv.source() + ": " + valid.error().message);
  }
  return d;
}

Expected<model::TrackerData> LoadTrackerCsv(const std::string& path) {
  VOLCOMP_TRY_ASSIGN(const CsvTable csv, CsvTable::ReadFile(path));
  return TrackerDataFromCsv(csv);
}

Expected<model::TrackerLatticeData> TrackerLatticeFromReadings(
    const std::string& source,
    std::size_t file_line,
    const std::vector<TrackerLatticeReading>& readings) {
  std::set<double> values[3];
  for (const TrackerLatticeReading& r : readings) {
    for (int a = 0; a < 3; ++a) values[a].insert(r.command_mm[a]);
  }
  model::TrackerLatticeData d;
  d.name = source;
  for (int a = 0; a < 3; ++a) {
    VOLCOMP_TRY_ASSIGN(d.lattice[static_cast<std::size_t>(a)],
                       AxisOf(source, file_line, values[a], "XYZ"[a]));
  }
  const GridAxes& g = d.lattice;
  const std::size_t total = static_cast<std::size_t>(g[0].nodes) * g[1].nodes * g[2].nodes;
  // Each node once, checked reading by reading before the lattice is allocated (n readings may
  // describe a lattice of up to n³ nodes).
  std::vector<std::size_t> node_of(readings.size());
  std::unordered_map<std::size_t, std::size_t> line_of;
  for (std::size_t row = 0; row < readings.size(); ++row) {
    const model::Vec3& c = readings[row].command_mm;
    const std::size_t i = NodeIndex(g[0], c.x), j = NodeIndex(g[1], c.y), k = NodeIndex(g[2], c.z);
    node_of[row] = (k * g[1].nodes + j) * g[0].nodes + i;
    const auto first = line_of.emplace(node_of[row], readings[row].line);
    if (!first.second) {
      return Fail(
          At(source, readings[row].line,
             "node given twice (first on line " + std::to_string(first.first->second) + ")"));
    }
  }
  if (readings.size() != total) {
    return Fail(At(source, file_line,
                   std::to_string(readings.size()) + " nodes for a " + std::to_string(g[0].nodes) +
                       "x" + std::to_string(g[1].nodes) + "x" + std::to_string(g[2].nodes) +
                       " lattice (" + std::to_string(total) + " needed)"));
  }
  d.position_mm.assign(total, model::Vec3{});
  for (std::size_t row = 0; row < readings.size(); ++row)
    d.position_mm[node_of[row]] = readings[row].reading_mm;
  return d;
}

Expected<model::TrackerLatticeData> TrackerLatticeFromCsv(const CsvTable& csv) {
  static const char* kCmd[3] = {"x_cmd_mm", "y_cmd_mm", "z_cmd_mm"};
  static const char* kPos[3] = {"x_mm", "y_mm", "z_mm"};
  for (int a = 0; a < 3; ++a) {
    VOLCOMP_TRY(csv.Require(kCmd[a]));
    VOLCOMP_TRY(csv.Require(kPos[a]));
  }
  std::vector<TrackerLatticeReading> readings;
  for (const tools::CsvRow& r : csv.rows()) {
    tools::CsvFields f(r);
    readings.push_back({{f.Number(kCmd[0]), f.Number(kCmd[1]), f.Number(kCmd[2])},
                        {f.Number(kPos[0]), f.Number(kPos[1]), f.Number(kPos[2])},
                        r.line()});
    VOLCOMP_TRY(f.status());
  }
  return TrackerLatticeFromReadings(csv.source(), csv.header_line(), readings);
}

Expected<model::TrackerLatticeData> LoadTrackerLatticeCsv(const std::string& path) {
  VOLCOMP_TRY_ASSIGN(const CsvTable csv, CsvTable::ReadFile(path));
  return TrackerLatticeFromCsv(csv);
}

}  // namespace volcomp::datasets
