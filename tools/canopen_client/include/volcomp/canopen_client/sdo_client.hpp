// CiA 301 SDO client: the PC tool's side of every object read and write, the table transfer
// included, as an event-driven state machine so the same code runs over a real bus (sdo_runner.hpp)
// and in the simulator's virtual time (OnFrame / Poll / PopTx). Directions are named from the PC:
// a write sends data to the node (an SDO download: expedited up to 4 bytes, else block transfer
// with CRC-16, or segmented), a read fetches it (an SDO upload; block transfer when asked).
//
// An answer counts only when it names the transfer's object (index and sub-index of initiate
// responses and aborts): a late answer to an earlier request is ignored, its timeout running on;
// a frame that fits neither the state nor the object aborts the transfer (0x05040001).
//
// A failed access is an SdoFailure: the Failure for people (kCommunication when the node did not
// answer in time or the link failed, kTransferAborted for an abort from either side, ...) and the
// abort code behind it, for the callers' decisions (retry a protocol abort, explain a refusal).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::canopen_client {

/// Why an SDO access failed. `code` is kCommunication when nothing answered in time (the client's
/// timeout abort) or the link failed, kTransferAborted for any other abort, sent or received;
/// `message` says what failed and why ("node 16 refused 2101:00: abort 0x08000022 (...)").
struct SdoFailure : Failure {
  /// The abort received (by_server) or sent; kNone for a failure without one (the link, a check).
  canopen::SdoAbort abort = canopen::SdoAbort::kNone;
  bool by_server = false;
};

template <typename T>
using SdoExpected = Expected<T, SdoFailure>;
using SdoOutcome = Expected<void, SdoFailure>;

/// A failure of the caller's own (no abort): `code` and `message`.
inline Unexpected<SdoFailure> SdoFail(Error code, std::string message) {
  SdoFailure f;
  f.code = code;
  f.message = std::move(message);
  return Fail(std::move(f));
}

/// The abort behind `r`: kNone when it succeeded or failed without one.
template <typename T>
canopen::SdoAbort AbortOf(const SdoExpected<T>& r) {
  return r.ok() ? canopen::SdoAbort::kNone : r.error().abort;
}

class SdoClient {
 public:
  struct Options {
    uint32_t timeout_ms = 1000;  // per response
    bool use_block = true;       // block transfer for downloads > 4 bytes
    uint8_t upload_block_size = 127;
    /// A block upload's sub-block that goes this long without a segment after its first one
    /// (its end was lost: a full receive buffer, a garbled frame) is acknowledged up to the last
    /// segment received in sequence, and the node sends the rest again (CiA 301 block transfer;
    /// the board does the same for block downloads). Well below the node's own timeout (1000 ms
    /// on the board). 0: wait for the timeout instead.
    uint32_t block_gap_ms = 200;
    /// Reads through NodeObjects are repeated up to this many attempts in all when one ends with
    /// a protocol abort from either side (0x0503xxxx / 0x0504xxxx: a timeout, a stale or garbled
    /// frame): a read changes nothing on the node, so a fresh attempt is safe. Writes are not
    /// repeated (a repeated table command is not the same request).
    uint8_t read_attempts = 2;
  };

  SdoClient(uint8_t node_id, Options options);
  explicit SdoClient(uint8_t node_id) : SdoClient(node_id, Options()) {}

  /// Starts writing `data` to (index, sub) (an SDO download). `progress(bytes_done, total)` is
  /// called as acknowledgements arrive (may be empty).
  void StartWrite(uint16_t index,
                  uint8_t sub,
                  std::vector<uint8_t> data,
                  std::function<void(uint32_t, uint32_t)> progress = {});
  /// Starts reading (index, sub) (an SDO upload); `block` asks for block transfer.
  void StartRead(uint16_t index, uint8_t sub, bool block = false);
  /// Ends the transfer with `why` without sending anything (the link to the node failed).
  void Abandon(const Failure& why);
  /// Appends "; " + `note` to the message of a failed transfer (nothing when `note` is empty or
  /// the transfer did not fail).
  void AddToFailure(const std::string& note);

