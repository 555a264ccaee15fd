// SocketCanPort: CanPort over SocketCanSocket with a paced software transmit queue.
#include "volcomp/hal/linux/socketcan_port.hpp"

namespace volcomp::hal::socketcan {

Expected<void> SocketCanPort::Open(const std::string& iface, const Options& options) {
  options_ = options;
  tx_.clear();
  rx_.clear();
  state_ = BusState::kErrorActive;
  last_failure_.reset();
  return socket_.Open(iface, options.socket);
}

Status SocketCanPort::DoSetBitrate(uint32_t bitrate_bps) {
  bitrate_check_ = BitrateCheck();
  bitrate_check_.configured_bps = bitrate_bps;
  if (!socket_.is_open()) return Error::kNotReady;
  const Expected<uint32_t> rate = ReadCanBitrate(socket_.iface());
  if (!rate.ok()) {
    bitrate_check_.note = rate.error().message;
    return Status::Ok();  // nothing to compare with (see bitrate_check())
  }
  bitrate_check_.interface_bps = *rate;
  if (*rate == bitrate_bps) return Status::Ok();
  last_failure_ =
      Failure{Error::kCanBitrateMismatch,
              "socketcan: " + socket_.iface() + " runs at " + std::to_string(*rate) +
                  " bit/s, the configuration in force asks for " + std::to_string(bitrate_bps) +
                  " bit/s (set it with `ip link set " + socket_.iface() + " type can bitrate " +
                  std::to_string(bitrate_bps) + "`, or store the interface's rate)"};
  return Error::kCanBitrateMismatch;
}

void SocketCanPort::Service() {
  if (!socket_.is_open()) return;
  Flush();
  for (;;) {
    CanFrame frame;
    CanErrorInfo info;
    bool is_error = false;
    int err = 0;
    const auto r = socket_.Read(&frame, &info, &is_error, &err);
    if (r != SocketCanSocket::IoResult::kOk) {
      if (r == SocketCanSocket::IoResult::kError) {
        last_failure_ = Failure{Error::kIoError, SocketCanErrorText("read", err)};
      }
      return;
    }
    counters_.rx_dropped = socket_.dropped_frames();
    if (is_error) {
      OnError(info);
    } else {
      ++counters_.rx_frames;
      rx_.push_back(frame);
    }
  }
}

Status SocketCanPort::DoSend(const CanFrame& frame) {
  if (!socket_.is_open()) return Error::kNotReady;
  if (tx_.size() >= options_.tx_capacity) {
    Flush();
    if (tx_.size() >= options_.tx_capacity) return Error::kFull;
  }
  tx_.push_back(frame);
  Flush();
  return Status::Ok();
}

bool SocketCanPort::DoReceive(CanFrame* frame) {
  if (!socket_.is_open()) return false;
  Flush();
  while (rx_.empty()) {
    CanFrame f;
    CanErrorInfo info;
    bool is_error = false;
    int err = 0;
    const auto r = socket_.Read(&f, &info, &is_error, &err);
    if (r != SocketCanSocket::IoResult::kOk) {
      if (r == SocketCanSocket::IoResult::kError) {
        last_failure_ = Failure{Error::kIoError, SocketCanErrorText("read", err)};
      }
      return false;
    }
    counters_.rx_dropped = socket_.dropped_frames();
    if (is_error) {
      OnError(info);
      continue;
    }
    ++counters_.rx_frames;
    *frame = f;
    return true;
  }
  *frame = rx_.front();
  rx_.pop_front();
  return true;
}

void SocketCanPort::Flush() {
  const auto now = Clock::now();
  if (now < retry_at_) return;
  while (!tx_.empty()) {
    int err = 0;
    const auto r = socket_.Write(tx_.front(), &err);
    if (r == SocketCanSocket::IoResult::kWouldBlock) {
      ++counters_.enobufs;
      retry_at_ = now + options_.enobufs_backoff;
      return;
    }
    if (r == SocketCanSocket::IoResult::kError) {
      // A hard error (interface down, ...): drop this frame so one bad state cannot wedge the
      // queue, and keep the reason for diagnostics.
      ++counters_.tx_dropped;
      last_failure_ = Failure{Error::kIoError, SocketCanErrorText("write", err)};
    } else {
      ++counters_.tx_frames;
    }
    tx_.pop_front();
  }
}

void SocketCanPort::OnError(const CanErrorInfo& info) {
  ++counters_.error_frames;
  last_failure_ =
      Failure{Error::kIoError, "socketcan: " + socket_.iface() + ": " + DescribeError(info)};
  if (info.state_changed) state_ = info.state;
  if (!info.bus_off) return;
  ++counters_.bus_off;
  const auto now = Clock::now();
  if (!options_.restart_on_bus_off) return;
  if (last_restart_ != Clock::time_point{} && now - last_restart_ < options_.restart_interval) {
    return;
  }
  last_restart_ = now;
  const Expected<void> restart = RequestCanRestart(socket_.iface());
  if (restart.ok()) {
    ++counters_.restarts;
  } else {
    last_failure_->message += "; restart failed: " + restart.error().message;
  }
}

}  // namespace volcomp::hal::socketcan
