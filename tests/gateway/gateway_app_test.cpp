// The board application in gateway mode (firmware/app GatewayApp) on the mock HAL: a CNC master
// and three CSP drives around it, a table uploaded over the controller bus by block download,
// referencing and the activation rules, corrected targets and feedback cycle by cycle against a
// closed-form expectation (a table that is linear in the position, which trilinear interpolation
// reproduces exactly), e-stop, the board's own frames, and tables persisting in flash files.
#include "volcomp/firmware/gateway_app.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <string>
#include <vector>

#include "csp_drives.hpp"
#include "temp_paths.hpp"
#include "test_tables.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen_client/node_objects.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"
#include "volcomp/hal/linux/file_flash.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"

namespace volcomp {
namespace {

using canopen::ObjectId;
using canopen_client::SdoClient;
using TransferResult = canopen_client::SdoExpected<std::vector<uint8_t>>;
using hal::InputLine;

constexpr uint8_t kNode = 0x10;
constexpr uint32_t kRpdo[3] = {0x201, 0x202, 0x203};
constexpr uint32_t kTpdo[3] = {0x181, 0x182, 0x183};
// Drive positions at the home (reference) point, and the machine positions assigned there.
constexpr int32_t kHomeTarget[3] = {501000, -20000, 7000};
constexpr int32_t kHomeMachine[3] = {1000, 500, 0};

// The table: correction (steps) = linear function of the machine position (steps), so that the
// trilinear interpolation is exact and the expectation is a formula.
double Exact(int axis, const double m[3]) {
  switch (axis) {
    case 0:
      return 20.0 + m[0] / 200.0;
    case 1:
      return -10.0 + m[1] / 400.0;
    default:
      return 3.0 + (m[0] + m[1]) / 1000.0;
  }
}

testing::AlignedBytes LinearTable(uint32_t id) {
  testing::GridCase g;
  g.frac_bits = 8;
  for (auto& d : g.dim) d = {5, 0, 1000};  // 0..4000 steps
  for (uint32_t k = 0; k < 5; ++k) {
    for (uint32_t j = 0; j < 5; ++j) {
      for (uint32_t i = 0; i < 5; ++i) {
        const double m[3] = {1000.0 * i, 1000.0 * j, 1000.0 * k};
        for (int c = 0; c < 3; ++c) {
          g.i16.push_back(static_cast<int16_t>(std::lround(Exact(c, m) * 256)));
        }
      }
    }
  }
  g.steps.assign(g.i16.size(), 0);
  return testing::WriteGridImage(g, id);
}

BoardSettings Settings() {
  BoardSettings s;
  s.node_id = kNode;
  s.board.tick_hz = 1000;
  for (int a = 0; a < 3; ++a) {
    s.board.axis[a].home_position_steps = kHomeMachine[a];
    s.board.axis[a].max_correction_rate_steps_s = 100000;
    s.board.axis[a].max_correction_accel_steps_s2 = 500000;  // below 1 step/tick^2
    s.board.axis[a].drive.max_rate_hz = 2000000;
  }
  return s;
}

gateway::GatewayConfig Mapping() { return testing::CspDriveMapping(3); }

CanFrame Pdo(uint32_t id, int32_t pos) { return testing::CspPdo(id, pos); }

// The CNC master, the drives and the board, one 1 ms cycle per Cycle() (one control tick).
class Machine {
 public:
  Machine(hal::Flash* tables, hal::Flash* settings)
      : io_(&clock_, nullptr),
        cnc_(&clock_, nullptr, 4096),
        drv_(&clock_, nullptr, 4096),
        app_({&cnc_, &drv_, &io_, tables, settings, &clock_}) {
    for (int a = 0; a < 3; ++a) target_[a] = kHomeTarget[a];
  }

  Status Start() {
    io_.SetInput(InputLine::kWriteEnable, true);
    io_.SetInput(InputLine::kEnable, true);
    firmware::AppOptions o;
    o.use_enable_input = true;
    return app_.Start(Settings(), Mapping(), o);
  }

