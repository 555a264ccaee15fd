// `volcomp sdo read|write INDEX:SUB [VALUE]` and `volcomp eds`: raw object access and the EDS.
#include <cstdio>
#include <fstream>
#include <iostream>

#include "can_options.hpp"
#include "commands.hpp"
#include "volcomp/canopen_client/eds_writer.hpp"

namespace volcomp::tools {
namespace {

std::pair<uint16_t, uint8_t> ParseAddress(const std::string& text) {
  const size_t colon = text.find(':');
  try {
    const unsigned long index = std::stoul(text.substr(0, colon), nullptr, 16);
    const unsigned long sub =
        colon == std::string::npos ? 0 : std::stoul(text.substr(colon + 1), nullptr, 0);
    if (index > 0xFFFF || sub > 0xFF) throw std::out_of_range("address");
    return {static_cast<uint16_t>(index), static_cast<uint8_t>(sub)};
  } catch (const std::logic_error&) {
    throw UsageError("object address \"" + text + "\": use INDEX:SUB in hex, e.g. 2104:0");
  }
}

}  // namespace

int RunSdo(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  auto pos = args.positionals();
  args.finish();
  if (pos.size() < 2 || (pos[0] != "read" && pos[0] != "write")) {
    throw UsageError("expected `read INDEX:SUB` or `write INDEX:SUB VALUE`");
  }
  const auto [index, sub] = ParseAddress(pos[1]);
  auto s = OpenSession(can);
  const canopen::ObjectEntry* e = canopen::FindEntry(index, sub);
  if (pos[0] == "read") {
    const auto r = canopen_client::Upload(s->link(), can.node, index, sub, false, s->options());
    if (!r.ok) throw InputError(r.message);
    if (e != nullptr && e->type == canopen::DataType::kVisibleString) {
      std::printf("%s\n", std::string(r.data.begin(), r.data.end()).c_str());
    } else if (r.data.size() <= 4) {
      uint32_t v = 0;
      for (size_t i = 0; i < r.data.size(); ++i) v |= uint32_t{r.data[i]} << (8 * i);
      const bool is_signed = e != nullptr && (e->type == canopen::DataType::kInteger32 ||
                                              e->type == canopen::DataType::kInteger16);
      if (is_signed) {
        std::printf("%d (0x%X)\n", static_cast<int32_t>(v), v);
      } else {
        std::printf("%u (0x%X)\n", v, v);
      }
    } else {
      for (uint8_t b : r.data) std::printf("%02X", b);
      std::printf("\n");
    }
    return 0;
  }
  if (pos.size() != 3) throw UsageError("write needs a VALUE");
  long long value = 0;
  try {
    value = std::stoll(pos[2], nullptr, 0);
  } catch (const std::logic_error&) {
    throw UsageError("VALUE \"" + pos[2] + "\" is not an integer");
  }
  const uint32_t size =
      e != nullptr && canopen::FixedSize(e->type) ? canopen::FixedSize(e->type) : 4;
  const auto r =
      canopen_client::WriteU32(s->link(), can.node, index, sub, static_cast<uint32_t>(value),
                               static_cast<uint8_t>(size), s->options());
  if (!r.ok) throw InputError(r.message);
  std::printf("ok\n");
  return 0;
}

int RunEds(Args& args) {
  const auto out = args.value("-o", "--output");
  args.finish();
  if (out) {
    std::ofstream f(*out);
    canopen_client::WriteEds(f);
    if (!f) throw InputError(*out + ": cannot write");
  } else {
    canopen_client::WriteEds(std::cout);
  }
  return 0;
}

}  // namespace volcomp::tools
