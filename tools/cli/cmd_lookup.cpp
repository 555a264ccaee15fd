// `volcomp lookup IMAGE`: the table's correction at points, computed by the firmware's lookup code.
//
// Input CSV (stdin, or --points FILE): per image axis a position column, <x>_steps or <x>_mm
// (<a>_deg for rotary axes), and optionally dir_<x> (+1 forward, -1 reverse; default +1) for axes
// with AXIS1D tables. Output CSV (stdout): <x>_steps per axis, then per axis d<x>_steps (exact Q8
// value) and d<x>_um (d<a>_arcsec for rotary axes). Positions given in mm are rounded to steps.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::tools {

int RunLookup(Args& args) {
  const auto points_path = args.value("--points");
  const auto pos = args.positionals();
  args.finish();
  if (pos.size() != 1) throw UsageError("expected one IMAGE file");
  const image::LoadedImage img = image::LoadImageFile(pos[0]);
  const image::ImageEvaluator eval(img);
  const table::TableView& v = img.view();
  const CsvTable csv =
      points_path ? CsvTable::ParseFile(*points_path) : CsvTable::Parse(std::cin, "<stdin>");

  // Column per axis.
  struct AxisColumns {
    std::string pos;
    bool in_steps;
    double units_per_step;
    std::string dir;
  };
  std::vector<AxisColumns> cols;
  for (uint8_t a = 0; a < v.axis_count; ++a) {
    const std::string base = image::ColumnName(v.axes[a].name);
    const bool rotary = v.axes[a].kind == table::AxisKind::kRotary;
    AxisColumns c{base + "_steps", true, v.axes[a].resolution_e9 * 1e-9, ""};
    if (!csv.find(c.pos)) {
      c.pos = base + (rotary ? "_deg" : "_mm");
      c.in_steps = false;
      if (!csv.find(c.pos)) {
        throw csv.error(csv.header_line(), "missing column \"" + base + "_steps\" or \"" + c.pos +
                                               "\" for axis " + std::string(1, v.axes[a].name));
      }
    }
    if (csv.find("dir_" + base)) c.dir = "dir_" + base;
    cols.push_back(c);
  }

  for (uint8_t a = 0; a < v.axis_count; ++a) {
    std::cout << (a ? "," : "") << image::ColumnName(v.axes[a].name) << "_steps";
  }
  for (uint8_t a = 0; a < v.axis_count; ++a) {
    const std::string d = "d" + image::ColumnName(v.axes[a].name);
    std::cout << "," << d << "_steps," << d
              << (v.axes[a].kind == table::AxisKind::kRotary ? "_arcsec" : "_um");
  }
  std::cout << "\n";

  for (const CsvRow& row : csv.rows()) {
    int32_t p[table::kMaxAxes] = {};
    bool reverse[table::kMaxAxes] = {};
    for (uint8_t a = 0; a < v.axis_count; ++a) {
      double steps = cols[a].in_steps
                         ? static_cast<double>(row.integer(cols[a].pos))
                         : std::round(row.number(cols[a].pos) / cols[a].units_per_step);
      if (steps < INT32_MIN || steps > INT32_MAX) {
        throw csv.error(row.line(), "column \"" + cols[a].pos + "\": position outside int32 steps");
      }
      p[a] = static_cast<int32_t>(steps);
      if (!cols[a].dir.empty()) {
        const long long d = row.integer(cols[a].dir);
        if (d != 1 && d != -1)
          throw csv.error(row.line(), "column \"" + cols[a].dir + "\": use +1 or -1");
        reverse[a] = d < 0;
      }
    }
    int32_t q8[table::kMaxAxes];
    eval.CorrectionQ8(p, reverse, q8);
    for (uint8_t a = 0; a < v.axis_count; ++a) std::cout << (a ? "," : "") << p[a];
    for (uint8_t a = 0; a < v.axis_count; ++a) {
      const double steps = q8[a] / 256.0;
      const double unit = v.axes[a].kind == table::AxisKind::kRotary
                              ? cols[a].units_per_step * 3600.0
                              : cols[a].units_per_step * 1000.0;
      char buf[64];
      std::snprintf(buf, sizeof buf, ",%.8f,%.6f", steps, steps * unit);
      std::cout << buf;
    }
    std::cout << "\n";
  }
  return 0;
}

}  // namespace volcomp::tools
