// CiA 301 node over one CAN channel with the pre-defined connection set: NMT slave, heartbeat and
// EMCY producers (inhibit time 0x1015 in 100 us units), error register and history, the SDO
// server, the transmit PDOs (0x1800+n / 0x1A00+n, tpdo.hpp; sampled by Poll() in NMT
// operational) and the receive PDOs (0x1400+n / 0x1600+n: their static mappings' objects, the
// command word or the temperatures, written to the application as an SDO write is, in NMT
// operational). The node answers the communication
// objects itself and passes every other object to the application's ObjectValues; frames out are
// drained with PopTx(). Single-threaded (main loop). States, objects, EMCY queueing and frame
// order: docs/canopen.md, "Node".
#pragma once

#include <cstdint>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/canopen/node_defaults.hpp"
#include "volcomp/canopen/object_values.hpp"
#include "volcomp/canopen/sdo_server.hpp"
#include "volcomp/canopen/tpdo.hpp"

namespace volcomp::canopen {

enum class NmtState : uint8_t {
  kInitialising = 0x00,
  kStopped = 0x04,
  kOperational = 0x05,
  kPreOperational = 0x7F,
};

/// NMT command specifiers (CiA 301 7.2.8.3.1): byte 0 of the NMT frame 0x000 [command, node-ID]
/// (node-ID 0: every node).
enum class NmtCommand : uint8_t {
  kStart = 0x01,  // to operational
  kStop = 0x02,   // to stopped (only NMT and heartbeat answered)
  kEnterPreOperational = 0x80,
  kResetNode = 0x81,           // the application restarts from its stored settings
  kResetCommunication = 0x82,  // the communication restarts from its stored parameters
};

enum class ResetRequest : uint8_t { kNone, kNode, kCommunication };

/// The communication parameters the node keeps (CiA 301 area 0x1000-0x1FFF that is writable).
struct CommunicationParameters {
  uint16_t heartbeat_ms = kDefaultHeartbeatMs;             // 0x1017 (0 = off)
  uint16_t emcy_inhibit_100us = kDefaultEmcyInhibit100us;  // 0x1015 (0 = no inhibit)
  /// 0x1800+n / 0x1A00+n, COB-IDs in stored form (board_settings.hpp PdoSettings: the bare
  /// pre-defined base 0x180 / 0x280 means base + node-ID).
  TpdoParameters tpdo[kTpdoCount] = {::volcomp::DefaultTpdo(0), ::volcomp::DefaultTpdo(1)};
  /// 0x1400+n:1-2 (the same stored COB-ID form, base RpdoCobBase(n)); the mappings are
  /// DefaultRpdo(n)'s.
  ::volcomp::PdoSettings rpdo[kRpdoCount] = {::volcomp::DefaultRpdo(0), ::volcomp::DefaultRpdo(1),
                                             ::volcomp::DefaultRpdo(2)};
};

/// The pre-defined CAN-ID base of TPDO n (CiA 301: 0x180, 0x280, 0x380, 0x480 + node-ID).
constexpr uint32_t TpdoCobBase(uint8_t n) { return 0x180u + 0x100u * n; }
/// The pre-defined CAN-ID base of RPDO n (CiA 301: 0x200, 0x300, 0x400 + node-ID).
constexpr uint32_t RpdoCobBase(uint8_t n) { return 0x200u + 0x100u * n; }

inline constexpr uint8_t kEmcyQueueLength = 8;
using ::volcomp::kRpdoCount;
using ::volcomp::kTpdoCount;

/// COB-IDs of the pre-defined connection set (EMCY and heartbeat: + node-ID; SDO:
/// sdo_protocol.hpp).
inline constexpr uint32_t kNmtCobId = 0x000;
inline constexpr uint32_t kEmcyCobBase = 0x080;
inline constexpr uint32_t kHeartbeatCobBase = 0x700;

/// Error register (0x1001) bits.
enum ErrorRegisterBit : uint8_t {
  kErrGeneric = 0x01,
  kErrCurrent = 0x02,
  kErrVoltage = 0x04,
  kErrTemperature = 0x08,
  kErrCommunication = 0x10,
  kErrDeviceProfile = 0x20,
  kErrManufacturer = 0x80,
};

class Node : private ObjectValues {
 public:
  /// Starts (or restarts after a reset node) with `node_id` (1..127) and the `stored`
  /// communication parameters in force: queues the boot-up message and enters pre-operational.
  /// `app` answers the non-communication objects. EMCYs raised before Start() go out after the
  /// boot-up message.
  void Start(uint8_t node_id,
             ObjectValues* app,
             uint32_t now_ms,
             const CommunicationParameters& stored = CommunicationParameters(),
             const SdoServerConfig& sdo = SdoServerConfig());
  /// NMT reset communication: the stored communication parameters back in force, the SDO server
  /// reset (a transfer in progress ends), boot-up, pre-operational.
  void ResetCommunication(uint32_t now_ms);

  void OnFrame(const CanFrame& frame, uint32_t now_ms);
  void Poll(uint32_t now_ms);
  bool PopTx(CanFrame* frame);

  /// Records an error: sets `register_bits` (plus the generic bit) in 0x1001, pushes `code` into
  /// the 0x1003 history and sends EMCY `code` with 5 manufacturer bytes (may be null).
  void RaiseError(uint16_t code, uint8_t register_bits, const uint8_t* manufacturer = nullptr);
  /// Clears the error register and sends the "error reset" EMCY (code 0x0000).
  void ClearErrors();
  /// Reports a one-off event that leaves no error standing (a refused request, a failed transfer
  /// or verification): RaiseError(code, register_bits) with `detail` little-endian in bytes 3..6
  /// and 0 in byte 7, then ClearErrors().
  void ReportEvent(uint16_t code, uint8_t register_bits, uint32_t detail);

