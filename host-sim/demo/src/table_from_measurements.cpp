// Compensation table from the parametric measurements.
#include "volcomp/sim/table_from_measurements.hpp"

#include <cstdio>
#include <fstream>
#include <utility>

#include "volcomp/base/byte_order.hpp"
#include "volcomp/builders/grid_section.hpp"
#include "volcomp/builders/grid_source.hpp"
#include "volcomp/builders/image_glue.hpp"
#include "volcomp/builders/image_grid.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/image/image_join.hpp"
#include "volcomp/image/image_reader.hpp"

namespace volcomp::sim {

Expected<model::Model> ModelFromParametric(const std::array<ParametricResult, 3>& runs,
                                           const model::KinematicChain& chain) {
  model::Model m;
  m.name = "measured (virtual 6-DOF laser, parametric runs through the reference point)";
  for (int a = 0; a < 3; ++a) {
    const ParametricResult& r = runs[static_cast<size_t>(a)];
    if (r.axis != a) {
      return Fail(Error::kInvalidArgument, "parametric runs are not X, Y, Z in order");
    }
    std::vector<model::AxisErrorSample> rows;
    for (const SixDofReading& s : r.measured) rows.push_back({s.linear_um, s.angular_urad});
    VOLCOMP_TRY_ASSIGN(m.axes[static_cast<size_t>(a)],
                       model::AxisErrorTable::Create(r.position_mm, rows));
  }
  m.chain = chain;
  m.chain.workpiece_errors = model::ErrorSide::kRelative;  // measured tool vs workpiece
  m.formulation = model::Formulation::kPhysical;
  m.order = model::Order::kSecond;
  VOLCOMP_TRY(model::ValidateModel(m));
  return m;
}

std::vector<image::AxisDef> ImageAxes(const std::array<double, 3>& step_mm) {
  std::vector<image::AxisDef> axes;
  for (int a = 0; a < 3; ++a) {
    image::AxisDef d;
    d.name = "XYZ"[a];
    d.kind = table::AxisKind::kLinear;
    d.resolution_e9 = static_cast<uint32_t>(std::llround(step_mm[static_cast<size_t>(a)] * 1e9));
    axes.push_back(d);
  }
  return axes;
}

builders::GridBuildOptions LatticeOptions(const std::array<double, 3>& lo_mm,
                                          const std::array<double, 3>& hi_mm,
                                          const std::array<double, 3>& spacing_mm,
                                          const std::array<double, 3>& step_mm) {
  builders::GridBuildOptions o;
  o.min_mm = lo_mm;
  o.max_mm = hi_mm;
  o.spacing_mm = spacing_mm;
  o.natural_spacing_mm = spacing_mm;
  o.step_mm = step_mm;
  return o;
}

model::PositioningData MeanDeviations(const metrology::PositioningResult& run) {
  model::PositioningData d;
  for (const metrology::PositionStats& p : run.positions) {
    if (!p.up || !p.down) continue;
    d.position.push_back(p.target);
    d.dev_forward.push_back(p.up->mean);
    d.dev_reverse.push_back(p.down->mean);
  }
  return d;
}

model::PositioningData PairMeans(const model::PositioningData& t) {
  model::PositioningData d;
  d.rotary = t.rotary;
  for (size_t i = 0; i + 1 < t.position.size(); i += 2) {
    d.position.push_back(0.5 * (t.position[i] + t.position[i + 1]));
    d.dev_forward.push_back(0.5 * (t.dev_forward[i] + t.dev_forward[i + 1]));
    d.dev_reverse.push_back(0.5 * (t.dev_reverse[i] + t.dev_reverse[i + 1]));
  }
  return d;
}

Expected<TableBuildResult> AssembleTable(const std::optional<builders::GridSection>& grid,
                                         const std::vector<builders::AxisSection>& axis_tables,
                                         const std::array<double, 3>& step_mm,
                                         uint32_t table_id,
                                         const std::map<std::string, std::string>& info) {
  if (grid && !axis_tables.empty()) {
    // Both: one image each, joined as `volcomp build image --grid --axis` joins them.
    VOLCOMP_TRY_ASSIGN(TableBuildResult r, AssembleTable(grid, {}, step_mm, table_id, info));
    VOLCOMP_TRY_ASSIGN(const TableBuildResult a,
                       AssembleTable(std::nullopt, axis_tables, step_mm, table_id, info));
    VOLCOMP_TRY_ASSIGN(const image::LoadedImage grid_image,
                       image::LoadedImage::FromBytes(r.image, "GRID3"));
    VOLCOMP_TRY_ASSIGN(const image::LoadedImage axis_image,
                       image::LoadedImage::FromBytes(a.image, "AXIS1D"));
    image::JoinOptions join;
    join.info = info;
    VOLCOMP_TRY_ASSIGN(const image::JoinedImage joined,
                       image::JoinImages({"GRID3", &grid_image}, {"AXIS1D", &axis_image}, join));
    r.axis_tables = axis_tables;
    r.image = joined.bytes;
    r.crc32 = LoadLe32(r.image.data() + r.image.size() - 4);
    return r;
  }
  TableBuildResult r;
  r.grid = grid;
  r.axis_tables = axis_tables;
  image::ImageRequest req;
  req.table_id = table_id;
  req.axes = ImageAxes(step_mm);
  if (grid) {
    req.grid = grid->section;
    r.info = grid->info;
  }
  for (const builders::AxisSection& a : axis_tables) req.axis_tables.push_back(a.section);
  for (const auto& [k, v] : info) r.info[k] = v;
  req.element = table::ElementType::kInt16;
  VOLCOMP_TRY_ASSIGN(req.frac_bits, image::ChooseFracBits(req));
  r.frac_bits = *req.frac_bits;
  r.lsb_um = builders::LsbUm(req.axes[0], r.frac_bits);
  req.info = r.info;
  VOLCOMP_TRY_ASSIGN(r.image, image::BuildImage(req));
  r.crc32 = LoadLe32(r.image.data() + r.image.size() - 4);
  return r;
}

Expected<builders::GridSection> BuildModelGridSection(const model::Model& measured,
                                                      const builders::GridBuildOptions& lattice) {
  return builders::BuildGridSection(lattice, ImageAxes(lattice.step_mm),
                                    builders::ModelGridSource(measured));
}

Expected<TableBuildResult> BuildTableImage(const model::Model& measured,
                                           const builders::GridBuildOptions& lattice,
                                           uint32_t table_id) {
  VOLCOMP_TRY_ASSIGN(builders::GridSection g, BuildModelGridSection(measured, lattice));
  return AssembleTable(
      std::move(g), {}, lattice.step_mm, table_id,
      {{"builder", "volcomp-sim demo (the sources and grid of `volcomp build model`)"},
       {"source", "measured 21-parameter model: 6-DOF laser runs of X, Y, Z"}});
}

Expected<builders::AxisSection> BuildAxisTable(const model::PositioningData& deviations,
                                               int axis,
                                               double spacing_mm,
                                               const std::array<double, 3>& step_mm) {
  builders::Axis1dOptions o;
  o.reverse = builders::ReverseMode::kBacklash;
  o.spacing = spacing_mm;
  const image::AxisDef image_axis = ImageAxes(step_mm)[static_cast<size_t>(axis)];
  return builders::BuildAxisSection(deviations, o, image_axis, static_cast<uint8_t>(axis), false);
}

Expected<builders::GridSection> BuildTrackerLatticeGridSection(
    const model::TrackerLatticeData& readings,
    const std::vector<uint8_t>& in_force,
    const builders::GridBuildOptions& grid) {
  VOLCOMP_TRY_ASSIGN(const image::LoadedImage table_in_force,
                     image::LoadedImage::FromBytes(in_force, "table 2"));
  VOLCOMP_TRY_ASSIGN(const model::TrackerLattice through, model::TrackerLattice::Create(readings));
  VOLCOMP_TRY_ASSIGN(const model::CorrectionGrid table2,
                     builders::GridOfImage(table_in_force, "table 2"));
  return builders::BuildGridSection(grid, ImageAxes(grid.step_mm),
                                    builders::TrackerLatticeThroughGridSource(through, table2));
}

Outcome WriteModelFiles(const model::Model& measured, const std::string& dir) {
  const auto cannot = [&](const std::string& name) {
    return Fail(Error::kIoError, "cannot write " + dir + "/" + name);
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
  return Outcome::Ok();
}

}  // namespace volcomp::sim
