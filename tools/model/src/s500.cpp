// The compiled-in STAN S500 model (data in s500_data.cpp).
#include "volcomp/model/s500.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "s500_data.hpp"

namespace volcomp::model {
namespace {

struct PrintedTable {
  const data::ParametricRow* rows;
  int count;
};

PrintedTable Printed(int axis) {
  switch (axis) {
    case 0:
      return {data::kTable3_2, 21};
    case 1:
      return {data::kTable3_3, 29};
    case 2:
      return {data::kTable3_4, 21};
    default:
      throw std::out_of_range("S500: axis must be 0, 1 or 2");
  }
}

}  // namespace

AxisErrorTable S500AxisTable(int axis) {
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
  return AxisErrorTable(std::move(pos), std::move(rows));
}

std::array<AxisErrorTable, 3> S500AxisTables() {
  return {S500AxisTable(0), S500AxisTable(1), S500AxisTable(2)};
}

PointErrors S500PointErrorsAtNode(int nx, int ny, int nz) {
  const int n[3] = {nx, ny, nz};
  PointErrors p{};
  for (int a = 0; a < 3; ++a) {
    const PrintedTable t = Printed(a);
    if (n[a] < 0 || n[a] >= t.count) {
      throw std::out_of_range(std::string("S500: no row ") + std::to_string(n[a]) + " on axis " +
                              "XYZ"[a]);
    }
    for (int j = 0; j < 3; ++j) {
      p.delta_um[a][j] = t.rows[n[a]].delta_um[j];
      p.eps_um_per_mm[a][j] = t.rows[n[a]].eps_um_per_mm[j];
    }
  }
  return p;
}

PointErrors S500MaxErrors() { return data::kTable3_5; }
PointErrors S500MinErrors() { return data::kTable3_6; }

Squareness S500Squareness() {
  Squareness s;
  s.c0y_urad = -1108.5;
  s.b0z_urad = 455.0;
  s.a0z_urad = -520.9;
  return s;
}

Model S500Model(const S500Options& options) {
  Model m;
  m.name = "STAN S500 (Pimushkin 2023, Tables 3.2-3.4)";
  m.axes = S500AxisTables();
  if (options.include_squareness) m.squareness = S500Squareness();
  m.tool_offset_mm = options.tool_offset_mm;
  m.chain = options.chain;
  m.order = options.order;
  m.formulation = Formulation::kPhysical;
  return m;
}

Model S500DissertationModel(Order order, DissertationCase which, double k) {
  Model m;
  m.name = "STAN S500, dissertation formulation (eqs. 3.8-3.10)";
  m.axes = S500AxisTables();
  m.tool_offset_mm = {10.0, 10.0, 10.0};
  m.formulation = Formulation::kDissertation;
  m.order = order;
  m.dissertation_case = which;
  m.angle_scale = k;
  return m;
}

}  // namespace volcomp::model