  // One cycle: SYNC + RPDOs from the master, drives take over at SYNC and answer with TPDOs,
  // then the control tick and the main loop. Records what each side saw.
  void Cycle() {
    for (const CanFrame& f : extra_down_) cnc_.Inject(f);
    extra_down_.clear();
    CanFrame sync;
    sync.id = 0x080;
    cnc_.Inject(sync);
    for (int a = 0; a < 3; ++a) cnc_.Inject(Pdo(kRpdo[a], target_[a]));
    app_.PumpFrames();
    for (const CanFrame& f : drv_.TakeSent()) {
      drive_bus_.push_back(f);
      if (f.id == 0x080) {  // the drives take over at SYNC and sample their position
        for (int a = 0; a < 3; ++a) {
          if (has_pending_[a]) position_[a] = pending_[a], has_position_[a] = true;
          has_pending_[a] = false;
          if (has_position_[a]) drv_.Inject(Pdo(kTpdo[a], position_[a]));
        }
        commanded_at_takeover_ = last_commanded_;
      }
      for (int a = 0; a < 3; ++a) {
        if (f.id == kRpdo[a]) {
          pending_[a] = testing::CspPdoPosition(f);
          has_pending_[a] = true;
          correction_[a] = pending_[a] - target_[a];
        }
      }
    }
    app_.PumpFrames();
    feedback_ok_ = true;
    for (const CanFrame& f : cnc_.TakeSent()) {
      for (int a = 0; a < 3; ++a) {
        if (f.id == kTpdo[a]) {
          const int32_t seen = testing::CspPdoPosition(f);
          feedback_ok_ = feedback_ok_ && seen == commanded_at_takeover_[a];
          ++feedback_frames_;
        }
      }
      if (f.id == 0x580u + kNode) sdo_replies_.push_back(f);
      controller_bus_.push_back(f);
    }
    last_commanded_ = {target_[0], target_[1], target_[2]};
    app_.Tick();
    app_.Poll();
    clock_.Advance(1000000);
  }

  TransferResult Run(SdoClient& c) {
    for (int guard = 0; guard < 5000 && !c.done(); ++guard) {
      CanFrame f;
      while (c.PopTx(&f)) extra_down_.push_back(f);
      Cycle();
      for (const CanFrame& r : sdo_replies_) c.OnFrame(r, clock_.now() / 1000);
      sdo_replies_.clear();
      c.Poll(clock_.now() / 1000);
    }
    CanFrame f;
    while (c.PopTx(&f)) extra_down_.push_back(f);
    Cycle();
    return c.result();
  }
  TransferResult Write(ObjectId id, uint32_t value) {
    SdoClient c(kNode);
    canopen_client::StartNumericWrite(c, id, value);
    return Run(c);
  }
  TransferResult Upload(const testing::AlignedBytes& img) {
    SdoClient c(kNode);
    c.StartWrite(0x2100, 0, std::vector<uint8_t>(img.data(), img.data() + img.size()));
    return Run(c);
  }
  // Uploads, references at home, waits at rest and activates; returns the activation result.
  TransferResult UploadReferenceActivate(const testing::AlignedBytes& img) {
    EXPECT_TRUE(Upload(img).ok());
    EXPECT_TRUE(Write(ObjectId::kTableControl, canopen::Value(canopen::TableCommand::kVerify))
                    .ok());  // verify
    EXPECT_TRUE(Write(ObjectId::kReferenceAxes, 7).ok());
    for (int i = 0; i < 150; ++i) Cycle();
    return Write(ObjectId::kTableControl, canopen::Value(canopen::TableCommand::kActivate));
  }

  // The machine position of the current target (drive increments = steps).
  void Machine3(double m[3]) const {
    for (int a = 0; a < 3; ++a) m[a] = double(target_[a]) - kHomeTarget[a] + kHomeMachine[a];
  }

