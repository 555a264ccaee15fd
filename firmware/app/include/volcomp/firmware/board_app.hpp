// The board application: wires the core (lib/) to the HAL and owns the two execution contexts.
//
//   Tick()  the control tick (timer ISR at BoardConfig::tick_hz): apply requests handed over by
//           the main loop (table switch, references), latch input counters, run the data path
//           (ControlTick), program the output timers. Nothing else.
//   Poll()  the main loop: slow lines (home switches, enable, e-stop, drive alarm, write enable),
//           status outputs, and the CANopen node (NMT, heartbeat, EMCY, SDO with the object
//           dictionary of BoardObjects: configuration, table staging, diagnostics).
//
// Requests from the main loop reach the tick through atomics: a reference bit mask, an
// "unreference" flag, and the table hand-over (two prepared-table slots; the tick switches to the
// one the main loop published, without copying it: table_hand_over.hpp). On the MCU the tick ISR
// preempts the main loop, never the reverse; on the host both run in one thread.
//
// Activation is one sequence, ActivateTable(): prepare the parsed image against the configuration
// in force, hand it to the tick, mark it active (0x2103 / 0x2104). Power-up (the stored table),
// ActivateImage() and table control (0x2101 = activate, through BoardControl) all use it.
//
// Storage: the table flash holds the dual-bank table store (active image + staging); the settings
// flash (optional) holds the stored BoardSettings. Start() loads the settings (or the defaults),
// mounts the tables and activates the stored image if it is intact and made for this board;
// otherwise the board runs as pure pass-through and reports why (stored_table_status()).
//
// StepIo is a static interface (volcomp/hal/step_io.hpp): no virtual call on the tick path.
#pragma once

#include <atomic>
#include <cstdint>

#include "volcomp/board_config.hpp"
#include "volcomp/canopen/node.hpp"
#include "volcomp/compensator.hpp"
#include "volcomp/control_tick.hpp"
#include "volcomp/firmware/board_control.hpp"
#include "volcomp/firmware/board_objects.hpp"
#include "volcomp/firmware/settings.hpp"
#include "volcomp/firmware/table_hand_over.hpp"
#include "volcomp/firmware/table_store.hpp"
#include "volcomp/hal/can.hpp"
#include "volcomp/hal/clock.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/hal/slow_io.hpp"
#include "volcomp/hal/step_io.hpp"
#include "volcomp/status.hpp"
#include "volcomp/table_image.hpp"

namespace volcomp::firmware {

struct AppOptions {
  /// When false the compensation is enabled without a wired enable input.
  bool use_enable_input = true;
  /// Bytes per table bank (0 = half the table flash).
  uint32_t table_bank_size = 0;
  /// Bytes per settings bank (0 = half the settings flash).
  uint32_t settings_bank_size = 0;
  /// Measure each Tick() with the clock and keep the maximum (diagnostics; costs two clock reads).
  bool measure_tick_cost = false;
  IdentityInfo identity;
  canopen::SdoServerConfig sdo;
};

template <class StepIo>
class BoardApp final : private BoardControl {
  static_assert(hal::IsStepIo<StepIo>::value, "StepIo must provide ReadCounters() and Apply()");

 public:
  struct Devices {
    StepIo* step_io = nullptr;
    hal::SlowIo* io = nullptr;
    hal::Flash* table_flash = nullptr;     // dual-bank table store
    hal::Flash* settings_flash = nullptr;  // optional: stored settings
    hal::CanPort* can = nullptr;           // optional: the CANopen node
    hal::Clock* clock = nullptr;           // required with `can` (timeouts, heartbeat)
  };

  explicit BoardApp(const Devices& devices)
      : dev_(devices), objects_(this, &tables_, &settings_store_, &node_, AppOptions().identity) {}

