// A GRID3 from corrections at the nodes of a lattice (see node_grid.hpp).
#include "volcomp/builders/node_grid.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>

#include "volcomp/image/axis_units.hpp"

namespace volcomp::builders {
namespace {

using image::AxisDef;
using tools::CsvRow;
using tools::CsvTable;

// A lattice position is an int32 step count (the image's origin_steps): a value beyond it is
// refused where it is read, before any arithmetic on it.
Expected<int64_t> WithinStepRange(const CsvTable& csv,
                                  const CsvRow& row,
                                  const std::string& column,
                                  double steps) {
  if (std::fabs(steps) <= INT32_MAX) return static_cast<int64_t>(steps);
  VOLCOMP_TRY_ASSIGN(const std::string text, row.Text(column));
  return Fail(csv.LineFailure(row.line(), "column \"" + column + "\": " + text +
                                              " is beyond the lattice's step range (at most " +
                                              std::to_string(INT32_MAX) + " steps from 0)"));
}

// Reads a position column (mm/deg or steps) of `row` as whole steps.
Expected<int64_t> PositionSteps(const CsvTable& csv, const CsvRow& row, const AxisDef& axis) {
  const std::string base = image::ColumnName(axis.name);
  const std::string unit_col = base + (axis.kind == table::AxisKind::kRotary ? "_deg" : "_mm");
  if (csv.find(base + "_steps")) {
    VOLCOMP_TRY_ASSIGN(const long long steps, row.Integer(base + "_steps"));
    return WithinStepRange(csv, row, base + "_steps", static_cast<double>(steps));
  }
  VOLCOMP_TRY_ASSIGN(const double v, row.Number(unit_col));
  const double steps = v / axis.units_per_step();
  const double rounded = std::round(steps);
  if (std::fabs(steps - rounded) > 1e-6) {
    VOLCOMP_TRY_ASSIGN(const std::string text, row.Text(unit_col));
    return Fail(csv.LineFailure(
        row.line(), "column \"" + unit_col + "\": " + text + " is not a whole number of steps (" +
                        std::to_string(axis.units_per_step()) + " per step)"));
  }
  return WithinStepRange(csv, row, unit_col, rounded);
}

Expected<double> CorrectionSteps(const CsvTable& csv, const CsvRow& row, const AxisDef& axis) {
  const std::string base = "d" + image::ColumnName(axis.name);
  if (csv.find(base + "_steps")) return row.Number(base + "_steps");
  if (axis.kind == table::AxisKind::kRotary) {
    VOLCOMP_TRY_ASSIGN(const double arcsec, row.Number(base + "_arcsec"));
    return arcsec / 3600.0 / axis.units_per_step();
  }
  VOLCOMP_TRY_ASSIGN(const double um, row.Number(base + "_um"));
  return um * 1e-3 / axis.units_per_step();
}

Expected<image::Lattice> LatticeOf(const CsvTable& csv,
                                   const std::set<int64_t>& values,
                                   char axis) {
  const std::string name = std::string("axis ") + axis;
  if (values.size() < 2) {
    return Fail(csv.LineFailure(csv.header_line(), name + " needs at least 2 node positions"));
  }
  std::vector<int64_t> v(values.begin(), values.end());
  const int64_t spacing = v[1] - v[0];
  for (size_t i = 2; i < v.size(); ++i) {
    if (v[i] - v[i - 1] != spacing) {
      return Fail(csv.LineFailure(csv.header_line(),
                                  name + " nodes are not equally spaced (steps " +
                                      std::to_string(v[i - 1]) + " to " + std::to_string(v[i]) +
                                      " vs spacing " + std::to_string(spacing) + ")"));
    }
  }
  if (v.front() < INT32_MIN || v.back() > INT32_MAX) {
    return Fail(csv.LineFailure(csv.header_line(), name + " positions exceed int32 steps"));
  }
  return image::Lattice{static_cast<uint32_t>(v.size()), static_cast<int32_t>(v.front()),
                        static_cast<uint32_t>(spacing)};
}

}  // namespace

Expected<image::GridCorrections> NodeGridFromCsv(const CsvTable& csv,
                                                 const std::vector<AxisDef>& axes) {
  if (csv.rows().empty()) return Fail(csv.LineFailure(csv.header_line(), "no data rows"));
  // Pass 1: read every row (failures by line), collect node positions per axis.
  const std::size_t rows = csv.rows().size();
  std::vector<std::array<int64_t, 3>> pos(rows);
  std::vector<std::array<double, 3>> corr(rows);
  std::array<std::set<int64_t>, 3> values;
  for (size_t r = 0; r < rows; ++r) {
    for (int d = 0; d < 3; ++d) {
      VOLCOMP_TRY_ASSIGN(pos[r][d], PositionSteps(csv, csv.rows()[r], axes[d]));
      VOLCOMP_TRY_ASSIGN(corr[r][d], CorrectionSteps(csv, csv.rows()[r], axes[d]));
      values[d].insert(pos[r][d]);
    }
  }
  image::GridCorrections grid;
  for (int d = 0; d < 3; ++d) {
    VOLCOMP_TRY_ASSIGN(grid.lattice[d], LatticeOf(csv, values[d], axes[d].name));
  }
  const uint64_t n0 = grid.lattice[0].nodes, n1 = grid.lattice[1].nodes, n2 = grid.lattice[2].nodes;
  if (n0 * n1 * n2 != rows) {
    return Fail(csv.LineFailure(csv.header_line(),
                                "lattice " + std::to_string(n0) + "x" + std::to_string(n1) + "x" +
                                    std::to_string(n2) + " needs " + std::to_string(n0 * n1 * n2) +
                                    " rows, found " + std::to_string(rows)));
  }
  // Pass 2: corrections into their node slots; every node exactly once.
  grid.correction_steps.assign(n0 * n1 * n2 * 3, 0.0);
  std::vector<size_t> line_of(n0 * n1 * n2, 0);
  for (size_t r = 0; r < rows; ++r) {
    const CsvRow& row = csv.rows()[r];
    uint64_t idx[3];
    for (int d = 0; d < 3; ++d) {
      idx[d] = static_cast<uint64_t>((pos[r][d] - grid.lattice[d].origin_steps) /
                                     grid.lattice[d].spacing_steps);
    }
    const uint64_t node = (idx[2] * n1 + idx[1]) * n0 + idx[0];
    if (line_of[node] != 0) {
      return Fail(
          csv.LineFailure(row.line(), "node repeats line " + std::to_string(line_of[node])));
    }
    line_of[node] = row.line();
    for (int c = 0; c < 3; ++c) grid.correction_steps[node * 3 + c] = corr[r][c];
  }
  return grid;
}

}  // namespace volcomp::builders
