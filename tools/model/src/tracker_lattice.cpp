// Laser-tracker lattice: trilinear forward map and its inverse (see tracker_lattice.hpp).
#include "volcomp/model/tracker_lattice.hpp"

#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>

namespace volcomp::model {
namespace {

using tools::CsvTable;

// Equally spaced node values of one axis, from the set of values the file gives.
GridAxis AxisOf(const CsvTable& csv, const std::set<double>& values, char axis) {
  const std::string name(1, axis);
  if (values.size() < 2) {
    throw csv.error(csv.header_line(), "the lattice needs at least 2 nodes along " + name);
  }
  const std::vector<double> v(values.begin(), values.end());
  const double h = (v.back() - v.front()) / static_cast<double>(v.size() - 1);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (std::fabs(v[i] - (v.front() + h * static_cast<double>(i))) > 1e-6) {
      throw csv.error(csv.header_line(), "the " + name + " nodes are not equally spaced (" +
                                             std::to_string(v[i]) + " mm)");
    }
  }
  return {v.front(), h, static_cast<uint32_t>(v.size())};
}

uint32_t NodeIndex(const GridAxis& g, double value) {
  return static_cast<uint32_t>(std::lround((value - g.origin_mm) / g.spacing_mm));
}

}  // namespace

TrackerLatticeData TrackerLatticeFromCsv(const CsvTable& csv) {
  const char* cmd[3] = {"x_cmd_mm", "y_cmd_mm", "z_cmd_mm"};
  const char* pos[3] = {"x_mm", "y_mm", "z_mm"};
  for (int a = 0; a < 3; ++a) {
    csv.require(cmd[a]);
    csv.require(pos[a]);
  }
  std::set<double> values[3];
  for (const tools::CsvRow& r : csv.rows()) {
    for (int a = 0; a < 3; ++a) values[a].insert(r.number(cmd[a]));
  }
  TrackerLatticeData d;
  d.name = csv.source();
  for (int a = 0; a < 3; ++a)
    d.lattice[static_cast<std::size_t>(a)] = AxisOf(csv, values[a], "XYZ"[a]);
  const GridAxes& g = d.lattice;
  const std::size_t total = static_cast<std::size_t>(g[0].nodes) * g[1].nodes * g[2].nodes;
  d.position_mm.assign(total, Vec3{});
  std::vector<std::size_t> line_of(total, 0);
  for (const tools::CsvRow& r : csv.rows()) {
    const uint32_t i = NodeIndex(g[0], r.number(cmd[0]));
    const uint32_t j = NodeIndex(g[1], r.number(cmd[1]));
    const uint32_t k = NodeIndex(g[2], r.number(cmd[2]));
    const std::size_t n = (static_cast<std::size_t>(k) * g[1].nodes + j) * g[0].nodes + i;
    if (line_of[n] != 0) {
      throw csv.error(r.line(),
                      "node given twice (first on line " + std::to_string(line_of[n]) + ")");
    }
    line_of[n] = r.line();
    d.position_mm[n] = {r.number(pos[0]), r.number(pos[1]), r.number(pos[2])};
  }
  if (csv.rows().size() != total) {
    throw csv.error(csv.header_line(), std::to_string(csv.rows().size()) + " nodes for a " +
                                           std::to_string(g[0].nodes) + "x" +
                                           std::to_string(g[1].nodes) + "x" +
                                           std::to_string(g[2].nodes) + " lattice (" +
                                           std::to_string(total) + " needed)");
  }
  return d;
}

TrackerLatticeData LoadTrackerLatticeCsv(const std::string& path) {
  return TrackerLatticeFromCsv(CsvTable::ParseFile(path));
}

TrackerLattice::TrackerLattice(TrackerLatticeData data) : data_(std::move(data)) {
  std::size_t total = 1;
  for (const GridAxis& a : data_.lattice) {
    if (a.nodes < 2 || !(a.spacing_mm > 0) || !std::isfinite(a.origin_mm)) {
      throw std::invalid_argument(
          "tracker lattice: every axis needs >= 2 nodes at a positive "
          "spacing");
    }
    total *= a.nodes;
  }
  if (data_.position_mm.size() != total) {
    throw std::invalid_argument("tracker lattice: " + std::to_string(data_.position_mm.size()) +
                                " readings for " + std::to_string(total) + " nodes");
  }
  for (const Vec3& p : data_.position_mm) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw std::invalid_argument("tracker lattice: a reading is not finite");
    }
  }
}

Vec3 TrackerLattice::Position_mm(const Vec3& command_mm) const {
  const GridAxes& g = data_.lattice;
  uint32_t cell[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const GridAxis& ax = g[static_cast<std::size_t>(a)];
    const double u = (command_mm[a] - ax.origin_mm) / ax.spacing_mm;
    const double c = std::fmin(std::fmax(std::floor(u), 0.0), static_cast<double>(ax.nodes - 2));
    cell[a] = static_cast<uint32_t>(c);
    f[a] = u - c;  // outside [0, 1] beyond the lattice: the boundary cell extrapolates
  }
  Vec3 p;
  for (uint32_t corner = 0; corner < 8; ++corner) {
    const uint32_t di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
    const double w = (di ? f[0] : 1 - f[0]) * (dj ? f[1] : 1 - f[1]) * (dk ? f[2] : 1 - f[2]);
    const std::size_t n =
        (static_cast<std::size_t>(cell[2] + dk) * g[1].nodes + cell[1] + dj) * g[0].nodes +
        cell[0] + di;
    p += w * data_.position_mm[n];
  }
  return p;
}

InverseSolution TrackerLattice::ExactInverse(const Vec3& target_mm, double tolerance_mm) const {
  const auto error_mm = [this](const Vec3& q) { return Position_mm(q) - q; };
  return InvertError(error_mm, target_mm, tolerance_mm);
}

}  // namespace volcomp::model
