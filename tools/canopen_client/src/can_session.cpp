// PC-tool session over a real CAN transport.
#include "volcomp/canopen_client/can_session.hpp"

#include "volcomp/can_io/logging_transport.hpp"
#include "volcomp/canopen/node.hpp"
#include "volcomp/canopen/sdo_protocol.hpp"

namespace volcomp::canopen_client {

Expected<std::unique_ptr<CanSession>> CanSession::Open(const std::string& spec,
                                                       uint8_t node,
                                                       const std::string& log_path,
                                                       SdoClient::Options options) {
  can_io::TransportOptions transport_options;
  transport_options.receive = ReceiveFilters(node);
  VOLCOMP_TRY_ASSIGN(auto transport,
                     can_io::OpenTransportWithLog(spec, log_path, transport_options));
  return std::unique_ptr<CanSession>(new CanSession(std::move(transport), node, options));
}

CanSession::CanSession(std::unique_ptr<can_io::CanTransport> transport,
                       uint8_t node,
                       SdoClient::Options options)
    : NodeObjects(link_, node, options), transport_(std::move(transport)) {
  link_.send = [this](const CanFrame& f) { return transport_->Send(f); };
  link_.receive = [this](uint64_t timeout_us) {
    return transport_->Receive(std::chrono::microseconds(timeout_us));
  };
  link_.now_us = [] {
    return static_cast<uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(
                                     std::chrono::steady_clock::now().time_since_epoch())
                                     .count());
  };
  link_.other = [this](const CanFrame& f) { Observe(f); };
  link_.diagnose = [this] { return DescribeDrops(); };
}

std::vector<can_io::ReceiveFilter> CanSession::ReceiveFilters(uint8_t node) {
  return {{static_cast<uint16_t>(canopen::sdo::kResponseCobBase + node), 0x7FF},
          {static_cast<uint16_t>(canopen::kEmcyCobBase + node), 0x7FF},
          {canopen::kHeartbeatCobBase, 0x780}};
}

std::string CanSession::DescribeDrops() {
  const uint64_t dropped = transport_->dropped_frames();
  if (dropped == drops_reported_) return "";
  const uint64_t n = dropped - drops_reported_;
  drops_reported_ = dropped;
  return std::to_string(n) + " received frame" + (n == 1 ? " was" : "s were") + " lost on " +
         transport_->description() +
         " before this program could read them (its receive buffer was full: the program did "
         "not run for a while; a busy computer?)";
}

void CanSession::Observe(const CanFrame& f) {
  if (f.extended || f.rtr) return;
  if (f.id == canopen::kHeartbeatCobBase + node() && f.dlc == 1) nmt_state_ = f.data[0];
  if (f.id == canopen::kEmcyCobBase + node() && f.dlc == 8) emcy_.push_back(f);
}

Outcome CanSession::Listen(std::chrono::milliseconds duration) {
  const auto end = std::chrono::steady_clock::now() + duration;
  for (;;) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= end) return Outcome::Ok();
    const auto left = std::chrono::duration_cast<std::chrono::microseconds>(end - now);
    VOLCOMP_TRY_ASSIGN(const std::optional<CanFrame> f, transport_->Receive(left));
    if (f) Observe(*f);
  }
}

std::vector<CanFrame> CanSession::TakeEmcy() {
  std::vector<CanFrame> out;
  out.swap(emcy_);
  return out;
}

Outcome CanSession::SendNmt(uint8_t command) {
  CanFrame f;
  f.id = canopen::kNmtCobId;
  f.dlc = 2;
  f.data[0] = command;
  f.data[1] = node();
  return transport_->Send(f);
}

Expected<bool> CanSession::ReceiveUntil(std::chrono::milliseconds timeout,
                                        const std::function<bool(const CanFrame&)>& done) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  for (auto now = std::chrono::steady_clock::now(); now < end;
       now = std::chrono::steady_clock::now()) {
    VOLCOMP_TRY_ASSIGN(
        const std::optional<CanFrame> f,
        transport_->Receive(std::chrono::duration_cast<std::chrono::microseconds>(end - now)));
    if (!f) continue;
    Observe(*f);
    if (!f->extended && !f->rtr && done(*f)) return true;
  }
  return false;
}

Expected<std::optional<uint8_t>> CanSession::WaitForBootUp(uint8_t expected,
                                                           std::chrono::milliseconds timeout) {
  std::optional<uint8_t> other;
  VOLCOMP_TRY_ASSIGN(const bool seen, ReceiveUntil(timeout, [&](const CanFrame& f) {
                       const bool boot_up = f.dlc == 1 && f.data[0] == 0 &&
                                            f.id > canopen::kHeartbeatCobBase &&
                                            f.id <= canopen::kHeartbeatCobBase + 127;
                       if (boot_up) other = static_cast<uint8_t>(f.id - canopen::kHeartbeatCobBase);
                       return boot_up && *other == expected;
                     }));
  return seen ? std::optional<uint8_t>(expected) : other;
}

Expected<std::optional<uint8_t>> CanSession::WaitForHeartbeat(std::chrono::milliseconds timeout) {
  std::optional<uint8_t> state;
  VOLCOMP_TRY(ReceiveUntil(timeout, [&](const CanFrame& f) {
    if (f.dlc != 1 || f.id != canopen::kHeartbeatCobBase + node()) return false;
    state = f.data[0];
    return true;
  }));
  return state;
}

Expected<std::optional<uint8_t>> CanSession::WaitForState(uint8_t state,
                                                          std::chrono::milliseconds timeout) {
  std::optional<uint8_t> last;
  VOLCOMP_TRY(ReceiveUntil(timeout, [&](const CanFrame& f) {
    if (f.dlc != 1 || f.id != canopen::kHeartbeatCobBase + node()) return false;
    last = f.data[0];
    return *last == state;
  }));
  return last;
}

std::string NmtStateName(uint8_t state) {
  switch (static_cast<canopen::NmtState>(state)) {
    case canopen::NmtState::kInitialising:
      return "boot-up";
    case canopen::NmtState::kStopped:
      return "stopped";
    case canopen::NmtState::kOperational:
      return "operational";
    case canopen::NmtState::kPreOperational:
      return "pre-operational";
    default:
      return "unknown state " + std::to_string(state);
  }
}

}  // namespace volcomp::canopen_client
