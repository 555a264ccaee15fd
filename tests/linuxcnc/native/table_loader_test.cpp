// Reloads outside the servo thread: the loader reads and checks the file on a request and
// publishes the table; the servo side switches it in by pointer and hands the old one back, which
// the loader frees; a refused file leaves the active table and posts its error; a table is freed
// only after the servo side switched away from it; the servo side's calls allocate nothing and
// open no file (counted here), also while a loader thread runs beside them.
#include "native/table_loader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include "native/native_compensator.hpp"
#include "native_tables.hpp"

// Counts every operator new of this test program per thread (the servo-side calls must make
// none; the loader thread allocates as it likes).
static thread_local long t_allocations = 0;
void* operator new(std::size_t n) {
  ++t_allocations;
  void* p = std::malloc(n == 0 ? 1 : n);
  if (p == nullptr) std::abort();
  return p;
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace volcomp::linuxcnc {
namespace {

using testing::Grid;
using volcomp::testing::WriteGridImage;

std::vector<std::string> g_messages;
void Record(TableLoader::Level level, const std::string& m) {
  g_messages.push_back(std::string(level == TableLoader::Level::kError ? "E " : "I ") + m);
}

std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "/table_loader_test_" + std::to_string(getpid()) + "_" + name;
}

void WriteImage(const std::string& path, const volcomp::testing::AlignedBytes& image) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(image.data()), static_cast<long>(image.size()));
}

struct Fixture {
  std::string path = TempPath("t.vct");
  std::unique_ptr<NativeTable> first;
  std::unique_ptr<NativeTable> reference;
  const NativeTable* active = nullptr;
  TableExchange exchange;
  Fixture() {
    const auto image = WriteGridImage(Grid(1, 10.0));
    WriteImage(path, image);
    first = testing::Load(image, path);
    reference = first->Copy(path).value();
    active = first.release();  // owned by the "servo side", as in the component
  }
  ~Fixture() {
    delete active;
    std::remove(path.c_str());
  }
};

TEST(TableLoader, ReloadsOnRequestAndFreesTheOldTableAfterTheSwitch) {
  Fixture f;
  TableLoader loader(Record);
  loader.Start({{"volcomp.0", f.path, f.reference.get(), &f.exchange}});
  loader.Stop();  // drive it by hand from here
  g_messages.clear();
  loader.Poll();
  EXPECT_FALSE(f.exchange.pending());  // no request, nothing read
  const auto second = WriteGridImage(Grid(2, 10.0));
  WriteImage(f.path, second);
  f.exchange.RequestReload();
  loader.Poll();
  ASSERT_TRUE(f.exchange.pending());
  EXPECT_EQ(f.exchange.last_error(), 0);
  ASSERT_EQ(g_messages.size(), 1u);
  EXPECT_EQ(g_messages[0].rfind("I volcomp.0: table \"" + f.path + "\" read again (", 0), 0u)
      << g_messages[0];
  const NativeTable* old = f.active;
  ASSERT_TRUE(f.exchange.SwapIn(&f.active));
  EXPECT_NE(f.active, old);
  EXPECT_EQ(f.active->crc32(), testing::Load(second)->crc32());
  // A second table cannot come in before the loader collected the first one.
  f.exchange.RequestReload();
  loader.Poll();  // collects `old`, publishes the same file again
  ASSERT_TRUE(f.exchange.pending());
  EXPECT_TRUE(f.exchange.SwapIn(&f.active));
  EXPECT_FALSE(f.exchange.SwapIn(&f.active));  // nothing waiting
  loader.Poll();
}

TEST(TableLoader, ARefusedReloadKeepsTheActiveTable) {
  Fixture f;
  TableLoader loader(Record);
  loader.Start({{"vc", f.path, f.reference.get(), &f.exchange}});
  loader.Stop();
  auto bad = WriteGridImage(Grid(3, 10.0));
  bad[60] ^= 0x10;
  WriteImage(f.path, bad);
  g_messages.clear();
  f.exchange.RequestReload();
  loader.Poll();
  EXPECT_FALSE(f.exchange.pending());
  EXPECT_EQ(f.exchange.last_error(), static_cast<int32_t>(Error::kImageBadCrc));
  ASSERT_EQ(g_messages.size(), 1u);
  EXPECT_EQ(g_messages[0], "E vc: table \"" + f.path +
                               "\" refused: invalid table image: image CRC-32 does not match "
                               "(kImageBadCrc); the active table stays");
  const NativeTable* before = f.active;
  EXPECT_FALSE(f.exchange.SwapIn(&f.active));
  EXPECT_EQ(f.active, before);
  // Another machine's table (an extra axis) is refused too; then a good one clears the error.
  WriteImage(f.path, testing::XyzaImage(Grid(4, 10.0)));
  f.exchange.RequestReload();
  loader.Poll();
  EXPECT_EQ(f.exchange.last_error(), static_cast<int32_t>(Error::kConfigAxisMismatch));
  std::remove(f.path.c_str());
  f.exchange.RequestReload();
  loader.Poll();
  EXPECT_EQ(f.exchange.last_error(), static_cast<int32_t>(Error::kNotFound));
  WriteImage(f.path, WriteGridImage(Grid(5, 10.0)));
  f.exchange.RequestReload();
  loader.Poll();
  EXPECT_EQ(f.exchange.last_error(), 0);
  EXPECT_TRUE(f.exchange.SwapIn(&f.active));
}

// The servo side as the component runs it, one period every 100 us for 0.5 s, with reload
// requests, while the loader thread reads, publishes and frees: the servo-side calls allocate
// nothing, every request ends in a switch, and the compensation runs on whichever table is in.
TEST(TableLoader, TheServoSideNeverAllocatesWhileTheLoaderWorks) {
  Fixture f;
  TableLoader loader(Record, 1);
  loader.Start({{"volcomp.0", f.path, f.reference.get(), &f.exchange}});
  NativeCompensator comp;
  comp.UseTable(f.active);
  ASSERT_TRUE(comp.SetPeriod(100000).ok());
  AxisLimits l = NativeCompensator::DefaultLimits(f.active->axis(0));
  double pos[3] = {0.1, 0.2, 0.3}, corr[3], vel[3];
  long servo_allocations = 0;
  int switches = 0;
  for (int period = 0; period < 5000; ++period) {
    const long before = t_allocations;
    if (period % 500 == 0) f.exchange.RequestReload();
    if (f.exchange.SwapIn(&f.active)) {
      comp.UseTable(f.active);
      ++switches;
    }
    if (period % 700 == 0) {
      l.max_vel *= 1.01;
      (void)comp.SetLimits(0, l);
    }
    pos[0] += 1e-4;
    comp.Tick(pos, true, true, corr, vel);
    (void)f.exchange.last_error();
    servo_allocations += t_allocations - before;
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  // Let the last request through.
  for (int i = 0; i < 2000 && switches < 10; ++i) {
    if (f.exchange.SwapIn(&f.active)) {
      comp.UseTable(f.active);
      ++switches;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  loader.Stop();
  EXPECT_EQ(servo_allocations, 0);
  EXPECT_EQ(switches, 10);
  EXPECT_EQ(f.exchange.last_error(), 0);
  EXPECT_TRUE(comp.engaged());
}

}  // namespace
}  // namespace volcomp::linuxcnc
