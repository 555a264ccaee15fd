// The table map against an image of known node values: a linear correction field (which
// trilinear interpolation reproduces exactly between the nodes) and linear AXIS1D tables. The
// SVG's geometry (node dots, arrow end points, cell colours) is checked from the field's numbers
// and the documented colour scale, not from the code under test.
#include "volcomp/image/table_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "expected_value.hpp"
#include "volcomp/image/image_builder.hpp"

namespace volcomp::image {
namespace {

using testing::ValueOf;

// Lattice, mm (1 µm per step): X 0..150 every 50, Y -20..60 every 40, Z 0..50 every 25.
constexpr double kFrom[3] = {0, -20, 0};
constexpr double kSpacing[3] = {50, 40, 25};
constexpr uint32_t kNodes[3] = {4, 3, 3};

// The correction field, µm, at (x, y, z) mm.
double Field(int c, double x, double y, double z) {
  switch (c) {
    case 0:
      return 10 + 0.2 * x - 0.1 * y;
    case 1:
      return -5 + 0.05 * x + 0.3 * z;
    default:
      return 2 + 0.1 * y - 0.2 * z;
  }
}

// AXIS1D of X, µm at x mm: forward and reverse tables, plus a backlash term of 2 µm.
double Forward(double x) { return 3 + 0.1 * x; }
double Reverse(double x) { return 1 - 0.04 * x; }
constexpr double kBacklashUm = 2;

LoadedImage FieldImage(bool with_axis_table) {
  ImageRequest r;
  r.table_id = 77;
  r.axes = {{'X'}, {'Y'}, {'Z'}};
  GridCorrections g;
  for (int d = 0; d < 3; ++d) {
    g.lattice[d] = {kNodes[d], static_cast<int32_t>(kFrom[d] * 1000),
                    static_cast<uint32_t>(kSpacing[d] * 1000)};
  }
  for (uint32_t k = 0; k < kNodes[2]; ++k) {
    for (uint32_t j = 0; j < kNodes[1]; ++j) {
      for (uint32_t i = 0; i < kNodes[0]; ++i) {
        for (int c = 0; c < 3; ++c) {
          g.correction_steps.push_back(Field(c, kFrom[0] + i * kSpacing[0],
                                             kFrom[1] + j * kSpacing[1],
                                             kFrom[2] + k * kSpacing[2]));
        }
      }
    }
  }
  r.grid = g;
  if (with_axis_table) {
    AxisCorrections t;
    t.lattice = {4, 0, 50000};
    for (int i = 0; i < 4; ++i) {
      t.forward_steps.push_back(Forward(50.0 * i));
      t.reverse_steps.push_back(Reverse(50.0 * i));
    }
    t.backlash_steps = kBacklashUm;
    r.axis_tables.push_back(t);
  }
  return ValueOf(LoadedImage::FromBytes(ValueOf(BuildImage(r)), "field.vct"));
}

// The documented colour bar limit: the smallest of 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 x 10^k at
// or above x.
double ColourBarLimit(double x) {
  for (double mag = 1e-3;; mag *= 10) {
    for (double m : {1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0}) {
      if (m * mag >= x - 1e-12) return m * mag;
    }
  }
}

// The documented diverging colour of t (clipped to [-1, 1]) as RGB.
std::array<int, 3> ExpectedColour(double t) {
  t = std::clamp(t, -1.0, 1.0);
  const std::array<int, 3> end =
      t >= 0 ? std::array<int, 3>{0xB2, 0x18, 0x2B} : std::array<int, 3>{0x21, 0x66, 0xAC};
  std::array<int, 3> rgb;
  for (int k = 0; k < 3; ++k)
    rgb[k] = static_cast<int>(std::lround(255 + (end[k] - 255) * std::fabs(t)));
  return rgb;
}

// A numeric attribute of an SVG element's text.
double Attr(const std::string& element, const std::string& name) {
  std::smatch m;
  const std::regex re(" " + name + "=\"([-0-9.]+)\"");
  if (!std::regex_search(element, m, re)) ADD_FAILURE() << name << " missing in " << element;
  return std::stod(m[1].str());
}

std::string TextAttr(const std::string& element, const std::string& name) {
  std::smatch m;
  const std::regex re(" " + name + "=\"([^\"]*)\"");
  return std::regex_search(element, m, re) ? m[1].str() : std::string();
}

std::vector<std::string> Elements(const std::string& svg, const std::string& tag) {
  std::vector<std::string> out;
  const std::regex re("<" + tag + " [^>]*/>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), re); it != std::sregex_iterator();
       ++it) {
    out.push_back(it->str());
  }
  return out;
}

const MapSlice& FindSlice(const TableMap& map, int u, int v, const char* which) {
  for (const MapSlice& s : map.slices) {
    if (s.u == u && s.v == v && std::string(s.which) == which) return s;
  }
  ADD_FAILURE() << "no slice";
  return map.slices.front();
}

// Every sample of every slice, between the nodes too, is the field there.
void ExpectSamplesAreTheField(const TableMap& map) {
  for (const MapSlice& s : map.slices) {
    const auto& pu = map.dim[s.u].sample_pos;
    const auto& pv = map.dim[s.v].sample_pos;
    ASSERT_EQ(s.value.size(), pu.size() * pv.size() * 3);
    for (size_t j = 0; j < pv.size(); ++j) {
      for (size_t i = 0; i < pu.size(); ++i) {
        double p[3];
        p[s.u] = pu[i];
        p[s.v] = pv[j];
        p[s.w] = s.position;
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(s.value[(j * pu.size() + i) * 3 + c], Field(c, p[0], p[1], p[2]), 0.005);
        }
      }
    }
  }
}

TEST(image_table_map, SummaryAndSlicesFollowTheField) {
  const LoadedImage img = FieldImage(false);
  const TableMap map = ValueOf(MapTable(img, "field.vct"));
  EXPECT_EQ(map.table_id, 77u);
  ASSERT_TRUE(map.has_grid);
  // Extremes over the nodes, found here from the field.
  for (int c = 0; c < 3; ++c) {
    double max_abs = 0;
    std::array<double, 3> at = {};
    for (uint32_t k = 0; k < kNodes[2]; ++k) {
      for (uint32_t j = 0; j < kNodes[1]; ++j) {
        for (uint32_t i = 0; i < kNodes[0]; ++i) {
          const double p[3] = {kFrom[0] + i * kSpacing[0], kFrom[1] + j * kSpacing[1],
                               kFrom[2] + k * kSpacing[2]};
          const double v = std::fabs(Field(c, p[0], p[1], p[2]));
          if (v > max_abs + 1e-9) {
            max_abs = v;
            at = {p[0], p[1], p[2]};
          }
        }
      }
    }
    EXPECT_NEAR(map.extreme[c].max_abs, max_abs, 1.0 / 256) << c;
    for (int q = 0; q < 3; ++q) EXPECT_DOUBLE_EQ(map.extreme[c].position[q], at[q]) << c;
    EXPECT_DOUBLE_EQ(map.extreme[c].colour_limit, ColourBarLimit(max_abs)) << c;
  }
  // Three planes, lower / middle / upper node of the third axis: Z 0, 25, 50; Y -20, 20, 60;
  // X 0, 50 (node 1 of 0..3), 150.
  ASSERT_EQ(map.slices.size(), 9u);
  const double expected[9] = {0, 25, 50, -20, 20, 60, 0, 50, 150};
  for (int s = 0; s < 9; ++s) EXPECT_DOUBLE_EQ(map.slices[s].position, expected[s]) << s;
  EXPECT_EQ(FindSlice(map, 1, 2, "middle").node, 1u);
  // Every sample, between the nodes too, is the field there (the firmware's trilinear lookup
  // reproduces a linear field; Q8 steps = 1/256 µm).
  ExpectSamplesAreTheField(map);
  EXPECT_GT(map.dim[0].sample_pos.size(), kNodes[0]);  // samples between the nodes
}

TEST(image_table_map, ArrowsAndColoursAtTheNodes) {
  const LoadedImage img = FieldImage(false);
  const TableMap map = ValueOf(MapTable(img, "field.vct"));
  const MapSlice& slice = FindSlice(map, 0, 1, "middle");  // XY at Z = 25 mm
  const std::vector<std::string> svgs = SliceSvgs(map, slice);
  ASSERT_EQ(svgs.size(), 4u);
  EXPECT_NE(svgs[0].find("<title>XY at Z = 25 mm (middle node 1 of 0..2): vectors</title>"),
            std::string::npos);

  // The node dots: 4 x 3, on an equally spaced grid of one scale (px per mm) in x and y.
  std::vector<std::string> dots;
  for (const std::string& c : Elements(svgs[0], "circle")) {
    if (TextAttr(c, "fill") == "#555555") dots.push_back(c);
  }
  ASSERT_EQ(dots.size(), 12u);
  std::set<double> xs, ys;
  for (const std::string& d : dots) {
    xs.insert(Attr(d, "cx"));
    ys.insert(Attr(d, "cy"));
  }
  ASSERT_EQ(xs.size(), 4u);
  ASSERT_EQ(ys.size(), 3u);
  const double x0 = *xs.begin(), y_bottom = *ys.rbegin();
  const double px_per_mm = (*xs.rbegin() - x0) / 150.0;
  EXPECT_NEAR((y_bottom - *ys.begin()) / 80.0, px_per_mm, 0.001);
  const auto node_px = [&](double x_mm, double y_mm) {
    return std::pair<double, double>{x0 + (x_mm - 0) * px_per_mm,
                                     y_bottom - (y_mm + 20) * px_per_mm};
  };

  // The magnification printed on the panel: 1 µm of correction drawn as M µm.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svgs[0], m, std::regex(">vectors ×([0-9.]+)<")));
  const double magnification = std::stod(m[1].str());
  EXPECT_DOUBLE_EQ(magnification, map.magnification[0]);
  std::vector<std::string> arrows;
  for (const std::string& l : Elements(svgs[0], "line")) {
    if (TextAttr(l, "stroke") == "#d62728") arrows.push_back(l);
  }
  ASSERT_EQ(arrows.size(), 12u);
  const double z = 25;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double x = 50.0 * i, y = -20 + 40.0 * j;
      const auto node = node_px(x, y);
      const double px = node.first, py = node.second;
      // The pixel values are printed with two decimals: within 0.02 px.
      const auto it = std::find_if(arrows.begin(), arrows.end(), [&](const std::string& l) {
        return std::fabs(Attr(l, "x1") - px) < 0.02 && std::fabs(Attr(l, "y1") - py) < 0.02;
      });
      ASSERT_NE(it, arrows.end()) << "no arrow from node " << i << "," << j;
      const double gain = magnification * 1e-3 * px_per_mm;  // px per µm
      EXPECT_NEAR(Attr(*it, "x2"), px + gain * Field(0, x, y, z), 0.03) << i << "," << j;
      EXPECT_NEAR(Attr(*it, "y2"), py - gain * Field(1, x, y, z), 0.03) << i << "," << j;
    }
  }

  // The colour maps: the cell centred on each node has the documented colour of the field's
  // value over the colour bar's limit (which the bar prints).
  for (int c = 0; c < 3; ++c) {
    const std::string& svg = svgs[1 + c];
    const double limit = map.extreme[c].colour_limit;
    EXPECT_NE(svg.find(">+" + std::to_string(static_cast<int>(limit)) + "<"), std::string::npos);
    std::vector<std::string> cells;
    for (const std::string& r : Elements(svg, "rect")) {
      if (TextAttr(r, "stroke") == "none") cells.push_back(r);
    }
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double x = 50.0 * i, y = -20 + 40.0 * j;
        const auto node = node_px(x, y);
        const double px = node.first, py = node.second;
        int found = 0;
        for (const std::string& r : cells) {
          const double cx = Attr(r, "x") + Attr(r, "width") / 2;
          const double cy = Attr(r, "y") + Attr(r, "height") / 2;
          if (std::fabs(cx - px) > 0.05 || std::fabs(cy - py) > 0.05) continue;
          ++found;
          const std::string fill = TextAttr(r, "fill");
          ASSERT_EQ(fill.size(), 7u);
          const std::array<int, 3> want = ExpectedColour(Field(c, x, y, z) / limit);
          for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(std::stoi(fill.substr(1 + 2 * k, 2), nullptr, 16), want[k], 1)
                << "component " << c << " node " << i << "," << j << " " << fill;
          }
        }
        EXPECT_EQ(found, 1) << "component " << c << " node " << i << "," << j;
      }
    }
  }
}

