// SocketCAN client transport.
#include "volcomp/can_io/socketcan_transport.hpp"

#include <stdexcept>
#include <thread>

namespace volcomp::can_io {

using hal::socketcan::BusState;
using hal::socketcan::CanErrorInfo;
using hal::socketcan::SocketCanSocket;
using Clock = std::chrono::steady_clock;

SocketCanTransport::SocketCanTransport(const std::string& iface, const SocketCanOptions& options)
    : options_(options) {
  const Expected<void> opened = socket_.Open(iface, options.socket);
  if (!opened.ok()) throw std::runtime_error(opened.error().message);
}

void SocketCanTransport::Send(const CanFrame& frame) {
  if (!frame.valid()) throw std::invalid_argument(description() + ": invalid CAN frame");
  // The bus state comes from error frames that Receive() reads; a bus-off seen there stops
  // sending until the controller reports a restart.
  const auto deadline = Clock::now() + options_.send_timeout;
  auto backoff = std::chrono::microseconds(100);
  for (;;) {
    if (state_ == BusState::kBusOff) {
      throw CanBusOffError(description() + ": controller is bus-off; frame not sent");
    }
    int err = 0;
    const auto r = socket_.Write(frame, &err);
    if (r == SocketCanSocket::IoResult::kOk) return;
    if (r == SocketCanSocket::IoResult::kError) {
      throw std::runtime_error(
          hal::socketcan::SocketCanErrorText(socket_.iface() + ": write", err));
    }
    if (Clock::now() + backoff > deadline) {
      throw std::runtime_error(description() + ": transmit queue full for " +
                               std::to_string(options_.send_timeout.count()) +
                               " ms (no other node acknowledging? raise the queue with `ip link "
                               "set " +
                               socket_.iface() + " txqueuelen 1000`)");
    }
    std::this_thread::sleep_for(backoff);
    backoff = std::min(backoff * 2, std::chrono::microseconds(2000));
  }
}

std::optional<CanFrame> SocketCanTransport::Receive(std::chrono::microseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    CanFrame frame;
    if (ReadOne(&frame)) return frame;
    const auto left =
        std::chrono::duration_cast<std::chrono::microseconds>(deadline - Clock::now());
    if (left.count() <= 0) return std::nullopt;
    socket_.WaitReadable(left);
  }
}

bool SocketCanTransport::ReadOne(CanFrame* frame) {
  for (;;) {
    CanErrorInfo info;
    bool is_error = false;
    int err = 0;
    const auto r = socket_.Read(frame, &info, &is_error, &err);
    if (r == SocketCanSocket::IoResult::kWouldBlock) return false;
    if (r == SocketCanSocket::IoResult::kError) {
      throw std::runtime_error(hal::socketcan::SocketCanErrorText(socket_.iface() + ": read", err));
    }
    if (!is_error) return true;
    OnError(info);
  }
}

void SocketCanTransport::OnError(const CanErrorInfo& info) {
  const std::string text = description() + ": " + hal::socketcan::DescribeError(info);
  BusEvent::Kind kind = BusEvent::Kind::kErrorFrame;
  if (info.state_changed) {
    state_ = info.state;
    switch (info.state) {
      case BusState::kErrorActive:
        kind = BusEvent::Kind::kErrorActive;
        break;
      case BusState::kErrorWarning:
        kind = BusEvent::Kind::kErrorWarning;
        break;
      case BusState::kErrorPassive:
        kind = BusEvent::Kind::kErrorPassive;
        break;
      case BusState::kBusOff:
        kind = BusEvent::Kind::kBusOff;
        break;
    }
  }
  events_.push_back({kind, text});
  if (info.bus_off && options_.restart_on_bus_off) {
    const Expected<void> restart = hal::socketcan::RequestCanRestart(socket_.iface());
    events_.push_back(
        {BusEvent::Kind::kBusOff,
         description() + (restart.ok() ? ": restart requested"
                                       : ": restart failed: " + restart.error().message)});
  }
}

std::vector<BusEvent> SocketCanTransport::TakeEvents() {
  // Events come from error frames read by Receive().
  std::vector<BusEvent> out;
  out.swap(events_);
  return out;
}

}  // namespace volcomp::can_io
