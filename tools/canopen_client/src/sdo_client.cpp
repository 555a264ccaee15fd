// CiA 301 SDO client state machine (frame layouts as in docs/canopen.md).
#include "volcomp/canopen_client/sdo_client.hpp"

#include <cstdio>

#include "volcomp/base/byte_order.hpp"
#include "volcomp/canopen/crc16.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen/sdo_protocol.hpp"

namespace volcomp::canopen_client {
using namespace canopen::sdo;  // NOLINT(build/namespaces): the frame vocabulary of this file

namespace {

std::string Hex(uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08X", v);
  return b;
}

// The result of a transfer that is still running (or was given up by its driver).
Unexpected<SdoFailure> NotFinished() {
  return SdoFail(Error::kNotReady, "the transfer did not finish");
}

}  // namespace

SdoClient::SdoClient(uint8_t node_id, Options options) : node_id_(node_id), opt_(options) {}

CanFrame SdoClient::Plain(uint8_t cmd) const {
  CanFrame f;
  f.id = kRequestCobBase + node_id_;
  f.dlc = 8;
  f.data[0] = cmd;
  return f;
}

CanFrame SdoClient::Request(uint8_t cmd) const {
  CanFrame f = Plain(cmd);
  StoreLe16(f.data + 1, index_);
  f.data[3] = sub_;
  return f;
}

void SdoClient::Queue(const CanFrame& f) { tx_.push_back(f); }

void SdoClient::Succeed() {
  result_ = std::move(received_);
  received_.clear();
  state_ = State::kDone;
}

void SdoClient::FailWith(Error code, std::string message, canopen::SdoAbort abort, bool by_server) {
  SdoFailure f;
  f.code = code;
  f.message = std::move(message);
  f.abort = abort;
  f.by_server = by_server;
  result_ = Fail(std::move(f));
  state_ = State::kDone;
}

void SdoClient::Abandon(const Failure& why) {
  if (state_ == State::kDone) return;
  FailWith(why.code, why.message, canopen::SdoAbort::kNone, false);
  tx_.clear();
  tx_pos_ = 0;
}

void SdoClient::AddToFailure(const std::string& note) {
  if (state_ != State::kDone || result_.ok() || note.empty()) return;
  SdoFailure f = result_.error();
  f.message += "; " + note;
  result_ = Fail(std::move(f));
}

void SdoClient::SendAbort(canopen::SdoAbort code, const std::string& message) {
  CanFrame f = Request(kAbort);
  StoreLe32(f.data + 4, canopen::Code(code));
  Queue(f);
  // Our own timeout: the node did not answer (absent, off, another node-ID): no board to talk to.
  FailWith(code == canopen::SdoAbort::kTimeout ? Error::kCommunication : Error::kTransferAborted,
           message + " (sent abort " + Hex(canopen::Code(code)) + ": " +
               canopen::SdoAbortText(code) + ")",
           code, false);
}

void SdoClient::StartWrite(uint16_t index,
                           uint8_t sub,
                           std::vector<uint8_t> data,
                           std::function<void(uint32_t, uint32_t)> progress) {
  result_ = NotFinished();
  received_.clear();
  index_ = index;
  sub_ = sub;
  data_ = std::move(data);
  progress_ = std::move(progress);
  pos_ = 0;
  resent_ = 0;
  const uint32_t size = static_cast<uint32_t>(data_.size());
  if (size <= 4 && size > 0) {
    CanFrame f = Request(Initiate(kCcsInitiateDownload, size, true));
    for (uint32_t i = 0; i < size; ++i) f.data[4 + i] = data_[i];
    Queue(f);
    state_ = State::kInitDownload;
  } else if (opt_.use_block) {
    CanFrame f = Request(Block(kCcsBlockDownload, kBlockInitiate, true, true));
    StoreLe32(f.data + 4, size);
    Queue(f);
    state_ = State::kBlockInit;
  } else {
    CanFrame f = Request(Initiate(kCcsInitiateDownload, 0, true));
    StoreLe32(f.data + 4, size);
    Queue(f);
    toggle_ = 0;
    state_ = State::kInitDownload;
  }
  deadline_us_ = 0;  // armed by the next Poll/OnFrame, which know the time
}

void SdoClient::StartRead(uint16_t index, uint8_t sub, bool block) {
  result_ = NotFinished();
  received_.clear();
  index_ = index;
  sub_ = sub;
  data_.clear();
  pos_ = 0;
  block_upload_ = block;
  if (block) {
    CanFrame f = Request(Block(kCcsBlockUpload, kBlockInitiate, true));
    f.data[4] = opt_.upload_block_size;
    f.data[5] = 0;  // no protocol switch
    Queue(f);
    state_ = State::kBlockUpInit;
  } else {
    Queue(Request(Command(kCcsInitiateUpload)));
    state_ = State::kInitUpload;
  }
  deadline_us_ = 0;  // armed by the next Poll/OnFrame, which know the time
}

void SdoClient::NextSegment() {
  // Segmented download: the next segment after pos_.
  const uint32_t size = static_cast<uint32_t>(data_.size());
  const uint32_t n = size - pos_ < kSegmentBytes ? size - pos_ : kSegmentBytes;
  const bool last = pos_ + n >= size;
  CanFrame f = Plain(Segment(toggle_, n, last));
  for (uint32_t i = 0; i < n; ++i) f.data[1 + i] = data_[pos_ + i];
  Queue(f);
}

bool SdoClient::PopTx(CanFrame* frame) {
  if (tx_pos_ < tx_.size()) {
    *frame = tx_[tx_pos_++];
    if (tx_pos_ == tx_.size()) {
      tx_.clear();
      tx_pos_ = 0;
    }
    return true;
  }
  if (state_ != State::kBlockSend) return false;
  // Next segment of the current sub-block, generated on demand.
  const uint32_t size = static_cast<uint32_t>(data_.size());
  const uint32_t start = sub_start_ + uint32_t{seq_} * kSegmentBytes;
  const uint32_t n = size - start < kSegmentBytes ? size - start : kSegmentBytes;
  const bool last = start + n >= size;
  ++seq_;
  CanFrame f = Plain(BlockSegment(seq_, last));
  for (uint32_t i = 0; i < n; ++i) f.data[1 + i] = data_[start + i];
  if (last || seq_ == blksize_) {
    state_ = State::kBlockAck;
    deadline_us_ = now_us_ + uint64_t{opt_.timeout_ms} * 1000;
  }
  *frame = f;
  return true;
}

void SdoClient::Poll(uint64_t now_us) {
  now_us_ = now_us;
  if (state_ == State::kDone || state_ == State::kBlockSend) return;
  if (state_ == State::kBlockUpRecv && up_sub_block_started_ && opt_.block_gap_ms != 0 &&
      now_us > up_gap_deadline_us_) {
    ++gap_acks_;
    AckUploadSubBlock();
    deadline_us_ = now_us + uint64_t{opt_.timeout_ms} * 1000;
    return;
  }
  if (deadline_us_ == 0) deadline_us_ = now_us + uint64_t{opt_.timeout_ms} * 1000;
  if (now_us > deadline_us_)
    SendAbort(canopen::SdoAbort::kTimeout, "no response from node " + std::to_string(node_id_));
}

bool SdoClient::ForThisObject(const CanFrame& f) const {
  return LoadLe16(f.data + 1) == index_ && f.data[3] == sub_;
}

void SdoClient::OnFrame(const CanFrame& f, uint64_t now_us) {
  now_us_ = now_us;
  if (f.id != kResponseCobBase + node_id_ || f.dlc != 8 || f.rtr || state_ == State::kDone) return;
  const Reply reply = f.data[0] == kAbort ? OnAbort(f) : OnReply(f);
  if (reply == Reply::kIgnored) return;  // not an answer to this transfer: no progress either
  if (reply == Reply::kUnexpected) {
    return SendAbort(canopen::SdoAbort::kCommand, "unexpected response " + Hex(f.data[0]));
  }
  deadline_us_ = now_us + uint64_t{opt_.timeout_ms} * 1000;
}

SdoClient::Reply SdoClient::OnAbort(const CanFrame& f) {
  // An abort names its object: one for another object ends an earlier transfer, not this one.
  if (!ForThisObject(f)) return Reply::kIgnored;
  const canopen::SdoAbort abort = canopen::AbortFromCode(LoadLe32(f.data + 4));
  char where[32];
  std::snprintf(where, sizeof where, "%04X:%02X", index_, sub_);
  FailWith(Error::kTransferAborted,
           std::string("node ") + std::to_string(node_id_) + " refused " + where + ": abort " +
               Hex(canopen::Code(abort)) + " (" + canopen::SdoAbortText(abort) + ")",
           abort, true);
  return Reply::kTaken;
}

SdoClient::Reply SdoClient::OnReply(const CanFrame& f) {
  switch (state_) {
    case State::kInitDownload:
    case State::kInitUpload:
    case State::kBlockInit:
    case State::kBlockUpInit:
      // The answer to an initiate carries the object's index and sub-index: an answer for
      // another object (a late one to an earlier request) is not ours.
      if (!ForThisObject(f)) return Reply::kIgnored;
      break;
    default:
      break;
  }
  switch (state_) {
    case State::kInitDownload:
    case State::kSegDownload:
      return OnDownloadReply(f);
    case State::kBlockInit:
    case State::kBlockSend:
    case State::kBlockAck:
    case State::kBlockEnd:
      return OnBlockDownloadReply(f);
    case State::kInitUpload:
    case State::kSegUpload:
      return OnUploadReply(f);
    case State::kBlockUpInit:
    case State::kBlockUpRecv:
    case State::kBlockUpEnd:
      return OnBlockUploadFrame(f);
    case State::kDone:
      break;
  }
  return Reply::kIgnored;
}

SdoClient::Reply SdoClient::OnDownloadReply(const CanFrame& f) {
  const uint8_t cmd = f.data[0];
  const uint32_t size = static_cast<uint32_t>(data_.size());
  if (state_ == State::kInitDownload) {
    if (cmd != Command(kScsInitiateDownload)) return Reply::kUnexpected;
    if (size <= 4 && size > 0) {
      if (progress_) progress_(size, size);
      Succeed();
      return Reply::kTaken;
    }
    state_ = State::kSegDownload;
    NextSegment();
    return Reply::kTaken;
  }
  if (cmd != SegmentAck(kScsDownloadSegment, toggle_)) return Reply::kUnexpected;
  pos_ += size - pos_ < kSegmentBytes ? size - pos_ : kSegmentBytes;
  if (progress_) progress_(pos_, size);
  if (pos_ >= size) {
    Succeed();
    return Reply::kTaken;
  }
  toggle_ = static_cast<uint8_t>(toggle_ ^ 1);
  NextSegment();
  return Reply::kTaken;
}

SdoClient::Reply SdoClient::OnBlockDownloadReply(const CanFrame& f) {
  const uint8_t cmd = f.data[0];
  switch (state_) {
    case State::kBlockInit:
      if (!IsBlockDownloadInitiateResponse(cmd)) return Reply::kUnexpected;
      blksize_ = f.data[4];
      if (blksize_ < 1 || blksize_ > kMaxBlockSize) {
        SendAbort(canopen::SdoAbort::kBlockSize, "server offered an invalid block size");
        return Reply::kTaken;
      }
      sub_start_ = 0;
      seq_ = 0;
      state_ = State::kBlockSend;
      return Reply::kTaken;
    case State::kBlockSend:
    case State::kBlockAck:
      if (cmd != Block(kScsBlockDownload, kBlockAck)) return Reply::kUnexpected;
      OnBlockAck(f.data[1], f.data[2]);
      return Reply::kTaken;
    default:  // kBlockEnd
      if (cmd != Block(kScsBlockDownload, kBlockEnd)) return Reply::kUnexpected;
      Succeed();
      return Reply::kTaken;
  }
}

void SdoClient::OnBlockAck(uint8_t ackseq, uint8_t next_blksize) {
  const uint32_t size = static_cast<uint32_t>(data_.size());
  if (ackseq > seq_) {
    return SendAbort(canopen::SdoAbort::kSequence, "ack beyond the segments sent");
  }
  resent_ += seq_ - ackseq;
  uint32_t acked = uint32_t{ackseq} * kSegmentBytes;
  if (sub_start_ + acked > size) acked = size - sub_start_;
  sub_start_ += acked;
  pos_ = sub_start_;
  if (progress_) progress_(pos_, size);
  blksize_ = next_blksize;
  if (blksize_ < 1 || blksize_ > kMaxBlockSize) {
    return SendAbort(canopen::SdoAbort::kBlockSize, "server asked for an invalid block size");
  }
  seq_ = 0;
  if (sub_start_ < size) {
    state_ = State::kBlockSend;
    return;
  }
  const uint32_t tail = size % kSegmentBytes;
  const uint32_t unused = tail == 0 ? 0 : kSegmentBytes - tail;
  CanFrame e = Plain(BlockEndCommand(kCcsBlockDownload, unused));
  StoreLe16(e.data + 1, canopen::Crc16Update(0, data_.data(), data_.size()));
  Queue(e);
  state_ = State::kBlockEnd;
}

SdoClient::Reply SdoClient::OnUploadReply(const CanFrame& f) {
  const uint8_t cmd = f.data[0];
  if (state_ == State::kInitUpload) {
    if (Specifier(cmd) != kScsInitiateUpload) return Reply::kUnexpected;
    if ((cmd & kExpedited) != 0) {
      const uint32_t n = ExpeditedBytes(cmd);
      received_.assign(f.data + 4, f.data + 4 + n);
      Succeed();
      return Reply::kTaken;
    }
    upload_size_ = (cmd & kSizeIndicated) != 0 ? LoadLe32(f.data + 4) : 0;
    toggle_ = 0;
    state_ = State::kSegUpload;
    Queue(Plain(SegmentAck(kCcsUploadSegment, toggle_)));
    return Reply::kTaken;
  }
  if (Specifier(cmd) != kScsUploadSegment || ToggleOf(cmd) != toggle_) return Reply::kUnexpected;
  const uint32_t n = SegmentBytes(cmd);
  received_.insert(received_.end(), f.data + 1, f.data + 1 + n);
  if ((cmd & kLastSegment) != 0) {
    Succeed();
    return Reply::kTaken;
  }
  toggle_ = static_cast<uint8_t>(toggle_ ^ 1);
  Queue(Plain(SegmentAck(kCcsUploadSegment, toggle_)));
  return Reply::kTaken;
}

SdoClient::Reply SdoClient::OnBlockUploadFrame(const CanFrame& f) {
  const uint8_t cmd = f.data[0];
  switch (state_) {
    case State::kBlockUpInit:
      if (!IsBlockUploadInitiateResponse(cmd)) return Reply::kUnexpected;
      upload_size_ = (cmd & kBlockSizeIndicated) != 0 ? LoadLe32(f.data + 4) : 0;
      up_last_seq_ = 0;
      up_last_ = false;
      up_sub_block_started_ = false;
      up_block_.clear();
      Queue(Plain(Block(kCcsBlockUpload, kBlockStartUpload)));
      state_ = State::kBlockUpRecv;
      return Reply::kTaken;
    case State::kBlockUpRecv:
      OnBlockUploadSegment(f);
      return Reply::kTaken;
    default:  // kBlockUpEnd
      if (!IsBlockUploadEnd(cmd)) return Reply::kUnexpected;
      OnBlockUploadEnd(f);
      return Reply::kTaken;
  }
}

void SdoClient::OnBlockUploadSegment(const CanFrame& f) {
  const uint8_t cmd = f.data[0];
  const uint8_t seq = BlockSequence(cmd);
  const bool last = (cmd & kBlockLastSegment) != 0;
  if (seq == up_last_seq_ + 1) {
    up_last_seq_ = seq;
    received_.insert(received_.end(), f.data + 1, f.data + 1 + kSegmentBytes);
    up_last_ = last;
  }
  up_sub_block_started_ = true;
  up_gap_deadline_us_ = now_us_ + uint64_t{opt_.block_gap_ms} * 1000;
  if (seq != opt_.upload_block_size && !last) return;
  AckUploadSubBlock();
}

void SdoClient::AckUploadSubBlock() {
  CanFrame a = Plain(Block(kCcsBlockUpload, kBlockAck));
  a.data[1] = up_last_seq_;
  a.data[2] = opt_.upload_block_size;
  Queue(a);
  up_sub_block_started_ = false;  // the node's turn: its silence now is the timeout's business
  if (up_last_) {
    state_ = State::kBlockUpEnd;
  } else {
    up_last_seq_ = 0;
  }
}

void SdoClient::OnBlockUploadEnd(const CanFrame& f) {
  const uint32_t unused = BlockEndUnused(f.data[0]);
  if (unused <= received_.size()) received_.resize(received_.size() - unused);
  if (upload_size_ != 0 && received_.size() != upload_size_) {
    return SendAbort(canopen::SdoAbort::kTypeMismatch, "block upload size differs from announced");
  }
  if (LoadLe16(f.data + 1) != canopen::Crc16Update(0, received_.data(), received_.size())) {
    return SendAbort(canopen::SdoAbort::kCrc, "block upload CRC mismatch");
  }
  Queue(Plain(Block(kCcsBlockUpload, kBlockEnd)));
  Succeed();
}

}  // namespace volcomp::canopen_client
