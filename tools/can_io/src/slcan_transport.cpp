// SLCAN client transport: open sequence, frame I/O, replies.
#include "volcomp/can_io/slcan_transport.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>

#include "fd_io.hpp"

namespace volcomp::can_io {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;
using Clock = std::chrono::steady_clock;

microseconds Left(Clock::time_point deadline) {
  return std::chrono::duration_cast<microseconds>(deadline - Clock::now());
}

bool IsReply(slcan::Kind k) {
  switch (k) {
    case slcan::Kind::kOk:
    case slcan::Kind::kError:
    case slcan::Kind::kStatusReply:
    case slcan::Kind::kVersionReply:
    case slcan::Kind::kDetailReply:
    case slcan::Kind::kSerialReply:
      return true;
    default:
      return false;
  }
}

std::string ReplyText(const slcan::Message& m) {
  char line[slcan::kMaxEncodedLength + 1] = {};
  const size_t n = slcan::Encode(m, line, sizeof line - 1);
  return n > 0 ? std::string(line, n - 1) : std::string();  // without the terminator
}

}  // namespace

SlcanTransport::SlcanTransport(int fd, std::string description, const SlcanOptions& options)
    : fd_(fd), description_(std::move(description)), options_(options) {}

Expected<std::unique_ptr<SlcanTransport>> SlcanTransport::Open(int fd,
                                                               std::string description,
                                                               const SlcanOptions& options) {
  // Owned from here: the destructor closes the fd whatever the open sequence says.
  std::unique_ptr<SlcanTransport> t(new SlcanTransport(fd, std::move(description), options));
  VOLCOMP_TRY(t->OpenChannel());
  return t;
}

Outcome SlcanTransport::OpenStep(const std::string& line, const char* what, bool* answers) {
  const std::string with_cr = line + "\r";
  VOLCOMP_TRY(
      detail::WriteAll(fd_, with_cr.data(), with_cr.size(), options_.send_timeout, description_));
  if (!*answers) return Outcome::Ok();
  const auto deadline = Clock::now() + options_.open_timeout;
  while (replies_.empty() && Left(deadline).count() > 0) VOLCOMP_TRY(ReadInput(Left(deadline)));
  if (replies_.empty()) {
    *answers = false;  // a silent adapter: do not wait for the next answers either
    return Outcome::Ok();
  }
  const slcan::Message reply = replies_.front();
  replies_.pop_front();
  if (what != nullptr && reply.kind == slcan::Kind::kError) {
    return Fail(Error::kCommunication,
                description_ + ": adapter refused '" + line + "' (" + what + ")");
  }
  return Outcome::Ok();
}

Outcome SlcanTransport::OpenChannel() {
  VOLCOMP_TRY(detail::SetNonBlocking(fd_, description_));
  // Close first (an adapter left open by a crashed client refuses S), then bitrate, then open.
  // Whatever the adapter answers to C is fine; a BEL to S or O is a refusal.
  bool answers = true;
  VOLCOMP_TRY(OpenStep("C", nullptr, &answers));
  if (options_.bitrate != 0) {
    const int index = slcan::IndexForBitrate(options_.bitrate);
    if (index < 0) {
      return Fail(Error::kInvalidArgument, description_ + ": bitrate " +
                                               std::to_string(options_.bitrate) +
                                               " has no SLCAN S command");
    }
    VOLCOMP_TRY(OpenStep("S" + std::to_string(index), "set bitrate", &answers));
  }
  VOLCOMP_TRY(OpenStep("O", "open channel", &answers));
  replies_.clear();
  channel_open_ = true;
  return Outcome::Ok();
}

SlcanTransport::~SlcanTransport() {
  if (!channel_open_) {  // the open sequence failed: nothing to close on the adapter
    ::close(fd_);
    return;
  }
  // Best effort: leave the adapter closed, as slcand does on shutdown.
  const char close_cmd[] = "C\r";
  // send(MSG_NOSIGNAL) so a vanished TCP peer cannot raise SIGPIPE; write() for ttys.
  if (::send(fd_, close_cmd, sizeof close_cmd - 1, MSG_NOSIGNAL) < 0 && errno == ENOTSOCK) {
    (void)!::write(fd_, close_cmd, sizeof close_cmd - 1);
  }
  ::close(fd_);
}

