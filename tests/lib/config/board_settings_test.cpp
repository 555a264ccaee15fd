// The board's settings (lib/config board_settings.hpp): the stored record (layout, versions, round
// trip of every field) and the node settings' rules.
#include "volcomp/config/board_settings.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace volcomp {
namespace {

// A record of version 4 or older is kSettingsBytesV4 long (its size LE16 at 6): what such a board
// stored, before the PDO parameters.
void OldSize(uint8_t* rec) {
  rec[6] = static_cast<uint8_t>(kSettingsBytesV4 & 0xFF);
  rec[7] = static_cast<uint8_t>(kSettingsBytesV4 >> 8);
}

// The settings record keeps 0x1015 in the slot after the heartbeat time (record version 2); a
// version-1 record (that slot reserved, 0) gives the default inhibit time, not 0.
TEST(SettingsRecord, KeepsTheEmcyInhibitTimeAndReadsVersion1Records) {
  BoardSettings s;
  s.heartbeat_ms = 0x0123;
  s.emcy_inhibit_100us = 37;
  uint8_t rec[kSettingsBytes];
  SerializeSettings(s, rec);
  EXPECT_EQ(rec[4], 8);  // version, LE16 at 4
  EXPECT_EQ(rec[5], 0);
  EXPECT_EQ(rec[12], 0x23);  // heartbeat LE16 at 12
  EXPECT_EQ(rec[13], 0x01);
  EXPECT_EQ(rec[14], 37);  // inhibit LE16 at 14
  EXPECT_EQ(rec[15], 0);
  BoardSettings back;
  ASSERT_TRUE(DeserializeSettings(rec, sizeof rec, &back).ok());
  EXPECT_EQ(back.emcy_inhibit_100us, 37);
  rec[4] = 1;
  OldSize(rec);
  rec[14] = 0;
  ASSERT_TRUE(DeserializeSettings(rec, sizeof rec, &back).ok());
  EXPECT_EQ(back.emcy_inhibit_100us, 100);  // the default, 10 ms
  EXPECT_EQ(back.heartbeat_ms, 0x0123);
  rec[4] = 9;  // a version from the future
  EXPECT_FALSE(DeserializeSettings(rec, sizeof rec, &back).ok());
}

// Version 3 keeps each axis's direction hysteresis in the 16-bit slot after the input counter
// width (axis records of 64 bytes from offset 24); a version-2 record (slot reserved, 0) gives
// the default of 1 step, not 0.
TEST(SettingsRecord, KeepsTheDirectionHysteresisAndReadsVersion2Records) {
  BoardSettings s;
  s.board.axis[1].direction_hysteresis_steps = 0x0203;
  uint8_t rec[kSettingsBytes];
  SerializeSettings(s, rec);
  EXPECT_EQ(rec[24 + 64 + 6], 0x03);
  EXPECT_EQ(rec[24 + 64 + 7], 0x02);
  BoardSettings back;
  ASSERT_TRUE(DeserializeSettings(rec, sizeof rec, &back).ok());
  EXPECT_EQ(back.board.axis[1].direction_hysteresis_steps, 0x0203);
  rec[4] = 2;
  OldSize(rec);
  rec[24 + 64 + 6] = rec[24 + 64 + 7] = 0;
  ASSERT_TRUE(DeserializeSettings(rec, sizeof rec, &back).ok());
  EXPECT_EQ(back.board.axis[1].direction_hysteresis_steps, 1);
}

// Version 4 keeps each axis's direction switch acceleration in the first reserved 32-bit slot
// after the home position (offset 52 of the axis record); a version-3 record (slot reserved, 0)
// gives the default, not 0 (which the rules would refuse).
TEST(SettingsRecord, KeepsTheDirectionSwitchAccelerationAndReadsVersion3Records) {
  BoardSettings s;
  s.board.axis[2].direction_switch_accel_steps_s2 = 0x01020304;
  uint8_t rec[kSettingsBytes];
  SerializeSettings(s, rec);
  const size_t at = 24 + 2 * 64 + 52;
  EXPECT_EQ(rec[at], 0x04);
  EXPECT_EQ(rec[at + 3], 0x01);
  BoardSettings back;
  ASSERT_TRUE(DeserializeSettings(rec, sizeof rec, &back).ok());
  EXPECT_EQ(back.board.axis[2].direction_switch_accel_steps_s2, 0x01020304u);
  EXPECT_EQ(back.board.axis[2].direction_hysteresis_steps, 1);
  rec[4] = 3;
  OldSize(rec);
  rec[at] = rec[at + 1] = rec[at + 2] = rec[at + 3] = 0;
  ASSERT_TRUE(DeserializeSettings(rec, sizeof rec, &back).ok());
  EXPECT_EQ(back.board.axis[2].direction_switch_accel_steps_s2,
            AxisConfig().direction_switch_accel_steps_s2);
}

// The direction switch is never slower than the correction: its acceleration below the
// correction's is refused, and its limiter takes the rate the drive has left beyond the input.
TEST(SettingsRules, DirectionSwitchAccelerationAtLeastTheCorrections) {
  BoardSettings s;
  ConfigFinding f;
  ASSERT_TRUE(ValidateSettings(s, &f).ok());
  s.board.axis[0].direction_switch_accel_steps_s2 =
      s.board.axis[0].max_correction_accel_steps_s2 - 1;
  EXPECT_FALSE(ValidateSettings(s, &f).ok());
  EXPECT_EQ(f.rule, ConfigRule::kDirectionSwitch);
  EXPECT_EQ(f.axis, 1);
  s.board.axis[0].direction_switch_accel_steps_s2 = s.board.axis[0].max_correction_accel_steps_s2;
  EXPECT_TRUE(ValidateSettings(s, &f).ok());
}

// Pulse timing against the drive rate, on a board with step outputs only: 2500 + 2500 ns a step
// send 1e9 / 5000 = 200 000 steps/s; a drive rate one above is refused (kPulseTiming, its axis),
// the rules every board keeps (the gateway's) do not ask it; a quadrature output sends edges, no
// pulses, and zero times set no bound.
TEST(SettingsRules, PulseTimingMustAllowTheDriveRateOnAStepBoard) {
  BoardSettings s;
  AxisConfig& y = s.board.axis[1];
  y.drive.pulse_width_ns = 2500;
  y.drive.step_space_ns = 2500;
  y.max_input_rate_hz = 190000;
  y.drive.max_rate_hz = 200000;
  EXPECT_EQ(PulseTimingRateHz(y), 200000u);
  ConfigFinding f;
  EXPECT_TRUE(ValidateSettings(s, &f, OutputStage::kStepPulses).ok());
  y.drive.max_rate_hz = 200001;
  EXPECT_FALSE(ValidateSettings(s, &f, OutputStage::kStepPulses).ok());
  EXPECT_EQ(f.rule, ConfigRule::kPulseTiming);
  EXPECT_EQ(f.axis, 2);
  EXPECT_TRUE(ValidateSettings(s, &f, OutputStage::kCanSetpoints).ok());
  EXPECT_EQ(f.rule, ConfigRule::kNone);
  EXPECT_TRUE(ValidateSettings(s, &f).ok());
  // A rule every board keeps comes first (here the drive cannot follow input + correction).
  y.max_input_rate_hz = 199000;
  EXPECT_FALSE(ValidateSettings(s, &f, OutputStage::kStepPulses).ok());
  EXPECT_EQ(f.rule, ConfigRule::kDriveKeepsUp);
  y.max_input_rate_hz = 190000;
  y.output_format = PulseFormat::kQuadrature;
  EXPECT_EQ(PulseTimingRateHz(y), 0u);
  EXPECT_TRUE(ValidateSettings(s, &f, OutputStage::kStepPulses).ok());
  y.output_format = PulseFormat::kCwCcw;
  y.drive.pulse_width_ns = y.drive.step_space_ns = 0;
  EXPECT_EQ(PulseTimingRateHz(y), 0u);
  EXPECT_TRUE(ValidateSettings(s, &f, OutputStage::kStepPulses).ok());
  // The factory settings keep it on every axis.
  EXPECT_TRUE(ValidateSettings(BoardSettings(), &f, OutputStage::kStepPulses).ok());
}

// The acceleration in effect: the configured one unless the limiter's period cannot represent it
// (accel < f^2 / n^2) or it would reach the drive's spare rate in under one period
// (accel <= rate * f / n), each worked by hand here.
TEST(SettingsRules, DirectionSwitchAccelerationInEffectNamesItsBound) {
  AxisConfig a;  // factory: 10^8 steps/s^2
  a.drive.max_rate_hz = 2000000;
  a.max_input_rate_hz = 1000000;
  SwitchAccelInEffect e = DirectionSwitchAccelInEffect(a, 50000, CompensationDivider(50000));
  EXPECT_EQ(e.steps_s2, 100000000u);  // (50000 / 3)^2 = 2.8e8 and 1e6 * 50000 / 3 both above
  EXPECT_EQ(e.bound, SwitchAccelBound::kNone);
  e = DirectionSwitchAccelInEffect(a, 1000, 1);  // 1 kHz: (10^6 - 1) / 1
  EXPECT_EQ(e.steps_s2, 999999u);
  EXPECT_EQ(e.bound, SwitchAccelBound::kPeriod);
  a.drive.max_rate_hz = 1000100;  // 100 steps/s to spare: 100 * 50000 / 3 = 1666666
  e = DirectionSwitchAccelInEffect(a, 50000, 3);
  EXPECT_EQ(e.steps_s2, 1666666u);
  EXPECT_EQ(e.bound, SwitchAccelBound::kRate);
  a.drive.max_rate_hz = 1000000;  // nothing to spare
  e = DirectionSwitchAccelInEffect(a, 50000, 3);
  EXPECT_EQ(e.steps_s2, 0u);
  EXPECT_EQ(e.bound, SwitchAccelBound::kRate);
}

TEST(SettingsRecord, EveryFieldRoundTripsAndARecordOnlyCountsWhenValid) {
  BoardSettings s;
  s.node_id = 0x22;
  s.bitrate_kbit = 250;
  s.board.tick_hz = 25000;
  s.board.axis_count = 4;
  s.board.axis[3].name = 'C';
  s.board.axis[3].kind = table::AxisKind::kRotary;
  s.board.axis[1].input_format = PulseFormat::kQuadrature;
  s.board.axis[2].output_format = PulseFormat::kCwCcw;
  s.board.axis[0].invert_input_dir = true;
  s.board.axis[0].input_counter_bits = 16;
  s.board.axis[0].max_input_rate_hz = 100000;
  s.board.axis[2].home_position_steps = -5000;
  s.board.axis[1].drive.dir_hold_ns = 12345;
  s.board.axis[2].direction_hysteresis_steps = 7;
  s.board.axis[1].direction_switch_accel_steps_s2 = 3000000;
  ASSERT_TRUE(ValidateSettings(s).ok());
  uint8_t rec[kSettingsBytes];
  SerializeSettings(s, rec);
  BoardSettings back;
  ASSERT_TRUE(DeserializeSettings(rec, sizeof rec, &back).ok());
  uint8_t again[kSettingsBytes];
  SerializeSettings(back, again);
  for (uint32_t i = 0; i < kSettingsBytes; ++i) ASSERT_EQ(rec[i], again[i]) << i;
  EXPECT_EQ(back.board.axis[3].kind, table::AxisKind::kRotary);
  EXPECT_TRUE(back.board.axis[0].invert_input_dir);
  EXPECT_EQ(back.board.axis[2].home_position_steps, -5000);
  EXPECT_EQ(back.board.axis[2].direction_hysteresis_steps, 7);
  EXPECT_EQ(back.board.axis[1].direction_switch_accel_steps_s2, 3000000u);
  // Short, or out of range (node-ID 0): not taken; *s untouched.
  BoardSettings untouched;
  EXPECT_FALSE(DeserializeSettings(rec, kSettingsBytes - 1, &untouched).ok());
  rec[8] = 0;  // node-ID
  EXPECT_EQ(DeserializeSettings(rec, sizeof rec, &untouched).error(), Error::kConfigInvalid);
  EXPECT_EQ(untouched.node_id, kDefaultNodeId);
}

TEST(BoardSettings, TheNodeSettingsAreCheckedBeforeTheInstallation) {
  BoardSettings s;
  ConfigFinding f;
  EXPECT_TRUE(ValidateSettings(s, &f).ok());
  EXPECT_EQ(f.rule, ConfigRule::kNone);
  s.node_id = 128;
  s.board.tick_hz = 1;  // also broken: the node-ID is named first
  EXPECT_EQ(ValidateSettings(s, &f).error(), Error::kConfigInvalid);
  EXPECT_EQ(f.rule, ConfigRule::kNodeId);
  s.node_id = 1;
  s.bitrate_kbit = 5;
  EXPECT_FALSE(ValidateSettings(s, &f).ok());
  EXPECT_EQ(f.rule, ConfigRule::kBitrate);
  s.bitrate_kbit = 1000;
  EXPECT_FALSE(ValidateSettings(s, &f).ok());
  EXPECT_EQ(f.rule, ConfigRule::kTickRate);
  s.board.tick_hz = 50000;
  s.board.axis[1].drive.max_rate_hz = 1000;
  EXPECT_FALSE(ValidateSettings(s, &f).ok());
  EXPECT_EQ(f.rule, ConfigRule::kDriveKeepsUp);
  EXPECT_EQ(f.axis, 2);
}

}  // namespace
}  // namespace volcomp

