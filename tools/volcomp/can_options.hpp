// Options every CAN command shares: --can SPEC, --node ID, --log FILE, --timeout-ms N.
#pragma once

#include <memory>
#include <string>

#include "volcomp/canopen_client/can_session.hpp"
#include "volcomp/tools/args.hpp"
#include "volcomp/tools/csv.hpp"

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

inline std::unique_ptr<canopen_client::CanSession> OpenSession(const CanOptions& o) {
  canopen_client::SdoClient::Options sdo;
  sdo.timeout_ms = o.timeout_ms;
  return std::make_unique<canopen_client::CanSession>(o.spec, o.node, o.log, sdo);
}

}  // namespace volcomp::tools
