// The CAN commands' connection options and session.
#include "can_options.hpp"

namespace volcomp::cli {

Expected<CanConnection> ParseCanOptions(Args& args) {
  CanConnection c;
  c.spec = args.Required("--can");
  const std::optional<long long> node = args.Integer("--node");
  c.log = args.Value("--log").value_or("");
  const std::optional<long long> timeout = args.Integer("--timeout-ms");
  VOLCOMP_TRY(args.status());  // a missing --can comes before the ranges
  if (node) {
    if (*node < 1 || *node > 127) return UsageFailure("--node must be 1..127");
    c.node = static_cast<uint8_t>(*node);
  }
  if (timeout) {
    if (*timeout < 10 || *timeout > 60000) return UsageFailure("--timeout-ms must be 10..60000");
    c.timeout_ms = static_cast<uint32_t>(*timeout);
  }
  return c;
}

Expected<std::unique_ptr<canopen_client::CanSession>> OpenSession(const CanConnection& can) {
  canopen_client::SdoClient::Options sdo;
  sdo.timeout_ms = can.timeout_ms;
  auto session = canopen_client::CanSession::Open(can.spec, can.node, can.log, sdo);
  if (!session.ok()) return CommunicationFailure(session.error().message);
  return session;
}

const Options& JsonResultOption() {
  static const Options kOptions = {
      {"--json", nullptr, nullptr, nullptr, nullptr,
       "the result as one JSON object on stdout (messages on stderr)"}};
  return kOptions;
}

}  // namespace volcomp::cli
