// The Linux board backends (hal/linux): file-backed NOR flash, the fake GPIO backend and its state
// file, debounced slow lines, line specs, the libgpiod backend's error path, SIGTERM through the
// signalfd, and the timerfd tick.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "volcomp/hal/linux/fake_gpio.hpp"
#include "volcomp/hal/linux/file_flash.hpp"
#include "volcomp/hal/linux/gpio_lines.hpp"
#include "volcomp/hal/linux/gpiod_backend.hpp"
#include "volcomp/hal/linux/linux_slow_io.hpp"
#include "volcomp/hal/linux/shutdown_signal.hpp"
#include "volcomp/hal/linux/tick_timer.hpp"

namespace volcomp::hal::linux_board {
namespace {

class TempDir {
 public:
  TempDir() {
    char t[] = "/tmp/volcomp-hal-test.XXXXXX";
    path_ = mkdtemp(t) != nullptr ? t : "";
  }
  ~TempDir() {
    for (const std::string& f : files_) std::remove((path_ + "/" + f).c_str());
    rmdir(path_.c_str());
  }
  std::string file(const std::string& name) {
    files_.push_back(name);
    files_.push_back(name + ".out");
    files_.push_back(name + ".tmp");
    return path_ + "/" + name;
  }

 private:
  std::string path_;
  std::vector<std::string> files_;
};

std::vector<uint8_t> ReadFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::vector<uint8_t>((std::istreambuf_iterator<char>(f)), {});
}

FileFlash::Options SmallFlash() {
  FileFlash::Options o;
  o.size = 16384;
  o.sector_size = 4096;
  o.program_unit = 8;
  return o;
}

TEST(FileFlashTest, NewFileIsErasedAndProgramOnlyClearsBits) {
  TempDir dir;
  const std::string path = dir.file("flash.bin");
  FileFlash flash;
  ASSERT_TRUE(flash.Open(path, SmallFlash()).ok());
  EXPECT_EQ(flash.size(), 16384u);
  const std::vector<uint8_t> file = ReadFile(path);
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
  const std::vector<uint8_t> after = ReadFile(path);
  EXPECT_EQ(after[0], 0x0F);
  EXPECT_EQ(after[4096], 0xFF);
}

TEST(FileFlashTest, ContentSurvivesReopenAndWrongSizeIsRefused) {
  TempDir dir;
  const std::string path = dir.file("flash.bin");
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
  TempDir dir;
  const std::string path = dir.file("flash.bin");
  FileFlash::Options o = SmallFlash();
  o.background = false;
  FileFlash flash;
  ASSERT_TRUE(flash.Open(path, o).ok());
  const uint8_t a[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  ASSERT_TRUE(flash.Program(64, a, 8).ok());
  EXPECT_EQ(flash.counters().written, 1u);
  const std::vector<uint8_t> file = ReadFile(path);  // no Flush() needed
  EXPECT_EQ(std::vector<uint8_t>(file.begin() + 64, file.begin() + 72),
            std::vector<uint8_t>(a, a + 8));
}

TEST(FileFlashTest, ManyQueuedOperationsLandInOrder) {
  TempDir dir;
  const std::string path = dir.file("flash.bin");
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
  const std::vector<uint8_t> file = ReadFile(path);
  EXPECT_EQ(std::vector<uint8_t>(file.begin(), file.begin() + 16),
            std::vector<uint8_t>(expect, expect + 16));
  EXPECT_EQ(file[16], 0xFF);
}

TEST(FileFlashTest, OneProcessAtATime) {
  TempDir dir;
  const std::string path = dir.file("flash.bin");
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
  TempDir dir;
  FileFlash flash;
  FileFlash::Options o = SmallFlash();
  o.sector_size = 3000;
  EXPECT_EQ(flash.Open(dir.file("x.bin"), o).error().code, Error::kInvalidArgument);
  const Expected<void> opened = flash.Open("/nonexistent-dir/flash.bin", SmallFlash());
  ASSERT_FALSE(opened.ok());
  EXPECT_NE(opened.error().message.find("cannot create"), std::string::npos);
}

TEST(GpioLineSpecTest, ParsesAndFormats) {
  GpioLineSpec s;
  auto parse = [&s](const std::string& text) {
    const Expected<GpioLineSpec> r = ParseGpioLineSpec(text);
    if (r.ok()) s = *r;
    return r.ok();
  };
  ASSERT_TRUE(parse("gpiochip0:17 active-low pull-up"));
  EXPECT_TRUE(s.used);
  EXPECT_EQ(s.chip, "gpiochip0");
  EXPECT_EQ(s.offset, 17u);
  EXPECT_TRUE(s.active_low);
  EXPECT_EQ(s.bias, Bias::kPullUp);
  EXPECT_EQ(FormatGpioLineSpec(s), "gpiochip0:17 active-low pull-up");
  ASSERT_TRUE(parse("/dev/gpiochip1:3"));
  EXPECT_EQ(s.chip, "/dev/gpiochip1");
  EXPECT_EQ(s.offset, 3u);
  EXPECT_FALSE(s.active_low);
  ASSERT_TRUE(parse("ESTOP_IN bias-disable"));
  EXPECT_TRUE(s.chip.empty());
  EXPECT_EQ(s.line_name, "ESTOP_IN");
  EXPECT_EQ(s.bias, Bias::kDisable);
  EXPECT_FALSE(parse("gpiochip0:x"));
  EXPECT_FALSE(parse(":4"));
  EXPECT_FALSE(parse("gpiochip0:4 open-drain"));
  EXPECT_FALSE(parse("gpiochip0:4 pull-up pull-down"));
  EXPECT_FALSE(parse("   "));
  InputLine in;
  EXPECT_TRUE(InputLineFromName("drive_alarm", &in));
  EXPECT_EQ(in, InputLine::kDriveAlarm);
  EXPECT_TRUE(InputLineFromName("home3", &in));
  EXPECT_EQ(in, HomeLine(3));
  EXPECT_FALSE(InputLineFromName("ready", &in));
  OutputLine out;
  EXPECT_TRUE(OutputLineFromName("compensating", &out));
  EXPECT_EQ(out, OutputLine::kCompensating);
}

TEST(FakeGpioTest, StateFileDrivesInputsAndReceivesOutputs) {
  TempDir dir;
  const std::string path = dir.file("gpio");
  {
    std::ofstream f(path);
    f << "# bench\nestop=1\nhome1 = 1   # switch pressed\nwrite_enable=0\n";
  }
  FakeGpio gpio(path);
  ASSERT_TRUE(gpio.Open(GpioConfig()).ok());
  gpio.SetInput(InputLine::kEnable, true);       // not named in the file: the memory value counts
  gpio.SetInput(InputLine::kWriteEnable, true);  // named in the file: the file wins
  bool levels[kInputLineCount];
  ASSERT_TRUE(gpio.ReadInputs(levels).ok());
  EXPECT_TRUE(levels[static_cast<int>(InputLine::kEStop)]);
  EXPECT_TRUE(levels[static_cast<int>(HomeLine(1))]);
  EXPECT_FALSE(levels[static_cast<int>(HomeLine(0))]);
  EXPECT_TRUE(levels[static_cast<int>(InputLine::kEnable)]);
  EXPECT_FALSE(levels[static_cast<int>(InputLine::kWriteEnable)]);
  // The file is re-read only when it changes.
  const uint32_t reads = gpio.file_reads();
  ASSERT_TRUE(gpio.ReadInputs(levels).ok());
  EXPECT_EQ(gpio.file_reads(), reads);
  {
    std::ofstream f(path, std::ios::trunc);
    f << "estop=0\n";  // another size: seen even within the same mtime tick
  }
  ASSERT_TRUE(gpio.ReadInputs(levels).ok());
  EXPECT_FALSE(levels[static_cast<int>(InputLine::kEStop)]);
  EXPECT_FALSE(levels[static_cast<int>(HomeLine(1))]);
  // Outputs go to PATH.out.
  ASSERT_TRUE(gpio.WriteOutput(OutputLine::kFault, true).ok());
  std::ifstream out(path + ".out");
  std::stringstream text;
  text << out.rdbuf();
  EXPECT_EQ(text.str(), "ready=0\ncompensating=0\nfault=1\n");
  EXPECT_TRUE(gpio.output(OutputLine::kFault));
  // A malformed line is reported with its number.
  {
    std::ofstream f(path, std::ios::trunc);
    f << "estop=1\nestpo=1\n";
  }
  const Expected<void> read = gpio.ReadInputs(levels);
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.error().message.find(":2:"), std::string::npos) << read.error().message;
}

TEST(LinuxSlowIoTest, DebouncesAndIsFailSafeForStopInputs) {
  FakeGpio gpio;
  ASSERT_TRUE(gpio.Open(GpioConfig()).ok());
  LinuxSlowIo::Options o;
  o.debounce_ms = 5;
  LinuxSlowIo io(&gpio, o);
  SlowIo& slow = io;
  gpio.SetInput(InputLine::kWriteEnable, true);
  io.Refresh(0);  // the first reading is taken as is
  EXPECT_TRUE(slow.Read(InputLine::kWriteEnable));
  // A home switch must be stable for 5 ms.
  gpio.SetInput(HomeLine(0), true);
  io.Refresh(1000000);
  EXPECT_FALSE(slow.Read(HomeLine(0)));
  EXPECT_TRUE(io.raw(HomeLine(0)));
  io.Refresh(5999999);
  EXPECT_FALSE(slow.Read(HomeLine(0)));
  io.Refresh(6000000);
  EXPECT_TRUE(slow.Read(HomeLine(0)));
  // A bounce restarts the timing.
  gpio.SetInput(HomeLine(0), false);
  io.Refresh(7000000);
  gpio.SetInput(HomeLine(0), true);
  io.Refresh(8000000);
  gpio.SetInput(HomeLine(0), false);
  io.Refresh(9000000);
  io.Refresh(13000000);
  EXPECT_TRUE(slow.Read(HomeLine(0)));
  io.Refresh(14000000);
  EXPECT_FALSE(slow.Read(HomeLine(0)));
  // E-stop and drive alarm: active at once, inactive only after the debounce time.
  gpio.SetInput(InputLine::kEStop, true);
  io.Refresh(20000000);
  EXPECT_TRUE(slow.Read(InputLine::kEStop));
  gpio.SetInput(InputLine::kEStop, false);
  io.Refresh(21000000);
  EXPECT_TRUE(slow.Read(InputLine::kEStop));
  io.Refresh(26000000);
  EXPECT_FALSE(slow.Read(InputLine::kEStop));
  gpio.SetInput(InputLine::kDriveAlarm, true);
  io.Refresh(27000000);
  EXPECT_TRUE(slow.Read(InputLine::kDriveAlarm));
  // Outputs are written through on change.
  slow.Write(OutputLine::kReady, true);
  EXPECT_TRUE(gpio.output(OutputLine::kReady));
  EXPECT_TRUE(io.output(OutputLine::kReady));
  EXPECT_EQ(io.errors(), 0u);
}

TEST(GpiodBackendTest, NamesTheMissingChip) {
  std::unique_ptr<GpioBackend> gpio = MakeGpiodBackend();
  if (!HaveLibgpiod()) {
    EXPECT_EQ(gpio, nullptr);
    GTEST_SKIP() << "built without libgpiod";
  }
  ASSERT_NE(gpio, nullptr);
  EXPECT_NE(gpio->Describe().find("libgpiod 1."), std::string::npos) << gpio->Describe();
  GpioConfig c;
  const Expected<GpioLineSpec> spec = ParseGpioLineSpec("volcomp-no-such-chip:3");
  ASSERT_TRUE(spec.ok());
  c.input[7] = *spec;
  const Expected<void> opened = gpio->Open(c);
  ASSERT_FALSE(opened.ok());
  const std::string why = opened.error().message;
  EXPECT_NE(why.find("estop"), std::string::npos) << why;
  EXPECT_NE(why.find("volcomp-no-such-chip"), std::string::npos) << why;
  // Nothing configured: nothing requested, every input reads inactive.
  EXPECT_TRUE(gpio->Open(GpioConfig()).ok());
  bool levels[kInputLineCount] = {true, true, true, true, true, true, true, true, true, true};
  EXPECT_TRUE(gpio->ReadInputs(levels).ok());
  for (bool l : levels) EXPECT_FALSE(l);
}

TEST(ShutdownSignalTest, SigtermArrivesOnTheFd) {
  ShutdownSignal sig;
  ASSERT_TRUE(sig.Open().ok());
  EXPECT_EQ(sig.Take(), 0);
  ASSERT_EQ(kill(getpid(), SIGTERM), 0);  // blocked: it stays pending for the signalfd
  EXPECT_EQ(sig.Take(), SIGTERM);
  EXPECT_EQ(sig.Take(), 0);
  sig.Close();
}

TEST(TickTimerTest, CountsExpirations) {
  TickTimer timer;
  hal::TickTimer& tick = timer;
  EXPECT_EQ(tick.SetRate(1000).error(), Error::kNotReady);  // not open
  ASSERT_TRUE(timer.Open().ok());
  EXPECT_GE(timer.fd(), 0);
  EXPECT_EQ(tick.SetRate(100000000).error(), Error::kConfigInvalid);  // a 10 ns period
  EXPECT_EQ(tick.Start().error(), Error::kNotReady);                  // no rate yet
  ASSERT_TRUE(tick.SetRate(1000).ok());                               // 1 ms
  EXPECT_EQ(timer.period_ns(), 1000000u);
  ASSERT_TRUE(tick.Start().ok());
  EXPECT_EQ(tick.SetRate(2000).error(), Error::kBusy);  // the rate changes only while stopped
  usleep(5000);
  EXPECT_GE(timer.Take(), 1u);  // at least one period passed
  timer.Close();
  EXPECT_EQ(timer.Take(), 0u);
}

TEST(TickTimerTest, StopDiscardsAndARestartRunsAtTheNewRate) {
  TickTimer timer;
  hal::TickTimer& tick = timer;
  ASSERT_TRUE(timer.Open().ok());
  const int fd = timer.fd();
  ASSERT_TRUE(tick.SetRate(10000).ok());
  ASSERT_TRUE(tick.Start().ok());
  usleep(3000);
  tick.Stop();
  EXPECT_EQ(timer.Take(), 0u);  // expirations before Stop() are gone
  usleep(2000);
  EXPECT_EQ(timer.Take(), 0u);  // stopped
  ASSERT_TRUE(tick.SetRate(2000).ok());
  ASSERT_TRUE(tick.Start().ok());
  EXPECT_EQ(timer.fd(), fd);  // the event loop keeps watching the same fd
  EXPECT_EQ(timer.starts(), 2u);
  // The kernel's own view of the armed period (independent of period_ns()).
  itimerspec spec{};
  ASSERT_EQ(timerfd_gettime(timer.fd(), &spec), 0);
  EXPECT_EQ(spec.it_interval.tv_sec, 0);
  EXPECT_EQ(spec.it_interval.tv_nsec, 500000);
}

}  // namespace
}  // namespace volcomp::hal::linux_board
