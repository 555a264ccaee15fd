// Board settings: validation and the stored record.
#include "volcomp/config/board_settings.hpp"

#include "volcomp/base/byte_order.hpp"

namespace volcomp {
namespace {
constexpr uint32_t kMagic = 0x47464356;  // "VCFG"
// 2: the EMCY inhibit time in the slot after the heartbeat; 3: each axis's direction hysteresis
// in its reserved 16-bit slot; 4: each axis's direction switch acceleration in the first of its
// reserved 32-bit slots (older records: the defaults); 5: the TPDO parameters after the version-4
// record (kPdoRecordBytes each); 6: the RPDO's COB-ID and transmission type after them
// (kRpdoRecordBytes); 7: the temperature channels after them (kChannelRecordBytes each; the
// record grows to kSettingsBytesV7); 8: RPDO2 and RPDO3 after them (kRpdoRecordBytes each; the
// record grows to kSettingsBytes).
constexpr uint16_t kVersion = 8;
constexpr uint16_t kVersionWithoutRpdo23 = 7;
constexpr uint16_t kVersionWithoutChannels = 6;
constexpr uint16_t kVersionWithoutRpdo = 5;
constexpr uint16_t kVersionWithoutPdo = 4;
constexpr uint16_t kVersionWithoutSwitch = 3;
constexpr uint16_t kVersionWithoutHysteresis = 2;
constexpr uint16_t kVersionWithoutInhibit = 1;
static_assert(kVersionWithoutInhibit < kVersionWithoutHysteresis &&
                  kVersionWithoutHysteresis < kVersionWithoutSwitch &&
                  kVersionWithoutSwitch < kVersionWithoutPdo &&
                  kVersionWithoutPdo < kVersionWithoutRpdo &&
                  kVersionWithoutRpdo < kVersionWithoutChannels &&
                  kVersionWithoutChannels < kVersionWithoutRpdo23 &&
                  kVersionWithoutRpdo23 < kVersion,
              "versions in order: every one between the first and kVersion is read");

class Writer {
 public:
  explicit Writer(uint8_t* p) : p_(p) {}
  void U8(uint8_t v) { *p_++ = v; }
  void U16(uint16_t v) {
    StoreLe16(p_, v);
    p_ += 2;
  }
  void U32(uint32_t v) {
    StoreLe32(p_, v);
    p_ += 4;
  }
  void I16(int16_t v) { U16(static_cast<uint16_t>(v)); }
  void I32(int32_t v) { U32(static_cast<uint32_t>(v)); }

 private:
  uint8_t* p_;
};

class Reader {
 public:
  explicit Reader(const uint8_t* p) : p_(p) {}
  uint8_t U8() { return *p_++; }
  uint16_t U16() {
    const uint16_t v = LoadLe16(p_);
    p_ += 2;
    return v;
  }
  uint32_t U32() {
    const uint32_t v = LoadLe32(p_);
    p_ += 4;
    return v;
  }
  int16_t I16() { return static_cast<int16_t>(U16()); }
  int32_t I32() { return static_cast<int32_t>(U32()); }

