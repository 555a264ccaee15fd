// The ISO 230-4 test program read back by a small RS274/NGC reader of this test's own (modal
// plane, motion and position; I/J/K offsets from the start), its geometry checked against the
// definitions: every arc on the nominal circle about the nominal centre, G3 counter-clockwise
// seen from the plane's positive normal (+Z for G17, +Y for G18, +X for G19, the RS274/NGC rule),
// and each measured 360° inside one blended run of the same direction with the run-in before it
// and the run-out after it.
#include "volcomp/metrology/circular_program.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::ValueOf;

using V3 = std::array<double, 3>;

struct Arc {
  bool ccw = false;
  int plane = 17;  // G17/G18/G19
  V3 start{}, end{}, centre{};
  std::string comment;
};

struct Program {
  bool blended = false;  // G64 in force at the arcs
  int feed_words = 0;
  double feed = 0;
  V3 first_position{};  // after the first G0
  std::vector<Arc> arcs;
  // Any other line with a word (M0, G4, G1 ...) after the first G0, with the number of arcs
  // before it.
  std::vector<std::pair<std::size_t, std::string>> other;
};

Program Parse(const std::string& text) {
  Program p;
  std::istringstream in(text);
  std::string line;
  int plane = 17, motion = -1;
  V3 pos{};
  bool positioned = false;
  while (std::getline(in, line)) {
    std::string comment, code;
    bool in_comment = false;
    for (char c : line) {
      if (c == '(')
        in_comment = true;
      else if (c == ')')
        in_comment = false;
      else
        (in_comment ? comment : code) += c;
    }
    std::map<char, std::vector<double>> words;
    for (std::size_t i = 0; i < code.size();) {
      const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(code[i])));
      if (!std::isalpha(static_cast<unsigned char>(letter))) {
        ++i;
        continue;
      }
      char* end = nullptr;
      const double v = std::strtod(code.c_str() + i + 1, &end);
      words[letter].push_back(v);
      i = static_cast<std::size_t>(end - code.c_str());
    }
    if (words.empty()) continue;
    bool motion_word = false;
    const std::vector<double> g_words = words.count('G') ? words['G'] : std::vector<double>{};
    for (double g : g_words) {
      const int n = static_cast<int>(std::lround(g));
      if (n >= 17 && n <= 19) plane = n;
      if (n == 64) p.blended = true;
      if (n == 61) p.blended = false;
      if (n <= 3) motion = n, motion_word = true;
    }
    if (words.count('F')) ++p.feed_words, p.feed = words['F'][0];
    V3 target = pos;
    const char* axis = "XYZ";
    bool has_axis = false;
    for (int a = 0; a < 3; ++a) {
      if (words.count(axis[a])) target[a] = words[axis[a]][0], has_axis = true;
    }
    if (!has_axis) {
      if (words.count('M') || (!g_words.empty() && !motion_word && g_words[0] == 4)) {
        if (positioned) p.other.emplace_back(p.arcs.size(), line);
      }
      continue;
    }
    if (motion == 0 && !positioned) {
      p.first_position = target;
      positioned = true;
    } else if (motion == 2 || motion == 3) {
      Arc arc;
      arc.ccw = motion == 3;
      arc.plane = plane;
      arc.start = pos;
      arc.end = target;
      arc.centre = pos;
      const char* offset = "IJK";
      for (int a = 0; a < 3; ++a) {
        if (words.count(offset[a])) arc.centre[a] += words[offset[a]][0];
      }
      arc.comment = comment;
      p.arcs.push_back(arc);
    } else {
      p.other.emplace_back(p.arcs.size(), line);
    }
    pos = target;
  }
  return p;
}

