// `volcomp build grid`: a GRID3 image from corrections given at the nodes of a regular lattice.
//
// CSV columns (header names, any order; extra columns ignored):
//   positions:   x_mm, y_mm, z_mm  (or x_steps, y_steps, z_steps; lower-case grid axis names)
//   corrections: dx_um, dy_um, dz_um  (or dx_steps, ...): the correction ADDED to the command,
//                i.e. command_out = command_in + correction (minus the measured error).
// Every node of the lattice must appear exactly once; node positions must be whole steps and
// equally spaced per axis.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <set>

#include "commands.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/model/build_cli.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::tools {
namespace {

using image::AxisDef;

// Reads a position column (mm/deg or steps) of `row` as whole steps.
int64_t PositionSteps(const CsvTable& csv, const CsvRow& row, const AxisDef& axis) {
  const std::string base = image::ColumnName(axis.name);
  const std::string unit_col = base + (axis.kind == table::AxisKind::kRotary ? "_deg" : "_mm");
  if (csv.find(base + "_steps")) {
    return row.integer(base + "_steps");
  }
  const double v = row.number(unit_col);
  const double steps = v / axis.units_per_step();
  const double rounded = std::round(steps);
  if (std::fabs(steps - rounded) > 1e-6) {
    throw csv.error(row.line(), "column \"" + unit_col + "\": " + row.text(unit_col) +
                                    " is not a whole number of steps (" +
                                    std::to_string(axis.units_per_step()) + " per step)");
  }
  return static_cast<int64_t>(rounded);
}

double CorrectionSteps(const CsvTable& csv, const CsvRow& row, const AxisDef& axis) {
  const std::string base = "d" + image::ColumnName(axis.name);
  if (csv.find(base + "_steps")) return row.number(base + "_steps");
  if (axis.kind == table::AxisKind::kRotary) {
    return row.number(base + "_arcsec") / 3600.0 / axis.units_per_step();
  }
  return row.number(base + "_um") * 1e-3 / axis.units_per_step();
}

image::Lattice LatticeOf(const CsvTable& csv, const std::set<int64_t>& values, char axis) {
  if (values.size() < 2) {
    throw csv.error(csv.header_line(),
                    std::string("axis ") + axis + " needs at least 2 node positions");
  }
  std::vector<int64_t> v(values.begin(), values.end());
  const int64_t spacing = v[1] - v[0];
  for (size_t i = 2; i < v.size(); ++i) {
    if (v[i] - v[i - 1] != spacing) {
      throw csv.error(csv.header_line(),
                      std::string("axis ") + axis + " nodes are not equally spaced (steps " +
                          std::to_string(v[i - 1]) + " to " + std::to_string(v[i]) +
                          " vs spacing " + std::to_string(spacing) + ")");
    }
  }
  if (v.front() < INT32_MIN || v.back() > INT32_MAX) {
    throw csv.error(csv.header_line(),
                    std::string("axis ") + axis + " positions exceed int32 steps");
  }
  return {static_cast<uint32_t>(v.size()), static_cast<int32_t>(v.front()),
          static_cast<uint32_t>(spacing)};
}

}  // namespace

int RunBuildGrid(Args& args) {
  const std::string csv_path = args.required("--csv");
  const std::string out_path = args.required("-o", "--output");
  const std::vector<char> names =
      image::ParseAxisList(args.value("--axes").value_or("X,Y,Z"), "--axes");
  if (names.size() != 3) throw UsageError("--axes: GRID3 needs exactly three axes");
  image::ImageRequest req;
  req.axes = image::MakeAxisDefs(names, args.value("--resolution-nm").value_or(""),
                                 args.value("--steps-per-unit").value_or(""));
  model::cli::ParseImageOptions(args, &req);
  args.finish();

  const CsvTable csv = CsvTable::ParseFile(csv_path);
  if (csv.rows().empty()) throw csv.error(csv.header_line(), "no data rows");
  // Pass 1: read every row (errors by line), collect node positions per axis.
  std::vector<std::array<int64_t, 3>> pos(csv.rows().size());
  std::vector<std::array<double, 3>> corr(csv.rows().size());
  std::array<std::set<int64_t>, 3> values;
  for (size_t r = 0; r < csv.rows().size(); ++r) {
    for (int d = 0; d < 3; ++d) {
      pos[r][d] = PositionSteps(csv, csv.rows()[r], req.axes[d]);
      corr[r][d] = CorrectionSteps(csv, csv.rows()[r], req.axes[d]);
      values[d].insert(pos[r][d]);
    }
  }
  image::GridCorrections grid;
  for (int d = 0; d < 3; ++d) grid.lattice[d] = LatticeOf(csv, values[d], names[d]);
  const uint64_t n0 = grid.lattice[0].nodes, n1 = grid.lattice[1].nodes, n2 = grid.lattice[2].nodes;
  if (n0 * n1 * n2 != csv.rows().size()) {
    throw csv.error(csv.header_line(), "lattice " + std::to_string(n0) + "x" + std::to_string(n1) +
                                           "x" + std::to_string(n2) + " needs " +
                                           std::to_string(n0 * n1 * n2) + " rows, found " +
                                           std::to_string(csv.rows().size()));
  }
  // Pass 2: corrections into their node slots; every node exactly once.
  grid.correction_steps.assign(n0 * n1 * n2 * 3, 0.0);
  std::vector<size_t> line_of(n0 * n1 * n2, 0);
  for (size_t r = 0; r < csv.rows().size(); ++r) {
    const CsvRow& row = csv.rows()[r];
    uint64_t idx[3];
    for (int d = 0; d < 3; ++d) {
      idx[d] = static_cast<uint64_t>((pos[r][d] - grid.lattice[d].origin_steps) /
                                     grid.lattice[d].spacing_steps);
    }
    const uint64_t node = (idx[2] * n1 + idx[1]) * n0 + idx[0];
    if (line_of[node] != 0) {
      throw csv.error(row.line(), "node repeats line " + std::to_string(line_of[node]));
    }
    line_of[node] = row.line();
    for (int c = 0; c < 3; ++c) grid.correction_steps[node * 3 + c] = corr[r][c];
  }
  req.grid = grid;
  req.info.emplace("source", csv_path);
  const std::vector<uint8_t> image = image::BuildImage(req);
  image::WriteFileBytes(out_path, image);
  std::cerr << "wrote " << out_path << ": " << image.size() << " bytes, " << n0 << "x" << n1 << "x"
            << n2 << " nodes\n";
  return 0;
}

}  // namespace volcomp::tools
