// The tracker lattice (trilinear forward map of readings at every node, its inverse) and the
// shared build entry points (grid sources, GRID3 and AXIS1D sections): against maps given in
// closed form.
#include "volcomp/model/tracker_lattice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "volcomp/model/axis_section.hpp"
#include "volcomp/model/grid_section.hpp"
#include "volcomp/model/grid_source.hpp"
#include "volcomp/model/s500.hpp"

namespace volcomp::model {
namespace {

// Readings of `machine` at a lattice 0..X every h mm (x fastest).
TrackerLatticeData Sample(const std::function<Vec3(const Vec3&)>& machine,
                          const GridAxes& lattice) {
  TrackerLatticeData d;
  d.name = "sampled";
  d.lattice = lattice;
  for (uint32_t k = 0; k < lattice[2].nodes; ++k) {
    for (uint32_t j = 0; j < lattice[1].nodes; ++j) {
      for (uint32_t i = 0; i < lattice[0].nodes; ++i) {
        d.position_mm.push_back(machine({lattice[0].origin_mm + i * lattice[0].spacing_mm,
                                         lattice[1].origin_mm + j * lattice[1].spacing_mm,
                                         lattice[2].origin_mm + k * lattice[2].spacing_mm}));
      }
    }
  }
  return d;
}

const GridAxes kLattice = {GridAxis{0, 40, 6}, GridAxis{-20, 30, 5}, GridAxis{0, 50, 3}};

// A machine with squareness-like shear, a scale error and a cross-axis term z += k·x·y, which is
// multilinear: trilinear interpolation reproduces it exactly, the three-line methods cannot (their
// map is a sum of one-variable functions).
Vec3 Multilinear(const Vec3& q) {
  return {q.x * (1 + 40e-6) - 0.0011 * q.y + 0.003, q.y + 0.0005 * q.z, q.z + 2e-7 * q.x * q.y};
}

TEST(model_tracker_lattice, ReproducesAMultilinearMachineEverywhereIncludingBeyond) {
  const TrackerLattice t(Sample(Multilinear, kLattice));
  for (const Vec3& q : {Vec3{0, -20, 0}, Vec3{200, 100, 100}, Vec3{13.7, 41.2, 77.7},
                        Vec3{-5, -30, -8}, Vec3{210, 110, 106}}) {
    const Vec3 want = Multilinear(q);
    EXPECT_LT(Norm(t.Position_mm(q) - want) * 1e3, 1e-9) << q.x << " " << q.y << " " << q.z;
  }
  // The inverse lands within its tolerance, and on the machine itself (the map is exact here).
  const Vec3 target = {123.4, 56.7, 89.0};
  const InverseSolution s = t.ExactInverse(target);
  EXPECT_TRUE(s.converged);
  EXPECT_LT(Norm(Multilinear(s.command_mm) - target) * 1e3, 1e-5);
}

TEST(model_tracker_lattice, InsideACellItIsTrilinearInTheNodes) {
  // A non-multilinear machine: between nodes the lattice gives the mean of the cell's corners at
  // the centre, and the node readings at the nodes.
  const auto bumpy = [](const Vec3& q) {
    return Vec3{q.x, q.y, q.z + 1e-3 * std::sin(q.x / 17.0) * std::cos(q.y / 11.0)};
  };
  const TrackerLatticeData d = Sample(bumpy, kLattice);
  const TrackerLattice t(d);
  EXPECT_LT(Norm(t.Position_mm({80, 10, 50}) - bumpy({80, 10, 50})), 1e-12);
  Vec3 mean;
  for (double x : {40.0, 80.0}) {
    for (double y : {10.0, 40.0}) {
      for (double z : {0.0, 50.0}) mean += 0.125 * bumpy({x, y, z});
    }
  }
  EXPECT_LT(Norm(t.Position_mm({60, 25, 25}) - mean), 1e-12);
}

TEST(model_tracker_lattice, CsvGivesTheLatticeAndRefusesHoles) {
  std::string csv = "x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm\n";
  for (int k = 0; k < 2; ++k) {
    for (int j = 0; j < 3; ++j) {
      for (int i = 1; i >= 0; --i) {  // any order
        csv += std::to_string(i * 10) + "," + std::to_string(j * 20) + "," + std::to_string(k * 5) +
               "," + std::to_string(i * 10 + 0.001) + "," + std::to_string(j * 20) + "," +
               std::to_string(k * 5 - 0.002 * j) + "\n";
      }
    }
  }
  const TrackerLatticeData d = TrackerLatticeFromCsv(tools::CsvTable::ParseString(csv, "t.csv"));
  EXPECT_EQ(d.lattice[0].nodes, 2u);
  EXPECT_EQ(d.lattice[1].nodes, 3u);
  EXPECT_EQ(d.lattice[2].nodes, 2u);
  EXPECT_DOUBLE_EQ(d.lattice[1].spacing_mm, 20.0);
  EXPECT_NEAR(TrackerLattice(d).Position_mm({10, 40, 5}).z, 5 - 0.004, 1e-12);
  // Drop one node: refused with the count.
  const std::string holed = csv.substr(0, csv.rfind('\n', csv.size() - 2) + 1);
  try {
    TrackerLatticeFromCsv(tools::CsvTable::ParseString(holed, "t.csv"));
    FAIL() << "a missing node must be refused";
  } catch (const tools::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("11 nodes for a 2x3x2 lattice"), std::string::npos)
        << e.what();
  }
  // A node given twice.
  try {
    TrackerLatticeFromCsv(tools::CsvTable::ParseString(csv + "0,0,0,0,0,0\n", "t.csv"));
    FAIL() << "a repeated node must be refused";
  } catch (const tools::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("node given twice"), std::string::npos) << e.what();
  }
}

