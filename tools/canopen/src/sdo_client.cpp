// CiA 301 SDO client state machine (frame layouts as in docs/canopen.md).
#include "volcomp/canopen_client/sdo_client.hpp"

#include <cstdio>

#include "volcomp/byte_order.hpp"
#include "volcomp/canopen/crc16.hpp"
#include "volcomp/canopen/sdo_abort.hpp"

namespace volcomp::canopen_client {
namespace {
constexpr uint32_t kRxBase = 0x580, kTxBase = 0x600;

std::string Hex(uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08X", v);
  return b;
}
}  // namespace

SdoClient::SdoClient(uint8_t node_id, Options options) : node_id_(node_id), opt_(options) {}

CanFrame SdoClient::Plain(uint8_t cmd) const {
  CanFrame f;
  f.id = kTxBase + node_id_;
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
  CanFrame f = Request(0x80);
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
    CanFrame f = Request(static_cast<uint8_t>(0x23 | ((4 - size) << 2)));
    for (uint32_t i = 0; i < size; ++i) f.data[4 + i] = data_[i];
    Queue(f);
    state_ = State::kInitDownload;
  } else if (opt_.use_block) {
    CanFrame f = Request(0xC6);  // block download, CRC supported, size indicated
    StoreLe32(f.data + 4, size);
    Queue(f);
    state_ = State::kBlockInit;
  } else {
    CanFrame f = Request(0x21);  // segmented, size indicated
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
    CanFrame f = Request(0xA4);  // block upload, CRC supported
    f.data[4] = opt_.upload_block_size;
    f.data[5] = 0;  // no protocol switch
    Queue(f);
    state_ = State::kBlockUpInit;
  } else {
    Queue(Request(0x40));
    state_ = State::kInitUpload;
  }
  deadline_us_ = 0;  // armed by the next Poll/OnFrame, which know the time
}

