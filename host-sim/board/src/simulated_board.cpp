// The firmware on the mock HAL on a simulated bus, in virtual time.
#include "volcomp/sim/simulated_board.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace volcomp::sim {

SimulatedBoard::SimulatedBoard(SimBus& bus, const SimulatedBoardOptions& options)
    : options_(options),
      endpoint_(bus.Attach("board")),
      io_(&clock_, nullptr),
      table_flash_(options.table_flash_bytes, options.flash_sector_bytes, 8, &clock_, nullptr),
      settings_flash_(
          options.settings_flash_bytes, options.flash_sector_bytes, 8, &clock_, nullptr),
      can_(endpoint_, 64) {
  step_io_ = std::make_unique<hal::mock::MockStepIo>(options.settings.board, nullptr);
  tick_io_ = std::make_unique<TickIo>(step_io_.get());
  hal::Flash* tables = &table_flash_;
  hal::Flash* settings = &settings_flash_;
  if (!options.flash_dir.empty()) {
    table_file_ =
        std::make_unique<WriteThroughFlash>(&table_flash_, options.flash_dir + "/tables.bin");
    settings_file_ =
        std::make_unique<WriteThroughFlash>(&settings_flash_, options.flash_dir + "/settings.bin");
    tables = table_file_.get();
    settings = settings_file_.get();
  }
  app_ = std::make_unique<App>(
      App::Devices{tick_io_.get(), &io_, tables, settings, &can_, &clock_, &tick_timer_});
}

SimulatedBoard::~SimulatedBoard() = default;

void SimulatedBoard::LoadFlash() {
  if (options_.flash_dir.empty()) return;
  for (auto [flash, name] :
       {std::pair{&table_flash_, "tables.bin"}, std::pair{&settings_flash_, "settings.bin"}}) {
    std::ifstream f(options_.flash_dir + "/" + name, std::ios::binary);
    if (!f) continue;
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(f)), {});
    if (bytes.size() == flash->raw().size()) flash->raw() = bytes;
  }
}

void SimulatedBoard::SaveFlash() const {
  if (options_.flash_dir.empty()) return;
  for (auto [flash, name] :
       {std::pair{&table_flash_, "tables.bin"}, std::pair{&settings_flash_, "settings.bin"}}) {
    std::ofstream f(options_.flash_dir + "/" + name, std::ios::binary | std::ios::trunc);
    const auto& raw = const_cast<hal::mock::MockFlash*>(flash)->raw();
    f.write(reinterpret_cast<const char*>(raw.data()), static_cast<std::streamsize>(raw.size()));
  }
}

Outcome SimulatedBoard::OpenFlashFiles() {
  if (!table_file_) return Outcome::Ok();
  std::error_code ec;
  std::filesystem::create_directories(options_.flash_dir, ec);
  if (ec) return Fail(Error::kIoError, options_.flash_dir + ": cannot create: " + ec.message());
  VOLCOMP_TRY(table_file_->Open());
  return settings_file_->Open();
}

Outcome SimulatedBoard::Start() {
  VOLCOMP_TRY(OpenFlashFiles());
  LoadFlash();
  if (options_.initial_table_flash.size() == table_flash_.raw().size()) {
    table_flash_.raw() = options_.initial_table_flash;
  }
  if (table_file_) {
    VOLCOMP_TRY(table_file_->WriteAll());
    VOLCOMP_TRY(settings_file_->WriteAll());
  }
  io_.SetInput(hal::InputLine::kEnable, options_.enable_input);
  io_.SetInput(hal::InputLine::kWriteEnable, options_.write_enable_input);
  clock_.Set(now_ns_);
  firmware::AppOptions app;
  app.identity.hardware_version = canopen::HardwareVersion(canopen::Hardware::kSimulator);
  const Status s = app_->Start(options_.settings, app);
  next_poll_ns_ = now_ns_;
  FollowTickTimer();
  if (!s.ok()) return Fail(s, "the firmware did not start");
  return Outcome::Ok();
}

void SimulatedBoard::FollowTickTimer() {
  if (!tick_timer_.running()) {
    next_tick_ns_ = UINT64_MAX;
    return;
  }
  if (tick_timer_.starts() == timer_starts_seen_) return;
  timer_starts_seen_ = tick_timer_.starts();
  tick_ns_ = 1000000000ull / tick_timer_.rate_hz();
  next_tick_ns_ = now_ns_;  // the first tick at the start, the next one a period later
}

uint64_t SimulatedBoard::NextEventTime() const {
  return next_tick_ns_ < next_poll_ns_ ? next_tick_ns_ : next_poll_ns_;
}

void SimulatedBoard::AdvanceTo(uint64_t t_ns) {
  while (NextEventTime() <= t_ns) {
    if (next_tick_ns_ <= next_poll_ns_) {
      now_ns_ = next_tick_ns_;
      clock_.Set(now_ns_);
      step_io_->set_tick_start_ns(now_ns_);
      app_->Tick();
      next_tick_ns_ += tick_ns_;
    } else {
      now_ns_ = next_poll_ns_;
      clock_.Set(now_ns_);
      app_->Poll();  // an NMT reset node restarts the tick timer here
      next_poll_ns_ += options_.poll_period_ns;
      FollowTickTimer();
    }
  }
  now_ns_ = t_ns;
  clock_.Set(now_ns_);
}

uint64_t NextEventTime(const SimBus& bus, const SimulatedBoard& board) {
  const uint64_t t = board.NextEventTime();
  const std::optional<uint64_t> b = bus.NextEventTime();
  return b && *b < t ? *b : t;
}

void StepTo(SimBus& bus, SimulatedBoard& board, uint64_t t_ns) {
  bus.RunUntil(t_ns);
  board.AdvanceTo(t_ns);
}

void AdvanceInEventOrder(SimBus& bus, SimulatedBoard& board, uint64_t t_ns) {
  for (uint64_t next = NextEventTime(bus, board); next <= t_ns; next = NextEventTime(bus, board)) {
    StepTo(bus, board, next);
  }
  StepTo(bus, board, t_ns);
}

}  // namespace volcomp::sim
