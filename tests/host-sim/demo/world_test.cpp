// The simulated installation: the real firmware between the CNC and the drive checkers, at 1 MHz
// per axis, in every output pulse format; homing; a table over the simulated bus.
#include "volcomp/sim/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "volcomp/firmware/board_objects.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/sim/board_session.hpp"

namespace volcomp::sim {
namespace {

// Board settings for the machine of `wo`.
BoardSettings SettingsFor(const WorldOptions& wo) {
  const Expected<Machine> m = Machine::Create(wo.machine);
  EXPECT_TRUE(m.ok()) << m.error().message;
  return m.ok() ? BoardSettingsFor(*m) : BoardSettings{};
}

WorldOptions Options(PulseFormat output = PulseFormat::kStepDir) {
  WorldOptions wo;
  wo.board = SettingsFor(wo);
  for (int a = 0; a < 3; ++a) wo.board.board.axis[a].output_format = output;
  return wo;
}

// The installation of `wo`, started.
std::unique_ptr<World> Started(const WorldOptions& wo) {
  Expected<std::unique_ptr<World>> w = World::Create(wo);
  EXPECT_TRUE(w.ok()) << w.error().message;
  if (!w.ok()) return nullptr;
  const Outcome started = (*w)->Start();
  EXPECT_TRUE(started.ok()) << started.error().message;
  return std::move(w).value();
}

void ExpectCleanRun(World& w) {
  w.RunFor(2000000);
  EXPECT_TRUE(w.CheckAtRest());
  const StepAudit audit = w.Audit();
  EXPECT_EQ(audit.lost_steps, 0u);
  EXPECT_EQ(audit.tick_mismatches, 0u);
  EXPECT_EQ(audit.timing_violations, 0u);
  EXPECT_EQ(audit.overruns, 0u);
  const LatencySummary lat = w.latency().Summarize();
  EXPECT_EQ(lat.samples, audit.input_steps);
  EXPECT_EQ(lat.unmatched, 0u);
  EXPECT_LE(lat.max_ticks, 2.0);
  EXPECT_GT(lat.max_ticks, 0.5);  // it is measured, not zero
}

class SimWorldFormats : public ::testing::TestWithParam<PulseFormat> {};

TEST_P(SimWorldFormats, PassThroughAtOneMegahertzLosesNothing) {
  const std::unique_ptr<World> world = Started(Options(GetParam()));
  ASSERT_TRUE(world);
  World& w = *world;
  w.cnc().QueueRapid({250000, 0, 0});       // X alone at 1 MHz
  w.cnc().QueueRapid({0, 200000, 150000});  // back on X, Y and Z together
  w.cnc().QueueRapid({120000, -30000, 0});
  ASSERT_TRUE(w.RunUntilCncIdle(10000000000ull));
  EXPECT_NEAR(w.cnc().peak_step_rate_hz(), 1e6, 1);
  ExpectCleanRun(w);
  // Without a table the drives are exactly where the CNC sent them.
  const auto d = w.DriveSteps();
  EXPECT_EQ(d[0], 120000);
  EXPECT_EQ(d[1], -30000);
  EXPECT_EQ(d[2], 0);
}

INSTANTIATE_TEST_SUITE_P(Outputs,
                         SimWorldFormats,
                         ::testing::Values(PulseFormat::kStepDir,
                                           PulseFormat::kCwCcw,
                                           PulseFormat::kQuadrature));

TEST(SimWorld, HomingReferencesTheBoardWhereTheSwitchCloses) {
  const WorldOptions wo = Options();
  const std::unique_ptr<World> world = Started(wo);
  ASSERT_TRUE(world);
  World& w = *world;
  w.cnc().QueueHome(7);
  ASSERT_TRUE(w.RunUntilCncIdle(60000000000ull));
  w.RunFor(1000000);
  const ControlTick& e = w.board().app().control_tick();
  EXPECT_TRUE(e.all_referenced());
  const auto d = w.DriveSteps();
  for (int a = 0; a < 3; ++a) {
    const Machine& m = w.machine();
    // The drive count at which the axis reaches the switch: (switch - power-up) / step.
    const int64_t closes = std::llround((m.home_switch_mm(a) - m.power_up_mm(a)) / m.step_mm(a));
    EXPECT_EQ(d[static_cast<size_t>(a)], closes) << a;
    const int32_t home = wo.board.board.axis[a].home_position_steps;
    EXPECT_EQ(home, std::lround(m.home_switch_mm(a) / m.step_mm(a)));
    EXPECT_EQ(e.machine_position(static_cast<uint8_t>(a)), home) << a;
    EXPECT_EQ(w.cnc().position(a), home) << a;
  }
  ExpectCleanRun(w);
}

// A GRID3 with the same correction at every node: (37, -12, 5) steps everywhere.
std::vector<uint8_t> ConstantImage() {
  image::ImageRequest req;
  req.table_id = 7;
  for (char name : {'X', 'Y', 'Z'}) {
    image::AxisDef d;
    d.name = name;
    d.resolution_e9 = 1000000;
    req.axes.push_back(d);
  }
  image::GridCorrections g;
  for (auto& l : g.lattice) l = {2, 0, 500000};
  for (int n = 0; n < 8; ++n) {
    g.correction_steps.push_back(37);
    g.correction_steps.push_back(-12);
    g.correction_steps.push_back(5);
  }
  req.grid = g;
  req.frac_bits = 0;
  return image::BuildImage(req).value();
}

TEST(SimWorld, TableOverTheBusThenCompensatedMotionLosesNothing) {
  const std::unique_ptr<World> world = Started(Options());
  ASSERT_TRUE(world);
  World& w = *world;
  const std::vector<uint8_t> image = ConstantImage();
  std::ostringstream log;
  const Expected<UploadReport> uploaded = UploadTable(w, image, log);
  ASSERT_TRUE(uploaded.ok()) << uploaded.error().message;
  const UploadReport& up = uploaded.value();
  EXPECT_EQ(up.staged_crc, up.image_crc);
  EXPECT_GT(up.transfer_s, 0);
  // Not referenced yet: the board refuses to activate.
  const Expected<ActivationReport> refused = ActivateTable(w, up.image_crc);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kIoError);
  EXPECT_NE(refused.error().message.find("referenced"), std::string::npos)
      << refused.error().message;