Outcome SlcanTransport::Send(const CanFrame& frame) {
  if (!frame.valid()) return Fail(Error::kInvalidArgument, description_ + ": invalid CAN frame");
  char line[slcan::kMaxEncodedLength];
  const size_t n = slcan::EncodeFrame(frame, line, sizeof line);
  return detail::WriteAll(fd_, line, n, options_.send_timeout, description_);
}

Expected<std::optional<CanFrame>> SlcanTransport::Receive(std::chrono::microseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    if (!rx_.empty()) {
      const CanFrame f = rx_.front();
      rx_.pop_front();
      return std::optional<CanFrame>(f);
    }
    const auto left = Left(deadline);
    VOLCOMP_TRY(ReadInput(left.count() > 0 ? left : microseconds(0)));
    if (rx_.empty() && Left(deadline).count() <= 0) return std::optional<CanFrame>();
  }
}

std::string SlcanTransport::description() const {
  return description_ +
         (options_.bitrate != 0 ? " @" + std::to_string(options_.bitrate) : std::string());
}

std::vector<BusEvent> SlcanTransport::TakeEvents() {
  std::vector<BusEvent> out;
  out.swap(events_);
  return out;
}

Expected<std::string> SlcanTransport::Command(const std::string& line,
                                              std::chrono::milliseconds timeout) {
  VOLCOMP_TRY(ReadInput(microseconds(0)));
  replies_.clear();
  const std::string with_cr = line + "\r";
  VOLCOMP_TRY(
      detail::WriteAll(fd_, with_cr.data(), with_cr.size(), options_.send_timeout, description_));
  // F/V/v/N have a specific reply; skip plain OKs (which may acknowledge earlier frames).
  const char c = line.empty() ? '\0' : line[0];
  const bool specific = line.size() == 1 && (c == 'F' || c == 'V' || c == 'v' || c == 'N');
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    while (!replies_.empty()) {
      const slcan::Message m = replies_.front();
      replies_.pop_front();
      if (m.kind == slcan::Kind::kError) {
        return Fail(Error::kCommunication,
                    description_ + ": adapter answered BEL to '" + line + "'");
      }
      if (specific && m.kind == slcan::Kind::kOk) continue;
      return ReplyText(m);
    }
    const auto left = Left(deadline);
    if (left.count() <= 0) {
      return Fail(Error::kCommunication, description_ + ": no answer to '" + line + "' within " +
                                             std::to_string(timeout.count()) + " ms");
    }
    VOLCOMP_TRY(ReadInput(left));
  }
}

Outcome SlcanTransport::ReadInput(std::chrono::microseconds timeout) {
  const short ev = detail::PollFd(fd_, POLLIN, timeout);
  if (ev == 0) return Outcome::Ok();
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(fd_, buf, sizeof buf);
    if (n > 0) {
      for (ssize_t i = 0; i < n; ++i) {
        slcan::Message m;
        if (decoder_.Feed(static_cast<uint8_t>(buf[i]), &m)) Handle(m);
      }
      if (static_cast<size_t>(n) < sizeof buf) return Outcome::Ok();
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return Outcome::Ok();
    if (n == 0)
      return Fail(Error::kCommunication, description_ + ": connection closed by the peer");
    const int err = errno;
    return Fail(Error::kCommunication, description_ + ": read failed: " + detail::ErrnoText(err) +
                                           (err == EIO ? " (device gone or pty closed)" : ""));
  }
}

void SlcanTransport::Handle(const slcan::Message& m) {
  switch (m.kind) {
    case slcan::Kind::kFrame:
      rx_.push_back(m.frame);
      return;
    case slcan::Kind::kTxAck:
    case slcan::Kind::kTxAckExt:
      return;
    case slcan::Kind::kMalformed:
      events_.push_back(
          {BusEvent::Kind::kAdapterError, description_ + ": unparsable line from adapter"});
      return;
    default:
      break;
  }
  if (!IsReply(m.kind)) return;
  if (m.kind == slcan::Kind::kError) {
    events_.push_back({BusEvent::Kind::kAdapterError,
                       description_ + ": adapter answered BEL (command or frame refused)"});
  }
  replies_.push_back(m);
  if (replies_.size() > 64) replies_.pop_front();  // nobody is asking: keep it bounded
}

}  // namespace volcomp::can_io
