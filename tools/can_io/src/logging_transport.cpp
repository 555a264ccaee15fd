// LoggingTransport: candump -L recording decorator.
#include "volcomp/can_io/logging_transport.hpp"

#include <stdexcept>

namespace volcomp::can_io {

LoggingTransport::LoggingTransport(std::unique_ptr<CanTransport> inner,
                                   std::unique_ptr<CandumpLogWriter> log)
    : inner_(std::move(inner)), log_(std::move(log)) {
  if (!inner_ || !log_) throw std::invalid_argument("LoggingTransport needs a transport and a log");
}

void LoggingTransport::Send(const CanFrame& frame) {
  inner_->Send(frame);
  log_->Write(frame, Direction::kTx);
}

std::optional<CanFrame> LoggingTransport::Receive(std::chrono::microseconds timeout) {
  auto frame = inner_->Receive(timeout);
  if (frame) log_->Write(*frame, Direction::kRx);
  return frame;
}

std::string LoggingTransport::description() const { return inner_->description() + " (logged)"; }

std::string LogInterfaceName(const std::string& spec) {
  const TransportSpec s = ParseTransportSpec(spec);
  return s.kind == TransportSpec::Kind::kSocketCan ? s.target : "slcan0";
}

std::unique_ptr<CanTransport> OpenTransportWithLog(const std::string& spec,
                                                   const std::string& log_path) {
  auto transport = OpenTransport(spec);
  if (log_path.empty()) return transport;
  return std::make_unique<LoggingTransport>(
      std::move(transport), CandumpLogWriter::OpenFile(log_path, LogInterfaceName(spec)));
}

}  // namespace volcomp::can_io
