// Typed access to one node's objects by ObjectId (addresses and sizes from the shared object
// dictionary) over any frame link: a real transport (CanSession) or the simulator's bus. Every
// access runs to completion; a failure is an SdoFailure (sdo_client.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen_client/sdo_runner.hpp"

namespace volcomp::canopen_client {

/// The payload of a write of `value` to numeric object `id`: little-endian in the size of its type
/// (4 bytes for other types).
std::vector<uint8_t> NumericPayload(canopen::ObjectId id, uint32_t value);

/// Starts that write on `client` (a transfer the caller runs over its own link).
void StartNumericWrite(SdoClient& client, canopen::ObjectId id, uint32_t value);

class NodeObjects {
 public:
  /// `link` must outlive this object (it is only referenced). `options` apply to every access.
  NodeObjects(const FrameLink& link, uint8_t node, SdoClient::Options options = {})
      : link_(&link), node_(node), options_(options) {}

  uint8_t node() const { return node_; }
  const FrameLink& link() const { return *link_; }
  const SdoClient::Options& options() const { return options_; }

  /// Numeric objects: written with the entry's size (4 bytes for non-numeric types).
  SdoOutcome Write(canopen::ObjectId id, uint32_t value);
  // Reads are repeated after a protocol abort (Options::read_attempts); read_retries() counts the
  // repeats of this object's life, for reports.
  /// Numeric objects of 1..4 bytes, zero-extended.
  SdoExpected<uint32_t> Read(canopen::ObjectId id);
  SdoExpected<std::string> ReadString(canopen::ObjectId id);
  /// Domains (a table image): written by block transfer (segmented when the options say so);
  /// `progress(bytes_done, total)` as the node acknowledges.
  SdoOutcome WriteDomain(canopen::ObjectId id,
                         const std::vector<uint8_t>& data,
                         std::function<void(uint32_t, uint32_t)> progress = {});
  /// Domains, read by block transfer.
  SdoExpected<std::vector<uint8_t>> ReadDomain(canopen::ObjectId id);
  /// Reads repeated after a protocol abort so far.
  uint32_t read_retries() const { return read_retries_; }

 private:
  // Runs `read` until it succeeds, fails otherwise than by a protocol abort, or the attempts end.
  template <typename ReadFn>
  auto Repeated(const ReadFn& read) -> decltype(read());

  const FrameLink* link_;
  uint8_t node_;
  SdoClient::Options options_;
  uint32_t read_retries_ = 0;
};

}  // namespace volcomp::canopen_client