 private:
  const uint8_t* p_;
};

// An RPDO's stored parameters (kRpdoRecordBytes): COB-ID, transmission type, 3 reserved.
void WriteRpdo(Writer& w, const PdoSettings& p) {
  w.U32(p.cob_id);
  w.U8(p.transmission_type);
  w.U8(0);
  w.U16(0);
}

// What 0x1400+n accepts (node.cpp): an 11-bit CAN-ID, an event-driven type.
bool ReadRpdo(Reader& r, PdoSettings* p) {
  p->cob_id = r.U32();
  p->transmission_type = r.U8();
  r.U8();
  r.U16();
  return (p->cob_id & 0x3FFFF800u) == 0 &&
         (p->transmission_type == 254 || p->transmission_type == 255);
}
}  // namespace

Status ValidateSettings(const BoardSettings& s, ConfigFinding* finding, OutputStage stage) {
  ConfigFinding f;
  if (s.node_id < 1 || s.node_id > 127) {
    f.rule = ConfigRule::kNodeId;
  } else if (s.bitrate_kbit < 10 || s.bitrate_kbit > 1000) {
    f.rule = ConfigRule::kBitrate;
  }
  if (f.rule == ConfigRule::kNone) {
    const Status b = stage == OutputStage::kStepPulses ? ValidateStepOutputConfig(s.board, &f)
                                                       : ValidateBoardConfig(s.board, &f);
    if (!b.ok()) {
      if (finding != nullptr) *finding = f;
      return b;
    }
    for (uint8_t ch = 0; ch < thermal::kMaxChannels; ++ch) {
      if (!thermal::ValidateChannelConfig(s.temperature[ch]).ok()) {
        f.rule = ConfigRule::kTemperatureChannel;
        f.axis = static_cast<uint8_t>(ch + 1);
        break;
      }
    }
  }
  if (finding != nullptr) *finding = f;
  return f.rule == ConfigRule::kNone ? Status::Ok() : Status(Error::kConfigInvalid);
}

void SerializeSettings(const BoardSettings& s, uint8_t* out) {
  for (uint32_t i = 0; i < kSettingsBytes; ++i) out[i] = 0;
  Writer w(out);
  w.U32(kMagic);
  w.U16(kVersion);
  w.U16(static_cast<uint16_t>(kSettingsBytes));
  w.U8(s.node_id);
  w.U8(s.board.axis_count);
  w.U16(s.bitrate_kbit);
  w.U16(s.heartbeat_ms);
  w.U16(s.emcy_inhibit_100us);
  w.U32(s.board.tick_hz);
  w.U32(s.board.pulse_clock_hz);
  for (uint32_t a = 0; a < table::kMaxAxes; ++a) {
    const AxisConfig& x = s.board.axis[a];
    w.U8(static_cast<uint8_t>(x.name));
    w.U8(static_cast<uint8_t>(x.kind));
    w.U8(static_cast<uint8_t>(x.input_format));
    w.U8(static_cast<uint8_t>(x.output_format));
    w.U8(x.invert_input_dir ? 1 : 0);
    w.U8(x.input_counter_bits);
    w.U16(x.direction_hysteresis_steps);
    w.U32(x.resolution_e9);
    w.U32(x.drive.pulse_width_ns);
    w.U32(x.drive.step_space_ns);
    w.U32(x.drive.dir_setup_ns);
    w.U32(x.drive.dir_hold_ns);
    w.U32(x.drive.max_rate_hz);
    w.U32(x.max_input_rate_hz);
    w.I32(x.max_correction_steps);
    w.U32(x.max_correction_rate_steps_s);
    w.U32(x.max_correction_accel_steps_s2);
    w.I32(x.home_position_steps);
    w.U32(x.direction_switch_accel_steps_s2);
    w.U32(0);
    w.U32(0);
  }
  w.U32(0);  // reserved (the version-4 record's last 8 bytes)
  w.U32(0);
  for (const PdoSettings& p : s.tpdo) {
    w.U32(p.cob_id);
    w.U8(p.transmission_type);
    w.U8(p.mapped);
    w.U16(p.inhibit_100us);
    w.U16(p.event_timer_ms);
    w.U16(0);
    for (uint32_t m : p.mapping) w.U32(m);
  }
  WriteRpdo(w, s.rpdo[0]);
  for (const thermal::ChannelConfig& c : s.temperature) {
    w.U8(static_cast<uint8_t>(c.source));
    w.U8(c.stuck_readings);
    w.U16(c.timeout_ms);
    w.I16(c.low_cC);
    w.I16(c.high_cC);
    w.U16(c.max_rate_cC_s);
    w.U16(0);
  }
  for (uint8_t n = 1; n < kRpdoCount; ++n) WriteRpdo(w, s.rpdo[n]);
}

Status DeserializeSettings(const uint8_t* in, uint32_t size, BoardSettings* out) {
  if (size < kSettingsBytesV4) return Error::kConfigInvalid;
  Reader r(in);
  if (r.U32() != kMagic) return Error::kConfigInvalid;
  const uint16_t version = r.U16();
  if (version < kVersionWithoutInhibit || version > kVersion) return Error::kConfigInvalid;
  const uint32_t bytes = version == kVersion                  ? kSettingsBytes
                         : version == kVersionWithoutRpdo23   ? kSettingsBytesV7
                         : version == kVersionWithoutChannels ? kSettingsBytesV6
                         : version == kVersionWithoutRpdo     ? kSettingsBytesV5
                                                              : kSettingsBytesV4;
  if (r.U16() != bytes || size < bytes) return Error::kConfigInvalid;
  BoardSettings s;
  s.node_id = r.U8();
  s.board.axis_count = r.U8();
  s.bitrate_kbit = r.U16();
  s.heartbeat_ms = r.U16();
  const uint16_t inhibit = r.U16();
  if (version != kVersionWithoutInhibit) s.emcy_inhibit_100us = inhibit;
  s.board.tick_hz = r.U32();
  s.board.pulse_clock_hz = r.U32();
  for (uint32_t a = 0; a < table::kMaxAxes; ++a) {
    AxisConfig& x = s.board.axis[a];
    x.name = static_cast<char>(r.U8());
    x.kind = static_cast<table::AxisKind>(r.U8());
    x.input_format = static_cast<PulseFormat>(r.U8());
    x.output_format = static_cast<PulseFormat>(r.U8());
    x.invert_input_dir = r.U8() != 0;
    x.input_counter_bits = r.U8();
    const uint16_t hysteresis = r.U16();
    if (version >= kVersionWithoutSwitch) x.direction_hysteresis_steps = hysteresis;
    x.resolution_e9 = r.U32();
    x.drive.pulse_width_ns = r.U32();
    x.drive.step_space_ns = r.U32();
    x.drive.dir_setup_ns = r.U32();
    x.drive.dir_hold_ns = r.U32();
    x.drive.max_rate_hz = r.U32();
    x.max_input_rate_hz = r.U32();
    x.max_correction_steps = r.I32();
    x.max_correction_rate_steps_s = r.U32();
    x.max_correction_accel_steps_s2 = r.U32();
    x.home_position_steps = r.I32();
    const uint32_t switch_accel = r.U32();
    if (version >= kVersionWithoutPdo) x.direction_switch_accel_steps_s2 = switch_accel;
    r.U32();
    r.U32();
  }
  r.U32();
  r.U32();
  if (version >= kVersionWithoutRpdo) {
    for (PdoSettings& p : s.tpdo) {
      p.cob_id = r.U32();
      p.transmission_type = r.U8();
      p.mapped = r.U8();
      p.inhibit_100us = r.U16();
      p.event_timer_ms = r.U16();
      r.U16();
      for (uint32_t& m : p.mapping) m = r.U32();
      if (p.mapped > kPdoMaxMapped) return Error::kConfigInvalid;
    }
  }
  if (version >= kVersionWithoutChannels && !ReadRpdo(r, &s.rpdo[0])) {
    return Error::kConfigInvalid;
  }
  if (version >= kVersionWithoutRpdo23) {
    for (thermal::ChannelConfig& c : s.temperature) {
      c.source = static_cast<thermal::ChannelSource>(r.U8());
      c.stuck_readings = r.U8();
      c.timeout_ms = r.U16();
      c.low_cC = r.I16();
      c.high_cC = r.I16();
      c.max_rate_cC_s = r.U16();
      r.U16();
    }
  }
  if (version == kVersion) {
    for (uint8_t n = 1; n < kRpdoCount; ++n) {
      if (!ReadRpdo(r, &s.rpdo[n])) return Error::kConfigInvalid;
    }
  }
  VOLCOMP_TRY(ValidateSettings(s));
  *out = s;
  return Status::Ok();
}

}  // namespace volcomp
