// The board application: wires the core (lib/) to the HAL, owns the settings in force and the two
// execution contexts (docs/architecture.md, "Firmware").
//
//   Tick()   the control tick, timer ISR at settings().board.tick_hz: StepTick() every tick
//            (counters -> targets -> output stage), CompensationTick() every
//            ControlTick::compensation_divider() ticks (requests from the main loop, then the
//            compensator). Static calls only, no allocation, no division; it may preempt Poll(),
//            never the reverse (on the host both run in one thread). Requests reach it through
//            atomics and the table hand-over (table_hand_over.hpp).
//   Poll()   the main loop: slow lines, status outputs, the thermal correction (BoardThermal:
//            the temperature channels, the active image's thermal model, its terms handed to the
//            run every kThermalPeriodMs; needs `clock`), the CANopen node with BoardObjects (the
//            dictionary's values) and BoardPolicy (what the bus may change, the one activation
//            sequence).
//   Start()  power-on and every NMT reset node: loads the stored settings (or the defaults) and
//            applies them with the tick stopped, in the order the tick needs (tick I/O,
//            ControlTick, tick timer, CAN bit rate); settings the hardware refuses give way to the
//            defaults, visibly (FAULT, EMCY kEmcyConfigRefused, config_status()). Then the stored
//            table.
//
// settings() is the one copy of the settings in force: the dictionary and the policy read it,
// ControlTick keeps only what the data path needs. Io is the tick's two ends as one static type
// (tick_io.hpp): StepDirIo<StepIo> (step/dir) or CspIo (CAN gateway, gateway_app.hpp).
#pragma once

#include <atomic>
#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/node.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/config/board_settings.hpp"
#include "volcomp/control/compensator.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/firmware/board_control.hpp"
#include "volcomp/firmware/board_objects.hpp"
#include "volcomp/firmware/board_policy.hpp"
#include "volcomp/firmware/board_thermal.hpp"
#include "volcomp/firmware/settings_store.hpp"
#include "volcomp/firmware/table_hand_over.hpp"
#include "volcomp/firmware/table_store.hpp"
#include "volcomp/firmware/tick_io.hpp"
#include "volcomp/hal/can.hpp"
#include "volcomp/hal/clock.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/hal/slow_io.hpp"
#include "volcomp/hal/temperature_inputs.hpp"
#include "volcomp/hal/tick_timer.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp::firmware {

struct AppOptions {
  /// When false the compensation is enabled without a wired enable input.
  bool use_enable_input = true;
  /// Bytes per table bank (0 = half the table flash).
  uint32_t table_bank_size = 0;
  /// Bytes per settings bank (0 = half the settings flash).
  uint32_t settings_bank_size = 0;
  IdentityInfo identity;
  canopen::SdoServerConfig sdo;
};

template <class Io>
class BoardApp final : private BoardControl {
  static_assert(IsTickIo<Io>::value,
                "Io must provide Configure(), ReadCounters(), Output() and output_status()");

 public:
  struct Devices {
    Io* tick_io = nullptr;  // the input and output stage (tick_io.hpp)
    hal::SlowIo* io = nullptr;
    hal::Flash* table_flash = nullptr;     // dual-bank table store
    hal::Flash* settings_flash = nullptr;  // optional: stored settings
    hal::CanPort* can = nullptr;           // optional: the CANopen node
    hal::Clock* clock = nullptr;           // required with `can` (timeouts, heartbeat)
    hal::TickTimer* tick_timer = nullptr;  // optional: the timer that calls Tick() (without it
                                           // the caller ticks at settings().board.tick_hz)
    hal::TemperatureInputs* temperatures = nullptr;  // optional: the board's own temperature
                                                     // sensors (without them a channel whose
                                                     // source is one stays waiting, then stale)
  };

  explicit BoardApp(const Devices& devices)
      : dev_(devices),
        policy_({&settings_, &control_tick_, &hand_over_, &pending_reference_, &thermal_}),
        objects_(ObjectParts(), AppOptions().identity) {}

