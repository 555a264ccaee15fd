// Blocking SDO operations over a frame link.
#include "volcomp/canopen_client/sdo_runner.hpp"

#include "volcomp/canopen/sdo_protocol.hpp"

namespace volcomp::canopen_client {

const SdoResult& RunToCompletion(SdoClient& client, const FrameLink& link) {
  client.Poll(link.now_us());
  while (!client.done()) {
    CanFrame f;
    while (client.PopTx(&f)) link.send(f);
    if (client.done()) break;
    const std::optional<CanFrame> rx = link.receive(10000);
    const uint64_t now = link.now_us();
    if (rx) {
      if (rx->id == canopen::sdo::kResponseCobBase + client.node_id()) {
        client.OnFrame(*rx, now);
      } else if (link.other) {
        link.other(*rx);
      }
    }
    client.Poll(now);
  }
  CanFrame f;
  while (client.PopTx(&f)) link.send(f);  // a final abort or acknowledgement
  return client.result();
}

SdoResult Download(const FrameLink& link,
                   uint8_t node,
                   uint16_t index,
                   uint8_t sub,
                   const std::vector<uint8_t>& data,
                   SdoClient::Options options,
                   std::function<void(uint32_t, uint32_t)> progress) {
  SdoClient c(node, options);
  c.StartDownload(index, sub, data, std::move(progress));
  return RunToCompletion(c, link);
}

SdoResult Upload(const FrameLink& link,
                 uint8_t node,
                 uint16_t index,
                 uint8_t sub,
                 bool block,
                 SdoClient::Options options) {
  SdoClient c(node, options);
  c.StartUpload(index, sub, block);
  return RunToCompletion(c, link);
}

SdoResult WriteU32(const FrameLink& link,
                   uint8_t node,
                   uint16_t index,
                   uint8_t sub,
                   uint32_t value,
                   uint8_t size_bytes,
                   SdoClient::Options options) {
  std::vector<uint8_t> d;
  for (uint8_t i = 0; i < size_bytes; ++i) d.push_back(static_cast<uint8_t>(value >> (8 * i)));
  return Download(link, node, index, sub, d, options);
}

SdoResult ReadU32(const FrameLink& link,
                  uint8_t node,
                  uint16_t index,
                  uint8_t sub,
                  uint32_t* value,
                  SdoClient::Options options) {
  SdoResult r = Upload(link, node, index, sub, false, options);
  if (r.ok) {
    if (r.data.empty() || r.data.size() > 4) {
      r.ok = false;
      r.message = "unexpected value size " + std::to_string(r.data.size());
      return r;
    }
    uint32_t v = 0;
    for (size_t i = 0; i < r.data.size(); ++i) v |= uint32_t{r.data[i]} << (8 * i);
    *value = v;
  }
  return r;
}

}  // namespace volcomp::canopen_client