  hal::mock::MockClock clock_;
  hal::mock::MockSlowIo io_;
  hal::mock::MockCan cnc_, drv_;
  firmware::GatewayApp app_;
  int32_t target_[3];
  int32_t correction_[3] = {};
  bool feedback_ok_ = true;
  int feedback_frames_ = 0;
  std::vector<CanFrame> drive_bus_, controller_bus_;

 private:
  std::vector<CanFrame> extra_down_, sdo_replies_;
  int32_t pending_[3] = {}, position_[3] = {};
  bool has_pending_[3] = {}, has_position_[3] = {};
  std::array<int32_t, 3> last_commanded_{kHomeTarget[0], kHomeTarget[1], kHomeTarget[2]};
  std::array<int32_t, 3> commanded_at_takeover_{};
};

class GatewayAppTest : public ::testing::Test {
 protected:
  GatewayAppTest()
      : tables_(256 * 1024, 2048, 8, &clock_, nullptr),
        settings_(8 * 1024, 2048, 8, &clock_, nullptr),
        m_(&tables_, &settings_) {}
  hal::mock::MockClock clock_;
  hal::mock::MockFlash tables_, settings_;
  Machine m_;
};

TEST_F(GatewayAppTest, PassThroughWithoutATable) {
  ASSERT_TRUE(m_.Start().ok());
  for (int i = 0; i < 50; ++i) {
    m_.target_[0] += 37;  // moving
    m_.target_[2] -= 11;
    m_.Cycle();
    for (int a = 0; a < 3; ++a) EXPECT_EQ(m_.correction_[a], 0);
    EXPECT_TRUE(m_.feedback_ok_) << "cycle " << i;
  }
  EXPECT_GT(m_.feedback_frames_, 100);
  EXPECT_EQ(m_.app_.gateway().counters().targets_corrected, 150u);
}

TEST_F(GatewayAppTest, UploadReferenceActivateAndCorrectEveryCycle) {
  ASSERT_TRUE(m_.Start().ok());
  for (int i = 0; i < 10; ++i) m_.Cycle();
  const testing::AlignedBytes img = LinearTable(33);
  ASSERT_TRUE(m_.Upload(img).ok());
  ASSERT_TRUE(m_.Write(ObjectId::kTableControl, canopen::Value(canopen::TableCommand::kVerify))
                  .ok());  // verify
  // Not referenced: refused.
  TransferResult r =
      m_.Write(ObjectId::kTableControl, canopen::Value(canopen::TableCommand::kActivate));
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(canopen_client::AbortOf(r), canopen::SdoAbort::kDeviceState);
  // Referenced at home, but moving: refused.
  ASSERT_TRUE(m_.Write(ObjectId::kReferenceAxes, 7).ok());
  EXPECT_TRUE(m_.app_.app().control_tick().all_referenced());
  for (int i = 0; i < 20; ++i) {
    m_.target_[1] += 50;
    m_.Cycle();
  }
  SdoClient c(kNode);
  canopen_client::StartNumericWrite(c, ObjectId::kTableControl,
                                    canopen::Value(canopen::TableCommand::kActivate));
  for (int i = 0; i < 5; ++i) m_.target_[1] += 50, m_.Cycle();
  r = m_.Run(c);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(canopen_client::AbortOf(r), canopen::SdoAbort::kDeviceState);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(m_.correction_[a], 0);
  // At rest for 150 ms: allowed.
  for (int i = 0; i < 150; ++i) m_.Cycle();
  ASSERT_TRUE(
      m_.Write(ObjectId::kTableControl, canopen::Value(canopen::TableCommand::kActivate)).ok());
  for (int i = 0; i < 100; ++i) {
    m_.Cycle();
    EXPECT_TRUE(m_.feedback_ok_) << "ramp-in cycle " << i;
  }
  // At rest: target + the table's correction at the machine position, within rounding.
  double pos[3];
  m_.Machine3(pos);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(m_.correction_[a], Exact(a, pos), 0.51) << "axis " << a;
    EXPECT_NE(m_.correction_[a], 0);
  }
  // Moving: each target is corrected with the table's value at a recent position: the control
  // tick computed it before this RPDO arrived, and the compensator refreshes its targets in a
  // few phases (one per tick), so the position may be up to kLag cycles old (here one cycle = one
  // tick). Any value between the exact corrections of the last kLag + 1 targets, within rounding,
  // is right; the controller always sees its own targets back.
  constexpr size_t kLag = 16;
  std::deque<std::array<double, 3>> recent;
  for (int i = 0; i < 600; ++i) {
    m_.target_[0] += 5;
    m_.target_[1] += 3;
    m_.target_[2] += 1;
    m_.Machine3(pos);
    recent.push_back({Exact(0, pos), Exact(1, pos), Exact(2, pos)});
    if (recent.size() > kLag + 1) recent.pop_front();
    m_.Cycle();
    for (int a = 0; a < 3; ++a) {
      double lo = recent.back()[a], hi = lo;
      for (const auto& e : recent) lo = std::min(lo, e[a]), hi = std::max(hi, e[a]);
      EXPECT_GE(m_.correction_[a], lo - 0.51) << "cycle " << i << " axis " << a;
      EXPECT_LE(m_.correction_[a], hi + 0.51) << "cycle " << i << " axis " << a;
    }
    ASSERT_TRUE(m_.feedback_ok_) << "cycle " << i;
  }
  // Stopped: the correction settles on the table's value at the final position (axis 0 moved
  // 3000 steps, its correction from 25 to 40 steps).
  for (int i = 0; i < 50; ++i) m_.Cycle();
  m_.Machine3(pos);
  EXPECT_NEAR(Exact(0, pos), 40.0, 1e-9);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(m_.correction_[a], Exact(a, pos), 0.51) << "axis " << a;
  // Nothing of the board's own traffic reached the drives, and the uploads used the controller bus.
  for (const CanFrame& f : m_.drive_bus_) {
    EXPECT_NE(f.id, 0x600u + kNode);
    EXPECT_NE(f.id, 0x580u + kNode);
    EXPECT_NE(f.id, 0x700u + kNode);
    EXPECT_NE(f.id, 0x080u + kNode);
  }
  EXPECT_GT(m_.app_.gateway().counters().local, 100u);  // the block download
}

TEST_F(GatewayAppTest, EStopRampsTheCorrectionOutWhileForwardingGoesOn) {
  ASSERT_TRUE(m_.Start().ok());
  ASSERT_TRUE(m_.UploadReferenceActivate(LinearTable(34)).ok());
  for (int i = 0; i < 100; ++i) m_.Cycle();
  EXPECT_NE(m_.correction_[0], 0);
  m_.io_.SetInput(InputLine::kEStop, true);
  for (int i = 0; i < 200; ++i) {
    m_.Cycle();
    EXPECT_TRUE(m_.feedback_ok_);
  }
  for (int a = 0; a < 3; ++a) EXPECT_EQ(m_.correction_[a], 0) << "axis " << a;
  EXPECT_FALSE(m_.app_.app().control_tick().all_referenced());  // the fault dropped the reference
  bool emcy = false;
  for (const CanFrame& f : m_.controller_bus_) {
    emcy = emcy || (f.id == 0x080u + kNode && LoadLe16(f.data) == canopen::kEmcyEStop);
  }
  EXPECT_TRUE(emcy);
}

TEST_F(GatewayAppTest, NmtReachesDrivesAndNode) {
  ASSERT_TRUE(m_.Start().ok());
  CanFrame nmt;
  nmt.id = 0x000;
  nmt.dlc = 2;
  nmt.data[0] = 0x01;  // start, all nodes
  m_.app_.OnControllerFrame(nmt);
  m_.app_.Poll();
  EXPECT_EQ(m_.app_.app().node().state(), canopen::NmtState::kOperational);
  const std::vector<CanFrame> sent = m_.drv_.TakeSent();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(sent[0], nmt);
  // The boot-up and heartbeats of the board only on the controller bus.
  m_.clock_.Advance(1500000000);
  m_.app_.Poll();
  bool heartbeat = false;
  for (const CanFrame& f : m_.cnc_.TakeSent()) heartbeat = heartbeat || f.id == 0x700u + kNode;
  EXPECT_TRUE(heartbeat);
  EXPECT_TRUE(m_.drv_.TakeSent().empty());
}

// The board's RPDO (0x200 + node-ID, the command word) on the controller bus is the board's, like
// its SDO requests: it reaches the node (in operational) and not the drives.
TEST_F(GatewayAppTest, TheBoardsRpdoReachesTheNodeNotTheDrives) {
  ASSERT_TRUE(m_.Start().ok());
  CanFrame nmt;
  nmt.id = 0x000;
  nmt.dlc = 2;
  nmt.data[0] = 0x01;
  m_.app_.OnControllerFrame(nmt);
  m_.app_.Poll();
  m_.drv_.TakeSent();
  CanFrame rpdo;
  rpdo.id = 0x200 + kNode;
  rpdo.dlc = 2;
  rpdo.data[0] = 0x07;  // reference axes 1-3
  EXPECT_EQ(m_.app_.OnControllerFrame(rpdo), gateway::Route::kLocal);
  m_.app_.Poll();
  EXPECT_EQ(m_.app_.app().node().rpdo_received(), 1u);
  EXPECT_TRUE(m_.drv_.TakeSent().empty());
  m_.Cycle();
  EXPECT_TRUE(m_.app_.app().control_tick().all_referenced());
  // RPDO2 and RPDO3 (the temperatures, 0x300 / 0x400 + node-ID) are the board's too.
  for (uint32_t base : {0x300u, 0x400u}) {
    CanFrame t;
    t.id = base + kNode;
    t.dlc = 8;
    for (int k = 0; k < 8; k += 2) t.data[k + 1] = 0x80;  // 0x8000: no reading, each slot
    EXPECT_EQ(m_.app_.OnControllerFrame(t), gateway::Route::kLocal) << base;
    m_.app_.Poll();
    EXPECT_TRUE(m_.drv_.TakeSent().empty()) << base;
  }
  EXPECT_EQ(m_.app_.app().node().rpdo_received(), 3u);
  // Another node's RPDO goes to the drives as before.
  rpdo.id = 0x201;
  rpdo.dlc = 2;
  EXPECT_EQ(m_.app_.OnControllerFrame(rpdo), gateway::Route::kForward);
  EXPECT_EQ(m_.drv_.TakeSent().size(), 1u);
  rpdo.id = 0x301;
  EXPECT_EQ(m_.app_.OnControllerFrame(rpdo), gateway::Route::kForward);
  EXPECT_EQ(m_.drv_.TakeSent().size(), 1u);
}

TEST_F(GatewayAppTest, DriveFramesWithTheBoardsCobIdsAreDropped) {
  ASSERT_TRUE(m_.Start().ok());
  m_.cnc_.TakeSent();
  CanFrame f;
  f.id = 0x700 + kNode;
  f.dlc = 1;
  EXPECT_EQ(m_.app_.OnDriveFrame(f), gateway::Route::kDrop);
  EXPECT_TRUE(m_.cnc_.TakeSent().empty());
  f.id = 0x701;
  EXPECT_EQ(m_.app_.OnDriveFrame(f), gateway::Route::kForward);
  EXPECT_EQ(m_.cnc_.TakeSent().size(), 1u);
}

TEST(GatewayAppMappingTest, StartRefusesAMappingForMissingAxes) {
  hal::mock::MockClock clock;
  hal::mock::MockFlash tables(256 * 1024, 2048, 8, &clock, nullptr);
  Machine m(&tables, nullptr);
  m.io_.SetInput(InputLine::kEnable, true);
  BoardSettings s = Settings();
  s.board.axis_count = 2;  // the mapping uses axis 2
  EXPECT_EQ(m.app_.Start(s, Mapping()).error(), Error::kConfigInvalid);
  EXPECT_FALSE(m.app_.gateway_active());
  // The board still forwards (untouched): the machine keeps running without compensation.
  const CanFrame rpdo = Pdo(0x203, 1234);
  EXPECT_EQ(m.app_.OnControllerFrame(rpdo), gateway::Route::kForward);
  const std::vector<CanFrame> sent = m.drv_.TakeSent();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(sent[0], rpdo);
}

// The gateway has no step outputs: drive pulse timing that a tick could not carry (it would stop a
// step/dir board, tests/firmware/board_app_test.cpp) does not concern it.
TEST(GatewayAppMappingTest, StepPulseTimingDoesNotConcernTheGateway) {
  hal::mock::MockClock clock;
  hal::mock::MockFlash tables(256 * 1024, 2048, 8, &clock, nullptr);
  Machine m(&tables, nullptr);
  BoardSettings s = Settings();
  for (AxisConfig& ax : s.board.axis) ax.drive.pulse_width_ns = ax.drive.step_space_ns = 15000;
  EXPECT_TRUE(m.app_.Start(s, Mapping()).ok());
  EXPECT_TRUE(m.app_.gateway_active());
  EXPECT_TRUE(m.io_.output(hal::OutputLine::kReady));
  // Nor its settings rules: the settings check (0x2123) finds nothing (a step/dir board would
  // name kPulseTiming: 30 us a step send 33 kHz, the drive rate is 2 MHz).
  m.io_.SetInput(hal::InputLine::kWriteEnable, true);
  EXPECT_TRUE(m.Write(ObjectId::kAxisDriveMaxRate1, 1900000).ok());
  SdoClient c(kNode);
  c.StartRead(0x2123, 0);
  const auto check = m.Run(c);
  ASSERT_TRUE(check.ok());
  ASSERT_EQ(check->size(), 4u);
  EXPECT_EQ((*check)[0], 0u);  // bits 0-7: the rule broken, none
}

// Tables live in files (hal/linux FileFlash): a new process finds the active table.
TEST(GatewayAppFilesTest, ActiveTableSurvivesARestart) {
  const volcomp::testing::ScratchDir temp("gateway_test");
  const std::string dir = temp.path();
  hal::linux_board::FileFlash::Options fo;
  fo.size = 2 * 128 * 1024;
  fo.sector_size = 4096;
  const testing::AlignedBytes img = LinearTable(35);
  {
    hal::linux_board::FileFlash tables;
    ASSERT_TRUE(tables.Open(dir + "/tables.bin", fo).ok());
    Machine m(&tables, nullptr);
    ASSERT_TRUE(m.Start().ok());
    EXPECT_EQ(m.app_.app().stored_table_status().error(), Error::kNotFound);
    ASSERT_TRUE(m.UploadReferenceActivate(img).ok());
    EXPECT_GT(tables.counters().programs, 10u);
  }
  {
    hal::linux_board::FileFlash tables;
    ASSERT_TRUE(tables.Open(dir + "/tables.bin", fo).ok());
    Machine m(&tables, nullptr);
    ASSERT_TRUE(m.Start().ok());
    EXPECT_TRUE(m.app_.app().stored_table_status().ok());
    m.Cycle();  // the stored table reaches the data path at the next tick
    EXPECT_TRUE(m.app_.app().control_tick().compensator().has_table());
    EXPECT_EQ(m.app_.app().control_tick().compensator().table_id(), 35u);
    // Referenced at home, the stored table corrects at once (ramping in).
    ASSERT_TRUE(m.Write(ObjectId::kReferenceAxes, 7).ok());
    for (int i = 0; i < 100; ++i) m.Cycle();
    double pos[3];
    m.Machine3(pos);
    EXPECT_NEAR(m.correction_[0], Exact(0, pos), 0.51);
  }
}

}  // namespace
}  // namespace volcomp
