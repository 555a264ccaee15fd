// CiA 301 SDO client (the PC tool's side of uploads, reads and writes), as an event-driven state
// machine so the same code runs against a real bus (Run() with a CanTransport-like link) and in
// virtual time inside the simulator (OnFrame / Poll / PopTx driven by the simulated bus).
//
// Download picks the protocol by size: expedited for <= 4 bytes, block transfer (CRC-16 on,
// size indicated) for larger values when `use_block` (default), segmented otherwise. Upload: block
// for DOMAIN reads when asked, expedited/segmented otherwise. Block download honours the server's
// block size from every ack and resends from the acknowledged sequence number.
//
// Answers are matched to the transfer: an initiate response or an abort that names another object
// (index and sub-index, bytes 1-3) is a late answer to an earlier request and is ignored (the
// transfer keeps waiting, its timeout still running); a frame that fits neither the transfer's
// state nor its object aborts the transfer (0x05040001).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/canopen/sdo_abort.hpp"

namespace volcomp::canopen_client {

struct SdoResult {
  bool ok = false;
  // From the server, or the one we sent (timeout, protocol error); kNone when the transfer
  // succeeded or failed without an abort (e.g. a check of the caller's).
  canopen::SdoAbort abort_code = canopen::SdoAbort::kNone;
  bool aborted_by_server = false;
  std::string message;        // readable: what failed and why
  std::vector<uint8_t> data;  // upload result
};

class SdoClient {
 public:
  struct Options {
    uint32_t timeout_ms = 1000;  // per response
    bool use_block = true;       // block transfer for downloads > 4 bytes
    uint8_t upload_block_size = 127;
  };

  SdoClient(uint8_t node_id, Options options);
  explicit SdoClient(uint8_t node_id) : SdoClient(node_id, Options()) {}

  /// Starts a download of `data` to (index, sub). `progress(bytes_done, total)` is called as
  /// acknowledgements arrive (may be empty).
  void StartDownload(uint16_t index,
                     uint8_t sub,
                     std::vector<uint8_t> data,
                     std::function<void(uint32_t, uint32_t)> progress = {});
  /// Starts an upload of (index, sub); `block` asks for block transfer.
  void StartUpload(uint16_t index, uint8_t sub, bool block = false);

  void OnFrame(const CanFrame& frame, uint64_t now_us);
  void Poll(uint64_t now_us);
  bool PopTx(CanFrame* frame);

  bool done() const { return state_ == State::kDone; }
  const SdoResult& result() const { return result_; }
  uint8_t node_id() const { return node_id_; }
  /// Segments resent after a gap acknowledgement (block download), for reports.
  uint32_t resent_segments() const { return resent_; }

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
  void OnBlockUploadEnd(const CanFrame& f);
  // Bytes 1-3 of an initiate response or abort name this transfer's object.
  bool ForThisObject(const CanFrame& f) const;

  void Finish(bool ok, const std::string& message);
  void SendAbort(canopen::SdoAbort code, const std::string& message);
  void Queue(const CanFrame& f);
  CanFrame Request(uint8_t cmd) const;  // with index and sub-index
  CanFrame Plain(uint8_t cmd) const;    // byte 0 only
  void NextSegment();

  uint8_t node_id_;
  Options opt_;
  State state_ = State::kDone;
  SdoResult result_;
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
  bool up_last_ = false;
  uint64_t deadline_us_ = 0;
  uint64_t now_us_ = 0;
  std::vector<CanFrame> tx_;
  size_t tx_pos_ = 0;
  uint32_t resent_ = 0;
};

}  // namespace volcomp::canopen_client
