// The simulated machine's own kinematics (host-sim/machine, homogeneous transforms) against the
// table builders' formulation (tools/model rigid_body, Rodrigues' rotations applied axis by axis):
// two independent implementations of the same definitions must agree to 1e-6 µm, so a sign or
// convention error on either side fails here. Plus cases worked out by hand.
#include "volcomp/sim/rigid_body_kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "volcomp/datasets/s500.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/sim/machine.hpp"
#include "volcomp/sim/random.hpp"

namespace volcomp::sim {
namespace {

// The tools/model tool point: nominal (q + r) plus its error.
Xyz ModelToolPoint_mm(const model::Model& m, const Xyz& q) {
  const model::Vec3 v = {q[0], q[1], q[2]};
  const model::Vec3 p = v + m.tool_offset_mm + 1e-3 * model::ToolPointError_um(m, v);
  return {p.x, p.y, p.z};
}

double Distance_um(const Xyz& a, const Xyz& b) {
  return 1e3 * std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                         (a[2] - b[2]) * (a[2] - b[2]));
}

// Worst disagreement over `n` random positions from 20 mm below to 20 mm beyond every table.
double WorstDisagreement_um(const model::Model& m, uint64_t seed, int n) {
  const RigidBodyKinematics k(GeometryOf(m));
  Random rng(seed);
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    Xyz q;
    for (size_t a = 0; a < 3; ++a) {
      q[a] = rng.Uniform(m.axes[a].min_mm() - 20, m.axes[a].max_mm() + 20);
    }
    worst = std::max(worst, Distance_um(k.ToolPoint_mm(q), ModelToolPoint_mm(m, q)));
  }
  return worst;
}

TEST(SimKinematics, AgreesWithTheBuildersModelOnTheS500) {
  EXPECT_LE(WorstDisagreement_um(datasets::S500Model(), 1, 5000), 1e-6);
}

// Random 21-parameter machines: errors up to 300 µm and 2000 µrad (second-order terms of tens of
// nm), every chain order and workpiece split, carriage tables, tool offsets, angle scales.
TEST(SimKinematics, AgreesWithTheBuildersModelOnRandomMachines) {
  Random rng(7);
  const char* chains[][2] = {{"", "XYZ"}, {"Y", "XZ"}, {"XY", "Z"}, {"ZX", "Y"},
                             {"", "ZYX"}, {"YZX", ""}, {"X", "ZY"}};
  for (int trial = 0; trial < 28; ++trial) {
    model::Model m;
    for (size_t a = 0; a < 3; ++a) {
      std::vector<double> pos;
      std::vector<model::AxisErrorSample> rows;
      double p = rng.Uniform(-50, 10);
      const int n = 2 + static_cast<int>(rng.Uniform(0, 12));
      for (int i = 0; i < n; ++i) {
        pos.push_back(p);
        p += rng.Uniform(3, 60);
        model::AxisErrorSample s;
        for (int c = 0; c < 3; ++c) {
          s.linear_um[c] = rng.Uniform(-300, 300);
          s.angular_urad[c] = rng.Uniform(-2000, 2000);
        }
        rows.push_back(s);
      }
      m.axes[a] = model::AxisErrorTable::Create(pos, rows).value();
    }
    m.squareness = {rng.Uniform(-2000, 2000), rng.Uniform(-2000, 2000), rng.Uniform(-2000, 2000)};
    m.tool_offset_mm = {rng.Uniform(-100, 100), rng.Uniform(-100, 100), rng.Uniform(-300, 0)};
    const auto& c = chains[trial % 7];
    m.chain = model::KinematicChain::Parse(c[0], c[1]).value();
    m.chain.workpiece_errors =
        trial % 2 == 0 ? model::ErrorSide::kRelative : model::ErrorSide::kCarriage;
    m.angle_scale = trial % 3 == 0 ? 1.0 : rng.Uniform(0.5, 2.0);
    EXPECT_LE(WorstDisagreement_um(m, 100 + static_cast<uint64_t>(trial), 500), 1e-6)
        << "trial " << trial << " chain " << m.chain.ToString();
  }
}

MachineGeometry Flat() {
  MachineGeometry g;
  for (auto& rows : g.axes)
    rows = {ErrorMotionRow{0, {0, 0, 0}, {0, 0, 0}}, ErrorMotionRow{500, {0, 0, 0}, {0, 0, 0}}};
  return g;
}