TEST(image_table_map, AxisTableCurvesAndJson) {
  const LoadedImage img = FieldImage(true);
  const TableMap map = ValueOf(MapTable(img, "field.vct"));
  ASSERT_EQ(map.axis_tables.size(), 1u);
  const MapAxisTable& t = map.axis_tables[0];
  EXPECT_TRUE(t.has_reverse);
  EXPECT_GT(t.position.size(), 4u);
  EXPECT_DOUBLE_EQ(t.position.front(), 0);
  EXPECT_DOUBLE_EQ(t.position.back(), 150);
  for (size_t i = 0; i < t.position.size(); ++i) {
    EXPECT_NEAR(t.forward[i], Forward(t.position[i]), 0.005) << t.position[i];
    EXPECT_NEAR(t.reverse[i], Reverse(t.position[i]) + kBacklashUm, 0.005) << t.position[i];
  }
  const tools::JsonValue j = TableMapJson(map);
  EXPECT_EQ(j.get("crc32")->string.substr(0, 2), "0x");
  const tools::JsonValue& a = j.get("axis1d")->array.at(0);
  // reverse - forward = -2 - 0.14 x + 2: from 0 at x = 0 to -21 at x = 150.
  EXPECT_NEAR(a.get("backlash_max")->number, 0, 0.01);
  EXPECT_NEAR(a.get("backlash_min")->number, -21, 0.01);
  EXPECT_NEAR(a.get("backlash_term")->number, kBacklashUm, 1e-9);
  const tools::JsonValue& dx = j.get("grid3")->get("components")->array.at(0);
  EXPECT_EQ(dx.get("component")->string, "dx");
  EXPECT_EQ(dx.get("unit")->string, "um");
  // dx = 10 + 0.2 x - 0.1 y is largest at x = 150, y = -20: 42 µm.
  EXPECT_NEAR(dx.get("max_abs")->number, 42, 0.005);
  EXPECT_DOUBLE_EQ(dx.get("max_abs_at")->get("X")->number, 150);
  EXPECT_DOUBLE_EQ(dx.get("max_abs_at")->get("Y")->number, -20);
  EXPECT_DOUBLE_EQ(dx.get("colour_limit")->number, 50);
  const auto& planes = j.get("grid3")->get("planes")->array;
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_EQ(planes[2].get("plane")->string, "YZ");
  EXPECT_EQ(planes[2].get("slices")->array.at(1).get("position")->number, 50);
}