TEST(model_tracker_lattice, GridSectionHoldsTheInverseOfTheCrossAxisTerm) {
  // z += k·x·y does not involve z, so the exact inverse is q = T − (0, 0, k·Tx·Ty'), with the
  // x, y part of the inverse first; on a map whose x, y are the identity: c(T) = (0, 0, −k·Tx·Ty).
  const auto sag = [](const Vec3& q) { return Vec3{q.x, q.y, q.z + 3e-7 * q.x * q.y}; };
  const GridSource src = TrackerLatticeGridSource(TrackerLattice(Sample(sag, kLattice)));
  EXPECT_EQ(src.min_mm[1], -20);
  EXPECT_EQ(src.max_mm[1], 100);
  EXPECT_EQ(src.natural_spacing_mm[2], 50);
  ASSERT_NE(src.forward_or_null(), nullptr);
  GridBuildOptions o;
  o.min_mm = src.min_mm;
  o.max_mm = src.max_mm;
  o.spacing_mm = {20, 20, 25};
  o.step_mm = {0.001, 0.001, 0.001};
  std::vector<image::AxisDef> axes(3);
  for (int a = 0; a < 3; ++a) {
    axes[static_cast<std::size_t>(a)].name = "XYZ"[a];
    axes[static_cast<std::size_t>(a)].resolution_e9 = 1000000;
  }
  const GridSection g = BuildGridSection(o, axes, src);
  const CorrectionGrid& grid = g.build.grid;
  for (uint32_t k = 0; k < grid.axes[2].nodes; ++k) {
    for (uint32_t j = 0; j < grid.axes[1].nodes; ++j) {
      for (uint32_t i = 0; i < grid.axes[0].nodes; ++i) {
        const Vec3 t = grid.NodePosition(i, j, k);
        const Vec3 c = grid.correction_mm[grid.Index(i, j, k)];
        EXPECT_NEAR(c.x * 1e3, 0, 1e-9);
        EXPECT_NEAR(c.z * 1e3, -3e-7 * t.x * t.y * 1e3, 1e-6);
      }
    }
  }
  // The section is in steps (1 µm): the largest correction, at (200, 100), is −6 µm.
  EXPECT_NEAR(g.section.correction_steps.back(), -3e-7 * 200 * 100 * 1e3, 1e-6);
  EXPECT_EQ(g.info.at("lattice_mm"), "0:20:200,-20:20:100,0:25:100");
  EXPECT_NE(g.info.at("method").find("lattice"), std::string::npos);
}

