// Tables for the native component: the messages say why a table is refused, in the words of
// `volcomp inspect` (a bad image), with errno's text (a missing file) and with the uid that could
// not read the file, its owner and mode (a permission error); a reload must be for the same axes.
#include "native/native_table.hpp"

#include <gtest/gtest.h>
#include <pwd.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "native_tables.hpp"
#include "table_file.hpp"

namespace volcomp::linuxcnc {
namespace {

using testing::Grid;
using volcomp::testing::WriteGridImage;

std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "/native_table_test_" + std::to_string(getpid()) + "_" + name;
}

void WriteFile(const std::string& path, const uint8_t* data, size_t size) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), size);
}

TEST(NativeTable, ReadsAValidFile) {
  const auto image = WriteGridImage(Grid(1, 10.0));
  const std::string path = TempPath("good.vct");
  WriteFile(path, image.data(), image.size());
  Expected<std::unique_ptr<NativeTable>> t = NativeTable::ReadFile(path);
  ASSERT_TRUE(t.ok()) << t.error().message;
  EXPECT_EQ((*t)->axis_count(), 3u);
  EXPECT_EQ((*t)->AxisNames(), "X Y Z");
  EXPECT_EQ((*t)->FindAxis('Y'), 1);
  EXPECT_EQ((*t)->FindAxis('A'), -1);
  EXPECT_DOUBLE_EQ((*t)->axis(0).units_per_step, 0.001);
  EXPECT_EQ((*t)->size_bytes(), image.size());
  std::remove(path.c_str());
}

TEST(NativeTable, SaysWhyAFileIsMissing) {
  const Expected<std::unique_ptr<NativeTable>> t = NativeTable::ReadFile("/nonexistent/t.vct");
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().code, Error::kNotFound);
  EXPECT_EQ(t.error().message,
            "cannot read table \"/nonexistent/t.vct\": No such file or directory");
  const Expected<std::unique_ptr<NativeTable>> rel = NativeTable::ReadFile("no-such-table.vct");
  ASSERT_FALSE(rel.ok());
  EXPECT_NE(rel.error().message.find("(the path is relative to /"), std::string::npos)
      << rel.error().message;
}

TEST(NativeTable, RefusesABadImageInTheWordsOfInspect) {
  auto image = WriteGridImage(Grid(2, 10.0));
  image[40] ^= 0x01;  // CRC no longer matches
  Expected<std::unique_ptr<NativeTable>> t =
      NativeTable::FromBytes(testing::Bytes(image), "/x/bad.vct");
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().code, Error::kImageBadCrc);
  EXPECT_EQ(t.error().message,
            "table \"/x/bad.vct\" refused: invalid table image: image CRC-32 does not match "
            "(kImageBadCrc)");
  image.resize(100);  // truncated: the size field no longer matches
  t = NativeTable::FromBytes(testing::Bytes(image), "short.vct");
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().message,
            "table \"short.vct\" refused: invalid table image: image size field does not match "
            "the data length (kImageSizeMismatch)");
}

// The component has no temperature channels: an image with a thermal model is refused whole, not
// loaded without it (the board applies the same image with its thermal part).
TEST(NativeTable, RefusesAnImageWithAThermalModel) {
  const volcomp::testing::GridCase g = Grid(3, 10.0);
  table::GridSpec spec;
  spec.frac_bits = g.frac_bits;
  for (int d = 0; d < 3; ++d) spec.dim[d] = g.dim[d];
  spec.values.type = g.type;
  spec.values.i16 = g.i16.data();
  table::ImageSpec img = volcomp::testing::XyzImageSpec(spec, 8);
  thermal::ThermalModel m;
  m.axis_count = 3;
  m.channel_mask = 1;
  m.axis[0].offset_um_per_K[0] = 2.0f;
  img.thermal = &m;
  const auto with_model = volcomp::testing::WriteImageBytes(img);
  Expected<std::unique_ptr<NativeTable>> t =
      NativeTable::FromBytes(testing::Bytes(with_model), "warm.vct");
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().code, Error::kThermalNotApplied);
  EXPECT_NE(t.error().message.find("table \"warm.vct\" refused: "), std::string::npos)
      << t.error().message;
  EXPECT_NE(t.error().message.find("(kThermalNotApplied)"), std::string::npos);
  img.thermal = nullptr;  // the same image without the model loads
  EXPECT_NE(testing::Load(volcomp::testing::WriteImageBytes(img)), nullptr);
}