  /// Starts with the stored settings, or `defaults` when none are stored (or the hardware refuses
  /// them: see config_status()), applied to the devices and the data path. Fails only when
  /// `defaults` are invalid or refused by the hardware (the board then stays in pass-through with
  /// kFault set and the tick stopped).
  Status Start(const BoardSettings& defaults, const AppOptions& options = AppOptions()) {
    // No tick while the data path is reconfigured (a node reset calls this while running).
    started_ = false;
    if (dev_.tick_timer != nullptr) dev_.tick_timer->Stop();
    defaults_ = defaults;
    options_ = options;
    objects_ = BoardObjects(ObjectParts(), options.identity);
    policy_.Restart();
    settings_ = defaults;
    if (dev_.settings_flash != nullptr) {
      const uint32_t bank = options.settings_bank_size != 0 ? options.settings_bank_size
                                                            : dev_.settings_flash->size() / 2;
      if (settings_store_.Init(dev_.settings_flash, bank).ok()) {
        settings_ = settings_store_.Load(defaults);
      }
    }
    config_status_ = ApplySettings(settings_, &config_refused_by_);
    Status s = Fatal(config_status_);
    if (!s.ok() && dev_.settings_flash != nullptr) {
      settings_ = defaults;  // stored settings this hardware cannot run: the factory defaults
      canopen::ConfigPart part = canopen::ConfigPart::kNone;
      s = Fatal(ApplySettings(settings_, &part));
    }
    started_ = s.ok();
    dev_.io->Write(hal::OutputLine::kReady, started_);
    dev_.io->Write(hal::OutputLine::kFault, !started_ || !config_status_.ok());
    if (!started_) return s;
    objects_.ResetPendingSettings();
    thermal_.Start(settings_, &control_tick_.compensator(), NowMs());
    thermal_reported_ = false;
    uint32_t counters[table::kMaxAxes];
    dev_.tick_io->ReadCounters(counters);
    control_tick_.LatchCounters(counters);
    for (uint8_t a = 0; a < table::kMaxAxes; ++a) home_level_[a] = dev_.io->Read(hal::HomeLine(a));
    const uint32_t bank =
        options.table_bank_size != 0 ? options.table_bank_size : dev_.table_flash->size() / 2;
    stored_status_ = tables_.Init(dev_.table_flash, bank);
    if (stored_status_.ok()) stored_status_ = ActivateStored();
    if (dev_.can != nullptr) {
      node_.Start(settings_.node_id, &objects_, NowMs(), CommunicationOf(settings_), options.sdo);
      if (!config_status_.ok()) {
        uint8_t m[5];
        canopen::EncodeConfigRefused(config_status_.error(), config_refused_by_, m);
        const bool bus = config_refused_by_ == canopen::ConfigPart::kCanBitrate;
        node_.RaiseError(canopen::kEmcyConfigRefused,
                         bus ? canopen::kErrCommunication : canopen::kErrManufacturer, m);
      }
    }
    if (dev_.tick_timer != nullptr) {
      const Status t = dev_.tick_timer->Start();
      if (!t.ok()) {
        started_ = false;
        dev_.io->Write(hal::OutputLine::kReady, false);
        dev_.io->Write(hal::OutputLine::kFault, true);
        return t;
      }
    }
    Poll();
    return Status::Ok();
  }

  /// Starts with `config` and default node settings (tests, simple setups).
  Status Start(const BoardConfig& config, const AppOptions& options = AppOptions()) {
    BoardSettings s;
    s.board = config;
    return Start(s, options);
  }

  /// The control tick as a whole: StepTick(), then CompensationTick() when it is due (every
  /// ControlTick::compensation_divider() ticks). No clock read and no virtual call: its cost on
  /// the MCU is a static figure (docs/mcu-target.md); TimedTick() measures it where a clock is
  /// cheap.
  void Tick() {
    if (StepTick()) CompensationTick();
  }

  /// The step path of a tick (the STM32 step/dir board's tick interrupt, row tick_isr_3axes):
  /// read the input stage's counters, targets = commanded + the published corrections, hand them
  /// to the output stage. Returns true when CompensationTick() is due; the caller runs it after
  /// this (in sequence, or in a lower-priority interrupt that this one pends).
  bool StepTick() {
    if (__builtin_expect(!started_, 0)) return false;
    uint32_t counters[table::kMaxAxes];
    dev_.tick_io->ReadCounters(counters);
    const bool due = control_tick_.RunSteps(counters);
    dev_.tick_io->Output(control_tick_);
    return due;
  }

