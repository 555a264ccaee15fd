// Compensation table from the parametric measurements.
#include "volcomp/sim/table_from_measurements.hpp"

#include <cstdio>
#include <fstream>

#include "volcomp/byte_order.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/model/grid_section.hpp"
#include "volcomp/model/image_glue.hpp"

namespace volcomp::sim {

SimResult<model::Model> ModelFromParametric(const std::array<ParametricResult, 3>& runs,
                                            const model::KinematicChain& chain) {
  model::Model m;
  m.name = "measured (virtual 6-DOF laser, parametric runs through the reference point)";
  for (int a = 0; a < 3; ++a) {
    const ParametricResult& r = runs[static_cast<size_t>(a)];
    if (r.axis != a) {
      return SimStatus(Error::kInvalidArgument, "parametric runs are not X, Y, Z in order");
    }
    std::vector<model::AxisErrorSample> rows;
    for (const SixDofReading& s : r.measured) rows.push_back({s.linear_um, s.angular_urad});
    m.axes[static_cast<size_t>(a)] = model::AxisErrorTable(r.position_mm, rows);
  }
  m.chain = chain;
  m.chain.workpiece_errors = model::ErrorSide::kRelative;  // measured tool vs workpiece
  m.formulation = model::Formulation::kPhysical;
  m.order = model::Order::kSecond;
  model::ValidateModel(m);
  return m;
}

TableBuildResult BuildTableImage(const model::Model& measured,
                                 const std::array<double, 3>& lo_mm,
                                 const std::array<double, 3>& hi_mm,
                                 const std::array<double, 3>& spacing_mm,
                                 const std::array<double, 3>& step_mm,
                                 uint32_t table_id) {
  model::GridBuildOptions o;
  o.min_mm = lo_mm;
  o.max_mm = hi_mm;
  o.spacing_mm = spacing_mm;
  o.natural_spacing_mm = spacing_mm;
  o.step_mm = step_mm;
  image::ImageRequest req;
  req.table_id = table_id;
  for (int a = 0; a < 3; ++a) {
    image::AxisDef d;
    d.name = "XYZ"[a];
    d.kind = table::AxisKind::kLinear;
    d.resolution_e9 = static_cast<uint32_t>(std::llround(step_mm[static_cast<size_t>(a)] * 1e9));
    req.axes.push_back(d);
  }
  // `volcomp build model`'s source and grid building blocks.
  model::GridSection g = model::BuildGridSection(o, req.axes, model::ModelGridSource(measured));
  TableBuildResult r;
  r.grid = std::move(g.build);
  req.grid = std::move(g.section);
  req.element = table::ElementType::kInt16;
  req.frac_bits = image::ChooseFracBits(req);
  r.frac_bits = *req.frac_bits;
  r.lsb_um = model::LsbUm(req.axes[0], r.frac_bits);
  r.info = std::move(g.info);
  r.info.emplace("builder", "volcomp-sim demo (the sources and grid of `volcomp build model`)");
  r.info.emplace("source", "measured 21-parameter model: 6-DOF laser runs of X, Y, Z");
  req.info = r.info;
  r.image = image::BuildImage(req);
  r.crc32 = LoadLe32(r.image.data() + r.image.size() - 4);
  return r;
}

SimStatus WriteModelFiles(const model::Model& measured, const std::string& dir) {
  const auto cannot = [&](const std::string& name) {
    return SimStatus(Error::kIoError, "cannot write " + dir + "/" + name);
  };
  for (int a = 0; a < 3; ++a) {
    const std::string name = std::string("measured_") + "xyz"[a] + ".csv";
    std::ofstream f(dir + "/" + name);
    if (!f) return cannot(name);
    f << "# " << static_cast<char>("XYZ"[a])
      << " axis, measured by volcomp-sim demo (virtual 6-DOF laser), zero at the reference point\n";
    f << "position_mm,ex_um,ey_um,ez_um,ea_urad,eb_urad,ec_urad\n";
    const model::AxisErrorTable& t = measured.axes[static_cast<size_t>(a)];
    for (size_t i = 0; i < t.size(); ++i) {
      const model::AxisErrorSample& s = t.row(i);
      char line[256];
      std::snprintf(line, sizeof line, "%.4f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f\n", t.position_mm(i),
                    s.linear_um.x, s.linear_um.y, s.linear_um.z, s.angular_urad.x, s.angular_urad.y,
                    s.angular_urad.z);
      f << line;
    }
  }
  std::ofstream c(dir + "/measured.conf");
  if (!c) return cannot("measured.conf");
  std::string workpiece, tool;
  for (int a : measured.chain.order) {
    (measured.chain.carries_workpiece[static_cast<size_t>(a)] ? workpiece : tool) += "XYZ"[a];
  }
  c << "# Measured by volcomp-sim demo: six error motions per axis through the reference point.\n"
    << "# Squareness is contained in the straightness columns (beam aligned with the nominal "
       "axes).\n"
    << "name = " << measured.name << "\n"
    << "axis_x = measured_x.csv\naxis_y = measured_y.csv\naxis_z = measured_z.csv\n"
    << "squareness_c0y_urad = 0\nsquareness_b0z_urad = 0\nsquareness_a0z_urad = 0\n"
    << "tool_offset_mm = 0, 0, 0\n"
    << "workpiece_axes = " << workpiece << "\ntool_axes = " << tool << "\n"
    << "workpiece_errors = relative\nformulation = physical\norder = exact\n";
  return SimStatus::Ok();
}

}  // namespace volcomp::sim