  w.cnc().QueueHome(7);
  ASSERT_TRUE(w.RunUntilCncIdle(60000000000ull));
  w.RunFor(150000000);
  const Expected<ActivationReport> act = ActivateTable(w, up.image_crc);
  ASSERT_TRUE(act.ok()) << act.error().message;
  w.RunFor(300000000);
  EXPECT_NE(ReadDeviceState(w) & canopen::kStateEngaged, 0);
  EXPECT_TRUE(w.CheckAtRest());
  const std::array<int64_t, 3> c = {37, -12, 5};
  auto d = w.DriveSteps();
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(d[static_cast<size_t>(a)], w.cnc().count(a) + c[static_cast<size_t>(a)]) << a;
  }
  w.cnc().QueueRapid({300000, 250000, 180000});
  w.cnc().QueueRapid({10000, 20000, 30000});
  ASSERT_TRUE(w.RunUntilCncIdle(10000000000ull));
  ExpectCleanRun(w);
  d = w.DriveSteps();
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(d[static_cast<size_t>(a)], w.cnc().count(a) + c[static_cast<size_t>(a)]) << a;
  }
}

// The board takes an axis's AXIS1D direction from the motion of its drive, not of its command.
// Where the GRID3 moves an axis whose command stands still (here Y's correction grows with X,
// like a squareness error), the drive reverses without a reversal of the command, the machine's
// lost motion is taken up, and the reverse table compensates it. Outside truth: the carriage
// positions of the machine's play operator (20 µm dead band on Y, 1 µm steps).
TEST(SimWorld, CorrectionDrivenReversalIsBacklashCompensated) {
  WorldOptions wo = Options();
  wo.machine.wear.lost_motion = true;
  wo.machine.wear.lost_motion_um = {0, 20, 0};
  wo.board = SettingsFor(wo);
  const std::unique_ptr<World> world = Started(wo);
  ASSERT_TRUE(world);
  World& w = *world;
  image::ImageRequest req;
  req.table_id = 9;
  for (char name : {'X', 'Y', 'Z'}) {
    image::AxisDef d;
    d.name = name;
    d.resolution_e9 = 1000000;
    req.axes.push_back(d);
  }
  image::GridCorrections g;  // Y correction = 1e-3 x (0 at x = 0, 400 steps at x = 400 mm)
  for (auto& l : g.lattice) l = {2, -10000, 410000};
  for (int k = 0; k < 2; ++k) {
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        const double x = i == 0 ? -10000 : 400000;
        g.correction_steps.insert(g.correction_steps.end(), {0, 1e-3 * x, 0});
      }
    }
  }
  req.grid = g;
  image::AxisCorrections y;  // the dead band: reverse table 20 steps below the forward one
  y.axis = 1;
  y.lattice = {2, -10000, 300000};
  y.forward_steps = {0, 0};
  y.reverse_steps = {-20, -20};
  req.axis_tables.push_back(y);
  req.frac_bits = 0;
  const std::vector<uint8_t> image = image::BuildImage(req).value();
  std::ostringstream log;
  const Expected<UploadReport> up = UploadTable(w, image, log);
  ASSERT_TRUE(up.ok()) << up.error().message;
  w.cnc().QueueHome(7);
  ASSERT_TRUE(w.RunUntilCncIdle(60000000000ull));
  w.RunFor(150000000);
  ASSERT_TRUE(ActivateTable(w, up->image_crc).ok());
  w.RunFor(300000000);
  auto carriage_y_um = [&]() { return 1e3 * w.AxisPositions_mm().y; };

  w.cnc().QueueRapid({0, 100000, 0});  // Y forward onto 100 mm
  ASSERT_TRUE(w.RunUntilCncIdle(10000000000ull));
  w.RunFor(20000000);
  const double forward = carriage_y_um();
  w.cnc().QueueRapid({0, 120000, 0});  // Y reverses onto 100 mm: the reverse table takes it up
  w.cnc().QueueRapid({0, 100000, 0});
  ASSERT_TRUE(w.RunUntilCncIdle(10000000000ull));
  w.RunFor(20000000);
  EXPECT_NEAR(carriage_y_um(), forward, 1.0);  // compensated: within a step
  w.cnc().QueueRapid({0, 80000, 0});           // Y forward again onto 100 mm
  w.cnc().QueueRapid({0, 100000, 0});
  w.cnc().QueueRapid({300000, 100000, 0});  // X out: Y's drive follows +300 µm (same direction)
  ASSERT_TRUE(w.RunUntilCncIdle(10000000000ull));
  w.RunFor(20000000);
  EXPECT_NEAR(carriage_y_um(), forward + 300, 1.0);
  w.cnc().QueueRapid({0, 100000, 0});  // X back: Y's drive reverses by 300 µm, command still
  ASSERT_TRUE(w.RunUntilCncIdle(10000000000ull));
  w.RunFor(20000000);
  // The dead band is taken up and compensated by the reverse table: Y is where it was before X
  // went out, within a step (without it, off by the full 20 µm).
  EXPECT_NEAR(carriage_y_um(), forward, 1.0);
  EXPECT_TRUE(w.CheckAtRest());
}

}  // namespace
}  // namespace volcomp::sim
