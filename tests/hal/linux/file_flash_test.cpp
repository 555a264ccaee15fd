// FileFlash: NOR semantics in a file, persistence, write-behind order, locking, bad geometry.
#include "volcomp/hal/linux/file_flash.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>
#include <vector>

#include "file_contents.hpp"
#include "temp_paths.hpp"

namespace volcomp::hal::linux_board {
namespace {

using volcomp::testing::ReadBytes;
using volcomp::testing::ScratchDir;

FileFlash::Options SmallFlash() {
  FileFlash::Options o;
  o.size = 16384;
  o.sector_size = 4096;
  o.program_unit = 8;
  return o;
}

TEST(FileFlashTest, NewFileIsErasedAndProgramOnlyClearsBits) {
  ScratchDir dir("hal_test");
  const std::string path = dir / "flash.bin";
  FileFlash flash;
  ASSERT_TRUE(flash.Open(path, SmallFlash()).ok());
  EXPECT_EQ(flash.size(), 16384u);
  const std::vector<uint8_t> file = ReadBytes(path);
  ASSERT_EQ(file.size(), 16384u);
  for (uint8_t b : file) ASSERT_EQ(b, 0xFF);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(flash.Map(0)) % 8, 0u);

  const uint8_t a[8] = {0x0F, 0xF0, 0x00, 0xFF, 1, 2, 3, 4};
  ASSERT_TRUE(flash.Program(4096, a, 8).ok());
  EXPECT_EQ(std::vector<uint8_t>(flash.Map(4096), flash.Map(4096) + 8),
            std::vector<uint8_t>(a, a + 8));
  // Clearing more bits is fine; setting one (0 -> 1) is refused and changes nothing.
  const uint8_t b[8] = {0x0E, 0xF0, 0x00, 0x7F, 0, 2, 3, 4};
  EXPECT_TRUE(flash.Program(4096, b, 8).ok());
  const uint8_t c[8] = {0x0F, 0xF0, 0x00, 0x7F, 0, 2, 3, 4};  // 0x0E -> 0x0F
  EXPECT_EQ(flash.Program(4096, c, 8).error(), Error::kIoError);
  EXPECT_EQ(flash.Map(4096)[0], 0x0E);
  EXPECT_EQ(flash.counters().refused, 1u);
  // Misaligned or out of range: refused by the interface.
  EXPECT_EQ(flash.Program(4100, a, 8).error(), Error::kOutOfRange);
  EXPECT_EQ(flash.Program(16384 - 8, a, 16).error(), Error::kOutOfRange);
  EXPECT_EQ(flash.Erase(100).error(), Error::kOutOfRange);
  // Erase sets the whole sector and nothing else.
  ASSERT_TRUE(flash.Program(0, a, 8).ok());
  ASSERT_TRUE(flash.Erase(4096).ok());
  for (uint32_t i = 4096; i < 8192; ++i) ASSERT_EQ(flash.Map(i)[0], 0xFF);
  EXPECT_EQ(flash.Map(0)[0], 0x0F);
  // Everything reaches the file, in order.
  EXPECT_TRUE(flash.Flush().ok());
  EXPECT_EQ(flash.counters().written, 4u);  // 3 programs and 1 erase (the refused one is not)
  const std::vector<uint8_t> after = ReadBytes(path);
  EXPECT_EQ(after[0], 0x0F);
  EXPECT_EQ(after[4096], 0xFF);
}

TEST(FileFlashTest, ContentSurvivesReopenAndWrongSizeIsRefused) {
  ScratchDir dir("hal_test");
  const std::string path = dir / "flash.bin";
  const uint8_t data[16] = {0xDE, 0xAD, 0xBE, 0xEF, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  {
    FileFlash flash;
    ASSERT_TRUE(flash.Open(path, SmallFlash()).ok());
    ASSERT_TRUE(flash.Program(8192, data, 16).ok());
  }
  {
    FileFlash flash;
    ASSERT_TRUE(flash.Open(path, SmallFlash()).ok());
    EXPECT_EQ(std::vector<uint8_t>(flash.Map(8192), flash.Map(8192) + 16),
              std::vector<uint8_t>(data, data + 16));
  }
  FileFlash::Options other = SmallFlash();
  other.size = 32768;
  FileFlash flash;
  const Expected<void> opened = flash.Open(path, other);
  ASSERT_FALSE(opened.ok());
  const std::string why = opened.error().message;
  EXPECT_NE(why.find("size is 16384 bytes, expected 32768"), std::string::npos) << why;
  EXPECT_EQ(opened.error().code, Error::kConfigInvalid);
  EXPECT_FALSE(flash.is_open());
}

TEST(FileFlashTest, WriteThroughModeWritesBeforeReturning) {
  ScratchDir dir("hal_test");
  const std::string path = dir / "flash.bin";
  FileFlash::Options o = SmallFlash();
  o.background = false;
  FileFlash flash;
  ASSERT_TRUE(flash.Open(path, o).ok());
  const uint8_t a[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  ASSERT_TRUE(flash.Program(64, a, 8).ok());
  EXPECT_EQ(flash.counters().written, 1u);
  const std::vector<uint8_t> file = ReadBytes(path);  // no Flush() needed
  EXPECT_EQ(std::vector<uint8_t>(file.begin() + 64, file.begin() + 72),
            std::vector<uint8_t>(a, a + 8));
}

TEST(FileFlashTest, ManyQueuedOperationsLandInOrder) {
  ScratchDir dir("hal_test");
  const std::string path = dir / "flash.bin";
  FileFlash flash;
  ASSERT_TRUE(flash.Open(path, SmallFlash()).ok());
  // The same sector erased and programmed over and over: only the order gives the final bytes.
  uint8_t expect[16] = {};
  for (int round = 0; round < 40; ++round) {
    ASSERT_TRUE(flash.Erase(0).ok());
    for (int i = 0; i < 16; ++i) expect[i] = static_cast<uint8_t>(round * 16 + i);
    ASSERT_TRUE(flash.Program(0, expect, 16).ok());
  }
  flash.Close();  // drains the queue
  const std::vector<uint8_t> file = ReadBytes(path);
  EXPECT_EQ(std::vector<uint8_t>(file.begin(), file.begin() + 16),
            std::vector<uint8_t>(expect, expect + 16));
  EXPECT_EQ(file[16], 0xFF);
}

TEST(FileFlashTest, OneProcessAtATime) {
  ScratchDir dir("hal_test");
  const std::string path = dir / "flash.bin";
  FileFlash first, second;
  ASSERT_TRUE(first.Open(path, SmallFlash()).ok());
  const Expected<void> opened = second.Open(path, SmallFlash());
  ASSERT_FALSE(opened.ok());
  EXPECT_NE(opened.error().message.find("in use"), std::string::npos) << opened.error().message;
  EXPECT_EQ(opened.error().code, Error::kBusy);
  first.Close();
  EXPECT_TRUE(second.Open(path, SmallFlash()).ok());
}

TEST(FileFlashTest, BadGeometryAndDirectoryAreReported) {
  ScratchDir dir("hal_test");
  FileFlash flash;
  FileFlash::Options o = SmallFlash();
  o.sector_size = 3000;
  EXPECT_EQ(flash.Open(dir / "x.bin", o).error().code, Error::kInvalidArgument);
  const Expected<void> opened = flash.Open("/nonexistent-dir/flash.bin", SmallFlash());
  ASSERT_FALSE(opened.ok());
  EXPECT_NE(opened.error().message.find("cannot create"), std::string::npos);
}

}  // namespace
}  // namespace volcomp::hal::linux_board
