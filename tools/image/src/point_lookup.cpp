// Corrections at points read from a CSV (see point_lookup.hpp).
#include "volcomp/image/point_lookup.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "volcomp/image/axis_units.hpp"

namespace volcomp::image {

Expected<PointLookup> PointLookup::Create(const LoadedImage& image, const tools::CsvTable& points) {
  VOLCOMP_TRY_ASSIGN(ImageEvaluator evaluator, ImageEvaluator::Create(image));
  PointLookup lookup(std::move(evaluator), points.source());
  const table::TableView& v = image.view();
  for (uint8_t a = 0; a < v.axis_count; ++a) {
    const std::string base = ColumnName(v.axes[a].name);
    AxisColumns c;
    c.rotary = v.axes[a].kind == table::AxisKind::kRotary;
    c.units_per_step = v.axes[a].resolution_e9 * 1e-9;
    c.position = base + "_steps";
    c.in_steps = true;
    if (!points.find(c.position)) {
      c.position = base + (c.rotary ? "_deg" : "_mm");
      c.in_steps = false;
      if (!points.find(c.position)) {
        return Fail(points.LineFailure(points.header_line(),
                                       "missing column \"" + base + "_steps\" or \"" + c.position +
                                           "\" for axis " + std::string(1, v.axes[a].name)));
      }
    }
    if (points.find("dir_" + base)) c.direction = "dir_" + base;
    lookup.names_.push_back(v.axes[a].name);
    lookup.columns_.push_back(c);
  }
  return lookup;
}

std::string PointLookup::Header() const {
  std::string s;
  for (std::size_t a = 0; a < names_.size(); ++a) {
    s += (a ? "," : "") + ColumnName(names_[a]) + "_steps";
  }
  for (std::size_t a = 0; a < names_.size(); ++a) {
    const std::string d = "d" + ColumnName(names_[a]);
    s += "," + d + "_steps," + d + (columns_[a].rotary ? "_arcsec" : "_um");
  }
  return s + "\n";
}

Expected<std::string> PointLookup::Row(const tools::CsvRow& row) const {
  const auto line_failure = [&](const std::string& message) {
    return Fail(Error::kInputInvalid, source_ + ":" + std::to_string(row.line()) + ": " + message);
  };
  int32_t p[table::kMaxAxes] = {};
  bool reverse[table::kMaxAxes] = {};
  for (std::size_t a = 0; a < columns_.size(); ++a) {
    const AxisColumns& c = columns_[a];
    double steps = 0;
    if (c.in_steps) {
      VOLCOMP_TRY_ASSIGN(const long long s, row.Integer(c.position));
      steps = static_cast<double>(s);
    } else {
      VOLCOMP_TRY_ASSIGN(const double units, row.Number(c.position));
      steps = std::round(units / c.units_per_step);
    }
    if (!(steps >= INT32_MIN && steps <= INT32_MAX)) {
      return line_failure("column \"" + c.position + "\": position outside int32 steps");
    }
    p[a] = static_cast<int32_t>(steps);
    if (!c.direction.empty()) {
      VOLCOMP_TRY_ASSIGN(const long long d, row.Integer(c.direction));
      if (d != 1 && d != -1) return line_failure("column \"" + c.direction + "\": use +1 or -1");
      reverse[a] = d < 0;
    }
  }
  int32_t q8[table::kMaxAxes];
  evaluator_.CorrectionQ8(p, reverse, q8);
  std::string s;
  for (std::size_t a = 0; a < columns_.size(); ++a) s += (a ? "," : "") + std::to_string(p[a]);
  for (std::size_t a = 0; a < columns_.size(); ++a) {
    const double steps = q8[a] / 256.0;
    const double unit = columns_[a].rotary ? columns_[a].units_per_step * 3600.0
                                           : columns_[a].units_per_step * 1000.0;
    char buf[64];
    std::snprintf(buf, sizeof buf, ",%.8f,%.6f", steps, steps * unit);
    s += buf;
  }
  return s + "\n";
}

}  // namespace volcomp::image
