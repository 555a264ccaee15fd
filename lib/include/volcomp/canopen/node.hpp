// CiA 301 node: NMT slave (boot-up, pre-operational / operational / stopped, resets), heartbeat
// producer (0x1017), EMCY producer with error register (0x1001) and error history (0x1003), and
// the SDO server, over one CAN channel with the pre-defined connection set (COB-IDs from the
// node-ID: NMT 0x000, EMCY 0x080+id, SDO 0x600+id / 0x580+id, heartbeat 0x700+id).
//
// The node answers the communication objects itself (0x1001, 0x1003, 0x1014, 0x1017, 0x1200) and
// passes every other object to the application's ObjectValues. Frames out are drained with
// PopTx() (boot-up, EMCY and heartbeat before SDO traffic). Single-threaded (main loop).
#pragma once

#include <cstdint>

#include "volcomp/can_frame.hpp"
#include "volcomp/canopen/node_defaults.hpp"
#include "volcomp/canopen/object_values.hpp"
#include "volcomp/canopen/sdo_server.hpp"

namespace volcomp::canopen {

enum class NmtState : uint8_t {
  kInitialising = 0x00,
  kStopped = 0x04,
  kOperational = 0x05,
  kPreOperational = 0x7F,
};

enum class ResetRequest : uint8_t { kNone, kNode, kCommunication };

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
  /// Starts (or restarts after a reset) with `node_id` (1..127): queues the boot-up message and
  /// enters pre-operational. `app` answers the non-communication objects.
  void Start(uint8_t node_id,
             ObjectValues* app,
             uint32_t now_ms,
             const SdoServerConfig& sdo = SdoServerConfig());

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
  /// A reset commanded over NMT, returned once; the application performs it and calls Start().
  ResetRequest TakeResetRequest() {
    const ResetRequest r = reset_;
    reset_ = ResetRequest::kNone;
    return r;
  }
  uint16_t heartbeat_ms() const { return heartbeat_ms_; }
  void set_heartbeat_ms(uint16_t ms) { heartbeat_ms_ = ms; }
  const SdoServer& sdo() const { return sdo_; }
  uint32_t emcy_sent() const { return emcy_sent_; }
  uint32_t malformed() const { return malformed_ + sdo_.malformed(); }

 private:
  uint32_t DoRead(const ObjectEntry& e,
                  uint32_t offset,
                  uint8_t* buf,
                  uint32_t cap,
                  uint32_t* copied,
                  uint32_t* total) override;
  uint32_t DoWrite(const ObjectEntry& e, const uint8_t* data, uint32_t size) override;
  uint32_t DoBeginDomainWrite(const ObjectEntry& e, uint32_t size) override;
  uint32_t DoDomainWriteData(const uint8_t* data, uint32_t size) override;
  uint32_t DoEndDomainWrite(bool complete) override;
  bool ReadCommunication(const ObjectEntry& e, uint32_t* value) const;
  void QueueUrgent(const CanFrame& f);

  uint8_t node_id_ = 1;
  ObjectValues* app_ = nullptr;
  SdoServer sdo_;
  NmtState state_ = NmtState::kInitialising;
  ResetRequest reset_ = ResetRequest::kNone;
  uint16_t heartbeat_ms_ = kDefaultHeartbeatMs;
  uint32_t last_heartbeat_ms_ = 0;
  uint8_t error_register_ = 0;
  uint32_t history_[8] = {};
  uint8_t history_count_ = 0;
  CanFrame urgent_[8];  // boot-up, EMCY, heartbeat
  uint8_t urgent_head_ = 0;
  uint8_t urgent_count_ = 0;
  uint32_t emcy_sent_ = 0;
  uint32_t malformed_ = 0;
  uint32_t reported_aborts_ = 0;
};

}  // namespace volcomp::canopen