  NmtState state() const { return state_; }
  uint8_t node_id() const { return node_id_; }
  uint8_t error_register() const { return error_register_; }
  /// A reset commanded over NMT, returned once; the application performs it: reset node
  /// restarts the application and calls Start(), reset communication calls ResetCommunication().
  ResetRequest TakeResetRequest() {
    const ResetRequest r = reset_;
    reset_ = ResetRequest::kNone;
    return r;
  }
  /// The communication parameters in force, and the stored ones (restored by the resets).
  const CommunicationParameters& communication() const { return comm_; }
  const CommunicationParameters& stored_communication() const { return stored_; }
  /// After the application stored the parameters (0x1010): they are what a reset restores.
  void set_stored_communication(const CommunicationParameters& c) { stored_ = c; }
  uint16_t heartbeat_ms() const { return comm_.heartbeat_ms; }
  /// Sets 0x1017 in force (as an SDO write does).
  void set_heartbeat_ms(uint16_t ms) { comm_.heartbeat_ms = ms; }
  const SdoServer& sdo() const { return sdo_; }
  /// EMCY frames handed to PopTx, and EMCYs replaced in a full queue (never sent).
  uint32_t emcy_sent() const { return emcy_sent_; }
  uint32_t emcy_suppressed() const { return emcy_suppressed_; }
  uint32_t malformed() const { return malformed_ + sdo_.malformed(); }
  /// RPDO frames (of every RPDO) written to the application (whatever it answered), and those not
  /// processed for their length (EMCY 0x8210 / 0x8220).
  uint32_t rpdo_received() const { return rpdo_received_; }
  /// RPDO n's COB-ID in force (0x1400+n:1 with the node-ID resolved; bit 31 set: no RPDO).
  uint32_t rpdo_cob_id(uint8_t n = 0) const { return RpdoCobId(n); }
  /// Whether `f` is on the COB-ID of one of the RPDOs in force (11-bit; a remote frame too).
  bool IsRpdo(const CanFrame& f) const { return RpdoOf(f) < kRpdoCount; }
  uint32_t rpdo_length_errors() const { return rpdo_length_errors_; }

 private:
  SdoAbort DoRead(const ObjectEntry& e,
                  uint32_t offset,
                  uint8_t* buf,
                  uint32_t cap,
                  uint32_t* copied,
                  uint32_t* total) override;
  SdoAbort DoWrite(const ObjectEntry& e, const uint8_t* data, uint32_t size) override;
  SdoAbort DoBeginDomainWrite(const ObjectEntry& e, uint32_t size) override;
  SdoAbort DoDomainWriteData(const uint8_t* data, uint32_t size) override;
  SdoAbort DoEndDomainWrite(SdoAbort outcome, AbortOrigin origin) override;
  uint32_t DoDomainWriteWindow() override;
  SdoAbort DoDomainWriteFlush(bool* done) override;
  bool ReadCommunication(const ObjectEntry& e, uint32_t* value) const;
  // 0x1800+n / 0x1A00+n writes (CiA 301 rules); false when `e` is no TPDO object.
  bool WriteTpdo(const ObjectEntry& e, uint32_t value, SdoAbort* result);
  // 0x1400+n:1-2 writes (the same rules as a TPDO's :1-2); false when `e` is no RPDO object.
  bool WriteRpdo(const ObjectEntry& e, uint32_t value, SdoAbort* result);
  uint32_t RpdoCobId(uint8_t n) const;
  // The RPDO whose COB-ID in force `f` (11-bit) is on, or kRpdoCount.
  uint8_t RpdoOf(const CanFrame& f) const;
  // A frame of RPDO n in operational: its mapped objects to the application.
  void OnRpdo(uint8_t n, const CanFrame& f);
  // TPDO n's parameters in force, its COB-ID resolved with the node-ID, to its engine.
  void ConfigureTpdo(uint8_t n);
  uint32_t TpdoCobId(uint8_t n) const;
  void Boot(uint32_t now_ms);
  void QueueUrgent(const CanFrame& f);
  void QueueEmcy(const CanFrame& f);
  bool PopEmcy(CanFrame* frame);

  uint8_t node_id_ = 1;
  ObjectValues* app_ = nullptr;
  SdoServerConfig sdo_config_;
  SdoServer sdo_;
  NmtState state_ = NmtState::kInitialising;
  ResetRequest reset_ = ResetRequest::kNone;
  CommunicationParameters stored_;
  CommunicationParameters comm_;
  uint32_t now_ms_ = 0;  // of the last Start / OnFrame / Poll (PopTx has no clock)
  uint32_t last_heartbeat_ms_ = 0;
  uint8_t error_register_ = 0;
  uint32_t history_[8] = {};
  uint8_t history_count_ = 0;
  CanFrame urgent_[4];  // boot-up, heartbeat
  uint8_t urgent_head_ = 0;
  uint8_t urgent_count_ = 0;
  CanFrame emcy_[kEmcyQueueLength];
  uint8_t emcy_head_ = 0;
  uint8_t emcy_count_ = 0;
  bool emcy_ever_sent_ = false;
  uint32_t last_emcy_ms_ = 0;
  uint32_t emcy_sent_ = 0;
  uint32_t emcy_suppressed_ = 0;
  uint32_t malformed_ = 0;
  uint32_t reported_aborts_ = 0;
  uint32_t rpdo_received_ = 0;
  uint32_t rpdo_length_errors_ = 0;
  Tpdo tpdo_[kTpdoCount];
  CanFrame pdo_tx_[kTpdoCount];  // a frame each TPDO has due, waiting for PopTx
  uint8_t pdo_waiting_ = 0;      // bit n: pdo_tx_[n] waits
};

}  // namespace volcomp::canopen
