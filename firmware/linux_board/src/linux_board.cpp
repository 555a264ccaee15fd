// volcomp-fw-linux's devices and board application (see linux_board.hpp).
#include "volcomp/linux_board/linux_board.hpp"

#include <cstdio>

#include "volcomp/hal/linux/fake_gpio.hpp"
#include "volcomp/hal/linux/gpiod_backend.hpp"

namespace volcomp::linux_board {

namespace lb = hal::linux_board;

LinuxBoard::LinuxBoard(const LinuxBoardConfig& config, const Options& options)
    : config_(config), options_(options) {}

LinuxBoard::~LinuxBoard() = default;

void LinuxBoard::Log(const std::string& line) const {
  if (options_.log) {
    options_.log(line);
  } else {
    std::fprintf(stderr, "volcomp-fw-linux: %s\n", line.c_str());
  }
}

Expected<void> LinuxBoard::Open(hal::CanPort* controller, hal::CanPort* drives) {
  lb::FileFlash::Options fo;
  fo.size = 2 * config_.table_bank_bytes;
  fo.sector_size = config_.sector_bytes;
  fo.sync = config_.flash_sync;
  fo.background = config_.flash_write_behind;
  Expected<void> opened = tables_.Open(config_.table_file, fo);
  if (!opened.ok()) return opened;
  have_settings_ = !config_.settings_file.empty();
  if (have_settings_) {
    fo.size = 2 * config_.sector_bytes;
    opened = settings_.Open(config_.settings_file, fo);
    if (!opened.ok()) return opened;
  }
  switch (config_.gpio_backend) {
    case GpioBackendKind::kNone:
      gpio_ = std::make_unique<lb::FakeGpio>();
      break;
    case GpioBackendKind::kFake:
      gpio_ = std::make_unique<lb::FakeGpio>(config_.fake_state_file);
      break;
    case GpioBackendKind::kGpiod:
      gpio_ = lb::MakeGpiodBackend();
      if (gpio_ == nullptr) {
        return Fail(Error::kNotFound,
                    "[gpio] backend = gpiod, but this build has no libgpiod (install "
                    "libgpiod-dev and rebuild, or use backend = fake)");
      }
      break;
  }
  opened = gpio_->Open(config_.gpio);
  if (!opened.ok()) return opened;
  lb::LinuxSlowIo::Options io;
  io.debounce_ms = config_.debounce_ms;
  io_ = std::make_unique<lb::LinuxSlowIo>(gpio_.get(), io);
  io_->Refresh(clock_.NowNs());
  opened = timer_.Open();
  if (!opened.ok()) return opened;
  temperatures_ =
      std::make_unique<TemperatureFiles>(config_.temperature_files, config_.temperature_period_ms);

  firmware::GatewayDevices dev;
  dev.controller = controller;
  dev.drives = drives;
  dev.io = io_.get();
  dev.table_flash = &tables_;
  dev.settings_flash = have_settings_ ? &settings_ : nullptr;
  dev.clock = &clock_;
  dev.tick_timer = &timer_;
  dev.temperatures = temperatures_.get();
  app_ = std::make_unique<firmware::GatewayApp>(dev);
  firmware::AppOptions ao;
  ao.use_enable_input = config_.enable_input;
  ao.table_bank_size = config_.table_bank_bytes;
  ao.settings_bank_size = config_.sector_bytes;
  ao.identity.hardware_version = canopen::HardwareVersion(canopen::Hardware::kLinuxBoard);
  ao.identity.serial_number = config_.serial_number;
  const Status s = app_->Start(config_.settings, config_.gateway, ao);
  if (!s.ok()) {
    return Fail(s.error(),
                std::string("start failed: ") + s.name() + " (" + ErrorText(s.error()) + ")");
  }
  timer_starts_seen_ = timer_.starts();
  temperatures_->Start();
  LogTemperatureSources();
  return Expected<void>::Ok();
}

// A file for a channel whose source in force is not a Linux file is not read into it; a channel
// whose source is a Linux file without one goes stale: both said at start and node reset.
void LinuxBoard::LogTemperatureSources() {
  const BoardSettings& s = app_->app().settings();
  for (uint8_t ch = 0; ch < thermal::kMaxChannels; ++ch) {
    const bool file = !config_.temperature_files[ch].empty();
    const bool linux_source = s.temperature[ch].source == thermal::ChannelSource::kLinuxFile;
    const std::string n = std::to_string(ch + 1);
    if (file && !linux_source) {
      Log("[sensors] temperature_file." + n + " is set, but temperature channel " + n +
          "'s source is not a Linux file: the file is not used");
    } else if (!file && linux_source) {
      Log("temperature channel " + n +
          "'s source is a Linux file, but [sensors] temperature_file." + n +
          " is not set: the channel has no readings (stale)");
    }
  }
}

void LinuxBoard::OnTimer() {
  const uint64_t n = timer_.Take();
  if (n != 0) {
    if (n > 1) ticks_.late += n - 1;
    const uint64_t run = n < kMaxCatchUpTicks ? n : kMaxCatchUpTicks;
    ticks_.skipped += n - run;
    for (uint64_t i = 0; i < run; ++i) {
      const uint64_t t0 = clock_.NowNs();
      app_->TimedTick();  // also the diagnostic object 0x2140
      const uint64_t dt = clock_.NowNs() - t0;
      ticks_.max_tick_ns = dt > ticks_.max_tick_ns ? dt : ticks_.max_tick_ns;
    }
    ticks_.ticks += run;
  }
  const uint64_t now = clock_.NowNs();
  if (now >= next_io_ns_) {
    io_->Refresh(now);
    next_io_ns_ = now + uint64_t{config_.io_poll_ms} * 1000000u;
  }
  app_->Poll();  // an NMT reset node reconfigures here, the tick timer included
  if (timer_.starts() != timer_starts_seen_) {
    timer_starts_seen_ = timer_.starts();
    Log("node reset: " + DescribeConfigInForce());
    LogTemperatureSources();
  }
  for (const std::string& line : temperatures_->TakeLog()) Log(line);
}

void LinuxBoard::Shutdown() {
  if (temperatures_ != nullptr) temperatures_->Stop();
  // Outputs inactive: the board is no longer compensating or ready.
  io_->Write(hal::OutputLine::kCompensating, false);
  io_->Write(hal::OutputLine::kReady, false);
  // Everything the stores wrote reaches the files before the process ends.
  for (lb::FileFlash* f : {&tables_, &settings_}) {
    if (!f->is_open()) continue;
    const Expected<void> flushed = f->Flush();
    if (!flushed.ok()) Log(flushed.error().message);
  }
}

std::string LinuxBoard::DescribeConfigInForce() const {
  const firmware::GatewayApp::App& app = app_->app();
  const BoardSettings& s = app.settings();
  char line[160];
  std::snprintf(line, sizeof line,
                "tick %u Hz (timer period %llu ns), bit rate %u kbit/s, node 0x%02X, %u axes",
                s.board.tick_hz, static_cast<unsigned long long>(timer_.period_ns()),
                unsigned{s.bitrate_kbit}, unsigned{s.node_id},
                unsigned{app.control_tick().axis_count()});
  std::string out = line;
  const Status c = app.config_status();
  if (c.error() == Error::kCanBitrateMismatch) {
    out += "; WARNING: the controller interface runs at another bit rate";
  } else if (!c.ok()) {
    out += std::string("; WARNING: the stored settings were refused (") + ErrorText(c.error()) +
           "): running the configuration file's";
  }
  if (options_.bus_detail) out += "; bit rate check: " + options_.bus_detail();
  return out;
}

}  // namespace volcomp::linux_board
