// The board application's CANopen node end to end on the mock HAL: table upload by block
// download, activation rules (0x08000022), write protection (0x08000020), status objects, EMCY,
// stored settings and NMT reset.
#include <gtest/gtest.h>

#include <functional>
#include <optional>

#include "test_tables.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen_client/node_objects.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/hal/mock/mock_step_io.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp {
namespace {

using canopen::ObjectId;
using canopen::TableCommand;
using canopen_client::SdoClient;
using canopen_client::SdoResult;
using hal::InputLine;

constexpr uint8_t kNode = 0x10;

testing::AlignedBytes UniformImage(double cx, uint32_t id, uint32_t resolution_y = 1000000) {
  testing::GridCase g;
  g.frac_bits = 8;
  for (auto& d : g.dim) d = {8, -100000, 30000};
  for (size_t i = 0; i < g.count(); i += 3) {
    g.i16.push_back(static_cast<int16_t>(cx * 256));
    g.i16.push_back(0);
    g.i16.push_back(0);
  }
  g.steps.assign(g.i16.size(), 0);
  testing::AlignedBytes img = testing::WriteGridImage(g, id);
  if (resolution_y != 1000000) {
    StoreLe32(img.data() + 24 + 8 + 4 + 8 + 4, resolution_y);
    testing::FixCrc(img);
  }
  return img;
}

class Bench : public ::testing::Test {
 protected:
  Bench()
      : config_(DefaultBoardConfig()),
        io_(&clock_, nullptr),
        tables_(256 * 1024, 2048, 8, &clock_, nullptr),
        settings_(8 * 1024, 2048, 8, &clock_, nullptr),
        can_(&clock_, nullptr, 256),
        step_io_(config_, nullptr),
        tick_io_(&step_io_),
        app_({&tick_io_, &io_, &tables_, &settings_, &can_, &clock_}) {}

  void Boot() {
    ASSERT_TRUE(app_.Start(config_).ok());
    io_.SetInput(InputLine::kEnable, true);
    Step(100);
    can_.TakeSent();
  }
  // Runs `ticks` 20 us ticks with a main-loop pass every 50 ticks (1 ms).
  void Step(int ticks) {
    for (int i = 0; i < ticks; ++i) {
      step_io_.set_tick_start_ns(clock_.now());
      app_.Tick();
      if (++tick_count_ % 50 == 0) app_.Poll();
      clock_.Advance(20000);
    }
  }
  SdoResult Run(SdoClient& c) {
    while (!c.done()) {
      CanFrame f;
      while (c.PopTx(&f)) can_.Inject(f);
      Step(50);
      for (const CanFrame& r : can_.TakeSent()) {
        sent_.push_back(r);
        c.OnFrame(r, clock_.now() / 1000);
      }
      c.Poll(clock_.now() / 1000);
    }
    CanFrame f;
    while (c.PopTx(&f)) can_.Inject(f);
    Step(50);
    return c.result();
  }
  SdoResult Write(ObjectId id, uint32_t value) {
    const auto& e = canopen::Entry(id);
    SdoClient c(kNode);
    c.StartDownload(e.index, e.sub, canopen_client::NumericPayload(id, value));
    return Run(c);
  }
  SdoResult Command(TableCommand c) { return Write(ObjectId::kTableControl, canopen::Value(c)); }
  uint32_t Read(ObjectId id) {
    const auto& e = canopen::Entry(id);
    SdoClient c(kNode);
    c.StartUpload(e.index, e.sub);
    const SdoResult r = Run(c);
    EXPECT_TRUE(r.ok) << r.message;
    uint32_t v = 0;
    for (size_t i = 0; i < r.data.size() && i < 4; ++i) v |= uint32_t{r.data[i]} << (8 * i);
    return v;
  }
  SdoResult Upload(const testing::AlignedBytes& img) {
    SdoClient c(kNode);
    c.StartDownload(0x2100, 0, std::vector<uint8_t>(img.data(), img.data() + img.size()));
    return Run(c);
  }
  void Home() {
    for (uint8_t a = 0; a < 3; ++a) io_.SetInput(hal::HomeLine(a), true);
    Step(100);
    for (uint8_t a = 0; a < 3; ++a) io_.SetInput(hal::HomeLine(a), false);
    Step(100);
  }
  // The PC tool's view of the board: a blocking frame link over the mock bus (requests to 0x2110
  // are counted).
  canopen_client::FrameLink Link() {
    canopen_client::FrameLink l;
    l.send = [this](const CanFrame& f) {
      if (LoadLe16(f.data + 1) == 0x2110) ++unlock_requests_;
      can_.Inject(f);
    };
    l.receive = [this](uint64_t timeout_us) -> std::optional<CanFrame> {
      const uint64_t end = clock_.now() + timeout_us * 1000;
      while (replies_.empty() && clock_.now() < end) {
        Step(50);
        for (const CanFrame& r : can_.TakeSent()) {
          sent_.push_back(r);
          replies_.push_back(r);
        }
      }
      if (replies_.empty()) return std::nullopt;
      const CanFrame f = replies_.front();
      replies_.erase(replies_.begin());
      return f;
    };
    l.now_us = [this] { return clock_.now() / 1000; };
    return l;
  }
  int CountEmcy(uint16_t code) const {
    int n = 0;
    for (const CanFrame& f : sent_) {
      canopen::Emcy e;
      if (canopen::DecodeEmcy(f, kNode, &e) && e.code == code) ++n;
    }
    return n;
  }