namespace volcomp {
namespace {

// Version 5 appends the TPDOs' parameters to the version-4 record (416 bytes), 44 bytes each:
// COB-ID LE32, transmission type, number mapped, inhibit LE16, event timer LE16, 2 reserved, the
// 8 mapping entries LE32. A version-4 record (416 bytes, all a board before the PDOs stored) still
// loads, with the default PDOs.
TEST(SettingsRecord, KeepsTheTpdosAndReadsVersion4Records) {
  EXPECT_EQ(kSettingsBytesV4, 416u);
  EXPECT_EQ(kSettingsBytesV5, 416u + 2 * 44);
  BoardSettings s;
  s.tpdo[1].cob_id = 0x80000391;
  s.tpdo[1].transmission_type = 255;
  s.tpdo[1].inhibit_100us = 0x0304;
  s.tpdo[1].event_timer_ms = 0x0506;
  s.tpdo[1].mapped = 1;
  s.tpdo[1].mapping[0] = 0x21220010;
  s.tpdo[1].mapping[7] = 0x0A0B0C0D;
  uint8_t rec[kSettingsBytes];
  SerializeSettings(s, rec);
  EXPECT_EQ(rec[6] | rec[7] << 8, 624);
  const size_t t1 = 416, t2 = 416 + 44;
  EXPECT_EQ(rec[t1 + 0], 0x80);  // TPDO1's default, stored form 0x180: base + node-ID
  EXPECT_EQ(rec[t1 + 1], 0x01);
  EXPECT_EQ(rec[t1 + 4], 254);
  EXPECT_EQ(rec[t1 + 5], 5);
  EXPECT_EQ(rec[t1 + 6], 200);    // inhibit 200 x 100 us
  EXPECT_EQ(rec[t1 + 8], 100);    // event timer 100 ms
  EXPECT_EQ(rec[t1 + 12], 0x10);  // 0x2122:0, 16 bits
  EXPECT_EQ(rec[t1 + 14], 0x22);
  EXPECT_EQ(rec[t1 + 15], 0x21);
  EXPECT_EQ(rec[t2 + 0], 0x91);
  EXPECT_EQ(rec[t2 + 1], 0x03);
  EXPECT_EQ(rec[t2 + 3], 0x80);
  EXPECT_EQ(rec[t2 + 4], 255);
  EXPECT_EQ(rec[t2 + 5], 1);
  EXPECT_EQ(rec[t2 + 6], 0x04);
  EXPECT_EQ(rec[t2 + 7], 0x03);
  EXPECT_EQ(rec[t2 + 8], 0x06);
  EXPECT_EQ(rec[t2 + 9], 0x05);
  EXPECT_EQ(rec[t2 + 12 + 28], 0x0D);
  EXPECT_EQ(rec[t2 + 12 + 31], 0x0A);
  BoardSettings back;
  ASSERT_TRUE(DeserializeSettings(rec, sizeof rec, &back).ok());
  EXPECT_EQ(back.tpdo[1].cob_id, 0x80000391u);
  EXPECT_EQ(back.tpdo[1].transmission_type, 255);
  EXPECT_EQ(back.tpdo[1].inhibit_100us, 0x0304);
  EXPECT_EQ(back.tpdo[1].event_timer_ms, 0x0506);
  EXPECT_EQ(back.tpdo[1].mapped, 1);
  EXPECT_EQ(back.tpdo[1].mapping[7], 0x0A0B0C0Du);
  EXPECT_EQ(back.tpdo[0].cob_id, 0x180u);
  // More than 8 mapped: not a record this firmware wrote.
  rec[t2 + 5] = 9;
  EXPECT_FALSE(DeserializeSettings(rec, sizeof rec, &back).ok());
  // The same record as version 4 stored it: 416 bytes, its size field 416.
  rec[4] = 4;
  OldSize(rec);
  BoardSettings old;
  ASSERT_TRUE(DeserializeSettings(rec, kSettingsBytesV4, &old).ok());
  EXPECT_EQ(old.tpdo[1].cob_id, 0x280u);
  EXPECT_EQ(old.tpdo[1].transmission_type, 254);
  EXPECT_EQ(old.tpdo[1].inhibit_100us, 200);
  EXPECT_EQ(old.tpdo[1].event_timer_ms, 100);
  EXPECT_EQ(old.tpdo[1].mapped, 4);
  EXPECT_EQ(old.tpdo[1].mapping[0], 0x21380310u);  // 0x2138:3, I16
  EXPECT_EQ(old.tpdo[0].mapping[1], 0x21250008u);
  // A version-8 record cut to the old length is not taken.
  rec[4] = 8;
  rec[6] = static_cast<uint8_t>(kSettingsBytes & 0xFF);
  rec[7] = static_cast<uint8_t>(kSettingsBytes >> 8);
  EXPECT_FALSE(DeserializeSettings(rec, kSettingsBytesV4, &old).ok());
}

// Version 6 appends the RPDO's COB-ID (LE32, stored form) and transmission type (U8) and 3
// reserved bytes to the version-5 record (504 bytes); its mapping is static, not stored. A
// version-5 record (504 bytes, a board with TPDOs but no RPDO) still loads, with the default RPDO.
// A COB-ID or type 0x1400 would refuse is not a record this firmware wrote.
TEST(SettingsRecord, KeepsTheRpdoAndReadsVersion5Records) {
  EXPECT_EQ(kSettingsBytesV6, 504u + 8);
  const BoardSettings defaults;
  EXPECT_EQ(defaults.rpdo[0].cob_id, 0x200u);  // stored form: 0x200 + node-ID
  EXPECT_EQ(defaults.rpdo[0].transmission_type, 254);
  ASSERT_EQ(defaults.rpdo[0].mapped, 1);
  EXPECT_EQ(defaults.rpdo[0].mapping[0], 0x21270010u);  // 0x2127:0, U16
  BoardSettings s;
  s.rpdo[0].cob_id = 0x80000321u;
  s.rpdo[0].transmission_type = 255;
  uint8_t rec[kSettingsBytes];
  SerializeSettings(s, rec);
  EXPECT_EQ(rec[504], 0x21);
  EXPECT_EQ(rec[505], 0x03);
  EXPECT_EQ(rec[507], 0x80);
  EXPECT_EQ(rec[508], 255);
  BoardSettings back;
  ASSERT_TRUE(DeserializeSettings(rec, sizeof rec, &back).ok());
  EXPECT_EQ(back.rpdo[0].cob_id, 0x80000321u);
  EXPECT_EQ(back.rpdo[0].transmission_type, 255);
  EXPECT_EQ(back.rpdo[0].mapping[0], 0x21270010u);
  rec[508] = 1;  // synchronous: no SYNC consumer
  EXPECT_FALSE(DeserializeSettings(rec, sizeof rec, &back).ok());
  rec[508] = 254;
  rec[506] = 0x01;  // bit 16: not an 11-bit CAN-ID
  EXPECT_FALSE(DeserializeSettings(rec, sizeof rec, &back).ok());
  rec[506] = 0;
  rec[4] = 5;
  rec[6] = static_cast<uint8_t>(kSettingsBytesV5 & 0xFF);
  rec[7] = static_cast<uint8_t>(kSettingsBytesV5 >> 8);
  BoardSettings old;
  ASSERT_TRUE(DeserializeSettings(rec, kSettingsBytesV5, &old).ok());
  EXPECT_EQ(old.rpdo[0].cob_id, 0x200u);
  EXPECT_EQ(old.rpdo[0].transmission_type, 254);
}

// Version 7 appends the 8 temperature channels to the version-6 record (512 bytes), 12 bytes
// each: source U8, stuck readings U8, timeout ms LE16, low and high 0.01 C LE16 (signed), max rate
// 0.01 K/s LE16, 2 reserved. A version-6 record still loads, every channel unused; a channel the
// channel rules refuse is not a record this firmware wrote, and ValidateSettings names it.
TEST(SettingsRecord, KeepsTheTemperatureChannelsAndReadsVersion6Records) {
  EXPECT_EQ(kSettingsBytesV7, 512u + 8 * 12);
  const BoardSettings defaults;
  for (const thermal::ChannelConfig& c : defaults.temperature)
    EXPECT_EQ(c.source, thermal::ChannelSource::kNone);
  BoardSettings s;
  s.temperature[2].source = thermal::ChannelSource::kCanObject;
  s.temperature[2].timeout_ms = 0x1234;
  s.temperature[2].low_cC = -1500;  // 0xFA24
  s.temperature[2].high_cC = 6000;  // 0x1770
  s.temperature[2].max_rate_cC_s = 50;
  s.temperature[7].source = thermal::ChannelSource::kBoardPt1000;
  s.temperature[7].stuck_readings = 20;
  uint8_t rec[kSettingsBytes];
  SerializeSettings(s, rec);
  const size_t c2 = 512 + 2 * 12, c7 = 512 + 7 * 12;
  EXPECT_EQ(rec[c2 + 0], 1);
  EXPECT_EQ(rec[c2 + 1], 0);
  EXPECT_EQ(rec[c2 + 2], 0x34);
  EXPECT_EQ(rec[c2 + 3], 0x12);
  EXPECT_EQ(rec[c2 + 4], 0x24);
  EXPECT_EQ(rec[c2 + 5], 0xFA);
  EXPECT_EQ(rec[c2 + 6], 0x70);
  EXPECT_EQ(rec[c2 + 7], 0x17);
  EXPECT_EQ(rec[c2 + 8], 50);
  EXPECT_EQ(rec[c7 + 0], 3);
  EXPECT_EQ(rec[c7 + 1], 20);
  EXPECT_EQ(rec[c7 + 2], 1500 & 0xFF);  // the default timeout, 1500 ms
  BoardSettings back;
  ASSERT_TRUE(DeserializeSettings(rec, sizeof rec, &back).ok());
  EXPECT_EQ(back.temperature[2].source, thermal::ChannelSource::kCanObject);
  EXPECT_EQ(back.temperature[2].timeout_ms, 0x1234);
  EXPECT_EQ(back.temperature[2].low_cC, -1500);
  EXPECT_EQ(back.temperature[2].high_cC, 6000);
  EXPECT_EQ(back.temperature[2].max_rate_cC_s, 50);
  EXPECT_EQ(back.temperature[7].stuck_readings, 20);
  EXPECT_EQ(back.temperature[0].source, thermal::ChannelSource::kNone);
  // low above high: refused, and the rule names the channel.
  rec[c2 + 4] = 0x71;
  rec[c2 + 5] = 0x17;
  EXPECT_FALSE(DeserializeSettings(rec, sizeof rec, &back).ok());
  s.temperature[2].low_cC = 6001;
  ConfigFinding f;
  EXPECT_EQ(ValidateSettings(s, &f).error(), Error::kConfigInvalid);
  EXPECT_EQ(f.rule, ConfigRule::kTemperatureChannel);
  EXPECT_EQ(f.axis, 3);  // channel 3 (index 2)
  rec[c2 + 4] = 0x24;
  rec[c2 + 5] = 0xFA;
  rec[c7 + 0] = 6;  // no such source
  EXPECT_FALSE(DeserializeSettings(rec, sizeof rec, &back).ok());
  // The same record as version 6 stored it: 512 bytes, no channels.
  rec[4] = 6;
  rec[6] = static_cast<uint8_t>(kSettingsBytesV6 & 0xFF);
  rec[7] = static_cast<uint8_t>(kSettingsBytesV6 >> 8);
  BoardSettings old;
  ASSERT_TRUE(DeserializeSettings(rec, kSettingsBytesV6, &old).ok());
  for (const thermal::ChannelConfig& c : old.temperature)
    EXPECT_EQ(c.source, thermal::ChannelSource::kNone);
}

// Version 8 appends RPDO2 and RPDO3 (0x1401, 0x1402: the temperatures) to the version-7 record
// (608 bytes), 8 bytes each as RPDO1's: COB-ID LE32 (stored form), type U8, 3 reserved. Their
// defaults are CiA 301's pre-defined connection set, 0x300 / 0x400 + node-ID, valid; a version-7
// record still loads, with those defaults.
TEST(SettingsRecord, KeepsRpdo2And3AndReadsVersion7Records) {
  EXPECT_EQ(kSettingsBytes, 608u + 2 * 8);
  const BoardSettings defaults;
  EXPECT_EQ(defaults.rpdo[1].cob_id, 0x300u);
  EXPECT_EQ(defaults.rpdo[2].cob_id, 0x400u);
  ASSERT_EQ(defaults.rpdo[1].mapped, 4);
  EXPECT_EQ(defaults.rpdo[1].mapping[0], 0x21500110u);  // 0x2150:1, I16
  EXPECT_EQ(defaults.rpdo[1].mapping[3], 0x21500410u);  // 0x2150:4
  ASSERT_EQ(defaults.rpdo[2].mapped, 4);
  EXPECT_EQ(defaults.rpdo[2].mapping[0], 0x21500510u);  // 0x2150:5
  EXPECT_EQ(defaults.rpdo[2].mapping[3], 0x21500810u);  // 0x2150:8
  BoardSettings s;
  s.rpdo[1].cob_id = 0x80000300u;  // disabled
  s.rpdo[2].cob_id = 0x455u;
  s.rpdo[2].transmission_type = 255;
  uint8_t rec[kSettingsBytes];
  SerializeSettings(s, rec);
  EXPECT_EQ(rec[4], 8);
  EXPECT_EQ(rec[6] | rec[7] << 8, 624);
  EXPECT_EQ(rec[608], 0x00);
  EXPECT_EQ(rec[609], 0x03);
  EXPECT_EQ(rec[611], 0x80);
  EXPECT_EQ(rec[612], 254);
  EXPECT_EQ(rec[616], 0x55);
  EXPECT_EQ(rec[617], 0x04);
  EXPECT_EQ(rec[620], 255);
  BoardSettings back;
  ASSERT_TRUE(DeserializeSettings(rec, sizeof rec, &back).ok());
  EXPECT_EQ(back.rpdo[1].cob_id, 0x80000300u);
  EXPECT_EQ(back.rpdo[2].cob_id, 0x455u);
  EXPECT_EQ(back.rpdo[2].transmission_type, 255);
  rec[620] = 0;  // not event-driven: not a record this firmware wrote
  EXPECT_FALSE(DeserializeSettings(rec, sizeof rec, &back).ok());
  rec[4] = 7;
  rec[6] = static_cast<uint8_t>(kSettingsBytesV7 & 0xFF);
  rec[7] = static_cast<uint8_t>(kSettingsBytesV7 >> 8);
  BoardSettings old;
  ASSERT_TRUE(DeserializeSettings(rec, kSettingsBytesV7, &old).ok());
  EXPECT_EQ(old.rpdo[1].cob_id, 0x300u);
  EXPECT_EQ(old.rpdo[2].cob_id, 0x400u);
  EXPECT_EQ(old.rpdo[2].transmission_type, 254);
}

}  // namespace
}  // namespace volcomp
