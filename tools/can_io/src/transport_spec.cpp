// Transport spec parsing and OpenTransport().
#include <cctype>
#include <stdexcept>

#include "volcomp/can_io/slcan_transport.hpp"
#include "volcomp/can_io/socketcan_transport.hpp"
#include "volcomp/can_io/transport.hpp"
#include "volcomp/can/slcan.hpp"

namespace volcomp::can_io {
namespace {

constexpr char kForms[] =
    "expected socketcan:IFACE, slcan:DEVICE[@BITRATE] or slcan-tcp:HOST:PORT[@BITRATE]";

[[noreturn]] void Bad(const std::string& spec, const std::string& why) {
  throw std::runtime_error("bad CAN transport '" + spec + "': " + why + " (" + kForms + ")");
}

bool StartsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// Splits "X@BITRATE" into X and the parsed bitrate (0 when absent).
std::string SplitBitrate(const std::string& spec, const std::string& rest, uint32_t* bitrate) {
  const size_t at = rest.rfind('@');
  if (at == std::string::npos) return rest;
  try {
    *bitrate = ParseBitrate(rest.substr(at + 1));
  } catch (const std::runtime_error& e) {
    Bad(spec, e.what());
  }
  return rest.substr(0, at);
}

}  // namespace

uint32_t ParseBitrate(const std::string& text) {
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
    throw std::runtime_error("bitrate '" + text +
                             "' is not one of 10k 20k 50k 100k 125k 250k 500k 800k 1M 83333");
  }
  return static_cast<uint32_t>(bitrate);
}

TransportSpec ParseTransportSpec(const std::string& spec) {
  TransportSpec out;
  if (StartsWith(spec, "socketcan:")) {
    out.kind = TransportSpec::Kind::kSocketCan;
    out.target = spec.substr(10);
    if (out.target.empty()) Bad(spec, "missing interface name");
    if (out.target.find_first_of("@:/ ") != std::string::npos) {
      Bad(spec, "interface name '" + out.target + "' has characters interface names do not");
    }
    return out;
  }
  if (StartsWith(spec, "slcan:")) {
    out.kind = TransportSpec::Kind::kSlcanSerial;
    out.target = SplitBitrate(spec, spec.substr(6), &out.bitrate);
    if (out.target.empty()) Bad(spec, "missing device path");
    return out;
  }
  if (StartsWith(spec, "slcan-tcp:")) {
    out.kind = TransportSpec::Kind::kSlcanTcp;
    const std::string hostport = SplitBitrate(spec, spec.substr(10), &out.bitrate);
    const size_t colon = hostport.rfind(':');
    if (colon == std::string::npos) Bad(spec, "missing :PORT");
    std::string host = hostport.substr(0, colon);
    if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
      host = host.substr(1, host.size() - 2);  // [IPv6]
    }
    if (host.empty()) Bad(spec, "missing host");
    const std::string port = hostport.substr(colon + 1);
    unsigned long value = 0;
    size_t used = 0;
    try {
      value = std::stoul(port, &used, 10);
    } catch (const std::exception&) {
      used = 0;
    }
    if (port.empty() || used != port.size() || value == 0 || value > 65535 ||
        !std::isdigit(static_cast<unsigned char>(port[0]))) {
      Bad(spec, "port '" + port + "' is not 1..65535");
    }
    out.target = host;
    out.port = static_cast<uint16_t>(value);
    return out;
  }
  Bad(spec, "unknown transport");
}

std::unique_ptr<CanTransport> OpenTransport(const std::string& spec) {
  const TransportSpec s = ParseTransportSpec(spec);
  SlcanOptions slcan;
  slcan.bitrate = s.bitrate;
  switch (s.kind) {
    case TransportSpec::Kind::kSocketCan:
      return std::make_unique<SocketCanTransport>(s.target, SocketCanOptions());
    case TransportSpec::Kind::kSlcanSerial:
      return OpenSlcanSerial(s.target, slcan);
    case TransportSpec::Kind::kSlcanTcp:
      return OpenSlcanTcp(s.target, s.port, slcan);
  }
  Bad(spec, "unknown transport");
}

}  // namespace volcomp::can_io
