// Typed object access over a frame link.
#include "volcomp/canopen_client/node_objects.hpp"

namespace volcomp::canopen_client {

std::vector<uint8_t> NumericPayload(canopen::ObjectId id, uint32_t value) {
  const uint32_t n = canopen::FixedSize(canopen::Entry(id).type);
  std::vector<uint8_t> bytes(n != 0 ? n : 4);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<uint8_t>(value >> (8 * i));
  return bytes;
}

SdoResult NodeObjects::Write(canopen::ObjectId id, uint32_t value) {
  return Download(id, NumericPayload(id, value));
}

SdoResult NodeObjects::Read(canopen::ObjectId id, uint32_t* value) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  return ReadU32(*link_, node_, e.index, e.sub, value, options_);
}

SdoResult NodeObjects::ReadString(canopen::ObjectId id, std::string* value) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  SdoResult r = Upload(*link_, node_, e.index, e.sub, false, options_);
  if (r.ok) value->assign(r.data.begin(), r.data.end());
  return r;
}

SdoResult NodeObjects::Download(canopen::ObjectId id,
                                const std::vector<uint8_t>& data,
                                std::function<void(uint32_t, uint32_t)> progress) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  return canopen_client::Download(*link_, node_, e.index, e.sub, data, options_,
                                  std::move(progress));
}

SdoResult NodeObjects::UploadDomain(canopen::ObjectId id, std::vector<uint8_t>* data) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  SdoResult r = Upload(*link_, node_, e.index, e.sub, true, options_);
  if (r.ok) *data = r.data;
  return r;
}

}  // namespace volcomp::canopen_client