// A lattice of 61 x 3 x 2 nodes: the slices sample every other node along X (and the last),
// arrows every 6th node; two-node Z has no middle slice.
TEST(image_table_map, LargeLatticeIsSampledAtNodes) {
  ImageRequest r;
  r.axes = {{'X'}, {'Y'}, {'Z'}};
  GridCorrections g;
  g.lattice = {Lattice{61, 0, 5000}, Lattice{3, 0, 10000}, Lattice{2, 0, 10000}};
  for (uint32_t k = 0; k < 2; ++k) {
    for (uint32_t j = 0; j < 3; ++j) {
      for (uint32_t i = 0; i < 61; ++i) {
        for (int c = 0; c < 3; ++c)
          g.correction_steps.push_back(Field(c, 5.0 * i, 10.0 * j, 10.0 * k));
      }
    }
  }
  r.grid = g;
  const LoadedImage img = ValueOf(LoadedImage::FromBytes(ValueOf(BuildImage(r)), "big.vct"));
  const TableMap map = ValueOf(MapTable(img, "big.vct"));
  const MapDimension& x = map.dim[0];
  EXPECT_EQ(x.node_stride, 2);
  ASSERT_EQ(x.sample_pos.size(), 31u);
  EXPECT_EQ(x.sample_node.back(), 60);
  EXPECT_DOUBLE_EQ(x.sample_pos.back(), 300);
  EXPECT_EQ(map.dim[1].samples_per_cell, 4);
  ASSERT_EQ(map.slices.size(), 2u + 3 + 3);
  EXPECT_STREQ(map.slices[1].which, "upper");
  ExpectSamplesAreTheField(map);
  // Arrows at X nodes 0, 6, ..., 60 and every Y node: 11 x 3 on the XY slices.
  const std::string vectors = SliceSvgs(map, map.slices[0])[0];
  size_t dots = 0;
  for (const std::string& c : Elements(vectors, "circle")) dots += TextAttr(c, "fill") == "#555555";
  EXPECT_EQ(dots, 33u);
}

