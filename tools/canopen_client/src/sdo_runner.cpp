// Blocking SDO operations over a frame link.
#include "volcomp/canopen_client/sdo_runner.hpp"

#include "volcomp/canopen/sdo_protocol.hpp"

namespace volcomp::canopen_client {

const SdoExpected<std::vector<uint8_t>>& RunToCompletion(SdoClient& client, const FrameLink& link) {
  client.Poll(link.now_us());
  while (!client.done()) {
    CanFrame f;
    while (client.PopTx(&f)) {
      const Outcome sent = link.send(f);
      if (!sent.ok()) {
        client.Abandon(sent.error());
        return client.result();
      }
    }
    if (client.done()) break;
    const Expected<std::optional<CanFrame>> rx = link.receive(10000);
    if (!rx.ok()) {
      client.Abandon(rx.error());
      return client.result();
    }
    const uint64_t now = link.now_us();
    if (const std::optional<CanFrame>& frame = *rx) {
      if (frame->id == canopen::sdo::kResponseCobBase + client.node_id()) {
        client.OnFrame(*frame, now);
      } else if (link.other) {
        link.other(*frame);
      }
    }
    client.Poll(now);
  }
  // A final abort or acknowledgement; the transfer's result stands even if the link fails now
  // (the next access reports that).
  CanFrame f;
  while (client.PopTx(&f)) {
    if (!link.send(f).ok()) break;
  }
  if (!client.result().ok() && link.diagnose) client.AddToFailure(link.diagnose());
  return client.result();
}

SdoOutcome WriteObject(const FrameLink& link,
                       uint8_t node,
                       uint16_t index,
                       uint8_t sub,
                       const std::vector<uint8_t>& data,
                       SdoClient::Options options,
                       std::function<void(uint32_t, uint32_t)> progress) {
  SdoClient c(node, options);
  c.StartWrite(index, sub, data, std::move(progress));
  const SdoExpected<std::vector<uint8_t>>& r = RunToCompletion(c, link);
  if (!r.ok()) return Fail(r.error());
  return SdoOutcome::Ok();
}

SdoExpected<std::vector<uint8_t>> ReadObject(const FrameLink& link,
                                             uint8_t node,
                                             uint16_t index,
                                             uint8_t sub,
                                             bool block,
                                             SdoClient::Options options) {
  SdoClient c(node, options);
  c.StartRead(index, sub, block);
  return RunToCompletion(c, link);
}

SdoOutcome WriteU32(const FrameLink& link,
                    uint8_t node,
                    uint16_t index,
                    uint8_t sub,
                    uint32_t value,
                    uint8_t size_bytes,
                    SdoClient::Options options) {
  std::vector<uint8_t> d;
  for (uint8_t i = 0; i < size_bytes; ++i) d.push_back(static_cast<uint8_t>(value >> (8 * i)));
  return WriteObject(link, node, index, sub, d, options);
}

SdoExpected<uint32_t> ReadU32(
    const FrameLink& link, uint8_t node, uint16_t index, uint8_t sub, SdoClient::Options options) {
  VOLCOMP_TRY_ASSIGN(const std::vector<uint8_t> data,
                     ReadObject(link, node, index, sub, false, options));
  if (data.empty() || data.size() > 4) {
    return SdoFail(Error::kInputInvalid, "unexpected value size " + std::to_string(data.size()));
  }
  uint32_t v = 0;
  for (size_t i = 0; i < data.size(); ++i) v |= uint32_t{data[i]} << (8 * i);
  return v;
}

}  // namespace volcomp::canopen_client