  /// The compensation run (the STM32 step/dir board's compensation interrupt, row
  /// compensation_isr_3axes): apply requests handed over by the main loop (table switch,
  /// references, enable and fault), then ControlTick::Compensate(). It preempts the main loop and
  /// is never preempted by it (the hand-over's rule); StepTick() may preempt it.
  void CompensationTick() {
    if (!started_) return;
    // A table switch and referencing in the same run share one rebase (the state is the same as
    // rebasing after each: a rebase overwrites all the tracking state), which takes this run's
    // target refresh slice: the rare run costs no more than a normal one. It is its own path
    // (ControlTick::CompensateRebasing()), so the static cycle bound does not add the hand-over's
    // work to a normal run's refresh (docs/mcu-target.md, "Two rates").
    const PreparedTable* table = nullptr;
    const bool taken = hand_over_.Take(&table);
    if (taken && table == nullptr) control_tick_.compensator().ClearTable();
    // The run completes without the main loop in between (the hand-over's rule), so a load and a
    // store take a request: no exclusive-access retry loop.
    const uint8_t refs = pending_reference_.load(std::memory_order_acquire);
    if (table != nullptr || refs != 0) {
      if (table != nullptr) control_tick_.compensator().BindTable(table);
      if (refs != 0) {
        pending_reference_.store(0, std::memory_order_relaxed);
        control_tick_.MarkReferenced(refs);  // referenced or not: one rebase costs no more
      }
      TakeEnableRequests();
      control_tick_.CompensateRebasing();
    } else {
      TakeEnableRequests();
      control_tick_.Compensate();
    }
  }

  /// Tick() timed with the clock (two clock reads, a virtual call each); the largest duration is
  /// the diagnostic object 0x2140 (max_tick_cost_ns(); 0 while only Tick() runs). Needs `clock`.
  void TimedTick() {
    const uint64_t t0 = dev_.clock->NowNs();
    Tick();
    const uint64_t dt = dev_.clock->NowNs() - t0;
    if (dt > max_tick_ns_)
      max_tick_ns_ = static_cast<uint32_t>(dt > 0xFFFFFFFFu ? 0xFFFFFFFFu : dt);
  }

  /// The main loop's slow work.
  void Poll() {
    if (!started_) return;
    PollLines();
    PollThermal();
    if (dev_.can != nullptr) PollCan();
  }

  /// Validates `image` against the board and makes it active at the next tick (it must stay valid
  /// and unchanged while active). On error nothing changes. (Tests and tools; the CAN path goes
  /// through the table store.)
  Status ActivateImage(const uint8_t* image, size_t size) {
    const Result<table::TableView> view = table::ParseImage(image, size);
    if (!view.ok()) return view.status();
    return policy_.Activate(*view);
  }

  const ControlTick& control_tick() const { return control_tick_; }
  ControlTick& control_tick() { return control_tick_; }
  /// The input and output stage (e.g. StepDirIo::output() for the step generators).
  const Io& tick_io() const { return *dev_.tick_io; }
  const canopen::Node& node() const { return node_; }
  const TableStore& tables() const { return tables_; }
  const BoardObjects& objects() const { return objects_; }
  const BoardPolicy& policy() const { return policy_; }
  const BoardThermal& thermal() const { return thermal_; }
  /// The settings in force (the one copy: applied by the last Start()).
  const BoardSettings& settings() const { return settings_; }
  Status stored_table_status() const { return stored_status_; }
  /// Ok, or why the hardware refused the loaded settings (the board then runs the factory
  /// defaults, except for kCanBitrateMismatch) and which device refused them.
  Status config_status() const { return config_status_; }
  canopen::ConfigPart config_refused_by() const { return config_refused_by_; }
  bool started() const { return started_; }

 private:
  // The run's unreferencing request, enable and fault (CompensationTick()).
  __attribute__((always_inline)) void TakeEnableRequests() {
    if (pending_unreference_.load(std::memory_order_acquire)) {
      pending_unreference_.store(false, std::memory_order_relaxed);
      control_tick_.Unreference();
    }
    control_tick_.compensator().SetEnabledAndFault(enabled_.load(std::memory_order_relaxed),
                                                   fault_flag_.load(std::memory_order_relaxed));
  }

