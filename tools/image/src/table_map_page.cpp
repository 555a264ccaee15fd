// The table map as report sections: slice panels (inline SVG), AXIS1D charts, the summary.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "table_map_layout.hpp"
#include "volcomp/image/table_map.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/svg.hpp"
#include "volcomp/report/xy_chart.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::image {
namespace {

using report::FormatNumber;
using report::Point;

constexpr const char* kArrowColour = "#d62728";
constexpr const char* kNodeColour = "#555555";
constexpr double kColourBarPx = 84;  // extra width of a colour panel for its bar and labels

std::string ComponentName(const TableMap& map, int c) {
  return "d" +
         std::string(1, static_cast<char>(std::tolower(map.axes[map.component_axis[c]].name)));
}

const MapAxis& AxisOfDim(const TableMap& map, int d) { return map.axes[map.dim[d].axis]; }

std::string Position(double value, const char* unit) { return FormatNumber(value, 6) + " " + unit; }

// The diverging colour of t in [-1, 1] (documented in table_map.hpp).
std::string Colour(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, -1.0, 1.0);
  const int to[2][3] = {{0x21, 0x66, 0xAC}, {0xB2, 0x18, 0x2B}};
  const int* end = to[t >= 0 ? 1 : 0];
  const double a = std::fabs(t);
  char text[8];
  std::snprintf(text, sizeof text, "#%02X%02X%02X",
                static_cast<int>(std::lround(255 + (end[0] - 255) * a)),
                static_cast<int>(std::lround(255 + (end[1] - 255) * a)),
                static_cast<int>(std::lround(255 + (end[2] - 255) * a)));
  return text;
}

std::string SliceTitle(const TableMap& map, const MapSlice& s) {
  const MapAxis& w = AxisOfDim(map, s.w);
  return PlaneName(map, PlaneOf(s)) + " at " + std::string(1, w.name) + " = " +
         Position(s.position, w.position_unit) + " (" + s.which + " node " +
         std::to_string(s.node) + " of 0.." + std::to_string(map.dim[s.w].nodes - 1) + ")";
}

// Frame, lattice lines at the drawn nodes, end labels and axis names.
void DrawFrame(report::Svg* svg, const TableMap& map, const PlaneLayout& l, bool lattice_lines) {
  const MapDimension& du = map.dim[l.u];
  const MapDimension& dv = map.dim[l.v];
  report::Style grid;
  grid.stroke = "#e5e5e5";
  for (size_t i = 0; lattice_lines && i < du.sample_pos.size(); ++i) {
    if (!l.ArrowAt(du.sample_node[i], 0)) continue;
    svg->Line({l.X(du.sample_pos[i]), l.Y(l.v0)}, {l.X(du.sample_pos[i]), l.Y(l.v1)}, grid);
  }
  for (size_t j = 0; lattice_lines && j < dv.sample_pos.size(); ++j) {
    if (!l.ArrowAt(0, dv.sample_node[j])) continue;
    svg->Line({l.X(l.u0), l.Y(dv.sample_pos[j])}, {l.X(l.u1), l.Y(dv.sample_pos[j])}, grid);
  }
  report::Style frame;
  frame.stroke = "#bbbbbb";
  svg->Rect(l.left, l.top, l.frame_w(), l.frame_h(), frame);
  report::TextStyle label;
  label.size_px = 10;
  label.anchor = report::Anchor::kMiddle;
  const double below = l.top + l.frame_h() + 12;
  svg->Text({l.X(l.u0), below}, FormatNumber(l.u0, 6), label);
  svg->Text({l.X(l.u1), below}, FormatNumber(l.u1, 6), label);
  const MapAxis& au = AxisOfDim(map, l.u);
  const MapAxis& av = AxisOfDim(map, l.v);
  svg->Text({l.left + l.frame_w() / 2, below + 12},
            std::string(1, au.name) + ", " + au.position_unit, label);
  label.anchor = report::Anchor::kEnd;
  svg->Text({l.left - 3, l.Y(l.v0) + 3}, FormatNumber(l.v0, 6), label);
  svg->Text({l.left - 3, l.Y(l.v1) + 3}, FormatNumber(l.v1, 6), label);
  label.anchor = report::Anchor::kMiddle;
  label.rotate_deg = -90;
  svg->Text({l.left - 30, l.top + l.frame_h() / 2},
            std::string(1, av.name) + ", " + av.position_unit, label);
}