  BoardConfig config_;
  hal::mock::MockClock clock_;
  hal::mock::MockSlowIo io_;
  hal::mock::MockFlash tables_, settings_;
  hal::mock::MockCan can_;
  hal::mock::MockStepIo step_io_;
  firmware::StepDirIo<hal::mock::MockStepIo> tick_io_;
  firmware::BoardApp<firmware::StepDirIo<hal::mock::MockStepIo>> app_;
  std::vector<CanFrame> sent_;
  std::vector<CanFrame> replies_;  // received through Link(), not yet taken
  int unlock_requests_ = 0;
  uint64_t tick_count_ = 0;
};

TEST_F(Bench, UploadIsRefusedWhileWriteProtectedAndAllowedWhenUnlocked) {
  Boot();
  const testing::AlignedBytes img = UniformImage(5, 42);
  SdoResult r = Upload(img);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.abort_code, canopen::kAbortCannotStore);
  EXPECT_EQ(CountEmcy(canopen::kEmcyRefused), 1);
  EXPECT_EQ(Read(ObjectId::kRefusedActions), 1u);
  EXPECT_EQ(Read(ObjectId::kWriteAccess), 0u);
  // Wrong signature: refused; right one: writable for 60 s.
  EXPECT_EQ(Write(ObjectId::kUnlock, 0x12345678).abort_code, canopen::kAbortInvalidValue);
  ASSERT_TRUE(Write(ObjectId::kUnlock, canopen::kUnlockSignature).ok);
  EXPECT_EQ(Read(ObjectId::kWriteAccess), 1u);
  r = Upload(img);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(Read(ObjectId::kStagedBytes), img.size());
  clock_.Advance(61ull * 1000 * 1000 * 1000);
  Step(50);
  EXPECT_EQ(Read(ObjectId::kWriteAccess), 0u);
  // The hardware write-enable input works without unlocking.
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  EXPECT_EQ(Read(ObjectId::kWriteAccess), 1u);
}