  // Applies `s` with the tick stopped, in the order the tick needs; the first refusal is returned
  // and its device named in *part. A bit-rate mismatch the port reports (it runs at the
  // interface's rate) still leaves everything else applied.
  Status ApplySettings(const BoardSettings& s, canopen::ConfigPart* part) {
    using canopen::ConfigPart;
    *part = ConfigPart::kSettings;
    VOLCOMP_TRY(ValidateSettings(s, nullptr, Io::kOutputStage));
    *part = ConfigPart::kTickIo;
    VOLCOMP_TRY(dev_.tick_io->Configure(s.board));
    *part = ConfigPart::kDataPath;
    VOLCOMP_TRY(control_tick_.Configure(s.board));
    if (dev_.tick_timer != nullptr) {
      *part = ConfigPart::kTickTimer;
      VOLCOMP_TRY(dev_.tick_timer->SetRate(s.board.tick_hz));
    }
    if (dev_.can != nullptr) {
      *part = ConfigPart::kCanBitrate;
      VOLCOMP_TRY(dev_.can->SetBitrate(uint32_t{s.bitrate_kbit} * 1000u));
    }
    *part = ConfigPart::kNone;
    return Status::Ok();
  }
  // A refusal the board cannot run with (a mismatch report is not one).
  static Status Fatal(Status s) {
    return s.error() == Error::kCanBitrateMismatch ? Status::Ok() : s;
  }

  Status ActivateStored() {
    const Result<table::TableView> view = tables_.MountActive(settings_.board);
    if (!view.ok()) {
      if (view.error() != Error::kNotFound && dev_.can != nullptr) {
        uint8_t m[5] = {static_cast<uint8_t>(view.error()), 0, 0, 0, 0};
        node_.RaiseError(canopen::kEmcyTableInvalid, canopen::kErrManufacturer, m);
      }
      return view.status();
    }
    return policy_.Activate(*view);
  }

  BoardObjects::Parts ObjectParts() {
    return {this,   &policy_,         &settings_, &control_tick_, &tables_, &settings_store_,
            &node_, Io::kOutputStage, &thermal_};
  }

  uint32_t NowMs() const {
    return dev_.clock != nullptr ? static_cast<uint32_t>(dev_.clock->NowNs() / 1000000u) : 0;
  }

  void PollLines() {
    hal::SlowIo& io = *dev_.io;
    uint8_t refs = 0;
    for (uint8_t a = 0; a < control_tick_.axis_count(); ++a) {
      const bool level = io.Read(hal::HomeLine(a));
      if (level && !home_level_[a]) refs = static_cast<uint8_t>(refs | (1u << a));
      home_level_[a] = level;
    }
    const bool estop = io.Read(hal::InputLine::kEStop);
    const bool alarm = io.Read(hal::InputLine::kDriveAlarm);
    const bool fault = estop || alarm;
    const bool was_fault = policy_.fault();
    if (fault && !was_fault) {
      pending_unreference_.store(true, std::memory_order_release);
      if (dev_.can != nullptr) {
        node_.RaiseError(estop ? canopen::kEmcyEStop : canopen::kEmcyDriveAlarm,
                         canopen::kErrManufacturer);
      }
    } else if (!fault && was_fault && dev_.can != nullptr) {
      node_.ClearErrors();
      if (thermal_reported_) RaiseThermalError();  // still standing
    }
    fault_flag_.store(fault, std::memory_order_relaxed);
    if (!fault && refs != 0) pending_reference_.fetch_or(refs, std::memory_order_release);
    enabled_.store(
        (!options_.use_enable_input || io.Read(hal::InputLine::kEnable)) && policy_.bus_enable(),
        std::memory_order_relaxed);
    policy_.SetLines(io.Read(hal::InputLine::kWriteEnable), fault);
    io.Write(hal::OutputLine::kCompensating, control_tick_.compensator().engaged());
    io.Write(hal::OutputLine::kFault, fault || !config_status_.ok());
  }