void Arrow(report::Svg* svg, Point from, Point to, const std::string& colour) {
  report::Style shaft;
  shaft.stroke = colour;
  shaft.stroke_width_px = 1.2;
  svg->Line(from, to, shaft);
  const double dx = to.x - from.x, dy = to.y - from.y, len = std::hypot(dx, dy);
  if (len < 3) return;
  const double ux = dx / len, uy = dy / len, head = std::min(5.0, len / 2);
  report::Style fill;
  fill.stroke = "none";
  fill.fill = colour;
  svg->Polygon({to,
                {to.x - head * ux + head * 0.45 * uy, to.y - head * uy - head * 0.45 * ux},
                {to.x - head * ux - head * 0.45 * uy, to.y - head * uy + head * 0.45 * ux}},
               fill);
}

std::string VectorPanel(const TableMap& map, const MapSlice& s, const PlaneLayout& l) {
  report::Svg svg(l.width(), l.height());
  svg.Title(SliceTitle(map, s) + ": vectors");
  DrawFrame(&svg, map, l, true);
  const MapDimension& du = map.dim[l.u];
  const MapDimension& dv = map.dim[l.v];
  const MapAxis& cu = map.axes[map.component_axis[l.u]];
  const std::string unit = cu.correction_name;
  report::TextStyle head;
  head.size_px = 11;
  head.bold = true;
  svg.Text({l.left, 16},
           l.length_plot
               ? "vectors ×" + FormatNumber(l.magnification, 6)
               : "vectors, 1 " + unit + " = " + FormatNumber(l.arrow_px_per_unit, 6) + " px",
           head);
  report::Style dot;
  dot.stroke = "none";
  dot.fill = kNodeColour;
  const size_t nu = du.sample_pos.size();
  for (size_t j = 0; j < dv.sample_pos.size(); ++j) {
    for (size_t i = 0; i < nu; ++i) {
      if (!l.ArrowAt(du.sample_node[i], dv.sample_node[j])) continue;
      const Point at{l.X(du.sample_pos[i]), l.Y(dv.sample_pos[j])};
      svg.Circle(at, 1.5, dot);
      const double* v = &s.value[(j * nu + i) * 3];
      Arrow(&svg, at, {at.x + l.arrow_px_per_unit * v[l.u], at.y - l.arrow_px_per_unit * v[l.v]},
            kArrowColour);
    }
  }
  if (l.arrow_px_per_unit > 0) {  // a reference arrow of a round length, about 40 px
    const double length = NiceFloor(40 / l.arrow_px_per_unit);
    const double y = l.top + l.frame_h() + 38;
    const double x = l.left + l.frame_w() - length * l.arrow_px_per_unit;
    Arrow(&svg, {x, y}, {x + length * l.arrow_px_per_unit, y}, "#222222");
    report::TextStyle t;
    t.size_px = 10;
    t.anchor = report::Anchor::kEnd;
    svg.Text({x - 4, y + 3}, FormatNumber(length, 6) + " " + unit, t);
  }
  return svg.str();
}

std::string ColourPanel(const TableMap& map, const MapSlice& s, const PlaneLayout& l, int c) {
  report::Svg svg(l.width() + kColourBarPx, l.height());
  const std::string unit = map.axes[map.component_axis[c]].correction_name;
  svg.Title(SliceTitle(map, s) + ": " + ComponentName(map, c));
  const MapDimension& du = map.dim[l.u];
  const MapDimension& dv = map.dim[l.v];
  const double limit = map.extreme[c].colour_limit;
  // Each sample's cell reaches halfway to its neighbours (as far on the outer side).
  const auto edges = [](const std::vector<double>& pos, size_t i) {
    const double lo = i > 0 ? (pos[i - 1] + pos[i]) / 2 : pos[i] - (pos[i + 1] - pos[i]) / 2;
    const double hi =
        i + 1 < pos.size() ? (pos[i] + pos[i + 1]) / 2 : pos[i] + (pos[i] - pos[i - 1]) / 2;
    return std::pair<double, double>{lo, hi};
  };
  const size_t nu = du.sample_pos.size();
  for (size_t j = 0; j < dv.sample_pos.size(); ++j) {
    const auto [v_lo, v_hi] = edges(dv.sample_pos, j);
    for (size_t i = 0; i < nu; ++i) {
      const auto [u_lo, u_hi] = edges(du.sample_pos, i);
      report::Style cell;
      cell.stroke = "none";
      cell.fill = Colour(s.value[(j * nu + i) * 3 + c] / limit);
      // 0.2 px over each edge, so that no seam of background shows between cells.
      svg.Rect(l.X(u_lo) - 0.2, l.Y(v_hi) - 0.2, l.X(u_hi) - l.X(u_lo) + 0.4,
               l.Y(v_lo) - l.Y(v_hi) + 0.4, cell);
    }
  }
  DrawFrame(&svg, map, l, false);
  report::TextStyle head;
  head.size_px = 11;
  head.bold = true;
  svg.Text({l.left, 16}, ComponentName(map, c) + ", " + unit, head);
  // The colour bar: +limit at the top, -limit at the bottom.
  const double x = l.left + l.frame_w() + 22, top = l.top, h = l.frame_h();
  constexpr int kBands = 32;
  for (int b = 0; b < kBands; ++b) {
    report::Style band;
    band.stroke = "none";
    band.fill = Colour(1.0 - (2.0 * b + 1) / kBands);
    svg.Rect(x, top + h * b / kBands, 14, h / kBands + 0.3, band);
  }
  report::Style outline;
  outline.stroke = "#bbbbbb";
  svg.Rect(x, top, 14, h, outline);
  report::TextStyle t;
  t.size_px = 10;
  svg.Text({x + 18, top + 4}, "+" + FormatNumber(limit, 6), t);
  svg.Text({x + 18, top + h / 2 + 3}, "0", t);
  svg.Text({x + 18, top + h + 3}, "−" + FormatNumber(limit, 6), t);
  svg.Text({x, top + h + 20}, unit, t);
  return svg.str();
}

