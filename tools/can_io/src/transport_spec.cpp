// Transport spec parsing and OpenTransport().
#include <cctype>

#include "volcomp/can/slcan.hpp"
#include "volcomp/can_io/slcan_transport.hpp"
#include "volcomp/can_io/socketcan_transport.hpp"
#include "volcomp/can_io/transport.hpp"

namespace volcomp::can_io {
namespace {

constexpr char kForms[] =
    "expected socketcan:IFACE, slcan:DEVICE[@BITRATE] or slcan-tcp:HOST:PORT[@BITRATE]";

Unexpected<Failure> Bad(const std::string& spec, const std::string& why) {
  return Fail(Error::kInvalidArgument,
              "bad CAN transport '" + spec + "': " + why + " (" + kForms + ")");
}

bool StartsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// Splits "X@BITRATE" into X and the parsed bitrate (0 when absent).
Expected<std::string> SplitBitrate(const std::string& spec,
                                   const std::string& rest,
                                   uint32_t* bitrate) {
  const size_t at = rest.rfind('@');
  if (at == std::string::npos) return rest;
  const Expected<uint32_t> parsed = ParseBitrate(rest.substr(at + 1));
  if (!parsed.ok()) return Bad(spec, parsed.error().message);
  *bitrate = *parsed;
  return rest.substr(0, at);
}

// "1".."65535", digits only.
bool ParsePort(const std::string& text, uint16_t* port) {
  if (text.empty()) return false;
  uint32_t value = 0;
  for (const char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    value = value * 10 + static_cast<uint32_t>(c - '0');
    if (value > 65535) return false;
  }
  if (value == 0 || value > 65535) return false;
  *port = static_cast<uint16_t>(value);
  return true;
}

}  // namespace

Expected<uint32_t> ParseBitrate(const std::string& text) {
  uint64_t value = 0;
  size_t i = 0;
  for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i) {
    value = value * 10 + static_cast<uint64_t>(text[i] - '0');
    if (value > 100000000) break;
  }
  uint64_t scale = 1;
  if (i + 1 == text.size() && (text[i] == 'k' || text[i] == 'K')) {
    scale = 1000;
    ++i;
  } else if (i + 1 == text.size() && text[i] == 'M') {
    scale = 1000000;
    ++i;
  }
  const uint64_t bitrate = value * scale;
  if (i == 0 || i != text.size() || bitrate > 0xFFFFFFFFu ||
      slcan::IndexForBitrate(static_cast<uint32_t>(bitrate)) < 0) {
    return Fail(
        Error::kInvalidArgument,
        "bitrate '" + text + "' is not one of 10k 20k 50k 100k 125k 250k 500k 800k 1M 83333");
  }
  return static_cast<uint32_t>(bitrate);
}

Expected<TransportSpec> ParseTransportSpec(const std::string& spec) {
  TransportSpec out;
  if (StartsWith(spec, "socketcan:")) {
    out.kind = TransportSpec::Kind::kSocketCan;
    out.target = spec.substr(10);
    if (out.target.empty()) return Bad(spec, "missing interface name");
    if (out.target.find_first_of("@:/ ") != std::string::npos) {
      return Bad(spec, "interface name '" + out.target + "' has characters interface names do not");
    }
    return out;
  }
  if (StartsWith(spec, "slcan:")) {
    out.kind = TransportSpec::Kind::kSlcanSerial;
    VOLCOMP_TRY_ASSIGN(out.target, SplitBitrate(spec, spec.substr(6), &out.bitrate));
    if (out.target.empty()) return Bad(spec, "missing device path");
    return out;
  }
  if (StartsWith(spec, "slcan-tcp:")) {
    out.kind = TransportSpec::Kind::kSlcanTcp;
    VOLCOMP_TRY_ASSIGN(const std::string hostport,
                       SplitBitrate(spec, spec.substr(10), &out.bitrate));
    const size_t colon = hostport.rfind(':');
    if (colon == std::string::npos) return Bad(spec, "missing :PORT");
    std::string host = hostport.substr(0, colon);
    if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
      host = host.substr(1, host.size() - 2);  // [IPv6]
    }
    if (host.empty()) return Bad(spec, "missing host");
    const std::string port = hostport.substr(colon + 1);
    if (!ParsePort(port, &out.port)) return Bad(spec, "port '" + port + "' is not 1..65535");
    out.target = host;
    return out;
  }
  return Bad(spec, "unknown transport");
}

Expected<std::unique_ptr<CanTransport>> OpenTransport(const std::string& spec,
                                                      const TransportOptions& options) {
  VOLCOMP_TRY_ASSIGN(const TransportSpec s, ParseTransportSpec(spec));
  SlcanOptions slcan;
  slcan.bitrate = s.bitrate;
  switch (s.kind) {
    case TransportSpec::Kind::kSocketCan: {
      SocketCanOptions socketcan;
      for (const ReceiveFilter& f : options.receive) {
        socketcan.socket.filters.push_back({f.id, f.mask, false});
      }
      VOLCOMP_TRY_ASSIGN(auto t, SocketCanTransport::Open(s.target, socketcan));
      return std::unique_ptr<CanTransport>(std::move(t));
    }
    case TransportSpec::Kind::kSlcanSerial: {
      VOLCOMP_TRY_ASSIGN(auto t, OpenSlcanSerial(s.target, slcan));
      return std::unique_ptr<CanTransport>(std::move(t));
    }
    case TransportSpec::Kind::kSlcanTcp: {
      VOLCOMP_TRY_ASSIGN(auto t, OpenSlcanTcp(s.target, s.port, slcan));
      return std::unique_ptr<CanTransport>(std::move(t));
    }
  }
  return Bad(spec, "unknown transport");
}

}  // namespace volcomp::can_io