  // The thermal period's work; its fault onsets become EMCYs that stand (error register bit 3)
  // until every channel is valid and every term fits again. The FAULT output is not driven: a
  // thermal fault holds and fades the thermal correction, it does not stop the machine.
  void PollThermal() {
    const ThermalEvents e = thermal_.Poll(NowMs(), dev_.temperatures);
    if (!e.any() || dev_.can == nullptr) return;
    if (e.channels.faulted != 0) {
      const uint8_t lowest = static_cast<uint8_t>(__builtin_ctz(e.channels.faulted));
      uint8_t m[5] = {e.channels.faulted, thermal_.channel_fault_mask(),
                      static_cast<uint8_t>(thermal_.channels().state(lowest)), 0, 0};
      node_.RaiseError(canopen::kEmcyTemperatureChannel, canopen::kErrTemperature, m);
    }
    if (e.saturated != 0) {
      uint8_t m[5] = {thermal_.saturated_axes(), 0, 0, 0, 0};
      node_.RaiseError(canopen::kEmcyThermalSaturated, canopen::kErrTemperature, m);
    }
    const bool was_reported = thermal_reported_;
    thermal_reported_ = thermal_.fault();
    if (was_reported && !thermal_reported_ && !policy_.fault()) node_.ClearErrors();
  }
  // The thermal errors still standing after another error was cleared: raised again (no channel
  // "just faulted": byte 3 is 0), so the error register and the last EMCY show them.
  void RaiseThermalError() {
    if (thermal_.channel_fault_mask() != 0) {
      uint8_t m[5] = {0, thermal_.channel_fault_mask(), 0, 0, 0};
      node_.RaiseError(canopen::kEmcyTemperatureChannel, canopen::kErrTemperature, m);
    }
    if (thermal_.saturated_axes() != 0) {
      uint8_t m[5] = {thermal_.saturated_axes(), 0, 0, 0, 0};
      node_.RaiseError(canopen::kEmcyThermalSaturated, canopen::kErrTemperature, m);
    }
  }

  void PollCan() {
    const uint32_t now = NowMs();
    policy_.set_now_ms(now);
    objects_.WatchLimits(now);
    CanFrame f;
    while (dev_.can->Receive(&f)) {
      objects_.CountFrame(true);
      node_.OnFrame(f, now);
    }
    node_.Poll(now);
    for (;;) {
      if (!have_tx_) {
        if (!node_.PopTx(&tx_)) break;
        have_tx_ = true;
      }
      if (!dev_.can->Send(tx_).ok()) break;  // port full: retry next pass
      have_tx_ = false;
      objects_.CountFrame(false);
    }
    switch (node_.TakeResetRequest()) {
      case canopen::ResetRequest::kNode:
        // Reload the stored settings, reconfigure, reboot the node. A failure leaves the board in
        // pass-through with kFault set (Start reports it on the outputs).
        Start(BoardSettings(defaults_), AppOptions(options_)).IgnoreError();
        break;
      case canopen::ResetRequest::kCommunication:
        node_.ResetCommunication(now);  // the stored 0x1015 / 0x1017 / TPDOs back in force
        break;
      case canopen::ResetRequest::kNone:
        break;
    }
  }

  // BoardControl: what only the tick knows.
  OutputStatus DoOutputStatus() const override { return dev_.tick_io->output_status(); }
  uint32_t DoMaxTickCostNs() const override { return max_tick_ns_; }

  Devices dev_;
  AppOptions options_;
  BoardSettings defaults_;  // factory defaults (from the first Start); stored settings override
  BoardSettings settings_;  // in force
  ControlTick control_tick_;
  TableStore tables_;
  SettingsStore settings_store_;
  canopen::Node node_;
  BoardThermal thermal_;
  bool thermal_reported_ = false;  // a thermal fault is standing in the error register
  BoardPolicy policy_;
  BoardObjects objects_;
  bool started_ = false;
  bool home_level_[table::kMaxAxes] = {};
  Status stored_status_ = Error::kNotFound;
  Status config_status_;
  canopen::ConfigPart config_refused_by_ = canopen::ConfigPart::kNone;
  CanFrame tx_;
  bool have_tx_ = false;
  uint32_t max_tick_ns_ = 0;
  TableHandOver hand_over_;
  std::atomic<uint8_t> pending_reference_{0};
  std::atomic<bool> pending_unreference_{false};
  std::atomic<bool> enabled_{false};
  std::atomic<bool> fault_flag_{false};
};

}  // namespace volcomp::firmware