// rtapi_app runs as RTAPI_UID (or the invoking user): a file only its owner may read is refused
// with that uid, the file's owner and mode. As root, the reading runs in a child process that
// drops to uid 65534 (nobody), as rtapi_app does.
TEST(NativeTable, NamesTheUidThatCouldNotReadTheFile) {
  const auto image = WriteGridImage(Grid(3, 10.0));
  const std::string path = TempPath("private.vct");
  WriteFile(path, image.data(), image.size());
  ASSERT_EQ(chmod(path.c_str(), geteuid() == 0 ? 0600 : 0000), 0);
  const std::string out_path = TempPath("message.txt");
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (geteuid() == 0 && setuid(65534) != 0) _exit(3);
    const Expected<std::vector<uint8_t>> r = ReadTableFile(path);
    if (geteuid() == 0) _exit(4);  // could not drop root: the test has no meaning
    std::FILE* f = std::fopen(out_path.c_str(), "w");
    if (f == nullptr) _exit(5);
    std::fprintf(f, "%d\n%s", r.ok() ? 0 : static_cast<int>(r.error().code),
                 r.ok() ? "" : r.error().message.c_str());
    std::fclose(f);
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "child status " << status;
  std::ifstream in(out_path);
  int code = 0;
  in >> code;
  in.get();
  const std::string message((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(code, static_cast<int>(Error::kIoError));
  EXPECT_NE(message.find("cannot read table \"" + path + "\": Permission denied"),
            std::string::npos)
      << message;
  const unsigned reader = geteuid() == 0 ? 65534u : static_cast<unsigned>(geteuid());
  EXPECT_NE(message.find("(rtapi_app reads as uid " + std::to_string(reader)), std::string::npos)
      << message;
  EXPECT_NE(message.find("; the file: uid " + std::to_string(geteuid())), std::string::npos)
      << message;
  EXPECT_NE(message.find(geteuid() == 0 ? ", mode 0600)" : ", mode 0000)"), std::string::npos)
      << message;
  std::remove(path.c_str());
  std::remove(out_path.c_str());
}

TEST(NativeTable, AReloadMustHaveTheSameAxes) {
  const auto first = testing::Load(WriteGridImage(Grid(4, 10.0)));
  const auto same = testing::Load(WriteGridImage(Grid(5, 10.0)));
  const auto more = testing::Load(testing::XyzaImage(Grid(6, 10.0)));
  ASSERT_TRUE(first && same && more);
  EXPECT_TRUE(first->CheckSameAxes(*same, "b.vct").ok());
  const Outcome o = first->CheckSameAxes(*more, "c.vct");
  ASSERT_FALSE(o.ok());
  EXPECT_EQ(o.error().code, Error::kConfigAxisMismatch);
  EXPECT_EQ(o.error().message,
            "table \"c.vct\" refused: its axes (X linear 0.001 mm/step, Y linear 0.001 mm/step, "
            "Z linear 0.001 mm/step, A rotary 0.001 deg/step) differ from those the component "
            "was loaded with (X linear 0.001 mm/step, Y linear 0.001 mm/step, Z linear 0.001 "
            "mm/step); a reload must be a table for the same machine (kConfigAxisMismatch)");
  const Expected<std::unique_ptr<NativeTable>> copy = first->Copy("copy");
  ASSERT_TRUE(copy.ok());
  EXPECT_EQ((*copy)->crc32(), first->crc32());
}

}  // namespace
}  // namespace volcomp::linuxcnc