  void OnFrame(const CanFrame& frame, uint64_t now_us);
  void Poll(uint64_t now_us);
  bool PopTx(CanFrame* frame);

  bool done() const { return state_ == State::kDone; }
  /// The bytes read (empty for a write), or why the transfer failed (kNotReady while it runs).
  const SdoExpected<std::vector<uint8_t>>& result() const { return result_; }
  uint8_t node_id() const { return node_id_; }
  /// Segments resent after a gap acknowledgement (block download), for reports.
  uint32_t resent_segments() const { return resent_; }
  /// Block upload sub-blocks acknowledged after a gap (Options::block_gap_ms), for reports.
  uint32_t gap_acks() const { return gap_acks_; }

 private:
  enum class State : uint8_t {
    kDone,
    kInitDownload,
    kSegDownload,
    kBlockInit,
    kBlockSend,
    kBlockAck,
    kBlockEnd,
    kInitUpload,
    kSegUpload,
    kBlockUpInit,
    kBlockUpRecv,
    kBlockUpEnd,
  };

  // What a received frame was to this transfer.
  enum class Reply : uint8_t {
    kTaken,       // the answer it waited for
    kIgnored,     // an answer for another object: dropped
    kUnexpected,  // fits neither: the transfer is aborted
  };

  // One handler per transfer kind, each for its own states.
  Reply OnAbort(const CanFrame& f);
  Reply OnReply(const CanFrame& f);
  Reply OnDownloadReply(const CanFrame& f);
  Reply OnBlockDownloadReply(const CanFrame& f);
  void OnBlockAck(uint8_t ackseq, uint8_t next_blksize);
  Reply OnUploadReply(const CanFrame& f);
  Reply OnBlockUploadFrame(const CanFrame& f);
  void OnBlockUploadSegment(const CanFrame& f);
  // Acknowledges the segments received in sequence; the next sub-block (or the end) follows.
  void AckUploadSubBlock();
  void OnBlockUploadEnd(const CanFrame& f);
  // Bytes 1-3 of an initiate response or abort name this transfer's object.
  bool ForThisObject(const CanFrame& f) const;

  void Succeed();
  void FailWith(Error code, std::string message, canopen::SdoAbort abort, bool by_server);
  void SendAbort(canopen::SdoAbort code, const std::string& message);
  void Queue(const CanFrame& f);
  CanFrame Request(uint8_t cmd) const;  // with index and sub-index
  CanFrame Plain(uint8_t cmd) const;    // byte 0 only
  void NextSegment();

  uint8_t node_id_;
  Options opt_;
  State state_ = State::kDone;
  SdoExpected<std::vector<uint8_t>> result_{std::vector<uint8_t>()};
  std::vector<uint8_t> received_;  // what a read has received so far
  uint16_t index_ = 0;
  uint8_t sub_ = 0;
  std::vector<uint8_t> data_;
  std::function<void(uint32_t, uint32_t)> progress_;
  uint32_t pos_ = 0;  // bytes acknowledged (download) / received (upload)
  uint8_t toggle_ = 0;
  uint8_t blksize_ = 0;
  uint8_t seq_ = 0;         // last segment sent in this sub-block
  uint32_t sub_start_ = 0;  // byte offset of this sub-block's first segment
  bool block_upload_ = false;
  uint32_t upload_size_ = 0;
  std::vector<uint8_t> up_block_;  // segments of the current upload sub-block
  uint8_t up_last_seq_ = 0;
  bool up_sub_block_started_ = false;  // a segment of the current sub-block arrived
  uint64_t up_gap_deadline_us_ = 0;
  uint32_t gap_acks_ = 0;
  bool up_last_ = false;
  uint64_t deadline_us_ = 0;
  uint64_t now_us_ = 0;
  std::vector<CanFrame> tx_;
  size_t tx_pos_ = 0;
  uint32_t resent_ = 0;
};

}  // namespace volcomp::canopen_client