TEST_F(Bench, ActivationNeedsReferencedAxesAtRest) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  const testing::AlignedBytes img = UniformImage(6, 77);
  ASSERT_TRUE(Upload(img).ok);
  ASSERT_TRUE(Command(TableCommand::kVerify).ok);  // verify
  const uint32_t status = Read(ObjectId::kTableStatus);
  EXPECT_EQ(canopen::DecodeTableStatus(status).staged, canopen::StagedState::kVerified)
      << std::hex << status;
  EXPECT_EQ(Read(ObjectId::kStagedTableCrc), LoadLe32(img.data() + img.size() - 4));
  EXPECT_EQ(Read(ObjectId::kStagedTableId), 77u);
  // Not referenced: refused with 0x08000022 and an EMCY.
  SdoResult r = Command(TableCommand::kActivate);
  EXPECT_EQ(r.abort_code, canopen::kAbortDeviceState);
  EXPECT_NE(r.message.find("not allowed in the present device state"), std::string::npos);
  EXPECT_EQ(CountEmcy(canopen::kEmcyRefused), 1);
  // Reference over CAN, then move an axis: still refused while moving.
  ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok);
  EXPECT_TRUE(app_.engine().all_referenced());
  step_io_.add_steps(0, 100);
  Step(1);
  EXPECT_EQ(Command(TableCommand::kActivate).abort_code, canopen::kAbortDeviceState);
  Step(10000);  // 200 ms at rest
  r = Command(TableCommand::kActivate);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(Read(ObjectId::kActiveTableCrc), LoadLe32(img.data() + img.size() - 4));
  EXPECT_EQ(Read(ObjectId::kActiveTableId), 77u);
  Step(20000);
  EXPECT_EQ(step_io_.drive(0).position(), 100 + 6);
  const uint32_t state = Read(ObjectId::kDeviceState);
  EXPECT_TRUE(canopen::DecodeDeviceState(state).engaged);
  EXPECT_TRUE(canopen::DecodeDeviceState(state).table_active);
  EXPECT_EQ(static_cast<int32_t>(Read(ObjectId::kAppliedCorrection1)), 6 * 256);
  EXPECT_EQ(Read(ObjectId::kCommandedPosition1), 100u);
  // Deactivate: ramps out, and stays off after a reset.
  ASSERT_TRUE(Command(TableCommand::kDeactivate).ok);
  Step(20000);
  EXPECT_EQ(step_io_.drive(0).position(), 100);
  EXPECT_EQ(Read(ObjectId::kActiveTableCrc), 0u);
}

TEST_F(Bench, ActiveTableSurvivesAResetAndBadUploads) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  const testing::AlignedBytes good = UniformImage(3, 1);
  ASSERT_TRUE(Upload(good).ok);
  ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok);
  Step(10000);
  ASSERT_TRUE(Command(TableCommand::kActivate).ok);
  const uint32_t crc = Read(ObjectId::kActiveTableCrc);
  // A corrupt image and an image for another board are staged but never become active.
  testing::AlignedBytes corrupt = UniformImage(9, 2);
  corrupt[60] ^= 0x01;
  ASSERT_TRUE(Upload(corrupt).ok);  // the transfer itself is fine
  EXPECT_EQ(Command(TableCommand::kVerify).abort_code, canopen::kAbortInvalidValue);
  EXPECT_EQ(Command(TableCommand::kActivate).abort_code, canopen::kAbortNoData);
  EXPECT_EQ(canopen::DecodeTableStatus(Read(ObjectId::kTableStatus)).error, Error::kImageBadCrc);
  ASSERT_TRUE(Upload(UniformImage(9, 3, 500000)).ok);
  EXPECT_EQ(Command(TableCommand::kVerify).abort_code, canopen::kAbortInvalidValue);
  EXPECT_EQ(canopen::DecodeTableStatus(Read(ObjectId::kTableStatus)).error,
            Error::kConfigResolutionMismatch);
  EXPECT_EQ(Read(ObjectId::kActiveTableCrc), crc);
  // NMT reset node: the stored active table comes back.
  can_.Inject(CanFrame{0x000, false, false, 2, {0x81, kNode}});
  Step(100);
  EXPECT_EQ(Read(ObjectId::kActiveTableCrc), crc);
  EXPECT_TRUE(app_.stored_table_status().ok());
}

TEST_F(Bench, SettingsAreStoredAndAppliedAfterReset) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  EXPECT_EQ(Read(ObjectId::kAxisMaxCorrection2), 1000u);
  ASSERT_TRUE(Write(ObjectId::kAxisMaxCorrection2, 250).ok);
  EXPECT_EQ(Write(ObjectId::kAxisMaxCorrection2, 1u << 20).abort_code, canopen::kAbortValueTooHigh);
  EXPECT_TRUE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).settings_pending);
  EXPECT_EQ(app_.settings().board.axis[1].max_correction_steps, 1000);
  EXPECT_EQ(Write(ObjectId::kStoreAll, 0x12345678).abort_code, canopen::kAbortCannotStore);
  ASSERT_TRUE(Write(ObjectId::kStoreAll, canopen::kSaveSignature).ok);
  can_.Inject(CanFrame{0x000, false, false, 2, {0x81, 0}});
  Step(100);
  EXPECT_EQ(app_.settings().board.axis[1].max_correction_steps, 250);
  EXPECT_FALSE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).settings_pending);
  // Restore defaults, reset: back to the defaults.
  ASSERT_TRUE(Write(ObjectId::kRestoreAll, canopen::kLoadSignature).ok);
  can_.Inject(CanFrame{0x000, false, false, 2, {0x81, 0}});
  Step(100);
  EXPECT_EQ(app_.settings().board.axis[1].max_correction_steps, 1000);
}

