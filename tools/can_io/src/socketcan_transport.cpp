// SocketCAN client transport.
#include "volcomp/can_io/socketcan_transport.hpp"

#include <thread>

namespace volcomp::can_io {

using hal::socketcan::BusState;
using hal::socketcan::CanErrorInfo;
using hal::socketcan::SocketCanSocket;
using Clock = std::chrono::steady_clock;

Expected<std::unique_ptr<SocketCanTransport>> SocketCanTransport::Open(
    const std::string& iface, const SocketCanOptions& options) {
  std::unique_ptr<SocketCanTransport> t(new SocketCanTransport(options));
  const Expected<void> opened = t->socket_.Open(iface, options.socket);
  if (!opened.ok()) {
    const Failure& f = opened.error();
    return Fail(f.code == Error::kInvalidArgument ? f.code : Error::kCommunication, f.message);
  }
  return t;
}

Outcome SocketCanTransport::Send(const CanFrame& frame) {
  if (!frame.valid()) return Fail(Error::kInvalidArgument, description() + ": invalid CAN frame");
  // The bus state comes from error frames that Receive() reads; a bus-off seen there stops
  // sending until the controller reports a restart.
  const auto deadline = Clock::now() + options_.send_timeout;
  auto backoff = std::chrono::microseconds(100);
  for (;;) {
    if (state_ == BusState::kBusOff) {
      return Fail(Error::kCommunication, description() + ": controller is bus-off; frame not sent");
    }
    int err = 0;
    const auto r = socket_.Write(frame, &err);
    if (r == SocketCanSocket::IoResult::kOk) return Outcome::Ok();
    if (r == SocketCanSocket::IoResult::kError) {
      return Fail(Error::kCommunication,
                  hal::socketcan::SocketCanErrorText(socket_.iface() + ": write", err));
    }
    if (Clock::now() + backoff > deadline) {
      return Fail(Error::kCommunication,
                  description() + ": transmit queue full for " +
                      std::to_string(options_.send_timeout.count()) +
                      " ms (no other node acknowledging? raise the queue with `ip link set " +
                      socket_.iface() + " txqueuelen 1000`)");
    }
    std::this_thread::sleep_for(backoff);
    backoff = std::min(backoff * 2, std::chrono::microseconds(2000));
  }
}

Expected<std::optional<CanFrame>> SocketCanTransport::Receive(std::chrono::microseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    CanFrame frame;
    VOLCOMP_TRY_ASSIGN(const bool got, ReadOne(&frame));
    if (got) return std::optional<CanFrame>(frame);
    const auto left =
        std::chrono::duration_cast<std::chrono::microseconds>(deadline - Clock::now());
    if (left.count() <= 0) return std::optional<CanFrame>();
    socket_.WaitReadable(left);
  }
}

Expected<bool> SocketCanTransport::ReadOne(CanFrame* frame) {
  for (;;) {
    CanErrorInfo info;
    bool is_error = false;
    int err = 0;
    const auto r = socket_.Read(frame, &info, &is_error, &err);
    if (r == SocketCanSocket::IoResult::kWouldBlock) return false;
    if (r == SocketCanSocket::IoResult::kError) {
      return Fail(Error::kCommunication,
                  hal::socketcan::SocketCanErrorText(socket_.iface() + ": read", err));
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
