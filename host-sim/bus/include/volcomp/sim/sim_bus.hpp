// SimBus: a discrete-event classic CAN bus in virtual time (ns) at a fixed bit rate: real frame
// timing, arbitration, fault hooks, and endpoints whose controller runs at another bit rate (off
// the bus, error frames, bus-off). The model is docs/can-transports.md "Simulated bus". Virtual
// time moves only in RunUntil(); NextEventTime() says when something happens next, so a caller
// runs in pure virtual time or paces it to the wall clock (realtime.hpp).
// Thread-safety: none; one thread drives a bus and its endpoints (receive callbacks run inside
// RunUntil() on that thread and may call Send()).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/can/can_frame.hpp"

namespace volcomp::sim {

enum class FaultAction : uint8_t { kNone, kDrop, kDuplicate, kCorrupt, kDestroy };

const char* FaultActionName(FaultAction action);

struct FaultDecision {
  FaultAction action = FaultAction::kNone;
  CanFrame corrupted;  // kCorrupt: the frame the receivers get instead
};

/// One transmission, as reported to the monitor.
struct FrameRecord {
  CanFrame frame;         // as sent
  size_t sender = 0;      // endpoint index
  uint64_t start_ns = 0;  // start of SOF
  uint64_t eof_ns = 0;    // end of EOF (receivers get the frame here)
  uint64_t idle_ns = 0;   // bus free again (after the intermission / error frame)
  uint32_t bits = 0;      // CanFrameBits(frame)
  FaultAction fault = FaultAction::kNone;
};

struct BusStats {
  uint64_t frames = 0;   // transmissions started (retransmissions included)
  uint64_t bits = 0;     // bit times spent, error frames included
  uint64_t busy_ns = 0;  // time the bus was not idle
  uint64_t dropped = 0;
  uint64_t duplicated = 0;
  uint64_t corrupted = 0;
  uint64_t destroyed = 0;
  uint64_t rx_overruns = 0;     // frames lost because a receive queue was full
  uint64_t bitrate_errors = 0;  // error frames caused by an endpoint at another bit rate
};

class SimBus;

class Endpoint {
 public:
  using ReceiveCallback = std::function<void(const CanFrame& frame, uint64_t t_ns)>;
  struct Stats {
    uint64_t sent = 0;         // frames transmitted successfully (duplicates counted once)
    uint64_t received = 0;     // frames delivered to this endpoint
    uint64_t rate_errors = 0;  // frames it could not send or receive: its bit rate is wrong
  };

  const std::string& name() const { return name_; }
  size_t index() const { return index_; }

  /// Queues a frame for transmission at the bus's current time (advance the bus to your time
  /// first). Invalid frames, and every frame while bus-off, are refused (false).
  bool Send(const CanFrame& frame);
  /// Pops the next received frame (when no callback is set).
  bool Receive(CanFrame* frame);
  /// Delivers frames to `callback` instead of the receive queue (nullptr: back to the queue).
  void SetReceiveCallback(ReceiveCallback callback) { on_receive_ = std::move(callback); }
  /// Receive queue limit (0 = unlimited); frames beyond it are lost (an overrun).
  void set_rx_capacity(size_t frames) { rx_capacity_ = frames; }

  size_t tx_pending() const { return tx_.size(); }
  size_t rx_pending() const { return rx_.size(); }
  const Stats& stats() const { return stats_; }

  /// The bit rate this endpoint's controller runs at (0 = the bus's rate, the default). Setting
  /// another rate than the current one re-initialises the controller: both queues are emptied
  /// and the error counter and bus-off state reset.
  void set_bitrate(uint32_t bitrate_bps);
  uint32_t bitrate() const { return bitrate_; }
  /// Transmit error counter (ISO 11898-1 rule: +8 per transmit error) and bus-off state.
  uint32_t tx_errors() const { return tx_errors_; }
  bool bus_off() const { return bus_off_; }

