// `volcomp sdo read|write INDEX:SUB [VALUE]` and `volcomp eds`: raw object access and the EDS.
//
// A write is checked against the object dictionary before anything is sent (value_check.hpp: the
// object exists and is writable, the value is an integer within its type and limits) and sent in
// the size of its type. When the board refuses, its reason is printed: the rule the settings
// break for a store (0x1010, from 0x2123), the staging error for table objects (from 0x2102).
#include <cstdio>
#include <fstream>
#include <iostream>

#include "can_options.hpp"
#include "commands.hpp"
#include "sdo_failure.hpp"
#include "volcomp/canopen_client/eds_writer.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/canopen_client/value_check.hpp"

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
  const canopen::ObjectEntry* e = canopen::FindEntry(index, sub);
  if (pos[0] == "read") {
    if (pos.size() != 2) throw UsageError("read takes no VALUE");
    return OverTheBus([&] {
      auto s = OpenSession(can);
      const auto r = canopen_client::Upload(s->link(), can.node, index, sub, false, s->options());
      Require(r);
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
    });
  }
  if (pos.size() != 3) throw UsageError("write needs a VALUE");
  if (e == nullptr) {
    throw UsageError("object " + pos[1] +
                     " is not in the dictionary (docs/volcomp.eds lists them)");
  }
  std::vector<uint8_t> payload;
  std::string why;
  if (!canopen_client::EncodeWriteValue(*e, pos[2], &payload, &why)) {
    throw UsageError("cannot write " + pos[1] + ": " + why + "; nothing was sent");
  }
  return OverTheBus([&] {
    auto s = OpenSession(can);
    canopen_client::SdoResult r =
        canopen_client::Download(s->link(), can.node, index, sub, payload, s->options());
    if (!r.ok && r.aborted_by_server) {
      using canopen::ObjectId;
      using canopen::TableCommand;
      const bool store = index == canopen::Entry(ObjectId::kStoreAll).index;
      const bool staging_step = (index == canopen::Entry(ObjectId::kTableControl).index &&
                                 (payload[0] == canopen::Value(TableCommand::kVerify) ||
                                  payload[0] == canopen::Value(TableCommand::kActivate))) ||
                                index == canopen::Entry(ObjectId::kTableData).index;
      const std::string reason = store          ? canopen_client::SettingsRefusalReason(*s)
                                 : staging_step ? canopen_client::StagingFailureReason(*s)
                                                : std::string();
      if (!reason.empty()) r.message += "; the board says: " + reason;
    }
    if (!r.ok) r = canopen_client::Explain(r, "writing " + pos[1]);
    Require(r);
    std::printf("ok\n");
    return 0;
  });
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
