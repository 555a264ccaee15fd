// WriteThroughFlash: every erase and program reaches the file at once; a file that cannot be
// opened or written is a failure, never an exception through the firmware.
#include "volcomp/sim/write_through_flash.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace volcomp::sim {
namespace {

std::string TempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("volcomp_wtf_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

std::vector<uint8_t> FileBytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::vector<uint8_t>((std::istreambuf_iterator<char>(f)), {});
}

TEST(SimWriteThroughFlash, OperationsReachTheFileAtOnce) {
  const std::string path = TempPath("ops.bin");
  hal::mock::MockFlash mock(4096, 1024, 8, nullptr, nullptr);
  WriteThroughFlash flash(&mock, path);
  ASSERT_TRUE(flash.Open().ok());
  ASSERT_TRUE(flash.WriteAll().ok());
  EXPECT_EQ(FileBytes(path).size(), 4096u);
  hal::Flash& f = flash;
  ASSERT_TRUE(f.Erase(1024).ok());
  const uint8_t data[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  ASSERT_TRUE(f.Program(1024, data, 8).ok());
  const std::vector<uint8_t> bytes = FileBytes(path);
  ASSERT_EQ(bytes.size(), 4096u);
  EXPECT_EQ(std::vector<uint8_t>(bytes.begin() + 1024, bytes.begin() + 1032),
            std::vector<uint8_t>(data, data + 8));
  EXPECT_EQ(bytes[1032], mock.raw()[1032]);  // the rest of the erased sector
  std::filesystem::remove(path);
}

TEST(SimWriteThroughFlash, AFileThatCannotBeOpenedIsAFailure) {
  const std::string blocker = TempPath("blocker");
  std::ofstream(blocker) << "a file, not a directory\n";
  const std::string path = blocker + "/flash.bin";
  hal::mock::MockFlash mock(4096, 1024, 8, nullptr, nullptr);
  WriteThroughFlash flash(&mock, path);
  const Outcome opened = flash.Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_EQ(opened.error().code, Error::kIoError);
  EXPECT_EQ(opened.error().message.rfind(path + ": cannot open: ", 0), 0u)
      << opened.error().message;
  // Not open: the operations fail (kIoError) instead of losing their bytes unnoticed.
  EXPECT_FALSE(flash.WriteAll().ok());
  hal::Flash& f = flash;
  EXPECT_EQ(f.Erase(0).error(), Error::kIoError);
  std::filesystem::remove(blocker);
}

}  // namespace
}  // namespace volcomp::sim
