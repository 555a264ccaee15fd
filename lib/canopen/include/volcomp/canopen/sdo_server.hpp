// CiA 301 SDO server for one node: expedited, segmented and block download and upload. Frames in:
// OnFrame() (0x600 + node-ID; DLC other than 8 counted as malformed and ignored); frames out:
// PopTx(); timeouts and paced flushes: Poll(). Failures are SDO aborts (sdo_abort.hpp) sent to the
// client. Bounded memory (block data streamed to ObjectValues as it arrives). Single-threaded: the
// main loop. Block transfer rules, pacing and abort handling: docs/canopen.md, "Node".
#pragma once

#include <cstdint>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/canopen/object_values.hpp"

namespace volcomp::canopen {

struct SdoServerConfig {
  uint32_t timeout_ms = 1000;
  uint32_t block_gap_ms = 100;
  uint8_t block_size = 127;  // 1..127
};

class SdoServer {
 public:
  void Init(uint8_t node_id,
            ObjectValues* values,
            const SdoServerConfig& config = SdoServerConfig());

  void OnFrame(const CanFrame& frame, uint32_t now_ms);
  void Poll(uint32_t now_ms);
  /// Next frame to send, if any.
  bool PopTx(CanFrame* frame);

  bool busy() const { return state_ != State::kIdle; }
  /// Transfers ended by an abort (sent or received), since Init().
  uint32_t aborts() const { return aborts_; }
  uint32_t malformed() const { return malformed_; }
  /// Abort code of the last aborted transfer (kNone if none), and who sent it.
  SdoAbort last_abort() const { return last_abort_; }
  AbortOrigin last_abort_origin() const { return last_abort_origin_; }

 private:
  enum class State : uint8_t {
    kIdle,
    kDownloadSegmented,
    kUploadSegmented,
    kBlockDownload,     // receiving sub-block segments
    kBlockDownloadEnd,  // last segment seen, waiting for the end frame
    kBlockUploadWaitStart,
    kBlockUploadSend,
    kBlockUploadWaitAck,
    kBlockUploadWaitEndAck,
  };

  void HandleIdle(const CanFrame& f);
  void InitiateDownload(const CanFrame& f);
  void DownloadSegment(const CanFrame& f);
  void InitiateUpload(const CanFrame& f);
  void UploadSegment(const CanFrame& f);
  void InitiateBlockDownload(const CanFrame& f);
  void BlockDownloadSegment(const CanFrame& f);
  void BlockDownloadEnd(const CanFrame& f);
  void InitiateBlockUpload(const CanFrame& f);
  void BlockUploadAck(const CanFrame& f);
  void BlockUploadEndAck(const CanFrame& f);

  // Checks the entry for reading or writing.
  SdoAbort Lookup(uint16_t index, uint8_t sub, bool write);
  // Start of a segmented or block download of `size` bytes (if known) into entry_: opens a domain
  // write or checks the size against the small-value buffer.
  SdoAbort BeginTransfer(bool size_known, uint32_t size);
  // Delivers download data to the value or the small-object buffer.
  SdoAbort Deliver(const uint8_t* data, uint32_t size);
  SdoAbort FinishDownload();
  void SendBlockAck();
  // A block acknowledgement now, or once the value's data is durable (paced transfers).
  void RequestBlockAck();
  void Respond(uint8_t cmd, const uint8_t* payload4 = nullptr);
  void Abort(SdoAbort code);
  // Ends the transfer in progress with `outcome` (kNone = completed) sent by `origin`.
  void EndTransfer(SdoAbort outcome, AbortOrigin origin = AbortOrigin::kServer);
  // The abort (sent or received) that ends a transfer a download of a fixed-size value would make
  // `size` bytes long: kNone when it fits, else too long / too short (CiA 301 0x06070012/13).
  SdoAbort CheckLength(uint32_t size) const;
  // On an abort inside a block download sub-block: drop what follows of that sub-block.
  void OpenDiscardWindow();
  // True (and the frame is dropped) when byte 0 `cmd` continues the aborted sub-block.
  bool DiscardLeftover(uint8_t cmd, uint32_t now_ms);
  void Queue(const CanFrame& f);
  CanFrame Frame(uint8_t cmd) const;  // a response frame with byte 0 = cmd, the rest 0

  uint8_t node_id_ = 1;
  ObjectValues* values_ = nullptr;
  SdoServerConfig config_;

  State state_ = State::kIdle;
  const ObjectEntry* entry_ = nullptr;
  uint16_t index_ = 0;
  uint8_t sub_ = 0;
  bool domain_ = false;  // streaming into the value vs. buffering a small value
  bool size_known_ = false;
  uint32_t size_ = 0;    // indicated size (download) or value size (upload)
  uint32_t offset_ = 0;  // bytes delivered (download) / bytes acknowledged (upload)
  uint8_t toggle_ = 0;
  uint16_t crc_ = 0;
  bool crc_on_ = false;
  uint32_t last_rx_ms_ = 0;

  // Block download sub-block state.
  uint8_t blksize_ = 127;
  bool paced_ = false;        // the value asks for flushes before acknowledgements
  bool ack_pending_ = false;  // an acknowledgement waits for the flush to complete
  uint8_t last_seq_ = 0;      // last in-sequence segment of this sub-block
  bool awaiting_first_ = false;
  uint8_t held_[7] = {};  // the last in-sequence segment, held until its length is known
  bool have_held_ = false;
  bool last_segment_seen_ = false;
  uint32_t taken_segments_ = 0;  // in-sequence segments of this transfer
  uint8_t discard_seq_ = 0;      // next sequence number of an aborted sub-block to drop (0 = none)
  uint32_t discard_segments_left_ = 0;  // segments of the transfer still to come (0 = unknown)
  uint32_t discard_rx_ms_ = 0;

  // Block upload state.
  uint8_t up_seq_ = 0;  // next segment number to send in this sub-block
  uint8_t up_blksize_ = 0;

  // Small (non-domain) values written segmented/block are collected here.
  uint8_t small_[64] = {};
  uint32_t small_len_ = 0;

  CanFrame tx_[4];
  uint8_t tx_head_ = 0;
  uint8_t tx_count_ = 0;

  uint32_t aborts_ = 0;
  uint32_t malformed_ = 0;
  SdoAbort last_abort_ = SdoAbort::kNone;
  AbortOrigin last_abort_origin_ = AbortOrigin::kServer;
};

}  // namespace volcomp::canopen
