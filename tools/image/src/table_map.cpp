// The table map's figures, evaluated with the firmware's lookup.
#include "volcomp/image/table_map.hpp"

#include <algorithm>
#include <cmath>

#include "table_map_layout.hpp"
#include "volcomp/lookup/axis_lookup.hpp"
#include "volcomp/lookup/grid_lookup.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::image {
namespace {

using tools::JsonValue;

// Samples per slice dimension: about 36 cells of colour across a plot.
constexpr uint32_t kSampleCells = 36;
// Samples of an AXIS1D curve: about 400 points.
constexpr uint32_t kCurveCells = 400;

MapAxis AxisOf(const table::AxisInfo& a) {
  MapAxis m;
  m.name = a.name;
  m.rotary = a.kind == table::AxisKind::kRotary;
  m.units_per_step = a.resolution_e9 * 1e-9;
  m.correction_unit = m.units_per_step * (m.rotary ? 3600.0 : 1000.0);
  m.position_unit = m.rotary ? "deg" : "mm";
  m.correction_name = m.rotary ? "arcsec" : "µm";
  return m;
}

MapDimension DimensionOf(const table::Dimension& d, uint8_t axis, const MapAxis& a) {
  MapDimension m;
  m.axis = axis;
  m.nodes = d.nodes;
  m.origin_steps = d.origin_steps;
  m.spacing_steps = d.spacing_steps;
  m.from = d.origin_steps * a.units_per_step;
  m.spacing = d.spacing_steps * a.units_per_step;
  m.to = m.from + double(d.nodes - 1) * m.spacing;
  const uint32_t cells = d.nodes - 1;
  if (cells <= kSampleCells) {
    m.samples_per_cell = static_cast<int>(std::clamp<uint32_t>(kSampleCells / cells, 1, 4));
    for (uint32_t k = 0; k <= cells * m.samples_per_cell; ++k) {
      const int64_t s =
          int64_t{d.origin_steps} + std::llround(double(k) * d.spacing_steps / m.samples_per_cell);
      m.sample_steps.push_back(static_cast<int32_t>(s));
      m.sample_node.push_back(
          k % m.samples_per_cell == 0 ? static_cast<int32_t>(k / m.samples_per_cell) : -1);
    }
  } else {
    m.node_stride = static_cast<int>((cells + kSampleCells - 1) / kSampleCells);
    for (uint32_t n = 0;; n += m.node_stride) {
      n = std::min(n, cells);
      m.sample_steps.push_back(
          static_cast<int32_t>(int64_t{d.origin_steps} + int64_t{n} * d.spacing_steps));
      m.sample_node.push_back(static_cast<int32_t>(n));
      if (n == cells) break;
    }
  }
  for (int32_t s : m.sample_steps) m.sample_pos.push_back(s * a.units_per_step);
  return m;
}

// The slices of one plane (u, v) at the lower, middle and upper node of w (fewer when they
// coincide).
void AddSlices(TableMap* map, const GridLookup& grid, int u, int v, int w) {
  const MapDimension& dw = map->dim[w];
  const uint32_t nodes[3] = {0, (dw.nodes - 1) / 2, dw.nodes - 1};
  const char* which[3] = {"lower", "middle", "upper"};
  for (int s = 0; s < 3; ++s) {
    if (s > 0 && nodes[s] == nodes[s - 1]) continue;
    MapSlice slice;
    slice.u = u;
    slice.v = v;
    slice.w = w;
    slice.node = nodes[s];
    slice.which = which[s];
    slice.position = dw.from + nodes[s] * dw.spacing;
    int32_t pos[table::kMaxAxes] = {};
    pos[dw.axis] =
        static_cast<int32_t>(int64_t{dw.origin_steps} + int64_t{nodes[s]} * dw.spacing_steps);
    for (int32_t sv : map->dim[v].sample_steps) {
      for (int32_t su : map->dim[u].sample_steps) {
        pos[map->dim[u].axis] = su;
        pos[map->dim[v].axis] = sv;
        int32_t q8[3];
        grid.Lookup(pos, q8);
        for (int c = 0; c < 3; ++c) {
          slice.value.push_back(q8[c] / 256.0 * map->axes[map->component_axis[c]].correction_unit);
        }
      }
    }
    map->slices.push_back(std::move(slice));
  }
}

// Node values: extremes per component and of the vector's length (trilinear interpolation is a
// weighted mean of the corners, so the extremes over the volume are at nodes).
void FindExtremes(TableMap* map, const GridLookup& grid) {
  for (auto& e : map->extreme) e = MapExtreme{};
  map->max_norm = 0;
  int32_t pos[table::kMaxAxes] = {};
  const auto& d = map->dim;
  for (uint32_t k = 0; k < d[2].nodes; ++k) {
    for (uint32_t j = 0; j < d[1].nodes; ++j) {
      for (uint32_t i = 0; i < d[0].nodes; ++i) {
        const uint32_t node[3] = {i, j, k};
        for (int q = 0; q < 3; ++q) {
          pos[d[q].axis] = static_cast<int32_t>(int64_t{d[q].origin_steps} +
                                                int64_t{node[q]} * d[q].spacing_steps);
        }
        int32_t q8[3];
        grid.Lookup(pos, q8);
        double norm2 = 0;
        for (int c = 0; c < 3; ++c) {
          const double val = q8[c] / 256.0 * map->axes[map->component_axis[c]].correction_unit;
          MapExtreme& e = map->extreme[c];
          e.min = std::min(e.min, val);
          e.max = std::max(e.max, val);
          if (std::fabs(val) > e.max_abs) {
            e.max_abs = std::fabs(val);
            for (int q = 0; q < 3; ++q) {
              e.node[q] = node[q];
              e.position[q] = d[q].from + node[q] * d[q].spacing;
            }
          }
          norm2 += val * val;
        }
        if (std::sqrt(norm2) > map->max_norm) {
          map->max_norm = std::sqrt(norm2);
          map->max_norm_node = {i, j, k};
        }
      }
    }
  }
  for (auto& e : map->extreme) e.colour_limit = ColourLimit(e.max_abs);
}

Outcome MapGrid(TableMap* map, const table::Grid3View& g) {
  GridLookup grid;
  if (!grid.Init(g).ok()) return Fail(Error::kInputInvalid, map->source + ": GRID3 refused");
  map->has_grid = true;
  for (int d = 0; d < 3; ++d) {
    map->component_axis[d] = g.axis[d];
    map->dim[d] = DimensionOf(g.dim[d], g.axis[d], map->axes[g.axis[d]]);
  }
  FindExtremes(map, grid);
  AddSlices(map, grid, 0, 1, 2);
  AddSlices(map, grid, 0, 2, 1);
  AddSlices(map, grid, 1, 2, 0);
  for (int p = 0; p < 3; ++p) {
    const PlaneLayout layout = LayoutPlane(*map, p);
    map->arrow_px_per_unit[p] = layout.arrow_px_per_unit;
    map->magnification[p] = layout.magnification;
  }
  return Outcome::Ok();
}

Outcome MapAxisTableOf(TableMap* map, const table::Axis1dView& t) {
  AxisLookup lookup;
  if (!lookup.Init(t).ok()) return Fail(Error::kInputInvalid, map->source + ": AXIS1D refused");
  const MapAxis& a = map->axes[t.axis];
  MapAxisTable m;
  m.axis = t.axis;
  m.nodes = t.dim.nodes;
  m.from = t.dim.origin_steps * a.units_per_step;
  m.to = m.from + double(t.dim.nodes - 1) * t.dim.spacing_steps * a.units_per_step;
  m.has_reverse = t.reverse != nullptr;
  m.wrap_period_steps = t.period_steps;
  m.backlash = t.backlash_q8 / 256.0 * a.correction_unit;
  const uint32_t cells = t.dim.nodes - 1;
  m.samples_per_cell = static_cast<int>(std::clamp<uint32_t>(kCurveCells / cells, 1, 8));
  for (uint32_t k = 0; k <= cells * m.samples_per_cell; ++k) {
    const int32_t s =
        static_cast<int32_t>(int64_t{t.dim.origin_steps} +
                             std::llround(double(k) * t.dim.spacing_steps / m.samples_per_cell));
    // A wrap table's last node is its first one period on: the lookup takes positions reduced
    // into [origin, origin + period), so the end is evaluated as the start.
    const int32_t at =
        t.period_steps != 0 && k == cells * m.samples_per_cell ? t.dim.origin_steps : s;
    m.position.push_back(s * a.units_per_step);
    m.forward.push_back(lookup.Lookup(at, false) / 256.0 * a.correction_unit);
    m.reverse.push_back(lookup.Lookup(at, true) / 256.0 * a.correction_unit);
  }
  map->axis_tables.push_back(std::move(m));
  return Outcome::Ok();
}

// As `volcomp inspect` and `lookup` name them (ASCII).
const char* CorrectionUnitName(const MapAxis& a) { return a.rotary ? "arcsec" : "um"; }

JsonValue AxisName(const TableMap& map, uint8_t axis) {
  return std::string(1, map.axes[axis].name);
}

}  // namespace