double Dist(const V3& a, const V3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// The plane's positive normal (RS274/NGC: arcs are seen from the positive end of the axis
// perpendicular to the plane).
V3 Normal(int plane) {
  if (plane == 18) return {0, 1, 0};
  if (plane == 19) return {1, 0, 0};
  return {0, 0, 1};
}

constexpr double kPi = 3.14159265358979323846;

// The arc's sweep in degrees, in its own sense, from the geometry only: the signed angle between
// start and end seen from the normal; an arc ending where it starts is a full circle.
double Sweep(const Arc& a) {
  const V3 n = Normal(a.plane);
  V3 r0, r1;
  for (int i = 0; i < 3; ++i) r0[i] = a.start[i] - a.centre[i], r1[i] = a.end[i] - a.centre[i];
  const V3 cross{r0[1] * r1[2] - r0[2] * r1[1], r0[2] * r1[0] - r0[0] * r1[2],
                 r0[0] * r1[1] - r0[1] * r1[0]};
  const double sin_part = cross[0] * n[0] + cross[1] * n[1] + cross[2] * n[2];
  const double cos_part = r0[0] * r1[0] + r0[1] * r1[1] + r0[2] * r1[2];
  double ccw_deg = std::atan2(sin_part, cos_part) * 180.0 / kPi;  // (−180, 180]
  if (Dist(a.start, a.end) < 1e-6) return 360.0;
  if (!a.ccw) ccw_deg = -ccw_deg;
  return ccw_deg < 0 ? ccw_deg + 360.0 : ccw_deg;
}

void CheckProgram(const CircularProgramOptions& o, int plane_word) {
  SCOPED_TRACE("plane G" + std::to_string(plane_word));
  const std::string text = ValueOf(EmitCircularProgram(o));
  const Program p = Parse(text);
  const V3 c = o.centre_mm;
  EXPECT_TRUE(p.blended) << text;
  EXPECT_EQ(p.feed_words, 1);
  EXPECT_DOUBLE_EQ(p.feed, o.feed_mm_min);
  // Nothing but the arcs from the first arc to the last: no stop, dwell or straight move.
  for (const auto& [arcs_before, line] : p.other) {
    EXPECT_TRUE(arcs_before == 0 || arcs_before == p.arcs.size()) << line;
  }
  EXPECT_NEAR(Dist(p.first_position, c), o.radius_mm, 1e-4);
  ASSERT_EQ(p.arcs.size(), 6u) << text;
  // Every arc on the nominal circle about the nominal centre, in the plane, continuous.
  V3 previous_end = p.first_position;
  for (const Arc& a : p.arcs) {
    EXPECT_EQ(a.plane, plane_word);
    EXPECT_NEAR(Dist(a.centre, c), 0.0, 1e-4) << a.comment;
    EXPECT_NEAR(Dist(a.start, c), o.radius_mm, 1e-4) << a.comment;
    EXPECT_NEAR(Dist(a.end, c), o.radius_mm, 1e-4) << a.comment;
    EXPECT_NEAR(Dist(a.start, previous_end), 0.0, 1e-9);
    const V3 n = Normal(a.plane);
    for (int i = 0; i < 3; ++i) {
      if (n[i] != 0) {
        EXPECT_NEAR(a.end[i], c[i], 1e-9) << "leaves the plane: " << a.comment;
      }
    }
    previous_end = a.end;
  }
  // CCW first, then CW; per direction: run-in, the measured full circle, run-out.
  for (int d = 0; d < 2; ++d) {
    const bool ccw = d == 0;
    const Arc& in = p.arcs[3 * d];
    const Arc& measured = p.arcs[3 * d + 1];
    const Arc& out = p.arcs[3 * d + 2];
    for (const Arc* a : {&in, &measured, &out}) EXPECT_EQ(a->ccw, ccw) << a->comment;
    EXPECT_NE(measured.comment.find("measured"), std::string::npos) << measured.comment;
    EXPECT_NEAR(Sweep(measured), 360.0, 1e-9);
    EXPECT_NEAR(Sweep(in), o.run_deg, 1e-3) << in.comment;
    EXPECT_NEAR(Sweep(out), o.run_deg, 1e-3) << out.comment;
    EXPECT_GE(Sweep(in), 45.0 - 1e-3);
    EXPECT_GE(Sweep(out), 45.0 - 1e-3);
  }
  // The measured circles start at the start angle: the CCW run-in ends there, a quarter turn
  // counter-clockwise of the start angle lies `run` further along for the CCW run-out.
  const double t = o.start_angle_deg * kPi / 180.0;
  V3 at = c;
  const int first = plane_word == 17 ? 0 : plane_word == 18 ? 2 : 1;
  const int second = plane_word == 17 ? 1 : plane_word == 18 ? 0 : 2;
  at[first] += o.radius_mm * std::cos(t);
  at[second] += o.radius_mm * std::sin(t);
  EXPECT_NEAR(Dist(p.arcs[1].start, at), 0.0, 1e-4);
  EXPECT_NEAR(Dist(p.arcs[4].start, at), 0.0, 1e-4);
  // The program ends where it began: the CW run-out retraces the CCW run-in.
  EXPECT_NEAR(Dist(p.arcs[5].end, p.first_position), 0.0, 1e-4);
}

TEST(CircularProgram, GeometryInEveryPlane) {
  CircularProgramOptions o;
  o.radius_mm = 100;
  o.centre_mm = {250, -40, 12.5};
  o.feed_mm_min = 2000;
  o.plane = CircularPlane::kXY;
  CheckProgram(o, 17);
  o.plane = CircularPlane::kZX;
  o.run_deg = 45;
  o.start_angle_deg = 30;
  CheckProgram(o, 18);
  o.plane = CircularPlane::kYZ;
  o.run_deg = 180;
  o.start_angle_deg = -100;
  CheckProgram(o, 19);
}

TEST(CircularProgram, G3IsCounterClockwiseSeenFromThePositiveNormal) {
  // XY, start 0°, run 90°: the CCW run-in starts at −90° (0, −R) and ends at 0° (R, 0).
  CircularProgramOptions o;
  o.radius_mm = 10;
  const Program p = Parse(ValueOf(EmitCircularProgram(o)));
  ASSERT_EQ(p.arcs.size(), 6u);
  EXPECT_NEAR(p.first_position[0], 0.0, 1e-9);
  EXPECT_NEAR(p.first_position[1], -10.0, 1e-9);
  EXPECT_TRUE(p.arcs[0].ccw);
  EXPECT_NEAR(p.arcs[0].end[0], 10.0, 1e-9);
  EXPECT_NEAR(p.arcs[0].end[1], 0.0, 1e-9);
  // The CCW run-out ends at 90° (0, R).
  EXPECT_NEAR(p.arcs[2].end[0], 0.0, 1e-9);
  EXPECT_NEAR(p.arcs[2].end[1], 10.0, 1e-9);
}

TEST(CircularProgram, PauseAtTheStartPoint) {
  CircularProgramOptions o;
  o.radius_mm = 150;
  o.pause = true;
  const std::string text = ValueOf(EmitCircularProgram(o));
  const std::size_t m0 = text.find("M0");
  ASSERT_NE(m0, std::string::npos);
  EXPECT_LT(text.find("G0 "), m0);
  EXPECT_LT(m0, text.find("G3 "));
}

// Hand-checked: R = 25.4 mm = 1 in about the origin, run-in 90°: the CCW run-in starts at -90°,
// (0, -1) in, and ends at 0°, (1, 0) in, with the centre 1 in along +Y of its start (J1);
// 254 mm/min is 10 in/min.
TEST(CircularProgram, InInches) {
  CircularProgramOptions o;
  o.radius_mm = 25.4;
  o.feed_mm_min = 254;
  o.inch = true;
  const std::string text = ValueOf(EmitCircularProgram(o));
  EXPECT_NE(text.find("\nG20 G90 G94 G17 G64\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("G21"), std::string::npos) << text;
  EXPECT_NE(text.find("G0 X0.00000 Y-1.00000 Z0.00000 (start of the CCW run-in)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\nF10.000\nG3 X1.00000 Y0.00000 I0.00000 J1.00000 (CCW run-in 90 deg)\n"),
            std::string::npos)
      << text;
}

TEST(CircularProgram, ImpossiblePlansAreRefused) {
  CircularProgramOptions o;
  testing::ExpectFailure(EmitCircularProgram(o), Error::kInvalidArgument, {"radius"});
  o.radius_mm = 50;
  o.run_deg = 0;
  testing::ExpectFailure(EmitCircularProgram(o), Error::kInvalidArgument, {"(0, 180]"});
  o.run_deg = 90;
  o.feed_mm_min = -1;
  testing::ExpectFailure(EmitCircularProgram(o), Error::kInvalidArgument, {"feed"});
}

}  // namespace
}  // namespace volcomp::metrology