std::string AxisChart(const TableMap& map, const MapAxisTable& t) {
  const MapAxis& a = map.axes[t.axis];
  report::XyChart c;
  c.title = "AXIS1D " + std::string(1, a.name) + ": forward, reverse and their difference";
  c.x_label = std::string(1, a.name) + ", " + a.position_unit;
  c.y_label = std::string("correction, ") + a.correction_name;
  report::XySeries f, r, d;
  f.label = "forward (+)";
  r.label = "reverse (−)";
  d.label = "reverse − forward";
  r.color = "#d62728";
  d.color = "#7f7f7f";
  d.dash = "5 3";
  for (report::XySeries* s : {&f, &r, &d}) s->marker = report::Marker::kNone;
  for (size_t i = 0; i < t.position.size(); ++i) {
    f.x.push_back(t.position[i]);
    r.x.push_back(t.position[i]);
    d.x.push_back(t.position[i]);
    f.y.push_back(t.forward[i]);
    r.y.push_back(t.reverse[i]);
    d.y.push_back(t.reverse[i] - t.forward[i]);
  }
  c.series = {f, r, d};
  return c.Render();
}

void AddSummary(report::HtmlPage* page, const TableMap& map) {
  std::vector<std::vector<std::string>> rows = {
      {"table id", std::to_string(map.table_id)},
      {"CRC-32", tools::Hex32(map.crc32)},
      {"image size", std::to_string(map.image_size) + " bytes"}};
  for (const MapAxis& a : map.axes) {
    rows.push_back({std::string("axis ") + a.name, std::string(a.rotary ? "rotary, " : "linear, ") +
                                                       FormatNumber(a.units_per_step, 6) + " " +
                                                       a.position_unit + "/step; corrections in " +
                                                       a.correction_name});
  }
  page->Table({"table", ""}, rows);
  if (map.has_grid) {
    std::vector<std::vector<std::string>> dims;
    for (const MapDimension& d : map.dim) {
      const MapAxis& a = map.axes[d.axis];
      dims.push_back(
          {std::string(1, a.name), std::to_string(d.nodes),
           FormatNumber(d.from, 6) + " .. " + FormatNumber(d.to, 6) + " " + a.position_unit,
           FormatNumber(d.spacing, 6) + " " + a.position_unit});
    }
    page->Table({"GRID3 lattice", "nodes", "range", "spacing"}, dims);
    std::vector<std::vector<std::string>> comps;
    for (int c = 0; c < 3; ++c) {
      const MapExtreme& e = map.extreme[c];
      std::string where;
      for (int q = 0; q < 3; ++q) {
        where += (q ? ", " : "") + std::string(1, AxisOfDim(map, q).name) + " = " +
                 FormatNumber(e.position[q], 6);
      }
      const std::string unit = map.axes[map.component_axis[c]].correction_name;
      comps.push_back({ComponentName(map, c) + ", " + unit, FormatNumber(e.min, 4),
                       FormatNumber(e.max, 4), FormatNumber(e.max_abs, 4), where});
    }
    page->Table({"component", "min", "max", "largest |.|", "at (node)"}, comps);
  }
  if (!map.axis_tables.empty()) {
    std::vector<std::vector<std::string>> rows1d;
    for (const MapAxisTable& t : map.axis_tables) {
      const MapAxis& a = map.axes[t.axis];
      const auto [fmin, fmax] = std::minmax_element(t.forward.begin(), t.forward.end());
      rows1d.push_back(
          {std::string(1, a.name), std::to_string(t.nodes),
           FormatNumber(t.from, 6) + " .. " + FormatNumber(t.to, 6) + " " + a.position_unit,
           FormatNumber(*fmin, 4) + " .. " + FormatNumber(*fmax, 4) + " " + a.correction_name,
           t.has_reverse ? "yes" : "no (forward used)",
           FormatNumber(t.backlash, 4) + " " + a.correction_name});
    }
    page->Table({"AXIS1D", "nodes", "range", "forward", "reverse table", "backlash term"}, rows1d);
  }
}

}  // namespace

