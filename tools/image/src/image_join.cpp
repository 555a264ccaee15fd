// Joining a GRID3 image and an AXIS1D image into one.
#include "volcomp/image/image_join.hpp"

#include <cstdio>

#include "section_copy.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/table/table_writer.hpp"

namespace volcomp::image {
namespace {

Unexpected<Failure> Invalid(const std::string& message) {
  return Fail(Error::kInputInvalid, message);
}

std::string AxisNames(const table::TableView& v) {
  std::string s;
  for (uint8_t i = 0; i < v.axis_count; ++i) s += (i ? ", " : "") + std::string(1, v.axes[i].name);
  return s;
}

std::string UnitsPerStep(const table::AxisInfo& a) {
  return ResolutionText(a.resolution_e9, a.kind == table::AxisKind::kRotary);
}

// The index of the axis named `name` in `v`, or -1.
int IndexOf(const table::TableView& v, char name) {
  for (uint8_t i = 0; i < v.axis_count; ++i) {
    if (v.axes[i].name == name) return i;
  }
  return -1;
}

}  // namespace

Expected<JoinedImage> JoinImages(const JoinPart& grid_part,
                                 const JoinPart& axis_part,
                                 const JoinOptions& options) {
  const table::TableView& g = grid_part.image->view();
  const table::TableView& a = axis_part.image->view();
  const std::string& gs = grid_part.source;
  const std::string& as = axis_part.source;
  if (!g.grid.present) return Invalid(gs + ": no GRID3 section (--grid takes a GRID3 image)");
  if (a.grid.present) {
    return Invalid(as + ": has a GRID3 section (--axis takes an image of AXIS1D tables only)");
  }
  if (a.axis1d_count == 0) return Invalid(as + ": no AXIS1D table");

  // Axes: every axis of the AXIS1D image must be the GRID3 image's axis of that name.
  for (uint8_t i = 0; i < a.axis_count; ++i) {
    const table::AxisInfo& ax = a.axes[i];
    const int j = IndexOf(g, ax.name);
    if (j < 0) {
      return Invalid("the images do not belong together: axis " + std::string(1, ax.name) + " of " +
                     as + " is not an axis of " + gs + " (" + AxisNames(g) + ")");
    }
    const table::AxisInfo& gx = g.axes[j];
    if (gx.kind != ax.kind || gx.resolution_e9 != ax.resolution_e9) {
      return Invalid("the images do not belong together: axis " + std::string(1, ax.name) + " is " +
                     UnitsPerStep(gx) + " in " + gs + " but " + UnitsPerStep(ax) + " in " + as);
    }
  }
  // Ids.
  uint32_t id = g.table_id;
  if (options.table_id) {
    id = *options.table_id;
  } else if (g.table_id != a.table_id) {
    return Invalid("the images do not belong together: table id " + std::to_string(g.table_id) +
                   " in " + gs + " but " + std::to_string(a.table_id) + " in " + as +
                   " (give the joined image its id with --table-id)");
  }
  if (id == 0) return Invalid("table id 0 means no table active: give an id from 1");

  table::ImageSpec spec;
  spec.table_id = id;
  spec.axis_count = g.axis_count;
  for (uint8_t i = 0; i < g.axis_count; ++i) spec.axes[i] = g.axes[i];

  SectionCopy copy;
  CopyGrid(g, &copy, &spec);

  // AXIS1D: the GRID3 image's own, then the AXIS1D image's, re-indexed by name.
  std::vector<bool> taken(g.axis_count, false);
  auto add = [&](const table::Axis1dView& t, uint8_t axis, const std::string& source) -> Outcome {
    if (taken[axis]) {
      return Invalid("both " + gs + " and " + as + " have an AXIS1D table for axis " +
                     std::string(1, g.axes[axis].name) + " (" + source + ")");
    }
    taken[axis] = true;
    CopyAxis1d(t, axis, &copy, &spec);
    return Outcome::Ok();
  };
  for (uint8_t i = 0; i < g.axis1d_count; ++i) {
    VOLCOMP_TRY(add(g.axis1d[i], g.axis1d[i].axis, gs));
  }
  for (uint8_t i = 0; i < a.axis1d_count; ++i) {
    const char name = a.axes[a.axis1d[i].axis].name;
    VOLCOMP_TRY(add(a.axis1d[i], static_cast<uint8_t>(IndexOf(g, name)), as));
  }

  // THERMAL: carried from whichever part has one, its axis records re-indexed by name.
  if (g.thermal != nullptr && a.thermal != nullptr) {
    return Invalid("both " + gs + " and " + as + " have a THERMAL section: join keeps one model");
  }
  thermal::ThermalModel thermal_model;
  if (g.thermal != nullptr) thermal_model = table::ReadThermal(g.thermal);
  if (a.thermal != nullptr) {
    const thermal::ThermalModel part = table::ReadThermal(a.thermal);
    thermal_model = part;
    thermal_model.axis_count = g.axis_count;
    for (auto& x : thermal_model.axis) x = thermal::AxisModel();
    for (uint8_t i = 0; i < a.axis_count; ++i) {
      thermal_model.axis[IndexOf(g, a.axes[i].name)] = part.axis[i];
    }
  }
  if (g.thermal != nullptr || a.thermal != nullptr) spec.thermal = &thermal_model;

  JoinedImage out;
  std::string info = "builder=volcomp build image\ngrid_image=" + gs + "\naxis_image=" + as + "\n";
  for (const auto& [k, v] : options.info) info += k + "=" + v + "\n";
  std::string info_text;
  VOLCOMP_TRY(SetInfo(info, PrefixedInfo(g, "grid.") + PrefixedInfo(a, "axis."), gs + " and " + as,
                      &info_text, &out.warnings, &spec));
  VOLCOMP_TRY_ASSIGN(out.bytes, WriteSpec(spec));
  return out;
}

}  // namespace volcomp::image
