// SimBus: event processing, arbitration, delivery, fault hooks.
#include "volcomp/sim/sim_bus.hpp"

#include <random>

#include "volcomp/sim/contract.hpp"

namespace volcomp::sim {

const char* FaultActionName(FaultAction action) {
  switch (action) {
    case FaultAction::kNone:
      return "none";
    case FaultAction::kDrop:
      return "drop";
    case FaultAction::kDuplicate:
      return "duplicate";
    case FaultAction::kCorrupt:
      return "corrupt";
    case FaultAction::kDestroy:
      return "destroy";
  }
  return "unknown";
}

uint64_t ArbitrationKey(const CanFrame& f) {
  // Bits in transmission order; a dominant 0 wins, so the numerically lower key wins.
  const uint64_t rtr = f.rtr ? 1 : 0;
  if (f.extended) {
    const uint64_t id = f.id & 0x1FFFFFFFu;
    return (id >> 18) << 21 | uint64_t{1} << 20 | uint64_t{1} << 19 | (id & 0x3FFFF) << 1 | rtr;
  }
  return uint64_t{f.id & 0x7FFu} << 21 | rtr << 20;  // IDE dominant; no bits after it
}

bool Endpoint::Send(const CanFrame& frame) {
  if (!frame.valid() || bus_off_) return false;
  tx_.push_back({frame, false});
  return true;
}

void Endpoint::set_bitrate(uint32_t bitrate_bps) {
  if (bitrate_bps == bitrate_) return;
  bitrate_ = bitrate_bps;
  tx_.clear();
  rx_.clear();
  tx_errors_ = 0;
  bus_off_ = false;
}

bool Endpoint::Receive(CanFrame* frame) {
  if (rx_.empty()) return false;
  *frame = rx_.front();
  rx_.pop_front();
  return true;
}

SimBus::SimBus(uint32_t bitrate) : bitrate_(bitrate) {
  VOLCOMP_SIM_EXPECT(bitrate > 0, "SimBus: bitrate must be > 0");
}

Endpoint& SimBus::Attach(std::string name) {
  endpoints_.push_back(std::unique_ptr<Endpoint>(new Endpoint(std::move(name), endpoints_.size())));
  return *endpoints_.back();
}

uint64_t SimBus::BitsToNs(uint64_t bits) const {
  return (bits * 1000000000ull + bitrate_ / 2) / bitrate_;
}

bool SimBus::AnyQueued() const {
  for (const auto& ep : endpoints_) {
    if (!ep->tx_.empty()) return true;
  }
  return false;
}

std::optional<uint64_t> SimBus::NextEventTime() const {
  if (current_) return current_->delivered ? current_->record.idle_ns : current_->record.eof_ns;
  if (AnyQueued()) return now_;
  return std::nullopt;
}

void SimBus::RunUntil(uint64_t t_ns) {
  for (;;) {
    const auto next = NextEventTime();
    if (!next || *next > t_ns) break;
    if (*next > now_) now_ = *next;
    Step();
  }
  if (t_ns > now_) now_ = t_ns;
}

uint64_t SimBus::RunUntilIdle(uint64_t limit_ns) {
  for (;;) {
    const auto next = NextEventTime();
    if (!next || *next > limit_ns) break;
    if (*next > now_) now_ = *next;
    Step();
  }
  return now_;
}

void SimBus::Step() {
  if (!current_) return StartNext();
  if (!current_->delivered) return Deliver();
  // The bus is free again.
  const FrameRecord record = current_->record;
  current_.reset();
  if (monitor_) monitor_(record);
}

void SimBus::StartNext() {
  Endpoint* winner = nullptr;
  uint64_t best = 0;
  for (const auto& ep : endpoints_) {
    if (ep->tx_.empty()) continue;
    const uint64_t key = ArbitrationKey(ep->tx_.front().frame);
    if (winner == nullptr || key < best) {
      winner = ep.get();
      best = key;
    }
  }
  if (winner == nullptr) return;
  const Endpoint::Queued queued = winner->tx_.front();
  winner->tx_.pop_front();

  Transmission t;
  t.record.frame = queued.frame;
  t.record.sender = winner->index_;
  t.record.start_ns = now_;
  t.record.bits = CanFrameBits(queued.frame);
  t.wrong_rate = !AtBusRate(*winner);
  if (fault_hook_ && !queued.retransmission && !t.wrong_rate) {
    t.fault = fault_hook_(queued.frame, *winner);
  }
  t.record.fault = t.fault.action;
  uint64_t bits = t.record.bits;
  uint64_t eof_bits = bits - 3;
  if (t.wrong_rate) {
    // The receivers see a bit error right after SOF: 6-bit error flag, 8-bit delimiter.
    eof_bits = 1 + 6 + 8;
    bits = eof_bits + 3;
  } else if (t.fault.action == FaultAction::kDestroy) {
    // Error detected at the CRC delimiter (bits - 12 into the frame), then a 6-bit error flag,
    // 8-bit error delimiter and the 3-bit intermission.
    eof_bits = bits - 12 + 6 + 8;
    bits = eof_bits + 3;
  }
  t.record.eof_ns = now_ + BitsToNs(eof_bits);
  t.record.idle_ns = now_ + BitsToNs(bits);
  ++stats_.frames;
  stats_.bits += bits;
  stats_.busy_ns += t.record.idle_ns - t.record.start_ns;
  current_ = t;
}

void SimBus::Deliver() {
  Transmission& t = *current_;
  t.delivered = true;
  Endpoint& sender = *endpoints_[t.record.sender];
  if (t.wrong_rate) {
    ++stats_.bitrate_errors;
    ++sender.stats_.rate_errors;
    sender.tx_errors_ += 8;
    if (sender.tx_errors_ >= 256) {
      sender.bus_off_ = true;
      sender.tx_.clear();
    } else {
      sender.tx_.push_front({t.record.frame, false});  // automatic retransmission
    }
    return;
  }
  const CanFrame* to_deliver = &t.record.frame;
  switch (t.fault.action) {
    case FaultAction::kDestroy:
      ++stats_.destroyed;
      sender.tx_.push_front({t.record.frame, false});  // automatic retransmission
      return;
    case FaultAction::kDrop:
      ++stats_.dropped;
      ++sender.stats_.sent;
      return;
    case FaultAction::kDuplicate:
      ++stats_.duplicated;
      sender.tx_.push_front({t.record.frame, true});
      break;
    case FaultAction::kCorrupt:
      ++stats_.corrupted;
      to_deliver = &t.fault.corrupted;
      ++sender.stats_.sent;
      break;
    case FaultAction::kNone:
      ++sender.stats_.sent;
      break;
  }
  const CanFrame frame = *to_deliver;  // callbacks may Send(), which never touches current_
  for (size_t i = 0; i < endpoints_.size(); ++i) {
    if (i == t.record.sender) continue;
    Endpoint& ep = *endpoints_[i];
    if (!AtBusRate(ep)) {
      ++ep.stats_.rate_errors;
      continue;
    }
    ++ep.stats_.received;
    if (ep.on_receive_) {
      ep.on_receive_(frame, now_);
    } else if (ep.rx_capacity_ != 0 && ep.rx_.size() >= ep.rx_capacity_) {
      ++stats_.rx_overruns;
      --ep.stats_.received;
    } else {
      ep.rx_.push_back(frame);
    }
  }
}

SimBus::FaultHook RandomFaults(uint64_t seed,
                               RandomFaultRates rates,
                               std::function<bool(const CanFrame&)> predicate) {
  auto rng = std::make_shared<std::mt19937_64>(seed);
  // Thresholds on a 53-bit uniform draw: identical sequences on every platform.
  auto uniform = [rng]() { return static_cast<double>((*rng)() >> 11) * 0x1.0p-53; };
  return [uniform, rng, rates, predicate](const CanFrame& frame, const Endpoint&) {
    FaultDecision d;
    if (predicate && !predicate(frame)) return d;
    double u = uniform();
    if ((u -= rates.drop) < 0) {
      d.action = FaultAction::kDrop;
    } else if ((u -= rates.duplicate) < 0) {
      d.action = FaultAction::kDuplicate;
    } else if ((u -= rates.corrupt) < 0) {
      d.action = FaultAction::kCorrupt;
      d.corrupted = frame;
      if (!frame.rtr && frame.dlc > 0) {
        const uint64_t bit = (*rng)() % (frame.dlc * 8u);
        d.corrupted.data[bit / 8] =
            static_cast<uint8_t>(d.corrupted.data[bit / 8] ^ (1u << (bit % 8)));
      } else {
        const uint32_t width = frame.extended ? 29 : 11;
        d.corrupted.id ^= 1u << ((*rng)() % width);
      }
    } else if ((u -= rates.destroy) < 0) {
      d.action = FaultAction::kDestroy;
    }
    return d;
  };
}

}  // namespace volcomp::sim
