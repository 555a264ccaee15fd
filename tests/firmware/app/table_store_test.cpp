// Table staging and activation: the active table survives failed uploads, and after a power loss
// at any flash operation of an upload + activation the board holds exactly the old or the new one.
#include "volcomp/firmware/table_store.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "test_tables.hpp"
#include "volcomp/base/crc32.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"

namespace volcomp {
namespace {

constexpr uint32_t kFlashSize = 128 * 1024, kSector = 2048, kUnit = 8;

testing::AlignedBytes Image(int16_t value, uint32_t id, uint32_t nodes = 6) {
  testing::GridCase g;
  g.frac_bits = 4;
  for (auto& d : g.dim) d = {nodes, -1000, 500};
  for (size_t i = 0; i < g.count(); ++i) g.i16.push_back(static_cast<int16_t>(value + i % 7));
  g.steps.assign(g.i16.size(), 0);
  return testing::WriteGridImage(g, id);
}

// Uploads `img` in chunks of 7 (like SDO segments) and activates it. Stops at the first error.
Status UploadAndActivate(firmware::TableStore& store,
                         const testing::AlignedBytes& img,
                         const BoardConfig& cfg) {
  VOLCOMP_TRY(store.BeginUpload(static_cast<uint32_t>(img.size())));
  for (size_t off = 0; off < img.size(); off += 7) {
    const uint32_t n = static_cast<uint32_t>(std::min<size_t>(7, img.size() - off));
    VOLCOMP_TRY(store.UploadData(img.data() + off, n));
  }
  VOLCOMP_TRY(store.FinishUpload());
  VOLCOMP_TRY(store.Verify(cfg));
  const Result<table::TableView> v = store.Activate();
  return v.status();
}

uint32_t ActiveCrc(hal::mock::MockFlash& flash, const BoardConfig& cfg, bool* present) {
  firmware::TableStore store;
  EXPECT_TRUE(store.Init(&flash, kFlashSize / 2).ok());
  const Result<table::TableView> v = store.MountActive(cfg);
  *present = v.ok();
  return v.ok() ? v->crc32 : 0;
}

TEST(TableStore, UploadVerifyActivateAndRejects) {
  hal::mock::MockClock clock;
  hal::mock::MockFlash flash(kFlashSize, kSector, kUnit, &clock, nullptr);
  const BoardConfig cfg = DefaultBoardConfig();
  firmware::TableStore store;
  ASSERT_TRUE(store.Init(&flash, kFlashSize / 2).ok());
  EXPECT_EQ(store.MountActive(cfg).error(), Error::kNotFound);
  const testing::AlignedBytes a = Image(10, 1);
  ASSERT_TRUE(UploadAndActivate(store, a, cfg).ok());
  bool present = false;
  EXPECT_EQ(ActiveCrc(flash, cfg, &present), LoadLe32(a.data() + a.size() - 4));
  EXPECT_TRUE(present);

  // Corrupt upload: verify fails, active unchanged.
  testing::AlignedBytes bad = Image(20, 2);
  bad[100] ^= 0xFF;
  EXPECT_EQ(UploadAndActivate(store, bad, cfg).error(), Error::kImageBadCrc);
  EXPECT_EQ(store.staged_state(), firmware::StagedState::kFailed);
  EXPECT_EQ(store.last_error(), Error::kImageBadCrc);
  EXPECT_EQ(ActiveCrc(flash, cfg, &present), LoadLe32(a.data() + a.size() - 4));

  // Truncated (transfer ended early): size mismatch.
  ASSERT_TRUE(store.BeginUpload(static_cast<uint32_t>(a.size())).ok());
  ASSERT_TRUE(store.UploadData(a.data(), 100).ok());
  EXPECT_EQ(store.FinishUpload().error(), Error::kImageSizeMismatch);
  // Aborted: the reason is the staging error.
  ASSERT_TRUE(store.BeginUpload(0).ok());
  store.AbandonUpload(Error::kTransferAborted);
  EXPECT_EQ(store.staged_state(), firmware::StagedState::kFailed);
  EXPECT_EQ(store.last_error(), Error::kTransferAborted);
  // For another board.
  BoardConfig other = cfg;
  other.axis[0].resolution_e9 = 500000;
  EXPECT_EQ(UploadAndActivate(store, Image(30, 3), other).error(),
            Error::kConfigResolutionMismatch);
  // Too large for a bank.
  EXPECT_EQ(store.BeginUpload(kFlashSize).error(), Error::kImageTooLarge);
  EXPECT_EQ(ActiveCrc(flash, cfg, &present), LoadLe32(a.data() + a.size() - 4));

  // A new good one replaces it; deactivation revokes persistently.
  const testing::AlignedBytes b = Image(40, 4);
  ASSERT_TRUE(UploadAndActivate(store, b, cfg).ok());
  EXPECT_EQ(ActiveCrc(flash, cfg, &present), LoadLe32(b.data() + b.size() - 4));
  ASSERT_TRUE(store.Deactivate().ok());
  ActiveCrc(flash, cfg, &present);
  EXPECT_FALSE(present);
}

TEST(TableStore, PowerLossAtEveryFlashOperationLeavesOldOrNew) {
  hal::mock::MockClock clock;
  const BoardConfig cfg = DefaultBoardConfig();
  const testing::AlignedBytes old_img = Image(-50, 100, 10);  // 10x10x10 nodes: ~6 KB
  const testing::AlignedBytes new_img = Image(70, 200, 10);
  const uint32_t old_crc = LoadLe32(old_img.data() + old_img.size() - 4);
  const uint32_t new_crc = LoadLe32(new_img.data() + new_img.size() - 4);
  // Count the operations of a clean upload + activation.
  uint32_t total_ops = 0;
  {
    hal::mock::MockFlash flash(kFlashSize, kSector, kUnit, &clock, nullptr);
    firmware::TableStore store;
    ASSERT_TRUE(store.Init(&flash, kFlashSize / 2).ok());
    ASSERT_TRUE(UploadAndActivate(store, old_img, cfg).ok());
    const uint32_t before = flash.erase_count() + flash.program_count();
    ASSERT_TRUE(UploadAndActivate(store, new_img, cfg).ok());
    total_ops = flash.erase_count() + flash.program_count() - before;
  }
  ASSERT_GT(total_ops, 700u);
  int saw_old = 0, saw_new = 0;
  for (uint32_t cut = 0; cut <= total_ops; ++cut) {
    hal::mock::MockFlash flash(kFlashSize, kSector, kUnit, &clock, nullptr);
    firmware::TableStore store;
    ASSERT_TRUE(store.Init(&flash, kFlashSize / 2).ok());
    ASSERT_TRUE(UploadAndActivate(store, old_img, cfg).ok());
    flash.InjectPowerLossAfter(cut);
    const Status s = UploadAndActivate(store, new_img, cfg);
    flash.PowerCycle();
    bool present = false;
    const uint32_t crc = ActiveCrc(flash, cfg, &present);
    ASSERT_TRUE(present) << "cut after " << cut << " operations: no table";
    ASSERT_TRUE(crc == old_crc || crc == new_crc) << "cut " << cut;
    if (cut < total_ops) {
      ASSERT_FALSE(s.ok()) << "cut " << cut;
      ASSERT_EQ(crc, old_crc) << "cut " << cut << " switched before the commit record";
    }
    (crc == old_crc ? saw_old : saw_new)++;
    // The board can finish the upload after the power comes back.
    firmware::TableStore again;
    ASSERT_TRUE(again.Init(&flash, kFlashSize / 2).ok());
    ASSERT_TRUE(again.MountActive(cfg).ok());
    ASSERT_TRUE(UploadAndActivate(again, new_img, cfg).ok()) << "cut " << cut;
  }
  std::printf(
      "[ metric ] power loss at each of %u flash operations of an upload: %d boots with "
      "the old table, %d with the new, 0 with neither or a mix\n",
      total_ops + 1, saw_old, saw_new);
  EXPECT_EQ(saw_new, 1);  // only when the commit record was fully programmed
}

}  // namespace
}  // namespace volcomp