// Measured through a table in force that adds a constant (10, −5, 3) µm: the readings are of
// F(u + c); the new grid must hold F's own inverse correction, (0, 0, −k·x·y), i.e. the table in
// force is composed in, not forgotten.
TEST(model_tracker_lattice, ThroughATableInForceTheNewGridReplacesIt) {
  const Vec3 c = {0.010, -0.005, 0.003};
  const auto sag = [](const Vec3& q) { return Vec3{q.x, q.y, q.z + 3e-7 * q.x * q.y}; };
  const auto through = [&](const Vec3& u) { return sag(u + c); };
  CorrectionGrid in_force;
  in_force.axes = {GridAxis{-100, 300, 3}, GridAxis{-100, 300, 3}, GridAxis{-100, 300, 3}};
  in_force.correction_mm.assign(27, c);
  const GridSource src =
      TrackerLatticeThroughGridSource(TrackerLattice(Sample(through, kLattice)), in_force);
  for (const Vec3& t : {Vec3{0, 0, 0}, Vec3{200, 100, 100}, Vec3{120, 40, 50}}) {
    const Vec3 q = src.inverse(t);
    EXPECT_NEAR((q.x - t.x) * 1e3, 0, 1e-6);
    EXPECT_NEAR((q.y - t.y) * 1e3, 0, 1e-6);
    EXPECT_NEAR((q.z - t.z) * 1e3, -3e-7 * t.x * t.y * 1e3, 1e-5);
    EXPECT_LT(Norm(src.forward(q) - t) * 1e3, 1e-5);  // what the builder verifies at the nodes
  }
}

TEST(model_grid_source, ModelSourceIsTheModelsExtentSpacingAndMaps) {
  const Model s500 = S500Model();
  const GridSource src = ModelGridSource(s500);
  EXPECT_EQ(src.max_mm[0], 400);
  EXPECT_EQ(src.max_mm[2], 200);
  EXPECT_EQ(src.natural_spacing_mm[0], 20);  // Table 3.2 every 20 mm
  EXPECT_EQ(src.natural_spacing_mm[1], 10);
  const Vec3 q = {123, 45, 67};
  const Vec3 p = src.forward(q);
  EXPECT_LT(Norm(src.forward(src.inverse(p)) - p) * 1e3, 1e-5);
  EXPECT_EQ(src.info.at("formulation"), "physical, exact rotations, chain |XYZ");
}

TEST(model_axis_section, StepsOfTheAxisAndTheKindChecked) {
  // Forward deviation +5 µm everywhere, reverse −3 µm: corrections −5 and +3 µm, i.e. −10 and
  // +6 steps of 0.5 µm.
  PositioningData d;
  d.position = {0, 10, 20};
  d.dev_forward = {5, 5, 5};
  d.dev_reverse = {-3, -3, -3};
  image::AxisDef x;
  x.name = 'X';
  x.resolution_e9 = 500000;
  const AxisSection s = BuildAxisSection(d, Axis1dOptions{}, x, 0, false);
  ASSERT_EQ(s.section.forward_steps.size(), 3u);
  EXPECT_NEAR(s.section.forward_steps[1], -10, 1e-6);
  EXPECT_NEAR(s.section.reverse_steps[2], 6, 1e-6);
  EXPECT_EQ(s.section.lattice.spacing_steps, 20000u);
  image::AxisDef b = x;
  b.name = 'B';
  b.kind = table::AxisKind::kRotary;
  try {
    BuildAxisSection(d, Axis1dOptions{}, b, 1, false);
    FAIL() << "a linear test for a rotary axis must be refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("axis B is rotary"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace volcomp::model
