// The compiled-in STAN S500 model and tracker lines (data in s500_data.cpp).
#include "volcomp/datasets/s500.hpp"

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "s500_data.hpp"

namespace volcomp::datasets {
namespace {

using model::AxisErrorSample;
using model::AxisErrorTable;

struct PrintedTable {
  const data::ParametricRow* rows;
  int count;
};

// Table 3.2, 3.3 or 3.4; axis must be 0, 1 or 2.
PrintedTable Printed(int axis) {
  switch (axis) {
    case 0:
      return {data::kTable3_2, 21};
    case 1:
      return {data::kTable3_3, 29};
    default:
      return {data::kTable3_4, 21};
  }
}

template <std::size_t N>
std::vector<model::TrackerNode> Line(const data::TrackerRow (&rows)[N], int axis) {
  std::vector<model::TrackerNode> out;
  for (const data::TrackerRow& r : rows) {
    model::TrackerNode n;
    n.q_mm = r.cmd_mm[axis];
    n.p_mm = {r.tracker_mm[0], r.tracker_mm[1], r.tracker_mm[2]};
    n.printed_cos = {r.cos[0], r.cos[1], r.cos[2]};
    out.push_back(n);
  }
  return out;
}

// Lines X, Y, Z of a printed tracker data set, with the direction cosines the tables print.
model::TrackerData PrintedTracker(std::string name,
                                  std::array<std::vector<model::TrackerNode>, 3> lines) {
  model::TrackerData d;
  d.name = std::move(name);
  d.lines = std::move(lines);
  d.has_printed_cosines = true;
  return d;
}

}  // namespace

Expected<AxisErrorTable> S500AxisTable(int axis) {
  if (axis < 0 || axis > 2) return Fail(Error::kInvalidArgument, "S500: axis must be 0, 1 or 2");
  const PrintedTable t = Printed(axis);
  std::vector<double> pos;
  std::vector<AxisErrorSample> rows;
  for (int i = 0; i < t.count; ++i) {
    const data::ParametricRow& r = t.rows[i];
    pos.push_back(r.position_mm);
    rows.push_back(
        {{r.delta_um[0], r.delta_um[1], r.delta_um[2]},
         {1e3 * r.eps_um_per_mm[0], 1e3 * r.eps_um_per_mm[1], 1e3 * r.eps_um_per_mm[2]}});
  }
  return AxisErrorTable::Create(std::move(pos), std::move(rows));
}

std::array<AxisErrorTable, 3> S500AxisTables() {
  // The printed tables are valid tables (tested), so the values are there.
  return {S500AxisTable(0).value(), S500AxisTable(1).value(), S500AxisTable(2).value()};
}

Expected<model::PointErrors> S500PointErrorsAtNode(int nx, int ny, int nz) {
  const int n[3] = {nx, ny, nz};
  model::PointErrors p{};
  for (int a = 0; a < 3; ++a) {
    const PrintedTable t = Printed(a);
    if (n[a] < 0 || n[a] >= t.count) {
      return Fail(Error::kInvalidArgument,
                  std::string("S500: no row ") + std::to_string(n[a]) + " on axis " + "XYZ"[a]);
    }
    for (int j = 0; j < 3; ++j) {
      p.delta_um[a][j] = t.rows[n[a]].delta_um[j];
      p.eps_um_per_mm[a][j] = t.rows[n[a]].eps_um_per_mm[j];
    }
  }
  return p;
}

model::PointErrors S500MaxErrors() { return data::kTable3_5; }
model::PointErrors S500MinErrors() { return data::kTable3_6; }

model::Squareness S500Squareness() {
  model::Squareness s;
  s.c0y_urad = -1108.5;
  s.b0z_urad = 455.0;
  s.a0z_urad = -520.9;
  return s;
}

model::Model S500Model(const S500Options& options) {
  model::Model m;
  m.name = "STAN S500 (Pimushkin 2023, Tables 3.2-3.4)";
  m.axes = S500AxisTables();
  if (options.include_squareness) m.squareness = S500Squareness();
  m.tool_offset_mm = options.tool_offset_mm;
  m.chain = options.chain;
  m.order = options.order;
  m.formulation = model::Formulation::kPhysical;
  return m;
}

model::Model S500DissertationModel(model::Order order, model::DissertationCase which, double k) {
  model::Model m;
  m.name = "STAN S500, dissertation formulation (eqs. 3.8-3.10)";
  m.axes = S500AxisTables();
  m.tool_offset_mm = {10.0, 10.0, 10.0};
  m.formulation = model::Formulation::kDissertation;
  m.order = order;
  m.dissertation_case = which;
  m.angle_scale = k;
  return m;
}

model::TrackerData S500Tracker315() {
  return PrintedTracker(
      "STAN S500 laser tracker, 315 mm cube (Tables 2.10-2.12)",
      {Line(data::kTable2_10, 0), Line(data::kTable2_11, 1), Line(data::kTable2_12, 2)});
}

model::TrackerData S500Tracker240() {
  return PrintedTracker(
      "STAN S500 laser tracker, 240 mm cube (Tables 2.6-2.8)",
      {Line(data::kTable2_6, 0), Line(data::kTable2_7, 1), Line(data::kTable2_8, 2)});
}

std::optional<model::TrackerData> S500TrackerNamed(const std::string& name) {
  if (name == "s500-315") return S500Tracker315();
  if (name == "s500-240") return S500Tracker240();
  return std::nullopt;
}

}  // namespace volcomp::datasets
