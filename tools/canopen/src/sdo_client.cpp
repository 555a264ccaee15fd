// CiA 301 SDO client state machine (frame layouts as in docs/canopen.md).
#include "volcomp/canopen_client/sdo_client.hpp"

#include <cstdio>

#include "volcomp/byte_order.hpp"
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

void SdoClient::Finish(bool ok, const std::string& message) {
  result_.ok = ok;
  result_.message = message;
  state_ = State::kDone;
}

void SdoClient::SendAbort(uint32_t code, const std::string& message) {
  CanFrame f = Request(kAbort);
  StoreLe32(f.data + 4, code);
  Queue(f);
  result_.abort_code = code;
  result_.aborted_by_server = false;
  Finish(false, message + " (sent abort " + Hex(code) + ": " + canopen::SdoAbortText(code) + ")");
}

void SdoClient::StartDownload(uint16_t index,
                              uint8_t sub,
                              std::vector<uint8_t> data,
                              std::function<void(uint32_t, uint32_t)> progress) {
  result_ = SdoResult();
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

void SdoClient::StartUpload(uint16_t index, uint8_t sub, bool block) {
  result_ = SdoResult();
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
  if (deadline_us_ == 0) deadline_us_ = now_us + uint64_t{opt_.timeout_ms} * 1000;
  if (now_us > deadline_us_)
    SendAbort(canopen::kAbortTimeout, "no response from node " + std::to_string(node_id_));
}

void SdoClient::OnFrame(const CanFrame& f, uint64_t now_us) {
  now_us_ = now_us;
  if (f.id != kResponseCobBase + node_id_ || f.dlc != 8 || f.rtr || state_ == State::kDone) return;
  const uint8_t cmd = f.data[0];
  deadline_us_ = now_us + uint64_t{opt_.timeout_ms} * 1000;
  if (cmd == kAbort) {
    result_.abort_code = LoadLe32(f.data + 4);
    result_.aborted_by_server = true;
    char where[32];
    std::snprintf(where, sizeof where, "%04X:%02X", LoadLe16(f.data + 1), f.data[3]);
    Finish(false, std::string("node ") + std::to_string(node_id_) + " refused " + where +
                      ": abort " + Hex(result_.abort_code) + " (" +
                      canopen::SdoAbortText(result_.abort_code) + ")");
    return;
  }
  const uint32_t size = static_cast<uint32_t>(data_.size());
  switch (state_) {
    case State::kInitDownload:
      if (cmd != Command(kScsInitiateDownload)) break;
      if (size <= 4 && size > 0) {
        if (progress_) progress_(size, size);
        return Finish(true, "ok");
      }
      state_ = State::kSegDownload;
      NextSegment();
      return;
    case State::kSegDownload: {
      if (cmd != SegmentAck(kScsDownloadSegment, toggle_)) break;
      pos_ += size - pos_ < kSegmentBytes ? size - pos_ : kSegmentBytes;
      if (progress_) progress_(pos_, size);
      if (pos_ >= size) return Finish(true, "ok");
      toggle_ = static_cast<uint8_t>(toggle_ ^ 1);
      NextSegment();
      return;
    }
    case State::kBlockInit:
      if (!IsBlockDownloadInitiateResponse(cmd)) break;
      blksize_ = f.data[4];
      if (blksize_ < 1 || blksize_ > kMaxBlockSize) {
        return SendAbort(canopen::kAbortBlockSize, "server offered an invalid block size");
      }
      sub_start_ = 0;
      seq_ = 0;
      state_ = State::kBlockSend;
      return;
    case State::kBlockSend:
    case State::kBlockAck: {
      if (cmd != Block(kScsBlockDownload, kBlockAck)) break;
      const uint8_t ackseq = f.data[1];
      if (ackseq > seq_) return SendAbort(canopen::kAbortSequence, "ack beyond the segments sent");
      resent_ += seq_ - ackseq;
      uint32_t acked = uint32_t{ackseq} * kSegmentBytes;
      if (sub_start_ + acked > size) acked = size - sub_start_;
      sub_start_ += acked;
      pos_ = sub_start_;
      if (progress_) progress_(pos_, size);
      blksize_ = f.data[2];
      if (blksize_ < 1 || blksize_ > kMaxBlockSize) {
        return SendAbort(canopen::kAbortBlockSize, "server asked for an invalid block size");
      }
      seq_ = 0;
      if (sub_start_ >= size) {
        const uint32_t tail = size % kSegmentBytes;
        const uint32_t unused = tail == 0 ? 0 : kSegmentBytes - tail;
        CanFrame e = Plain(BlockEndCommand(kCcsBlockDownload, unused));
        StoreLe16(e.data + 1, canopen::Crc16Update(0, data_.data(), data_.size()));
        Queue(e);
        state_ = State::kBlockEnd;
      } else {
        state_ = State::kBlockSend;
      }
      return;
    }
    case State::kBlockEnd:
      if (cmd != Block(kScsBlockDownload, kBlockEnd)) break;
      return Finish(true, "ok");
    case State::kInitUpload: {
      if (Specifier(cmd) != kScsInitiateUpload) break;
      if ((cmd & kExpedited) != 0) {
        const uint32_t n = ExpeditedBytes(cmd);
        result_.data.assign(f.data + 4, f.data + 4 + n);
        return Finish(true, "ok");
      }
      upload_size_ = (cmd & kSizeIndicated) != 0 ? LoadLe32(f.data + 4) : 0;
      toggle_ = 0;
      state_ = State::kSegUpload;
      CanFrame r = Plain(SegmentAck(kCcsUploadSegment, toggle_));
      Queue(r);
      return;
    }
    case State::kSegUpload: {
      if (Specifier(cmd) != kScsUploadSegment || ToggleOf(cmd) != toggle_) break;
      const uint32_t n = SegmentBytes(cmd);
      result_.data.insert(result_.data.end(), f.data + 1, f.data + 1 + n);
      if ((cmd & kLastSegment) != 0) return Finish(true, "ok");
      toggle_ = static_cast<uint8_t>(toggle_ ^ 1);
      CanFrame r = Plain(SegmentAck(kCcsUploadSegment, toggle_));
      Queue(r);
      return;
    }
    case State::kBlockUpInit: {
      if (!IsBlockUploadInitiateResponse(cmd)) break;
      upload_size_ = (cmd & kBlockSizeIndicated) != 0 ? LoadLe32(f.data + 4) : 0;
      up_last_seq_ = 0;
      up_last_ = false;
      up_block_.clear();
      CanFrame s = Plain(Block(kCcsBlockUpload, kBlockStartUpload));
      Queue(s);
      state_ = State::kBlockUpRecv;
      return;
    }
    case State::kBlockUpRecv: {
      const uint8_t seq = BlockSequence(cmd);
      const bool last = (cmd & kBlockLastSegment) != 0;
      if (seq == up_last_seq_ + 1) {
        up_last_seq_ = seq;
        result_.data.insert(result_.data.end(), f.data + 1, f.data + 1 + kSegmentBytes);
        up_last_ = last;
      }
      if (seq == opt_.upload_block_size || last) {
        CanFrame a = Plain(Block(kCcsBlockUpload, kBlockAck));
        a.data[1] = up_last_seq_;
        a.data[2] = opt_.upload_block_size;
        Queue(a);
        if (up_last_) {
          state_ = State::kBlockUpEnd;
        } else {
          up_last_seq_ = 0;
        }
      }
      return;
    }
    case State::kBlockUpEnd: {
      if (!IsBlockUploadEnd(cmd)) break;
      const uint32_t unused = BlockEndUnused(cmd);
      if (unused <= result_.data.size()) result_.data.resize(result_.data.size() - unused);
      if (upload_size_ != 0 && result_.data.size() != upload_size_) {
        return SendAbort(canopen::kAbortTypeMismatch, "block upload size differs from announced");
      }
      if (LoadLe16(f.data + 1) !=
          canopen::Crc16Update(0, result_.data.data(), result_.data.size())) {
        return SendAbort(canopen::kAbortCrc, "block upload CRC mismatch");
      }
      CanFrame a = Plain(Block(kCcsBlockUpload, kBlockEnd));
      Queue(a);
      return Finish(true, "ok");
    }
    case State::kDone:
      return;
  }
  SendAbort(canopen::kAbortCommand, "unexpected response " + Hex(cmd));
}

}  // namespace volcomp::canopen_client