Expected<TableMap> MapTable(const LoadedImage& image, const std::string& source) {
  const table::TableView& v = image.view();
  TableMap map;
  map.source = source;
  map.table_id = v.table_id;
  map.crc32 = v.crc32;
  map.image_size = v.image_size;
  for (uint8_t i = 0; i < v.axis_count; ++i) map.axes.push_back(AxisOf(v.axes[i]));
  if (v.grid.present) VOLCOMP_TRY(MapGrid(&map, v.grid));
  for (uint8_t i = 0; i < v.axis1d_count; ++i) VOLCOMP_TRY(MapAxisTableOf(&map, v.axis1d[i]));
  return map;
}

JsonValue TableMapJson(const TableMap& map) {
  JsonValue d = JsonValue::Object();
  d.Set("table_id", uint64_t{map.table_id});
  d.Set("crc32", tools::Hex32(map.crc32));
  d.Set("image_size", uint64_t{map.image_size});
  JsonValue& axes = d["axes"] = JsonValue::Array();
  for (const MapAxis& a : map.axes) {
    JsonValue x = JsonValue::Object();
    x.Set("name", std::string(1, a.name));
    x.Set("kind", a.rotary ? "rotary" : "linear");
    x.Set("position_unit", a.position_unit);
    x.Set("correction_unit", CorrectionUnitName(a));
    axes.Push(std::move(x));
  }
  if (map.has_grid) {
    JsonValue& g = d["grid3"] = JsonValue::Object();
    JsonValue& dims = g["dimensions"] = JsonValue::Array();
    for (const MapDimension& m : map.dim) {
      JsonValue x = JsonValue::Object();
      x.Set("axis", AxisName(map, m.axis));
      x.Set("nodes", uint64_t{m.nodes});
      x.Set("from", m.from);
      x.Set("to", m.to);
      x.Set("spacing", m.spacing);
      x.Set("samples_per_cell", m.samples_per_cell);
      x.Set("node_stride", m.node_stride);
      dims.Push(std::move(x));
    }
    JsonValue& comps = g["components"] = JsonValue::Array();
    for (int c = 0; c < 3; ++c) {
      const MapExtreme& e = map.extreme[c];
      JsonValue x = JsonValue::Object();
      x.Set("component",
            "d" + std::string(
                      1, static_cast<char>(std::tolower(map.axes[map.component_axis[c]].name))));
      x.Set("axis", AxisName(map, map.component_axis[c]));
      x.Set("unit", CorrectionUnitName(map.axes[map.component_axis[c]]));
      x.Set("min", e.min);
      x.Set("max", e.max);
      x.Set("max_abs", e.max_abs);
      JsonValue& at = x["max_abs_at"] = JsonValue::Object();
      for (int q = 0; q < 3; ++q) at.Set(AxisName(map, map.dim[q].axis).string, e.position[q]);
      x.Set("colour_limit", e.colour_limit);
      comps.Push(std::move(x));
    }
    g.Set("max_norm", map.max_norm);
    JsonValue& at = g["max_norm_at"] = JsonValue::Object();
    for (int q = 0; q < 3; ++q) {
      at.Set(AxisName(map, map.dim[q].axis).string,
             map.dim[q].from + map.max_norm_node[q] * map.dim[q].spacing);
    }
    JsonValue& planes = g["planes"] = JsonValue::Array();
    for (int p = 0; p < 3; ++p) {
      JsonValue x = JsonValue::Object();
      x.Set("plane", PlaneName(map, p));
      x.Set("arrow_px_per_unit", map.arrow_px_per_unit[p]);
      x.Set("magnification", map.magnification[p]);
      JsonValue& slices = x["slices"] = JsonValue::Array();
      for (const MapSlice& s : map.slices) {
        if (PlaneOf(s) != p) continue;
        JsonValue y = JsonValue::Object();
        y.Set("which", s.which);
        y.Set("axis", AxisName(map, map.dim[s.w].axis));
        y.Set("node", uint64_t{s.node});
        y.Set("position", s.position);
        slices.Push(std::move(y));
      }
      planes.Push(std::move(x));
    }
  }
  JsonValue& tables = d["axis1d"] = JsonValue::Array();
  for (const MapAxisTable& t : map.axis_tables) {
    JsonValue x = JsonValue::Object();
    x.Set("axis", AxisName(map, t.axis));
    x.Set("unit", CorrectionUnitName(map.axes[t.axis]));
    x.Set("nodes", uint64_t{t.nodes});
    x.Set("from", t.from);
    x.Set("to", t.to);
    x.Set("has_reverse", t.has_reverse);
    x.Set("wrap_period_steps", uint64_t{t.wrap_period_steps});
    x.Set("backlash_term", t.backlash);
    const auto [fmin, fmax] = std::minmax_element(t.forward.begin(), t.forward.end());
    const auto [rmin, rmax] = std::minmax_element(t.reverse.begin(), t.reverse.end());
    double dmin = 0, dmax = 0;
    for (size_t i = 0; i < t.forward.size(); ++i) {
      const double diff = t.reverse[i] - t.forward[i];
      dmin = i == 0 ? diff : std::min(dmin, diff);
      dmax = i == 0 ? diff : std::max(dmax, diff);
    }
    x.Set("forward_min", *fmin);
    x.Set("forward_max", *fmax);
    x.Set("reverse_min", *rmin);
    x.Set("reverse_max", *rmax);
    x.Set("backlash_min", dmin);
    x.Set("backlash_max", dmax);
    tables.Push(std::move(x));
  }
  return d;
}

}  // namespace volcomp::image
