// CiA 301 SDO server state machine. Frame layouts: CiA 301 section 7.2.4.3 (summarised in
// docs/canopen.md): byte 0 command specifier, bytes 1-2 index (LE), byte 3 sub-index.
#include "volcomp/canopen/sdo_server.hpp"

#include "volcomp/base/byte_order.hpp"
#include "volcomp/canopen/crc16.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen/sdo_protocol.hpp"

namespace volcomp::canopen {
using namespace sdo;  // NOLINT(build/namespaces): the frame vocabulary of this file

namespace {

constexpr uint32_t kSmallCapacity = 64;

bool Elapsed(uint32_t now_ms, uint32_t since_ms, uint32_t limit_ms) {
  return static_cast<uint32_t>(now_ms - since_ms) >= limit_ms;
}

}  // namespace

void SdoServer::Init(uint8_t node_id, ObjectValues* values, const SdoServerConfig& config) {
  // A re-init (NMT reset communication) ends a transfer in progress: a value being streamed into
  // hears that it was aborted (its staging is not left "receiving").
  if (values_ != nullptr) EndTransfer(SdoAbort::kGeneral);
  node_id_ = node_id;
  values_ = values;
  config_ = config;
  if (config_.block_size < 1 || config_.block_size > kMaxBlockSize) {
    config_.block_size = kMaxBlockSize;
  }
  state_ = State::kIdle;
  ack_pending_ = false;
  tx_count_ = 0;
  discard_seq_ = 0;
  aborts_ = malformed_ = 0;
  last_abort_ = SdoAbort::kNone;
}

CanFrame SdoServer::Frame(uint8_t cmd) const {
  CanFrame f;
  f.id = kResponseCobBase + node_id_;
  f.dlc = 8;
  f.data[0] = cmd;
  return f;
}

void SdoServer::Queue(const CanFrame& f) {
  if (tx_count_ == sizeof(tx_) / sizeof(tx_[0])) return;  // responses never exceed the ring
  tx_[(tx_head_ + tx_count_) % 4] = f;
  ++tx_count_;
}

void SdoServer::Respond(uint8_t cmd, const uint8_t* payload4) {
  CanFrame f = Frame(cmd);
  StoreLe16(f.data + 1, index_);
  f.data[3] = sub_;
  if (payload4 != nullptr) {
    for (int i = 0; i < 4; ++i) f.data[4 + i] = payload4[i];
  }
  Queue(f);
}

void SdoServer::EndTransfer(SdoAbort outcome, AbortOrigin origin) {
  const bool downloading = state_ == State::kDownloadSegmented || state_ == State::kBlockDownload ||
                           state_ == State::kBlockDownloadEnd;
  if (domain_ && downloading) {
    // A failure of a complete transfer is reported by FinishDownload(), not here.
    (void)values_->EndDomainWrite(outcome, origin);
  }
  state_ = State::kIdle;
  domain_ = false;
  ack_pending_ = false;
}

void SdoServer::OpenDiscardWindow() {
  // The client sends a whole sub-block before it reads our answer: the segments after the last
  // one we took may still be on their way.
  if (state_ != State::kBlockDownload || last_seq_ >= blksize_) return;
  // With the size indicated, the segments still to come tell which one carries the c bit; a
  // client past its own indicated size leaves that unknown (0).
  const uint32_t total = size_ == 0 ? 1u : (size_ + kSegmentBytes - 1) / kSegmentBytes;
  discard_segments_left_ = size_known_ && taken_segments_ < total ? total - taken_segments_ : 0;
  discard_seq_ = static_cast<uint8_t>(last_seq_ + 1);
  discard_rx_ms_ = last_rx_ms_;
}

void SdoServer::Abort(SdoAbort code) {
  uint8_t payload[4];
  StoreLe32(payload, Code(code));
  Respond(kAbort, payload);
  OpenDiscardWindow();
  EndTransfer(code);
  ++aborts_;
  last_abort_ = code;
  last_abort_origin_ = AbortOrigin::kServer;
}

bool SdoServer::DiscardLeftover(uint8_t cmd, uint32_t now_ms) {
  // The next segment exactly: its sequence number, and the c bit where the size tells whether it
  // is the transfer's last segment.
  const bool last = (cmd & kBlockLastSegment) != 0;
  const bool continues = BlockSequence(cmd) == discard_seq_ &&
                         (discard_segments_left_ == 0 || last == (discard_segments_left_ == 1));
  if (!continues || Elapsed(now_ms, discard_rx_ms_, config_.block_gap_ms)) {
    discard_seq_ = 0;  // not (or no longer) the aborted sub-block: a request
    return false;
  }
  const bool sub_block_ends = last || discard_seq_ >= blksize_;
  discard_seq_ = sub_block_ends ? 0 : static_cast<uint8_t>(discard_seq_ + 1);
  if (discard_segments_left_ > 0) --discard_segments_left_;
  discard_rx_ms_ = now_ms;
  return true;
}

SdoAbort SdoServer::Lookup(uint16_t index, uint8_t sub, bool write) {
  index_ = index;
  sub_ = sub;
  bool index_exists = false;
  entry_ = FindEntry(index, sub, &index_exists);
  if (entry_ == nullptr) return index_exists ? SdoAbort::kNoSubIndex : SdoAbort::kNoObject;
  if (write && !Writable(entry_->access)) return SdoAbort::kReadOnly;
  if (!write && !Readable(entry_->access)) return SdoAbort::kWriteOnly;
  return SdoAbort::kNone;
}

SdoAbort SdoServer::CheckLength(uint32_t size) const {
  const uint32_t fixed = FixedSize(entry_->type);
  if (fixed == 0 || size == fixed) return SdoAbort::kNone;
  return size > fixed ? SdoAbort::kTooLong : SdoAbort::kTooShort;
}

SdoAbort SdoServer::Deliver(const uint8_t* data, uint32_t size) {
  if (size_known_ && offset_ + size > size_) return SdoAbort::kTooLong;
  if (crc_on_) crc_ = Crc16Update(crc_, data, size);
  offset_ += size;
  if (domain_) return values_->DomainWriteData(data, size);
  const uint32_t fixed = FixedSize(entry_->type);
  if (small_len_ + size > (fixed != 0 ? fixed : kSmallCapacity)) return SdoAbort::kTooLong;
  for (uint32_t i = 0; i < size; ++i) small_[small_len_++] = data[i];
  return SdoAbort::kNone;
}

SdoAbort SdoServer::FinishDownload() {
  if (size_known_ && offset_ != size_) {
    return offset_ < size_ ? SdoAbort::kTooShort : SdoAbort::kTooLong;
  }
  if (domain_) {
    const SdoAbort code = values_->EndDomainWrite(SdoAbort::kNone);
    domain_ = false;  // ended, successfully or not
    return code;
  }
  const SdoAbort length = CheckLength(small_len_);
  if (Failed(length)) return length;
  return values_->Write(*entry_, small_, small_len_);
}

void SdoServer::OnFrame(const CanFrame& f, uint32_t now_ms) {
  if (f.rtr || f.dlc != 8) {
    ++malformed_;
    return;
  }
  const uint8_t cmd = f.data[0];
  if (discard_seq_ != 0 && DiscardLeftover(cmd, now_ms)) return;
  discard_seq_ = 0;
  last_rx_ms_ = now_ms;
  if (cmd == kAbort) {  // abort from the client: end silently
    if (state_ != State::kIdle) {
      SdoAbort code = AbortFromCode(LoadLe32(f.data + 4));
      if (!Failed(code)) code = SdoAbort::kGeneral;  // 0 is no abort code: still a failure
      ++aborts_;
      last_abort_ = code;
      last_abort_origin_ = AbortOrigin::kClient;
      OpenDiscardWindow();
      EndTransfer(code, AbortOrigin::kClient);
    }
    return;
  }
  switch (state_) {
    case State::kIdle:
      HandleIdle(f);
      return;
    case State::kDownloadSegmented:
      if (Specifier(cmd) == kCcsDownloadSegment) return DownloadSegment(f);
      break;
    case State::kUploadSegmented:
      if (Specifier(cmd) == kCcsUploadSegment) return UploadSegment(f);
      break;
    case State::kBlockDownload:
      return BlockDownloadSegment(f);
    case State::kBlockDownloadEnd:
      if (IsBlockDownloadEnd(cmd)) return BlockDownloadEnd(f);
      // A repeated last segment (our ack was lost): acknowledge again.
      if (BlockSequence(cmd) == last_seq_) return RequestBlockAck();
      break;
    case State::kBlockUploadWaitStart:
      if (cmd == Block(kCcsBlockUpload, kBlockStartUpload)) {
        state_ = State::kBlockUploadSend;
        up_seq_ = 1;
        return;
      }
      break;
    case State::kBlockUploadSend:
    case State::kBlockUploadWaitAck:
      if (cmd == Block(kCcsBlockUpload, kBlockAck)) return BlockUploadAck(f);
      break;
    case State::kBlockUploadWaitEndAck:
      if (cmd == Block(kCcsBlockUpload, kBlockEnd)) return BlockUploadEndAck(f);
      break;
  }
  // A new initiate while a transfer runs: the client gave up on the old one; start over.
  if (IsInitiate(cmd)) {
    EndTransfer(SdoAbort::kGeneral);
    HandleIdle(f);
    return;
  }
  Abort(SdoAbort::kCommand);
}

void SdoServer::HandleIdle(const CanFrame& f) {
  const uint8_t cmd = f.data[0];
  if (IsInitiateDownload(cmd)) return InitiateDownload(f);
  if (IsInitiateUpload(cmd)) return InitiateUpload(f);
  if (IsBlockUploadInitiate(cmd)) return InitiateBlockUpload(f);
  if (IsBlockDownloadInitiate(cmd)) return InitiateBlockDownload(f);
  index_ = LoadLe16(f.data + 1);
  sub_ = f.data[3];
  Abort(SdoAbort::kCommand);
}

void SdoServer::InitiateDownload(const CanFrame& f) {
  const uint8_t cmd = f.data[0];
  const SdoAbort code = Lookup(LoadLe16(f.data + 1), f.data[3], true);
  if (Failed(code)) return Abort(code);
  const bool expedited = (cmd & kExpedited) != 0, size_indicated = (cmd & kSizeIndicated) != 0;
  domain_ = false;
  small_len_ = 0;
  offset_ = 0;
  crc_on_ = false;
  if (expedited) {
    uint32_t n = ExpeditedBytes(cmd);
    const uint32_t fixed = FixedSize(entry_->type);
    if (!size_indicated && fixed != 0) n = fixed;
    if (entry_->type == DataType::kDomain) {
      SdoAbort c = values_->BeginDomainWrite(*entry_, n);
      if (!Failed(c)) c = values_->DomainWriteData(f.data + 4, n);
      if (!Failed(c)) c = values_->EndDomainWrite(SdoAbort::kNone);
      if (Failed(c)) return Abort(c);
    } else {
      if (const SdoAbort length = CheckLength(n); Failed(length)) return Abort(length);
      const SdoAbort c = values_->Write(*entry_, f.data + 4, n);
      if (Failed(c)) return Abort(c);
    }
    return Respond(Command(kScsInitiateDownload));
  }
  const SdoAbort c = BeginTransfer(size_indicated, size_indicated ? LoadLe32(f.data + 4) : 0);
  if (Failed(c)) return Abort(c);
  toggle_ = 0;
  state_ = State::kDownloadSegmented;
  Respond(Command(kScsInitiateDownload));
}

SdoAbort SdoServer::BeginTransfer(bool size_known, uint32_t size) {
  size_known_ = size_known;
  size_ = size;
  if (entry_->type == DataType::kDomain) {
    const SdoAbort c = values_->BeginDomainWrite(*entry_, size_);
    domain_ = !Failed(c);
    return c;
  }
  // A fixed-size value announced with the wrong size is refused at once, on every path.
  if (!size_known_) return SdoAbort::kNone;
  if (FixedSize(entry_->type) != 0) return CheckLength(size_);
  return size_ > kSmallCapacity ? SdoAbort::kTooLong : SdoAbort::kNone;
}

void SdoServer::DownloadSegment(const CanFrame& f) {
  const uint8_t cmd = f.data[0];
  if (ToggleOf(cmd) != toggle_) return Abort(SdoAbort::kToggle);
  const uint32_t n = SegmentBytes(cmd);
  const SdoAbort c = Deliver(f.data + 1, n);
  if (Failed(c)) return Abort(c);
  const uint8_t response = SegmentAck(kScsDownloadSegment, toggle_);
  toggle_ = static_cast<uint8_t>(toggle_ ^ 1u);
  if ((cmd & kLastSegment) != 0) {
    const SdoAbort done = FinishDownload();
    if (Failed(done)) return Abort(done);
    state_ = State::kIdle;
  }
  CanFrame r = Frame(response);
  Queue(r);
}

void SdoServer::InitiateUpload(const CanFrame& f) {
  const SdoAbort code = Lookup(LoadLe16(f.data + 1), f.data[3], false);
  if (Failed(code)) return Abort(code);
  uint8_t buf[4] = {0, 0, 0, 0};
  uint32_t copied = 0, total = 0;
  const SdoAbort c = values_->Read(*entry_, 0, buf, 4, &copied, &total);
  if (Failed(c)) return Abort(c);
  if (total >= 1 && total <= 4 && copied == total) {
    return Respond(Initiate(kScsInitiateUpload, total, true), buf);
  }
  size_ = total;
  offset_ = 0;
  toggle_ = 0;
  state_ = State::kUploadSegmented;
  uint8_t size_le[4];
  StoreLe32(size_le, total);
  Respond(Initiate(kScsInitiateUpload, 0, true), size_le);
}

void SdoServer::UploadSegment(const CanFrame& f) {
  if (ToggleOf(f.data[0]) != toggle_) return Abort(SdoAbort::kToggle);
  CanFrame r = Frame(0);
  uint32_t copied = 0, total = 0;
  const SdoAbort c = values_->Read(*entry_, offset_, r.data + 1, kSegmentBytes, &copied, &total);
  if (Failed(c)) return Abort(c);
  offset_ += copied;
  const bool last = offset_ >= size_ || copied < kSegmentBytes;
  r.data[0] = Segment(toggle_, copied, last);
  toggle_ = static_cast<uint8_t>(toggle_ ^ 1u);
  if (last) state_ = State::kIdle;
  Queue(r);
}

void SdoServer::InitiateBlockDownload(const CanFrame& f) {
  const uint8_t cmd = f.data[0];
  const SdoAbort code = Lookup(LoadLe16(f.data + 1), f.data[3], true);
  if (Failed(code)) return Abort(code);
  const bool size_indicated = (cmd & kBlockSizeIndicated) != 0;
  crc_on_ = (cmd & kBlockCrc) != 0;
  crc_ = 0;
  offset_ = 0;
  small_len_ = 0;
  domain_ = false;
  const SdoAbort c = BeginTransfer(size_indicated, size_indicated ? LoadLe32(f.data + 4) : 0);
  if (Failed(c)) return Abort(c);
  blksize_ = config_.block_size;
  paced_ = false;
  ack_pending_ = false;
  if (domain_) {
    // A sub-block delivers at most blksize segments before the next flush (the segment held
    // back from the sub-block before, and all but the last of this one).
    const uint32_t window = values_->DomainWriteWindow();
    if (window != 0) {
      paced_ = true;
      const uint32_t fit = window / kSegmentBytes;
      if (fit < blksize_) blksize_ = static_cast<uint8_t>(fit < 1 ? 1 : fit);
    }
  }
  last_seq_ = 0;
  taken_segments_ = 0;
  have_held_ = false;
  last_segment_seen_ = false;
  awaiting_first_ = true;
  state_ = State::kBlockDownload;
  const uint8_t payload[4] = {blksize_, 0, 0, 0};
  Respond(Block(kScsBlockDownload, kBlockInitiate, crc_on_), payload);
}

void SdoServer::BlockDownloadSegment(const CanFrame& f) {
  const uint8_t seq = BlockSequence(f.data[0]);
  const bool last = (f.data[0] & kBlockLastSegment) != 0;
  if (ack_pending_) return;                // sent before our acknowledgement: ignore
  if (seq == 0 || seq > blksize_) return;  // not a segment of this sub-block: ignore
  if (seq <= last_seq_) return;            // duplicate
  if (seq != last_seq_ + 1) {
    // Gap: acknowledge what arrived in sequence; the client resends the rest from 1.
    if (!awaiting_first_) RequestBlockAck();
    return;
  }
  awaiting_first_ = false;
  last_seq_ = seq;  // taken (an abort below discards the segments after it)
  ++taken_segments_;
  if (have_held_) {
    const SdoAbort c = Deliver(held_, kSegmentBytes);
    if (Failed(c)) return Abort(c);
  }
  for (int i = 0; i < static_cast<int>(kSegmentBytes); ++i) held_[i] = f.data[1 + i];
  have_held_ = true;
  if (last) {
    last_segment_seen_ = true;
    state_ = State::kBlockDownloadEnd;
    RequestBlockAck();
  } else if (seq == blksize_) {
    RequestBlockAck();
  }
}

void SdoServer::RequestBlockAck() {
  if (paced_) {
    ack_pending_ = true;  // Poll() flushes, then acknowledges
  } else {
    SendBlockAck();
  }
}

void SdoServer::SendBlockAck() {
  ack_pending_ = false;
  CanFrame r = Frame(Block(kScsBlockDownload, kBlockAck));
  r.data[1] = last_seq_;
  r.data[2] = blksize_;
  Queue(r);
  if (state_ == State::kBlockDownload) {
    last_seq_ = 0;  // the next sub-block starts at 1
    awaiting_first_ = true;
  }
}

void SdoServer::BlockDownloadEnd(const CanFrame& f) {
  const uint32_t unused = BlockEndUnused(f.data[0]);
  if (have_held_) {
    const SdoAbort c = Deliver(held_, kSegmentBytes - unused);
    if (Failed(c)) return Abort(c);
    have_held_ = false;
  }
  if (crc_on_ && LoadLe16(f.data + 1) != crc_) return Abort(SdoAbort::kCrc);
  const SdoAbort done = FinishDownload();
  if (Failed(done)) return Abort(done);
  state_ = State::kIdle;
  ack_pending_ = false;
  CanFrame r = Frame(Block(kScsBlockDownload, kBlockEnd));
  Queue(r);
}

void SdoServer::InitiateBlockUpload(const CanFrame& f) {
  const uint8_t cmd = f.data[0];
  const SdoAbort code = Lookup(LoadLe16(f.data + 1), f.data[3], false);
  if (Failed(code)) return Abort(code);
  const uint8_t blk = f.data[4];
  if (blk < 1 || blk > kMaxBlockSize) return Abort(SdoAbort::kBlockSize);
  uint8_t probe[1];
  uint32_t copied = 0, total = 0;
  const SdoAbort c = values_->Read(*entry_, 0, probe, 0, &copied, &total);
  if (Failed(c)) return Abort(c);
  size_ = total;
  offset_ = 0;
  crc_on_ = (cmd & kBlockCrc) != 0;
  crc_ = 0;
  up_blksize_ = blk;
  up_seq_ = 1;
  state_ = State::kBlockUploadWaitStart;
  uint8_t size_le[4];
  StoreLe32(size_le, total);
  Respond(Block(kScsBlockUpload, kBlockInitiate, crc_on_, true), size_le);
}

void SdoServer::BlockUploadAck(const CanFrame& f) {
  const uint8_t ackseq = f.data[1];
  const uint8_t next_blk = f.data[2];
  const uint32_t sent_here = static_cast<uint32_t>(up_seq_ - 1u);
  if (ackseq > sent_here || next_blk < 1 || next_blk > kMaxBlockSize) {
    return Abort(SdoAbort::kSequence);
  }
  // Bytes confirmed by this ack: fold them into the CRC.
  uint32_t confirmed = ackseq * kSegmentBytes;
  if (offset_ + confirmed > size_) confirmed = size_ - offset_;
  uint8_t buf[28];
  uint32_t done = 0;
  while (done < confirmed) {
    uint32_t copied = 0, total = 0;
    const uint32_t want = confirmed - done < sizeof buf ? confirmed - done : sizeof buf;
    const SdoAbort c = values_->Read(*entry_, offset_ + done, buf, want, &copied, &total);
    if (Failed(c) || copied == 0) return Abort(Failed(c) ? c : SdoAbort::kGeneral);
    if (crc_on_) crc_ = Crc16Update(crc_, buf, copied);
    done += copied;
  }
  offset_ += confirmed;
  up_blksize_ = next_blk;
  up_seq_ = 1;
  if (offset_ >= size_) {
    // All data confirmed: end with the CRC and the unused byte count of the last segment.
    const uint32_t tail = size_ % kSegmentBytes;
    const uint32_t unused =
        (size_ == 0 || tail == 0) ? (size_ == 0 ? kSegmentBytes : 0u) : kSegmentBytes - tail;
    CanFrame r = Frame(BlockEndCommand(kScsBlockUpload, unused));
    StoreLe16(r.data + 1, crc_);
    Queue(r);
    state_ = State::kBlockUploadWaitEndAck;
    return;
  }
  state_ = State::kBlockUploadSend;
}

void SdoServer::BlockUploadEndAck(const CanFrame& f) {
  (void)f;
  state_ = State::kIdle;
}

void SdoServer::Poll(uint32_t now_ms) {
  if (state_ == State::kIdle) return;
  if (Elapsed(now_ms, last_rx_ms_, config_.timeout_ms)) {
    Abort(SdoAbort::kTimeout);
    return;
  }
  // Silence in the middle of a block download sub-block means its tail was lost: acknowledge
  // the good part so the client resends the rest. (Silence after our ack is left to the client:
  // repeating an ack it already acted on would acknowledge segments it has not sent yet.)
  if (ack_pending_) {
    bool done = false;
    const SdoAbort c = values_->DomainWriteFlush(&done);
    if (Failed(c)) return Abort(c);
    if (done) {
      SendBlockAck();
      last_rx_ms_ = now_ms;  // the client's turn starts now
    }
    return;
  }
  if (state_ == State::kBlockDownload && !awaiting_first_ &&
      Elapsed(now_ms, last_rx_ms_, config_.block_gap_ms)) {
    SendBlockAck();
  }
}

bool SdoServer::PopTx(CanFrame* frame) {
  if (tx_count_ > 0) {
    *frame = tx_[tx_head_];
    tx_head_ = static_cast<uint8_t>((tx_head_ + 1) % 4);
    --tx_count_;
    return true;
  }
  if (state_ != State::kBlockUploadSend) return false;
  // Generate the next block upload segment on demand.
  const uint32_t start = offset_ + (up_seq_ - 1u) * kSegmentBytes;
  CanFrame r = Frame(0);
  uint32_t copied = 0, total = 0;
  const SdoAbort c = values_->Read(*entry_, start, r.data + 1, kSegmentBytes, &copied, &total);
  if (Failed(c)) {
    Abort(c);
    return PopTx(frame);
  }
  const bool last = start + copied >= size_;
  r.data[0] = BlockSegment(up_seq_, last);
  if (last || up_seq_ == up_blksize_) {
    state_ = State::kBlockUploadWaitAck;
  }
  ++up_seq_;
  *frame = r;
  return true;
}

}  // namespace volcomp::canopen