// Outside truth, worked by hand.
TEST(SimKinematics, HandWorkedCases) {
  {  // No errors: the tool point is the axis positions plus the tool offset.
    MachineGeometry g = Flat();
    g.tool_offset_mm = {1, 2, -50};
    const Xyz p = RigidBodyKinematics(g).ToolPoint_mm({10, 20, 30});
    EXPECT_NEAR(p[0], 11, 1e-12);
    EXPECT_NEAR(p[1], 22, 1e-12);
    EXPECT_NEAR(p[2], -20, 1e-12);
  }
  {  // Pitch E_BX = 100 µrad of X (first in the chain) with Z at 200 mm: Abbe error 20 µm in x,
     // and z shortened by 200 (1 − cos 1e-4) = 1 nm.
    MachineGeometry g = Flat();
    for (ErrorMotionRow& r : g.axes[0]) r.angular_urad = {0, 100, 0};
    const Xyz p = RigidBodyKinematics(g).ToolPoint_mm({50, 0, 200});
    EXPECT_NEAR(1e3 * (p[0] - 50), 200 * std::sin(1e-4) * 1e3, 1e-9);
    EXPECT_NEAR(1e3 * (p[2] - 200), -200 * (1 - std::cos(1e-4)) * 1e3, 1e-9);
  }
  {  // The last axis's rotation acts only on the tool offset: yaw E_CZ = 1000 µrad, offset
     // (100, 0, 0) mm turns the tool point by 100 (sin, cos − 1).
    MachineGeometry g = Flat();
    g.tool_offset_mm = {100, 0, 0};
    for (ErrorMotionRow& r : g.axes[2]) r.angular_urad = {0, 0, 1000};
    const Xyz p = RigidBodyKinematics(g).ToolPoint_mm({0, 300, 40});
    EXPECT_NEAR(p[0], 100 * std::cos(1e-3), 1e-12);
    EXPECT_NEAR(p[1], 300 + 100 * std::sin(1e-3), 1e-12);
    EXPECT_NEAR(p[2], 40, 1e-12);
  }
  {  // Squareness: C0Y = 1000 µrad tilts Y toward −x; B0Z, A0Z tilt Z toward +x and −y.
    MachineGeometry g = Flat();
    g.c0y_urad = 1000;
    g.b0z_urad = 500;
    g.a0z_urad = 200;
    const Xyz p = RigidBodyKinematics(g).ToolPoint_mm({0, 100, 100});
    EXPECT_NEAR(p[0], -100 * std::sin(1e-3) + 100 * std::cos(2e-4) * std::sin(5e-4), 1e-12);
    EXPECT_NEAR(p[1], 100 * std::cos(1e-3) - 100 * std::sin(2e-4), 1e-12);
    EXPECT_NEAR(p[2], 100 * std::cos(2e-4) * std::cos(5e-4), 1e-12);
  }
  {  // Tables: linear between rows (E_XX 0 → 10 µm over 0..100 mm), end rows held beyond.
    MachineGeometry g = Flat();
    g.axes[0] = {ErrorMotionRow{0, {0, 0, 0}, {0, 0, 0}},
                 ErrorMotionRow{100, {10, 4, 0}, {0, 0, 0}}};
    const RigidBodyKinematics k(g);
    EXPECT_NEAR(1e3 * (k.ToolPoint_mm({25, 0, 0})[0] - 25), 2.5, 1e-9);
    EXPECT_NEAR(1e3 * k.ToolPoint_mm({25, 0, 0})[1], 1.0, 1e-9);
    EXPECT_NEAR(1e3 * (k.ToolPoint_mm({150, 0, 0})[0] - 150), 10, 1e-9);
    EXPECT_NEAR(1e3 * (k.ToolPoint_mm({-20, 0, 0})[0] + 20), 0, 1e-9);
  }
  {  // Carriage tables of a workpiece axis count with the opposite sign.
    MachineGeometry g = Flat();
    g.carries_workpiece = {false, true, false};
    g.workpiece_tables_are_carriage_motion = true;
    for (ErrorMotionRow& r : g.axes[1]) r.linear_um = {0, 0, 7};
    EXPECT_NEAR(1e3 * RigidBodyKinematics(g).ToolPoint_mm({0, 10, 0})[2], -7, 1e-9);
  }
}

}  // namespace
}  // namespace volcomp::sim
