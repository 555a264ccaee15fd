// CiA 301 node: NMT, heartbeat, EMCY, communication objects, SDO routing.
#include "volcomp/canopen/node.hpp"

#include "volcomp/base/byte_order.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen/sdo_protocol.hpp"

namespace volcomp::canopen {

namespace {

constexpr uint8_t kUrgentLength = 4;

// The EMCY gap on the millisecond clock: 0x1015 rounded up to whole milliseconds, plus one for
// the clock's own resolution (two readings 1 ms apart may be only just over 0 ms apart).
uint32_t EmcyGapMs(uint16_t inhibit_100us) {
  return inhibit_100us == 0 ? 0u : (inhibit_100us + 9u) / 10u + 1u;
}

// The stored COB-ID form (board_settings.hpp PdoSettings): the bare base means base + node-ID.
uint32_t ResolvedCobId(uint32_t stored, uint32_t base, uint8_t node_id) {
  return (stored & 0x7FFu) == base ? stored + node_id : stored;
}

// CiA 301's rule for a write of a PDO's COB-ID (:1) given the one in force (`resolved`, whose
// bit 31 says whether the PDO exists): only bit 31 changes while the PDO exists; 11-bit CAN-IDs
// only (bits 29..11 clear), none of the restricted ones (0x000-0x07F, 0x101-0x180, 0x581-0x5FF,
// 0x601-0x67F, 0x6E0-0x7FF) and not the bare pre-defined base (its stored form). The value to
// store in *stored.
bool AcceptCobId(uint32_t v, uint32_t resolved, uint32_t base, uint8_t node_id, uint32_t* stored) {
  const uint32_t id = v & 0x7FFu;
  const bool restricted = id <= 0x07F || (id >= 0x101 && id <= 0x180) ||
                          (id >= 0x581 && id <= 0x5FF) || (id >= 0x601 && id <= 0x67F) ||
                          id >= 0x6E0 || id == base;
  if ((v & 0x3FFFF800u) != 0 || restricted) return false;
  const bool valid = (resolved & kPdoCobIdInvalid) == 0;
  if (valid && (v & ~kPdoCobIdInvalid) != (resolved & ~kPdoCobIdInvalid)) return false;
  *stored = id == base + node_id ? (v & ~0x7FFu) | base : v;
  return true;
}

// The transmission types the node offers (it has no SYNC consumer): event-driven only.
bool EventDriven(uint32_t type) {
  return type == kPdoEventDrivenManufacturer || type == kPdoEventDrivenProfile;
}

}  // namespace

void Node::Start(uint8_t node_id,
                 ObjectValues* app,
                 uint32_t now_ms,
                 const CommunicationParameters& stored,
                 const SdoServerConfig& sdo) {
  node_id_ = node_id;
  app_ = app;
  stored_ = stored;
  sdo_config_ = sdo;
  Boot(now_ms);
}

void Node::ResetCommunication(uint32_t now_ms) { Boot(now_ms); }

void Node::Boot(uint32_t now_ms) {
  comm_ = stored_;
  for (uint8_t n = 0; n < kTpdoCount; ++n) ConfigureTpdo(n);
  pdo_waiting_ = 0;
  sdo_.Init(node_id_, this, sdo_config_);
  reported_aborts_ = 0;
  urgent_count_ = 0;
  reset_ = ResetRequest::kNone;
  CanFrame boot;
  boot.id = kHeartbeatCobBase + node_id_;
  boot.dlc = 1;
  boot.data[0] = 0x00;
  QueueUrgent(boot);
  state_ = NmtState::kPreOperational;
  now_ms_ = now_ms;
  last_heartbeat_ms_ = now_ms;
}

void Node::QueueUrgent(const CanFrame& f) {
  if (urgent_count_ == kUrgentLength) {  // drop the oldest heartbeat rather than block
    urgent_head_ = static_cast<uint8_t>((urgent_head_ + 1) % kUrgentLength);
    --urgent_count_;
  }
  urgent_[(urgent_head_ + urgent_count_) % kUrgentLength] = f;
  ++urgent_count_;
}

void Node::QueueEmcy(const CanFrame& e) {
  if (emcy_count_ == kEmcyQueueLength) {
    // Full: the newest waiting EMCY gives way to this one, so the last EMCY sent still tells
    // the current state.
    emcy_[(emcy_head_ + emcy_count_ - 1) % kEmcyQueueLength] = e;
    ++emcy_suppressed_;
    return;
  }
  emcy_[(emcy_head_ + emcy_count_) % kEmcyQueueLength] = e;
  ++emcy_count_;
}

bool Node::PopEmcy(CanFrame* frame) {
  // Not before the boot-up message, not while stopped (CiA 301: only NMT and heartbeat).
  if (emcy_count_ == 0 || state_ == NmtState::kInitialising || state_ == NmtState::kStopped) {
    return false;
  }
  if (emcy_ever_sent_ &&
      static_cast<uint32_t>(now_ms_ - last_emcy_ms_) < EmcyGapMs(comm_.emcy_inhibit_100us)) {
    return false;
  }
  *frame = emcy_[emcy_head_];
  frame->id = kEmcyCobBase + node_id_;  // the node-ID in force when it leaves
  emcy_head_ = static_cast<uint8_t>((emcy_head_ + 1) % kEmcyQueueLength);
  --emcy_count_;
  emcy_ever_sent_ = true;
  last_emcy_ms_ = now_ms_;
  ++emcy_sent_;
  return true;
}

void Node::OnFrame(const CanFrame& f, uint32_t now_ms) {
  now_ms_ = now_ms;
  if (f.extended) return;
  if (f.id == kNmtCobId) {
    if (f.rtr || f.dlc != 2) {
      ++malformed_;
      return;
    }
    if (f.data[1] != 0 && f.data[1] != node_id_) return;
    switch (static_cast<NmtCommand>(f.data[0])) {
      case NmtCommand::kStart:
        // Entering operational: each TPDO sends its state at once (they are polled only while
        // operational).
        if (state_ != NmtState::kOperational) {
          for (Tpdo& t : tpdo_) t.Restart();
        }
        state_ = NmtState::kOperational;
        break;
      case NmtCommand::kStop:
        state_ = NmtState::kStopped;
        break;
      case NmtCommand::kEnterPreOperational:
        state_ = NmtState::kPreOperational;
        break;
      case NmtCommand::kResetNode:
        reset_ = ResetRequest::kNode;
        break;
      case NmtCommand::kResetCommunication:
        reset_ = ResetRequest::kCommunication;
        break;
      default:
        ++malformed_;
        break;
    }
    return;
  }
  if (f.id == sdo::kRequestCobBase + node_id_ && state_ != NmtState::kStopped) {
    sdo_.OnFrame(f, now_ms);
    return;
  }
  // The RPDOs: only in operational, while they exist; a remote request for one is not served.
  if (state_ == NmtState::kOperational && !f.rtr) {
    const uint8_t n = RpdoOf(f);
    if (n < kRpdoCount) OnRpdo(n, f);
  }
}

void Node::Poll(uint32_t now_ms) {
  now_ms_ = now_ms;
  if (state_ != NmtState::kStopped) sdo_.Poll(now_ms);
  // Report the transfers this node found broken (protocol aborts it sent: toggle, timeout,
  // sequence, CRC, ...) by EMCY; the application reports the requests it refuses itself. A
  // client's abort is no error of this node, whatever its code: it is not reported.
  if (sdo_.aborts() != reported_aborts_) {
    reported_aborts_ = sdo_.aborts();
    const SdoAbort code = sdo_.last_abort();
    if (IsProtocolAbort(code) && sdo_.last_abort_origin() == AbortOrigin::kServer) {
      ReportEvent(kEmcySdoTransferFailed, kErrCommunication, Code(code));
    }
  }
  // The TPDOs, only while operational (main loop: the values they sample are the main loop's).
  // A frame still waiting for PopTx is replaced by the newer one of the same PDO (its latest
  // state goes out).
  if (state_ == NmtState::kOperational) {
    for (uint8_t n = 0; n < kTpdoCount; ++n) {
      if (tpdo_[n].Poll(*this, true, now_ms, &pdo_tx_[n])) {
        pdo_waiting_ = static_cast<uint8_t>(pdo_waiting_ | 1u << n);
      }
    }
  }
  const uint16_t heartbeat_ms = comm_.heartbeat_ms;
  if (heartbeat_ms != 0 && static_cast<uint32_t>(now_ms - last_heartbeat_ms_) >= heartbeat_ms) {
    last_heartbeat_ms_ = now_ms;
    CanFrame hb;
    hb.id = kHeartbeatCobBase + node_id_;
    hb.dlc = 1;
    hb.data[0] = static_cast<uint8_t>(state_);
    QueueUrgent(hb);
  }
}

bool Node::PopTx(CanFrame* frame) {
  if (urgent_count_ > 0) {
    *frame = urgent_[urgent_head_];
    urgent_head_ = static_cast<uint8_t>((urgent_head_ + 1) % kUrgentLength);
    --urgent_count_;
    return true;
  }
  if (PopEmcy(frame)) return true;
  if (pdo_waiting_ != 0) {
    if (state_ != NmtState::kOperational) {
      pdo_waiting_ = 0;  // left operational since they were due
    } else {
      const uint8_t n = (pdo_waiting_ & 1u) != 0 ? 0 : 1;
      static_assert(kTpdoCount == 2, "one bit per TPDO");
      pdo_waiting_ = static_cast<uint8_t>(pdo_waiting_ & ~(1u << n));
      *frame = pdo_tx_[n];
      return true;
    }
  }
  return state_ != NmtState::kStopped && sdo_.PopTx(frame);
}

void Node::RaiseError(uint16_t code, uint8_t register_bits, const uint8_t* manufacturer) {
  error_register_ = static_cast<uint8_t>(error_register_ | register_bits | kErrGeneric);
  for (int i = 7; i > 0; --i) history_[i] = history_[i - 1];
  history_[0] = code;
  if (history_count_ < 8) ++history_count_;
  if (state_ == NmtState::kStopped) return;  // EMCY is not sent while stopped
  Emcy e;
  e.code = code;
  e.error_register = error_register_;
  for (int i = 0; i < 5; ++i) e.data[i] = manufacturer != nullptr ? manufacturer[i] : 0;
  QueueEmcy(EncodeEmcy(node_id_, e));
}

void Node::ClearErrors() {
  if (error_register_ == 0) return;
  error_register_ = 0;
  if (state_ == NmtState::kStopped) return;
  Emcy reset;
  reset.code = kEmcyErrorReset;
  QueueEmcy(EncodeEmcy(node_id_, reset));
}

void Node::ReportEvent(uint16_t code, uint8_t register_bits, uint32_t detail) {
  uint8_t m[5];
  StoreLe32(m, detail);
  m[4] = 0;
  RaiseError(code, register_bits, m);
  ClearErrors();
}

uint32_t Node::TpdoCobId(uint8_t n) const {
  return ResolvedCobId(comm_.tpdo[n].cob_id, TpdoCobBase(n), node_id_);
}

uint32_t Node::RpdoCobId(uint8_t n) const {
  return ResolvedCobId(comm_.rpdo[n].cob_id, RpdoCobBase(n), node_id_);
}

uint8_t Node::RpdoOf(const CanFrame& f) const {
  if (f.extended) return kRpdoCount;
  uint8_t n = 0;
  while (n < kRpdoCount && RpdoCobId(n) != f.id) ++n;  // bit 31 set never matches an 11-bit ID
  return n;
}

void Node::ConfigureTpdo(uint8_t n) {
  TpdoParameters p = comm_.tpdo[n];
  p.cob_id = TpdoCobId(n);
  tpdo_[n].Configure(p);
}

bool Node::WriteTpdo(const ObjectEntry& e, uint32_t v, SdoAbort* result) {
  const bool comm = e.index >= 0x1800 && e.index < 0x1800 + kTpdoCount;
  const bool map = e.index >= 0x1A00 && e.index < 0x1A00 + kTpdoCount;
  if (!comm && !map) return false;
  const uint8_t n = static_cast<uint8_t>(e.index & 0xFFu);
  TpdoParameters& p = comm_.tpdo[n];
  const bool valid = (p.cob_id & kPdoCobIdInvalid) == 0;
  *result = SdoAbort::kNone;
  TpdoParameters next = p;
  if (comm) {
    switch (e.sub) {
      case 1:
        if (!AcceptCobId(v, TpdoCobId(n), TpdoCobBase(n), node_id_, &next.cob_id)) {
          *result = SdoAbort::kInvalidValue;
          return true;
        }
        break;
      case 2:
        if (!EventDriven(v) || (valid && v != p.transmission_type)) {
          *result = SdoAbort::kInvalidValue;
          return true;
        }
        next.transmission_type = static_cast<uint8_t>(v);
        break;
      case 3:
        if (valid && v != p.inhibit_100us) {
          *result = SdoAbort::kInvalidValue;
          return true;
        }
        next.inhibit_100us = static_cast<uint16_t>(v);
        break;
      case 5:
        next.event_timer_ms = static_cast<uint16_t>(v);
        break;
      default:
        *result = SdoAbort::kReadOnly;
        return true;
    }
  } else if (e.sub == 0) {
    if (valid) {
      *result = SdoAbort::kDeviceState;  // CiA 301: the mapping changes only while invalid
      return true;
    }
    next.mapped = static_cast<uint8_t>(v);
    *result = CheckTpdoMapping(next);
    if (*result != SdoAbort::kNone) return true;
  } else {
    if (valid || p.mapped != 0) {
      *result = SdoAbort::kDeviceState;  // CiA 301: entries only with sub 0 = 0
      return true;
    }
    next.mapping[e.sub - 1] = v;
  }
  p = next;
  ConfigureTpdo(n);
  return true;
}

bool Node::WriteRpdo(const ObjectEntry& e, uint32_t v, SdoAbort* result) {
  if (e.index < 0x1400 || e.index >= 0x1400 + kRpdoCount) return false;
  const uint8_t n = static_cast<uint8_t>(e.index & 0xFFu);
  ::volcomp::PdoSettings& p = comm_.rpdo[n];
  const bool valid = (p.cob_id & kPdoCobIdInvalid) == 0;
  *result = SdoAbort::kNone;
  if (e.sub == 1) {
    uint32_t stored = 0;
    if (!AcceptCobId(v, RpdoCobId(n), RpdoCobBase(n), node_id_, &stored)) {
      *result = SdoAbort::kInvalidValue;
    } else {
      p.cob_id = stored;
    }
  } else if (e.sub == 2) {
    if (!EventDriven(v) || (valid && v != p.transmission_type)) {
      *result = SdoAbort::kInvalidValue;
    } else {
      p.transmission_type = static_cast<uint8_t>(v);
    }
  } else {
    *result = SdoAbort::kReadOnly;
  }
  return true;
}

void Node::OnRpdo(uint8_t n, const CanFrame& f) {
  // The static mappings (DefaultRpdo): RPDO1 the command word (2 bytes), RPDO2 / RPDO3 four
  // temperatures (I16 each, 8 bytes). CiA 301: a frame of another length is not processed (EMCY
  // 0x8210 shorter, 0x8220 longer; byte 3 = its DLC).
  const uint8_t mapped_bytes = n == 0 ? 2 : 2 * ::volcomp::kRpdoTemperatureChannels;
  if (f.dlc != mapped_bytes) {
    ++rpdo_length_errors_;
    ReportEvent(f.dlc < mapped_bytes ? kEmcyPdoLength : kEmcyPdoLengthExceeded, kErrCommunication,
                f.dlc);
    return;
  }
  ++rpdo_received_;
  // The application checks and reports a refusal (EMCY) of each object as it does for an SDO
  // write of it; there is no one to answer.
  if (n == 0) {
    (void)app_->Write(Entry(ObjectId::kCommandWord), f.data, 2);
    return;
  }
  const uint32_t first = static_cast<uint32_t>(ObjectId::kTemperature1) +
                         (n - 1u) * ::volcomp::kRpdoTemperatureChannels;
  for (uint32_t k = 0; k < ::volcomp::kRpdoTemperatureChannels; ++k) {
    (void)app_->Write(Entry(static_cast<ObjectId>(first + k)), f.data + 2 * k, 2);
  }
}

bool Node::ReadCommunication(const ObjectEntry& e, uint32_t* value) const {
  if (e.index >= 0x1400 && e.index < 0x1400 + kRpdoCount && (e.sub == 1 || e.sub == 2)) {
    const uint8_t n = static_cast<uint8_t>(e.index & 0xFFu);
    *value = e.sub == 1 ? RpdoCobId(n) : comm_.rpdo[n].transmission_type;
    return true;
  }
  if (e.index >= 0x1800 && e.index < 0x1800 + kTpdoCount && e.sub != 0) {
    const uint8_t n = static_cast<uint8_t>(e.index & 0xFFu);
    const TpdoParameters& p = comm_.tpdo[n];
    *value = e.sub == 1   ? TpdoCobId(n)
             : e.sub == 2 ? p.transmission_type
             : e.sub == 3 ? p.inhibit_100us
                          : p.event_timer_ms;
    return true;
  }
  if (e.index >= 0x1A00 && e.index < 0x1A00 + kTpdoCount) {
    const TpdoParameters& p = comm_.tpdo[e.index & 0xFFu];
    *value = e.sub == 0 ? p.mapped : p.mapping[e.sub - 1];
    return true;
  }
  switch (e.id) {
    case ObjectId::kErrorRegister:
      *value = error_register_;
      return true;
    case ObjectId::kErrorCount:
      *value = history_count_;
      return true;
    case ObjectId::kCobIdEmcy:
      *value = kEmcyCobBase + node_id_;
      return true;
    case ObjectId::kEmcyInhibitTime:
      *value = comm_.emcy_inhibit_100us;
      return true;
    case ObjectId::kHeartbeatTime:
      *value = comm_.heartbeat_ms;
      return true;
    case ObjectId::kSdoCobIdRx:
      *value = sdo::kRequestCobBase + node_id_;
      return true;
    case ObjectId::kSdoCobIdTx:
      *value = sdo::kResponseCobBase + node_id_;
      return true;
    default:
      if (e.index == 0x1003 && e.sub >= 1 && e.sub <= 8) {
        *value = e.sub <= history_count_ ? history_[e.sub - 1] : 0;
        return true;
      }
      return false;
  }
}

SdoAbort Node::DoRead(const ObjectEntry& e,
                      uint32_t offset,
                      uint8_t* buf,
                      uint32_t cap,
                      uint32_t* copied,
                      uint32_t* total) {
  uint32_t value = 0;
  if (!ReadCommunication(e, &value)) return app_->Read(e, offset, buf, cap, copied, total);
  uint8_t bytes[4];
  StoreLe32(bytes, value);
  *total = FixedSize(e.type);
  *copied = 0;
  for (uint32_t i = offset; i < *total && *copied < cap; ++i) buf[(*copied)++] = bytes[i];
  return SdoAbort::kNone;
}

SdoAbort Node::DoWrite(const ObjectEntry& e, const uint8_t* data, uint32_t size) {
  uint32_t v = 0;
  for (uint32_t i = 0; i < size && i < 4; ++i) v |= uint32_t{data[i]} << (8 * i);
  SdoAbort pdo = SdoAbort::kNone;
  if (WriteTpdo(e, v, &pdo) || WriteRpdo(e, v, &pdo)) return pdo;
  switch (e.id) {
    case ObjectId::kErrorCount:
      if (size != 1 || data[0] != 0) return SdoAbort::kInvalidValue;  // only 0 (clear) allowed
      history_count_ = 0;
      return SdoAbort::kNone;
    case ObjectId::kEmcyInhibitTime:
      comm_.emcy_inhibit_100us = LoadLe16(data);
      return SdoAbort::kNone;
    case ObjectId::kHeartbeatTime:
      comm_.heartbeat_ms = LoadLe16(data);
      return SdoAbort::kNone;
    default:
      return app_->Write(e, data, size);
  }
}

SdoAbort Node::DoBeginDomainWrite(const ObjectEntry& e, uint32_t size) {
  return app_->BeginDomainWrite(e, size);
}
SdoAbort Node::DoDomainWriteData(const uint8_t* data, uint32_t size) {
  return app_->DomainWriteData(data, size);
}
SdoAbort Node::DoEndDomainWrite(SdoAbort outcome, AbortOrigin origin) {
  return app_->EndDomainWrite(outcome, origin);
}
// The application's pacing of a domain download (how much it takes between flushes, and its
// flush steps), so the server sizes sub-blocks and holds acknowledgements as it asks.
uint32_t Node::DoDomainWriteWindow() { return app_->DomainWriteWindow(); }
SdoAbort Node::DoDomainWriteFlush(bool* done) { return app_->DomainWriteFlush(done); }

}  // namespace volcomp::canopen
