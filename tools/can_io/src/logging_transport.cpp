// LoggingTransport: candump -L recording decorator.
#include "volcomp/can_io/logging_transport.hpp"

namespace volcomp::can_io {

LoggingTransport::LoggingTransport(std::unique_ptr<CanTransport> inner,
                                   std::unique_ptr<CandumpLogWriter> log)
    : inner_(std::move(inner)), log_(std::move(log)) {}

Outcome LoggingTransport::Send(const CanFrame& frame) {
  VOLCOMP_TRY(inner_->Send(frame));
  log_->Write(frame, Direction::kTx);
  return Outcome::Ok();
}

Expected<std::optional<CanFrame>> LoggingTransport::Receive(std::chrono::microseconds timeout) {
  VOLCOMP_TRY_ASSIGN(const std::optional<CanFrame> frame, inner_->Receive(timeout));
  if (frame) log_->Write(*frame, Direction::kRx);
  return frame;
}

std::string LoggingTransport::description() const { return inner_->description() + " (logged)"; }

Expected<std::string> LogInterfaceName(const std::string& spec) {
  VOLCOMP_TRY_ASSIGN(const TransportSpec s, ParseTransportSpec(spec));
  return s.kind == TransportSpec::Kind::kSocketCan ? s.target : std::string("slcan0");
}

Expected<std::unique_ptr<CanTransport>> OpenTransportWithLog(const std::string& spec,
                                                             const std::string& log_path,
                                                             const TransportOptions& options) {
  VOLCOMP_TRY_ASSIGN(auto transport, OpenTransport(spec, options));
  if (log_path.empty()) return transport;
  VOLCOMP_TRY_ASSIGN(const std::string iface, LogInterfaceName(spec));
  VOLCOMP_TRY_ASSIGN(auto log, CandumpLogWriter::OpenFile(log_path, iface));
  return std::unique_ptr<CanTransport>(
      std::make_unique<LoggingTransport>(std::move(transport), std::move(log)));
}

}  // namespace volcomp::can_io