 private:
  friend class SimBus;
  Endpoint(std::string name, size_t index) : name_(std::move(name)), index_(index) {}

  struct Queued {
    CanFrame frame;
    bool retransmission = false;  // a duplicate's second copy: no further faults
  };
  std::string name_;
  size_t index_;
  std::deque<Queued> tx_;
  std::deque<CanFrame> rx_;
  size_t rx_capacity_ = 0;
  ReceiveCallback on_receive_;
  Stats stats_;
  uint32_t bitrate_ = 0;
  uint32_t tx_errors_ = 0;
  bool bus_off_ = false;
};

class SimBus {
 public:
  using FaultHook = std::function<FaultDecision(const CanFrame& frame, const Endpoint& sender)>;
  using Monitor = std::function<void(const FrameRecord& record)>;

  /// `bitrate` in bit/s. Precondition: bitrate > 0.
  explicit SimBus(uint32_t bitrate);
  SimBus(const SimBus&) = delete;
  SimBus& operator=(const SimBus&) = delete;

  /// Adds an endpoint; the reference stays valid for the bus's lifetime.
  Endpoint& Attach(std::string name);
  Endpoint& endpoint(size_t index) { return *endpoints_[index]; }
  size_t endpoint_count() const { return endpoints_.size(); }

  uint64_t now() const { return now_; }
  uint32_t bitrate() const { return bitrate_; }
  /// Time of the next event (a frame ends, the bus frees up, or — when idle with frames queued —
  /// now); nullopt when nothing is pending.
  std::optional<uint64_t> NextEventTime() const;
  /// Processes every event up to and including `t_ns`, then sets now() to `t_ns` (time never
  /// goes backwards: an earlier t_ns processes nothing).
  void RunUntil(uint64_t t_ns);
  /// Runs until nothing is pending or `limit_ns` is reached; returns now().
  uint64_t RunUntilIdle(uint64_t limit_ns = UINT64_MAX);
  bool idle() const { return !current_ && !AnyQueued(); }

  /// Duration of `bits` bit times in ns (rounded to nearest).
  uint64_t BitsToNs(uint64_t bits) const;

  void SetFaultHook(FaultHook hook) { fault_hook_ = std::move(hook); }
  /// Called at the end of every transmission (after delivery).
  void SetMonitor(Monitor monitor) { monitor_ = std::move(monitor); }
  const BusStats& stats() const { return stats_; }

 private:
  friend class Endpoint;
  struct Transmission {
    FrameRecord record;
    FaultDecision fault;
    bool delivered = false;
    bool wrong_rate = false;  // sent by an endpoint at another bit rate: an error frame
  };
  bool AnyQueued() const;
  bool AtBusRate(const Endpoint& endpoint) const {
    return endpoint.bitrate_ == 0 || endpoint.bitrate_ == bitrate_;
  }
  void Step();
  void StartNext();
  void Deliver();

  uint32_t bitrate_;
  uint64_t now_ = 0;
  std::vector<std::unique_ptr<Endpoint>> endpoints_;
  std::optional<Transmission> current_;
  FaultHook fault_hook_;
  Monitor monitor_;
  BusStats stats_;
};

/// The 64-bit key arbitration compares (lower wins): base id, RTR/SRR, IDE, extension, RTR.
uint64_t ArbitrationKey(const CanFrame& frame);

/// Probabilities (0..1) of each fault per transmission.
struct RandomFaultRates {
  double drop = 0;
  double duplicate = 0;
  double corrupt = 0;
  double destroy = 0;
};

/// A deterministic fault hook: for frames matching `predicate` (all when empty) it draws one
/// fault per transmission with the given rates from a generator seeded with `seed`; corruption
/// flips one random bit of the data (or of the id when the frame has no data).
SimBus::FaultHook RandomFaults(uint64_t seed,
                               RandomFaultRates rates,
                               std::function<bool(const CanFrame&)> predicate = {});

}  // namespace volcomp::sim