  /// Starts with the stored settings, or `defaults` when none are stored. Fails only for an
  /// invalid configuration (the board then stays in pass-through with kFault set).
  Status Start(const BoardSettings& defaults, const AppOptions& options = AppOptions()) {
    defaults_ = defaults;
    options_ = options;
    objects_ = BoardObjects(this, &tables_, &settings_store_, &node_, options.identity);
    settings_ = defaults;
    if (dev_.settings_flash != nullptr) {
      const uint32_t bank = options.settings_bank_size != 0 ? options.settings_bank_size
                                                            : dev_.settings_flash->size() / 2;
      if (settings_store_.Init(dev_.settings_flash, bank).ok()) {
        settings_ = settings_store_.Load(defaults);
      }
    }
    Status s = ValidateSettings(settings_);
    if (s.ok()) s = engine_.Configure(settings_.board);
    started_ = s.ok();
    dev_.io->Write(hal::OutputLine::kReady, started_);
    dev_.io->Write(hal::OutputLine::kFault, !started_);
    if (!started_) return s;
    objects_.SetSettings(settings_);
    uint32_t counters[table::kMaxAxes];
    dev_.step_io->ReadCounters(counters);
    engine_.LatchCounters(counters);
    for (uint8_t a = 0; a < table::kMaxAxes; ++a) home_level_[a] = dev_.io->Read(hal::HomeLine(a));
    const uint32_t bank =
        options.table_bank_size != 0 ? options.table_bank_size : dev_.table_flash->size() / 2;
    stored_status_ = tables_.Init(dev_.table_flash, bank);
    if (stored_status_.ok()) stored_status_ = ActivateStored();
    if (dev_.can != nullptr) {
      node_.Start(settings_.node_id, &objects_, NowMs(),
                  {settings_.heartbeat_ms, settings_.emcy_inhibit_100us}, options.sdo);
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

  /// The control tick.
  void Tick() {
    if (!started_) return;
    const uint64_t t0 = options_.measure_tick_cost ? dev_.clock->NowNs() : 0;
    const PreparedTable* table = nullptr;
    if (hand_over_.Take(&table)) {
      if (table != nullptr) {
        int32_t machine[table::kMaxAxes];
        for (uint8_t a = 0; a < engine_.axis_count(); ++a) machine[a] = engine_.machine_position(a);
        engine_.compensator().UseTable(table, machine);
      } else {
        engine_.compensator().ClearTable();
      }
    }
    const uint8_t refs = pending_reference_.exchange(0, std::memory_order_acquire);
    for (uint8_t a = 0; a < engine_.axis_count(); ++a) {
      if ((refs & (1u << a)) != 0) engine_.Reference(a);
    }
    if (pending_unreference_.exchange(false, std::memory_order_acquire)) engine_.Unreference();
    engine_.compensator().SetEnabled(enabled_.load(std::memory_order_relaxed));
    engine_.compensator().SetFault(fault_flag_.load(std::memory_order_relaxed));
    uint32_t counters[table::kMaxAxes];
    dev_.step_io->ReadCounters(counters);
    engine_.Run(counters, plans_);
    dev_.step_io->Apply(plans_);
    if (options_.measure_tick_cost) {
      const uint64_t dt = dev_.clock->NowNs() - t0;
      if (dt > max_tick_ns_)
        max_tick_ns_ = static_cast<uint32_t>(dt > 0xFFFFFFFFu ? 0xFFFFFFFFu : dt);
    }
  }

  /// The main loop's slow work.
  void Poll() {
    if (!started_) return;
    PollLines();
    if (dev_.can != nullptr) PollCan();
  }

  /// Validates `image` against the board and makes it active at the next tick (it must stay valid
  /// and unchanged while active). On error nothing changes. (Tests and tools; the CAN path goes
  /// through the table store.)
  Status ActivateImage(const uint8_t* image, size_t size) {
    const Result<table::TableView> view = table::ParseImage(image, size);
    if (!view.ok()) return view.status();
    return ActivateTable(*view);
  }

  const ControlTick& engine() const { return engine_; }
  ControlTick& engine() { return engine_; }
  const canopen::Node& node() const { return node_; }
  const TableStore& tables() const { return tables_; }
  const BoardObjects& objects() const { return objects_; }
  const BoardSettings& settings() const { return settings_; }
  Status stored_table_status() const { return stored_status_; }
  bool started() const { return started_; }

 private:
  Status ActivateStored() {
    const Result<table::TableView> view = tables_.MountActive(settings_.board);
    if (!view.ok()) {
      if (view.error() != Error::kNotFound && dev_.can != nullptr) {
        uint8_t m[5] = {static_cast<uint8_t>(view.error()), 0, 0, 0, 0};
        node_.RaiseError(canopen::kEmcyTableInvalid, canopen::kErrManufacturer, m);
      }
      return view.status();
    }
    return ActivateTable(*view);
  }

  uint32_t NowMs() const {
    return dev_.clock != nullptr ? static_cast<uint32_t>(dev_.clock->NowNs() / 1000000u) : 0;
  }

  void PollLines() {
    hal::SlowIo& io = *dev_.io;
    uint8_t refs = 0;
    for (uint8_t a = 0; a < engine_.axis_count(); ++a) {
      const bool level = io.Read(hal::HomeLine(a));
      if (level && !home_level_[a]) refs = static_cast<uint8_t>(refs | (1u << a));
      home_level_[a] = level;
    }
    const bool estop = io.Read(hal::InputLine::kEStop);
    const bool alarm = io.Read(hal::InputLine::kDriveAlarm);
    const bool fault = estop || alarm;
    if (fault && !fault_) {
      pending_unreference_.store(true, std::memory_order_release);
      if (dev_.can != nullptr) {
        node_.RaiseError(estop ? canopen::kEmcyEStop : canopen::kEmcyDriveAlarm,
                         canopen::kErrManufacturer);
      }
    } else if (!fault && fault_ && dev_.can != nullptr) {
      node_.ClearErrors();
    }
    fault_ = fault;
    fault_flag_.store(fault, std::memory_order_relaxed);
    if (!fault && refs != 0) pending_reference_.fetch_or(refs, std::memory_order_release);
    enabled_.store((!options_.use_enable_input || io.Read(hal::InputLine::kEnable)) && bus_enable_,
                   std::memory_order_relaxed);
    write_enable_ = io.Read(hal::InputLine::kWriteEnable);
    io.Write(hal::OutputLine::kCompensating, engine_.compensator().engaged());
    io.Write(hal::OutputLine::kFault, fault);
  }

  void PollCan() {
    const uint32_t now = NowMs();
    objects_.set_now_ms(now);
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
        node_.ResetCommunication(now);  // the stored 0x1015 / 0x1017 back in force
        break;
      case canopen::ResetRequest::kNone:
        break;
    }
  }

  // BoardControl.
  // The activation sequence: prepare against the configuration in force (in the slot the tick does
  // not use), hand over to the tick, mark active. On error nothing changes.
  Status DoActivateTable(const table::TableView& view) override {
    PreparedTable& slot = hand_over_.BeginWrite();
    const Status s = slot.Prepare(view, engine_.config());
    if (!s.ok()) {
      hand_over_.Abandon();
      return s;
    }
    hand_over_.Publish();
    objects_.set_active(view.table_id, view.crc32);
    return Status::Ok();
  }
  void DoRequestClearTable() override { hand_over_.PublishClear(); }
  void DoRequestReference(uint8_t mask) override {
    if (!fault_) pending_reference_.fetch_or(mask, std::memory_order_release);
  }
  void DoSetBusEnable(bool on) override { bus_enable_ = on; }
  bool DoBusEnable() const override { return bus_enable_; }
  const ControlTick& DoEngine() const override { return engine_; }
  bool DoMoving() const override {
    const uint64_t still_ticks = uint64_t{kStillMs} * engine_.config().tick_hz / 1000u;
    return engine_.idle_ticks() < still_ticks;
  }
  bool DoFault() const override { return fault_; }
  bool DoWriteEnableInput() const override { return write_enable_; }
  uint32_t DoMaxTickCostNs() const override { return max_tick_ns_; }

  Devices dev_;
  AppOptions options_;
  BoardSettings defaults_;  // factory defaults (from the first Start); stored settings override
  BoardSettings settings_;
  ControlTick engine_;
  TableStore tables_;
  SettingsStore settings_store_;
  canopen::Node node_;
  BoardObjects objects_;
  PulsePlan plans_[table::kMaxAxes];
  bool started_ = false;
  bool fault_ = false;
  bool write_enable_ = false;
  bool bus_enable_ = canopen::kDefaultCompensationEnable != 0;
  bool home_level_[table::kMaxAxes] = {};
  Status stored_status_ = Error::kNotFound;
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
