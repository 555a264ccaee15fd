// Options every CAN command shares: --can SPEC, --node ID, --log FILE, --timeout-ms N.
#pragma once

#include <memory>
#include <string>

#include "volcomp/canopen_client/can_session.hpp"
#include "volcomp/tools/args.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/exit_codes.hpp"

namespace volcomp::tools {

inline constexpr const char* kCanUsage =
    "--can socketcan:IFACE|slcan:DEVICE[@BITRATE]|slcan-tcp:HOST:PORT [--node ID] [--log FILE]"
    " [--timeout-ms N]";

struct CanOptions {
  std::string spec;
  uint8_t node = 0x10;
  std::string log;
  uint32_t timeout_ms = 1000;
};

inline CanOptions ParseCanOptions(Args& args) {
  CanOptions o;
  o.spec = args.required("--can");
  if (auto n = args.integer("--node")) {
    if (*n < 1 || *n > 127) throw UsageError("--node must be 1..127");
    o.node = static_cast<uint8_t>(*n);
  }
  o.log = args.value("--log").value_or("");
  if (auto t = args.integer("--timeout-ms")) {
    if (*t < 10 || *t > 60000) throw UsageError("--timeout-ms must be 10..60000");
    o.timeout_ms = static_cast<uint32_t>(*t);
  }
  return o;
}

/// Opens the adapter; CommunicationError (exit 3) when it cannot be opened.
inline std::unique_ptr<canopen_client::CanSession> OpenSession(const CanOptions& o) {
  canopen_client::SdoClient::Options sdo;
  sdo.timeout_ms = o.timeout_ms;
  try {
    return std::make_unique<canopen_client::CanSession>(o.spec, o.node, o.log, sdo);
  } catch (const std::runtime_error& e) {
    throw CommunicationError(e.what());
  }
}

/// Runs `body` (the bus part of a command); a failure of the link itself (the transport's
/// std::runtime_error: connection cut, bus-off) becomes CommunicationError (exit 3). Refusals
/// (InputError), usage errors and communication errors pass unchanged.
template <class Body>
auto OverTheBus(Body&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const InputError&) {
    throw;
  } catch (const UsageError&) {
    throw;
  } catch (const CommunicationError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw CommunicationError(e.what());
  }
}

}  // namespace volcomp::tools