// A rotary axis's wrap table: positions in degrees, corrections in arcsec, the end of the turn
// evaluated as its start.
TEST(image_table_map, RotaryAxisTableInDegreesAndArcsec) {
  ImageRequest r;
  r.axes = {{'X'}, {'A', table::AxisKind::kRotary, 1000000}};  // 0.001 deg per step
  AxisCorrections t;
  t.axis = 1;
  t.lattice = {5, 0, 90000};
  t.forward_steps = {0, 1, 2, 1, 0};
  t.wrap_period_steps = 360000;
  r.axis_tables.push_back(t);
  const LoadedImage img = ValueOf(LoadedImage::FromBytes(ValueOf(BuildImage(r)), "a.vct"));
  const TableMap map = ValueOf(MapTable(img, "a.vct"));
  EXPECT_FALSE(map.has_grid);
  ASSERT_EQ(map.axis_tables.size(), 1u);
  const MapAxisTable& a = map.axis_tables[0];
  EXPECT_DOUBLE_EQ(a.to, 360);
  const double arcsec_per_step = 0.001 * 3600;
  for (size_t i = 0; i < a.position.size(); ++i) {
    const double deg = a.position[i];
    const double steps = deg <= 180 ? deg / 90 : (360 - deg) / 90;
    EXPECT_NEAR(a.forward[i], steps * arcsec_per_step, 0.02) << deg;
    EXPECT_NEAR(a.reverse[i], a.forward[i], 1e-12) << deg;
  }
  const tools::JsonValue j = TableMapJson(map);
  EXPECT_EQ(j.get("axes")->array.at(1).get("correction_unit")->string, "arcsec");
  EXPECT_EQ(j.get("axes")->array.at(1).get("position_unit")->string, "deg");
  EXPECT_EQ(j.get("grid3"), nullptr);
  report::HtmlPage page("map");
  AddTableMapSections(&page, map, 2);
  EXPECT_NE(page.Render().find("correction, arcsec"), std::string::npos);
}

TEST(image_table_map, PageIsSelfContained) {
  const LoadedImage img = FieldImage(true);
  const TableMap map = ValueOf(MapTable(img, "field.vct"));
  report::HtmlPage page("map");
  AddTableMapSections(&page, map, 2);
  const std::string html = page.Render();
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("src="), std::string::npos);
  EXPECT_EQ(html.find("href="), std::string::npos);
  // 9 slices of 4 panels and one AXIS1D chart.
  size_t svgs = 0;
  for (size_t p = html.find("<svg"); p != std::string::npos; p = html.find("<svg", p + 1)) ++svgs;
  EXPECT_EQ(svgs, 9u * 4 + 1);
  EXPECT_NE(html.find("AXIS1D X"), std::string::npos);
  EXPECT_NE(html.find("magnified ×"), std::string::npos);
}

}  // namespace
}  // namespace volcomp::image