std::vector<std::string> SliceSvgs(const TableMap& map, const MapSlice& slice) {
  const PlaneLayout l = LayoutPlane(map, PlaneOf(slice));
  std::vector<std::string> svgs = {VectorPanel(map, slice, l)};
  for (int c = 0; c < 3; ++c) svgs.push_back(ColourPanel(map, slice, l, c));
  return svgs;
}

void AddTableMapSections(report::HtmlPage* page, const TableMap& map, int level) {
  level = std::clamp(level, 1, 3);
  page->Heading(level, "Correction map: " + map.source);
  page->Paragraph(
      "The correction the table applies, as the board's own lookup computes it (before the "
      "board's clamp and rate limiter). Positions in mm (deg on a rotary axis), corrections in "
      "µm (arcsec on a rotary axis).");
  AddSummary(page, map);
  if (map.has_grid) {
    for (int p = 0; p < 3; ++p) {
      const PlaneLayout l = LayoutPlane(map, p);
      const MapAxis& w = AxisOfDim(map, 3 - l.u - l.v);
      page->Heading(level + 1, "GRID3, plane " + PlaneName(map, p));
      std::string text = "Slices at the lower, middle and upper lattice node of " +
                         std::string(1, w.name) + ". Arrows: the in-plane correction at each ";
      if (l.arrow_stride_u > 1 || l.arrow_stride_v > 1) {
        text += "drawn node (one node in " + std::to_string(l.arrow_stride_u) + " along " +
                AxisOfDim(map, l.u).name + ", one in " + std::to_string(l.arrow_stride_v) +
                " along " + AxisOfDim(map, l.v).name + ")";
      } else {
        text += "node";
      }
      if (l.length_plot) {
        text += ", magnified ×" + FormatNumber(l.magnification, 6) +
                " (1 µm of correction is "
                "drawn as " +
                FormatNumber(l.magnification, 6) + " µm of travel)";
      } else {
        text += ", 1 unit of correction drawn as " + FormatNumber(l.arrow_px_per_unit, 6) + " px";
      }
      text +=
          ". Colour: each component between the nodes, the same scale on every slice "
          "(red positive, blue negative).";
      page->Paragraph(text);
      for (const MapSlice& s : map.slices) {
        if (PlaneOf(s) != p) continue;
        std::string panels;
        for (const std::string& svg : SliceSvgs(map, s)) panels += svg;
        page->Figure(panels, SliceTitle(map, s) + ".");
      }
    }
  }
  for (const MapAxisTable& t : map.axis_tables) {
    const MapAxis& a = map.axes[t.axis];
    page->Heading(level + 1, std::string("AXIS1D ") + a.name);
    page->Figure(
        AxisChart(map, t),
        std::string("Correction of ") + a.name +
            " by its own position: forward while it moves +, reverse (the reverse "
            "table or the forward one, plus the backlash term) while it moves −; the "
            "dashed curve is their difference reverse − forward, the backlash the table corrects." +
            (t.wrap_period_steps != 0 ? " The table wraps every turn." : ""));
  }
}

Expected<std::string> WriteTableMapReport(const TableMap& map, const std::string& dir) {
  VOLCOMP_TRY_ASSIGN(const std::string path, report::PrepareReportPath(dir, "index.html"));
  report::HtmlPage page("volcomp table map: " + map.source);
  AddTableMapSections(&page, map, 2);
  VOLCOMP_TRY(page.WriteFile(path));
  return path;
}

}  // namespace volcomp::image