TEST_F(Bench, DiagnosticsAndIdentity) {
  Boot();
  EXPECT_EQ(Read(ObjectId::kVendorId), 0x564F4C43u);
  SdoClient c(kNode);
  c.StartUpload(0x1008, 0);
  const SdoResult name = Run(c);
  ASSERT_TRUE(name.ok);
  EXPECT_EQ(std::string(name.data.begin(), name.data.end()), "volcomp");
  EXPECT_GT(Read(ObjectId::kCanRxFrames), 0u);
  EXPECT_GT(Read(ObjectId::kTicks), 100u);
  EXPECT_EQ(Read(ObjectId::kLostStepChecks), 0u);
  // Heartbeat: 1000 ms by default, state pre-operational.
  sent_.clear();
  can_.TakeSent();
  Step(50 * 1100);
  int hb = 0;
  for (const CanFrame& f : can_.TakeSent()) hb += f.id == 0x700u + kNode && f.data[0] == 0x7F;
  EXPECT_EQ(hb, 1);
}

// The PC tool's staging steps (tools/canopen table_staging.hpp, used by `volcomp upload` and the
// simulator's demo) against the real board objects.
TEST_F(Bench, StagingStepsUnlockStageAndVerify) {
  Boot();
  const testing::AlignedBytes img = UniformImage(5, 42);
  const uint32_t crc = LoadLe32(img.data() + img.size() - 4);
  const canopen_client::FrameLink link = Link();
  canopen_client::NodeObjects node(link, kNode);
  SdoResult r = canopen_client::PrepareStaging(node);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(unlock_requests_, 1);  // write-protected: the steps unlocked it
  EXPECT_EQ(Read(ObjectId::kWriteAccess), 1u);
  r = node.Download(ObjectId::kTableData,
                    std::vector<uint8_t>(img.data(), img.data() + img.size()));
  ASSERT_TRUE(r.ok) << r.message;
  uint32_t staged = 0;
  r = canopen_client::VerifyStaged(node, crc, &staged);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(staged, crc);
  EXPECT_EQ(Read(ObjectId::kStagedTableId), 42u);
  // A CRC that is not the image's: a failure of its own (no abort code), naming both values.
  r = canopen_client::VerifyStaged(node, crc ^ 1u, &staged);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.abort_code, 0u);
  EXPECT_NE(
      r.message.find("staged CRC-32 " + tools::Hex32(crc) + ", expected " + tools::Hex32(crc ^ 1u)),
      std::string::npos)
      << r.message;
  // Activation before referencing: the step, the board's reason and what to do.
  r = canopen_client::Explain(
      node.Write(ObjectId::kTableControl, canopen::Value(TableCommand::kActivate)), "activating");
  EXPECT_EQ(r.abort_code, canopen::kAbortDeviceState);
  EXPECT_EQ(r.message.rfind("activating: ", 0), 0u) << r.message;
  EXPECT_NE(r.message.find("; the axes must be referenced (homed) and at rest"), std::string::npos)
      << r.message;
  // Already writable (hardware input): no unlock request.
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  ASSERT_TRUE(canopen_client::EnsureWritable(node).ok);
  EXPECT_EQ(unlock_requests_, 1);
}

TEST_F(Bench, StagingStepsNameTheStepThatFailed) {
  Boot();
  const canopen_client::FrameLink link = Link();
  canopen_client::NodeObjects node(link, kNode);
  ASSERT_TRUE(canopen_client::PrepareStaging(node).ok);
  // Nothing was downloaded: the board's verification refuses.
  const SdoResult r = canopen_client::VerifyStaged(node, 0x12345678u);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.abort_code, 0u);
  EXPECT_EQ(r.message.rfind("verifying on the board (0x2101 = 4): ", 0), 0u) << r.message;
}

}  // namespace
}  // namespace volcomp
