// The board application: wires the core (lib/) to the HAL and owns the two execution contexts.
//
//   Tick()  the control tick (timer ISR at BoardConfig::tick_hz): latch input counters, run the
//           data path (ControlTick), program the output timers. Nothing else.
//   Poll()  the main loop: slow lines (home switches, enable, e-stop, drive alarm), status outputs,
//           and (with the CAN issue) the CANopen node. Never touches the data path directly:
//           reference requests are handed to the next Tick() through an atomic bit mask.
//
// Tables: Start() activates the image stored in the table flash if it is valid and matches the
// board; otherwise the board runs as pure pass-through and reports why (stored_table_status()).
// A table is only ever read in place from storage that stays valid while it is active.
//
// StepIo is a static interface (volcomp/hal/step_io.hpp): no virtual call on the tick path.
#pragma once

#include <atomic>
#include <cstdint>

#include "volcomp/board_config.hpp"
#include "volcomp/compensator.hpp"
#include "volcomp/control_tick.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/hal/slow_io.hpp"
#include "volcomp/hal/step_io.hpp"
#include "volcomp/status.hpp"
#include "volcomp/table_image.hpp"

namespace volcomp::firmware {

struct AppOptions {
  /// When false the compensation is enabled without a wired enable input.
  bool use_enable_input = true;
};

template <class StepIo>
class BoardApp {
  static_assert(hal::IsStepIo<StepIo>::value, "StepIo must provide ReadCounters() and Apply()");

 public:
  struct Devices {
    StepIo* step_io = nullptr;
    hal::SlowIo* io = nullptr;
    hal::Flash* table_flash = nullptr;  // holds the stored table image at offset 0
  };

  explicit BoardApp(const Devices& devices) : dev_(devices) {}

  /// Configures the data path and activates the stored table if valid. Fails only for an invalid
  /// configuration (the board then stays in pass-through with kFault set).
  Status Start(const BoardConfig& config, const AppOptions& options = AppOptions()) {
    options_ = options;
    const Status s = engine_.Configure(config);
    started_ = s.ok();
    dev_.io->Write(hal::OutputLine::kReady, started_);
    dev_.io->Write(hal::OutputLine::kFault, !started_);
    if (!started_) return s;
    uint32_t counters[table::kMaxAxes];
    dev_.step_io->ReadCounters(counters);
    engine_.LatchCounters(counters);
    for (uint8_t a = 0; a < table::kMaxAxes; ++a) {
      home_level_[a] = dev_.io->Read(hal::HomeLine(a));
    }
    stored_status_ = ActivateStored();
    Poll();
    return Status::Ok();
  }

  /// The control tick.
  void Tick() {
    if (!started_) return;
    const uint8_t refs = pending_reference_.exchange(0, std::memory_order_acquire);
    if (refs != 0) {
      for (uint8_t a = 0; a < engine_.axis_count(); ++a) {
        if ((refs & (1u << a)) != 0) engine_.Reference(a);
      }
    }
    if (pending_unreference_.exchange(false, std::memory_order_acquire)) engine_.Unreference();
    uint32_t counters[table::kMaxAxes];
    dev_.step_io->ReadCounters(counters);
    engine_.Run(counters, plans_);
    dev_.step_io->Apply(plans_);
  }

  /// The main loop's slow work.
  void Poll() {
    if (!started_) return;
    hal::SlowIo& io = *dev_.io;
    uint8_t refs = 0;
    for (uint8_t a = 0; a < engine_.axis_count(); ++a) {
      const bool level = io.Read(hal::HomeLine(a));
      if (level && !home_level_[a]) refs = static_cast<uint8_t>(refs | (1u << a));
      home_level_[a] = level;
    }
    const bool fault = io.Read(hal::InputLine::kEStop) || io.Read(hal::InputLine::kDriveAlarm);
    if (fault && !fault_) pending_unreference_.store(true, std::memory_order_release);
    fault_ = fault;
    if (!fault && refs != 0) pending_reference_.fetch_or(refs, std::memory_order_release);
    Compensator& comp = engine_.compensator();
    comp.SetFault(fault);
    comp.SetEnabled(!options_.use_enable_input || io.Read(hal::InputLine::kEnable));
    io.Write(hal::OutputLine::kCompensating, comp.engaged());
    io.Write(hal::OutputLine::kFault, fault);
  }

  /// Validates `image` against the board and makes it active (it must stay valid and unchanged
  /// while active). On error nothing changes.
  Status ActivateImage(const uint8_t* image, size_t size) {
    const Result<table::TableView> view = table::ParseImage(image, size);
    if (!view.ok()) return view.status();
    PreparedTable prepared;
    VOLCOMP_TRY(prepared.Prepare(*view, engine_.config()));
    int32_t machine[table::kMaxAxes];
    for (uint8_t a = 0; a < engine_.axis_count(); ++a) machine[a] = engine_.machine_position(a);
    engine_.compensator().SetTable(prepared, machine);
    return Status::Ok();
  }

  /// Activates the image stored in the table flash.
  Status ActivateStored() {
    const hal::Flash& flash = *dev_.table_flash;
    const uint8_t* base = flash.Map(0);
    const Result<uint32_t> size = table::PeekImageSize(base, flash.size());
    if (!size.ok()) return size.status();
    return ActivateImage(base, *size);
  }

  /// Drops the active table; the correction ramps out.
  void Deactivate() { engine_.compensator().ClearTable(); }

  const ControlTick& engine() const { return engine_; }
  ControlTick& engine() { return engine_; }
  Status stored_table_status() const { return stored_status_; }
  bool started() const { return started_; }

 private:
  Devices dev_;
  AppOptions options_;
  ControlTick engine_;
  PulsePlan plans_[table::kMaxAxes];
  bool started_ = false;
  bool fault_ = false;
  bool home_level_[table::kMaxAxes] = {};
  Status stored_status_ = Error::kNotFound;
  std::atomic<uint8_t> pending_reference_{0};
  std::atomic<bool> pending_unreference_{false};
};

}  // namespace volcomp::firmware