void SdoClient::NextSegment() {
  // Segmented download: the next segment after pos_.
  const uint32_t size = static_cast<uint32_t>(data_.size());
  const uint32_t n = size - pos_ < 7 ? size - pos_ : 7;
  CanFrame f;
  f.id = kTxBase + node_id_;
  f.dlc = 8;
  const bool last = pos_ + n >= size;
  f.data[0] = static_cast<uint8_t>((toggle_ << 4) | ((7 - n) << 1) | (last ? 1 : 0));
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
  const uint32_t start = sub_start_ + uint32_t{seq_} * 7u;
  const uint32_t n = size - start < 7 ? size - start : 7;
  const bool last = start + n >= size;
  ++seq_;
  CanFrame f = Plain(static_cast<uint8_t>(seq_ | (last ? 0x80 : 0)));
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
  if (f.id != kRxBase + node_id_ || f.dlc != 8 || f.rtr || state_ == State::kDone) return;
  const uint8_t cmd = f.data[0];
  deadline_us_ = now_us + uint64_t{opt_.timeout_ms} * 1000;
  if (cmd == 0x80) {
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
      if (cmd != 0x60) break;
      if (size <= 4 && size > 0) {
        if (progress_) progress_(size, size);
        return Finish(true, "ok");
      }
      state_ = State::kSegDownload;
      NextSegment();
      return;
    case State::kSegDownload: {
      if (cmd != (0x20 | (toggle_ << 4))) break;
      pos_ += size - pos_ < 7 ? size - pos_ : 7;
      if (progress_) progress_(pos_, size);
      if (pos_ >= size) return Finish(true, "ok");
      toggle_ = static_cast<uint8_t>(toggle_ ^ 1);
      NextSegment();
      return;
    }
    case State::kBlockInit:
      if ((cmd & 0xFB) != 0xA0) break;
      blksize_ = f.data[4];
      if (blksize_ < 1 || blksize_ > 127) {
        return SendAbort(canopen::kAbortBlockSize, "server offered an invalid block size");
      }
      sub_start_ = 0;
      seq_ = 0;
      state_ = State::kBlockSend;
      return;
    case State::kBlockSend:
    case State::kBlockAck: {
      if (cmd != 0xA2) break;
      const uint8_t ackseq = f.data[1];
      if (ackseq > seq_) return SendAbort(canopen::kAbortSequence, "ack beyond the segments sent");
      resent_ += seq_ - ackseq;
      uint32_t acked = uint32_t{ackseq} * 7u;
      if (sub_start_ + acked > size) acked = size - sub_start_;
      sub_start_ += acked;
      pos_ = sub_start_;
      if (progress_) progress_(pos_, size);
      blksize_ = f.data[2];
      if (blksize_ < 1 || blksize_ > 127) {
        return SendAbort(canopen::kAbortBlockSize, "server asked for an invalid block size");
      }
      seq_ = 0;
      if (sub_start_ >= size) {
        const uint32_t tail = size % 7;
        const uint32_t unused = tail == 0 ? 0 : 7 - tail;
        CanFrame e = Plain(static_cast<uint8_t>(0xC1 | (unused << 2)));
        StoreLe16(e.data + 1, canopen::Crc16Update(0, data_.data(), data_.size()));
        Queue(e);
        state_ = State::kBlockEnd;
      } else {
        state_ = State::kBlockSend;
      }
      return;
    }
    case State::kBlockEnd:
      if (cmd != 0xA1) break;
      return Finish(true, "ok");
    case State::kInitUpload: {
      if ((cmd & 0xE0) != 0x40) break;
      if ((cmd & 0x02) != 0) {  // expedited
        const uint32_t n = (cmd & 0x01) != 0 ? 4u - ((cmd >> 2) & 3u) : 4u;
        result_.data.assign(f.data + 4, f.data + 4 + n);
        return Finish(true, "ok");
      }
      upload_size_ = (cmd & 0x01) != 0 ? LoadLe32(f.data + 4) : 0;
      toggle_ = 0;
      state_ = State::kSegUpload;
      CanFrame r = Plain(0x60);
      Queue(r);
      return;
    }
    case State::kSegUpload: {
      if ((cmd & 0xE0) != 0 || ((cmd >> 4) & 1) != toggle_) break;
      const uint32_t n = 7u - ((cmd >> 1) & 7u);
      result_.data.insert(result_.data.end(), f.data + 1, f.data + 1 + n);
      if ((cmd & 0x01) != 0) return Finish(true, "ok");
      toggle_ = static_cast<uint8_t>(toggle_ ^ 1);
      CanFrame r = Plain(static_cast<uint8_t>(0x60 | (toggle_ << 4)));
      Queue(r);
      return;
    }
    case State::kBlockUpInit: {
      if ((cmd & 0xF9) != 0xC0) break;
      upload_size_ = (cmd & 0x02) != 0 ? LoadLe32(f.data + 4) : 0;
      up_last_seq_ = 0;
      up_last_ = false;
      up_block_.clear();
      CanFrame s = Plain(0xA3);
      Queue(s);
      state_ = State::kBlockUpRecv;
      return;
    }
    case State::kBlockUpRecv: {
      const uint8_t seq = cmd & 0x7F;
      const bool last = (cmd & 0x80) != 0;
      if (seq == up_last_seq_ + 1) {
        up_last_seq_ = seq;
        result_.data.insert(result_.data.end(), f.data + 1, f.data + 8);
        up_last_ = last;
      }
      if (seq == opt_.upload_block_size || last) {
        CanFrame a = Plain(0xA2);
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
      if ((cmd & 0xE3) != 0xC1) break;
      const uint32_t unused = (cmd >> 2) & 7u;
      if (unused <= result_.data.size()) result_.data.resize(result_.data.size() - unused);
      if (upload_size_ != 0 && result_.data.size() != upload_size_) {
        return SendAbort(canopen::kAbortTypeMismatch, "block upload size differs from announced");
      }
      if (LoadLe16(f.data + 1) !=
          canopen::Crc16Update(0, result_.data.data(), result_.data.size())) {
        return SendAbort(canopen::kAbortCrc, "block upload CRC mismatch");
      }
      CanFrame a = Plain(0xA1);
      Queue(a);
      return Finish(true, "ok");
    }
    case State::kDone:
      return;
  }
  SendAbort(canopen::kAbortCommand, "unexpected response " + Hex(cmd));
}

}  // namespace volcomp::canopen_client
