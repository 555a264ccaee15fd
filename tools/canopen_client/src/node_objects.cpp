// Typed object access over a frame link.
#include "volcomp/canopen_client/node_objects.hpp"

namespace volcomp::canopen_client {

std::vector<uint8_t> NumericPayload(canopen::ObjectId id, uint32_t value) {
  const uint32_t n = canopen::FixedSize(canopen::Entry(id).type);
  std::vector<uint8_t> bytes(n != 0 ? n : 4);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<uint8_t>(value >> (8 * i));
  return bytes;
}

void StartNumericWrite(SdoClient& client, canopen::ObjectId id, uint32_t value) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  client.StartWrite(e.index, e.sub, NumericPayload(id, value));
}

SdoOutcome NodeObjects::Write(canopen::ObjectId id, uint32_t value) {
  return WriteDomain(id, NumericPayload(id, value));
}

template <typename ReadFn>
auto NodeObjects::Repeated(const ReadFn& read) -> decltype(read()) {
  auto r = read();
  for (uint8_t attempt = 1;
       attempt < options_.read_attempts && !r.ok() && canopen::IsProtocolAbort(r.error().abort);
       ++attempt) {
    ++read_retries_;
    r = read();
  }
  return r;
}

SdoExpected<uint32_t> NodeObjects::Read(canopen::ObjectId id) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  return Repeated([&] { return ReadU32(*link_, node_, e.index, e.sub, options_); });
}

SdoExpected<std::string> NodeObjects::ReadString(canopen::ObjectId id) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  VOLCOMP_TRY_ASSIGN(const std::vector<uint8_t> data, Repeated([&] {
                       return ReadObject(*link_, node_, e.index, e.sub, false, options_);
                     }));
  return std::string(data.begin(), data.end());
}

SdoOutcome NodeObjects::WriteDomain(canopen::ObjectId id,
                                    const std::vector<uint8_t>& data,
                                    std::function<void(uint32_t, uint32_t)> progress) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  return WriteObject(*link_, node_, e.index, e.sub, data, options_, std::move(progress));
}

SdoExpected<std::vector<uint8_t>> NodeObjects::ReadDomain(canopen::ObjectId id) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  return Repeated([&] { return ReadObject(*link_, node_, e.index, e.sub, true, options_); });
}

}  // namespace volcomp::canopen_client
