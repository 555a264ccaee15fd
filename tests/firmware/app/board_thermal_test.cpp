// The thermal correction on the board end to end (docs/thermal.md): the channels configured by
// their objects (0x2158-0x215D: checked at the write and at the store, in force from the next
// reset node), temperature channels written over CAN (0x2150 by SDO, RPDO2 / RPDO3), the active
// image's THERMAL model applied to the drive outputs, a channel that
// stops updating detected within 2 s (EMCY 0x4000, device-state bit, 0x2151-0x2153) with the
// correction held, and its recovery. Expected positions come from the model's definition
// (offset + slope x (p - p0), per K of each channel), not from the board's code.
#include <gtest/gtest.h>

#include <cstdint>

#include "board_bench.hpp"
#include "test_tables.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/table/table_writer.hpp"
#include "volcomp/thermal/temperature_channels.hpp"

namespace volcomp {
namespace {

using bench::Bench;
using bench::InputLine;
using bench::kNode;
using bench::ObjectId;
using bench::TableCommand;

bool Contains(const std::vector<std::string>& frames, const std::string& frame) {
  for (const std::string& f : frames) {
    if (f == frame) return true;
  }
  return false;
}

// The model: X offset 2 um/K on channel 1 (T_ref 20 C); Y slope 50 um/(K m) on channel 2 (T_ref
// 20 C, p0 0); calibrated 10..40 C; a fast slew (50 um/s) so the test settles in a second.
thermal::ThermalModel Model() {
  thermal::ThermalModel m;
  m.axis_count = 3;
  m.channel_mask = 0x03;
  m.slew_um_s = 50.0f;
  m.hold_ms = 60000;
  for (int j = 0; j < 2; ++j) {
    m.reference_cC[j] = 2000;
    m.calibrated_low_cC[j] = 1000;
    m.calibrated_high_cC[j] = 4000;
  }
  m.axis[0].offset_um_per_K[0] = 2.0f;
  m.axis[0].reach_mm = 200.0f;
  m.axis[1].slope_um_per_K_m[1] = 50.0f;
  m.axis[1].reach_mm = 200.0f;
  return m;
}

// A uniform grid of +3 steps on X (1 um per step on X, Y, Z) with the model.
testing::AlignedBytes ThermalImage(const thermal::ThermalModel& m, uint32_t id) {
  static std::vector<int16_t> values;
  values.clear();
  for (int i = 0; i < 8 * 8 * 8; ++i) {
    values.push_back(3 * 256);
    values.push_back(0);
    values.push_back(0);
  }
  table::GridSpec g;
  g.frac_bits = 8;
  for (auto& d : g.dim) d = {8, -100000, 30000};
  g.values.type = table::ElementType::kInt16;
  g.values.i16 = values.data();
  table::ImageSpec s = testing::XyzImageSpec(g, id);
  s.thermal = &m;
  return testing::WriteImageBytes(s);
}

class ThermalBench : public Bench {
 protected:
  void BootWithCanChannels() {
    BoardSettings s;
    s.board = config_;
    s.temperature[0].source = thermal::ChannelSource::kCanObject;
    s.temperature[1].source = thermal::ChannelSource::kCanObject;
    Boot(s);
  }
  // `ms` of machine time, both channels (or channel 2 only) written every 200 ms as a PLC would.
  void Feed(int ms, bool channel1 = true) {
    for (int t = 0; t < ms; t += 200) {
      const uint64_t start = clock_.now();
      if (channel1) {
        ASSERT_TRUE(Write(ObjectId::kTemperature1, t1_cC_).ok());
      }
      ASSERT_TRUE(Write(ObjectId::kTemperature2, t2_cC_).ok());
      while (clock_.now() - start < 200000000u) Step(50);
    }
  }
  uint32_t t1_cC_ = 2500;
  uint32_t t2_cC_ = 2500;
};

TEST_F(ThermalBench, TheModelMovesTheDrivesAndAStoppedChannelIsFlaggedAndHeld) {
  BootWithCanChannels();
  io_.SetInput(InputLine::kWriteEnable, true);
  Feed(400);
  EXPECT_EQ(Read(ObjectId::kTemperatureState1), 2u);  // valid
  EXPECT_EQ(Read(ObjectId::kTemperature1), 2500u);
  EXPECT_EQ(Read(ObjectId::kTemperatureState3), 0u);  // unused
  // A channel with another source (here: none) is not written over CAN.
  EXPECT_EQ(canopen_client::AbortOf(Write(ObjectId::kTemperature3, 2500)),
            canopen::SdoAbort::kReadOnly);

  const thermal::ThermalModel m = Model();
  ASSERT_TRUE(Upload(ThermalImage(m, 31)).ok());
  ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok());
  step_io_.add_steps(1, 20000);  // Y at 20 mm
  Feed(400);
  ASSERT_TRUE(Command(TableCommand::kActivate).ok());
  Feed(2000);  // the table's ramp and the thermal slew (25 um of reach at 50 um/s)

  // At 25 C on both channels: X = table 3 + 2 um/K x 5 K = 10 um; Y = 50 um/(K m) x 5 K x 0.020 m
  // = 5 um (1 um per step).
  EXPECT_EQ(step_io_.drive(0).position(), 3 + 10);
  EXPECT_EQ(step_io_.drive(1).position(), 20000 + 5);
  EXPECT_EQ(static_cast<int32_t>(Read(ObjectId::kThermalOffset1)), 10000);       // nm
  EXPECT_EQ(static_cast<int32_t>(Read(ObjectId::kThermalSlope2)), 250000);       // nm per m
  EXPECT_EQ(Read(ObjectId::kThermalStatus), uint32_t{canopen::kThermalActive});  // settled
  EXPECT_FALSE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).thermal_fault);

  // Channel 1 stops: stale after its 1.5 s timeout, seen at the next 100 ms period.
  const size_t seen = sent_.size();
  const uint64_t last_reading_ns = clock_.now();
  uint64_t flagged_ns = 0;
  canopen::Emcy emcy;
  for (int i = 0; i < 15 && flagged_ns == 0; ++i) {
    Feed(200, /*channel1=*/false);
    for (size_t k = seen; k < sent_.size() && flagged_ns == 0; ++k) {
      if (canopen::DecodeEmcy(sent_[k], kNode, &emcy) &&
          emcy.code == canopen::kEmcyTemperatureChannel) {
        flagged_ns = clock_.now();
      }
    }
  }
  ASSERT_NE(flagged_ns, 0u) << "no EMCY 0x4000 within 3 s";
  const double detected_s = static_cast<double>(flagged_ns - last_reading_ns) * 1e-9;
  EXPECT_GE(detected_s, 1.5);
  EXPECT_LE(detected_s, 2.0);
  EXPECT_EQ(emcy.data[0], 0x01);  // channel 1 just faulted
  EXPECT_EQ(emcy.data[1], 0x01);  // the channels in a fault now
  EXPECT_EQ(emcy.data[2], static_cast<uint8_t>(thermal::ChannelState::kStale));
  EXPECT_NE(emcy.error_register & canopen::kErrTemperature, 0);
  EXPECT_TRUE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).thermal_fault);
  EXPECT_EQ(Read(ObjectId::kTemperatureState1), 3u);  // stale
  EXPECT_EQ(Read(ObjectId::kTemperatureFaults1), 1u);
  EXPECT_EQ(Read(ObjectId::kThermalFaultChannels), 1u);
  EXPECT_EQ(Read(ObjectId::kThermalStatus),
            uint32_t{canopen::kThermalActive | canopen::kThermalHolding});
  // Held, not dropped: the drives stay where the model put them.
  Feed(1000, /*channel1=*/false);
  EXPECT_EQ(step_io_.drive(0).position(), 3 + 10);
  EXPECT_EQ(step_io_.drive(1).position(), 20000 + 5);

  // Back: valid after 3 good readings, the error cleared (EMCY 0x0000), the flag off. A warmer
  // channel 1 (27 C) moves X to 3 + 14 at the slew limit.
  t1_cC_ = 2700;
  const size_t before_recovery = sent_.size();
  Feed(2000);
  EXPECT_EQ(Read(ObjectId::kTemperatureState1), 2u);
  EXPECT_FALSE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).thermal_fault);
  int resets = 0;
  for (size_t k = before_recovery; k < sent_.size(); ++k) {
    resets += canopen::DecodeEmcy(sent_[k], kNode, &emcy) && emcy.code == canopen::kEmcyErrorReset;
  }
  EXPECT_EQ(resets, 1);
  EXPECT_EQ(step_io_.drive(0).position(), 3 + 14);
}

// A model that uses a channel the settings leave unused cannot be applied: it is accepted (the
// geometric table works) but flagged at once, EMCY 0x4000 naming the channel with state "unused",
// and the thermal correction holds at zero.
TEST_F(ThermalBench, AModelOnAnUnconfiguredChannelIsFlagged) {
  BoardSettings s;
  s.board = config_;
  s.temperature[0].source = thermal::ChannelSource::kCanObject;  // channel 2 left unused
  Boot(s);
  io_.SetInput(InputLine::kWriteEnable, true);
  ASSERT_TRUE(Upload(ThermalImage(Model(), 33)).ok());
  ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok());
  const size_t seen = sent_.size();
  for (int i = 0; i < 10; ++i) {
    ASSERT_TRUE(Write(ObjectId::kTemperature1, 2500).ok());
    Step(10000);
  }
  ASSERT_TRUE(Command(TableCommand::kActivate).ok());
  for (int i = 0; i < 10; ++i) {
    ASSERT_TRUE(Write(ObjectId::kTemperature1, 2500).ok());
    Step(10000);
  }
  int flagged = 0;
  canopen::Emcy emcy;
  for (size_t k = seen; k < sent_.size(); ++k) {
    if (canopen::DecodeEmcy(sent_[k], kNode, &emcy) &&
        emcy.code == canopen::kEmcyTemperatureChannel) {
      ++flagged;
      EXPECT_EQ(emcy.data[0], 0x02);  // channel 2
      EXPECT_EQ(emcy.data[2], static_cast<uint8_t>(thermal::ChannelState::kUnused));
    }
  }
  EXPECT_EQ(flagged, 1);
  EXPECT_TRUE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).thermal_fault);
  EXPECT_EQ(Read(ObjectId::kThermalFaultChannels), 0x02u);
  EXPECT_EQ(Read(ObjectId::kThermalStatus),
            uint32_t{canopen::kThermalActive | canopen::kThermalHolding});
  EXPECT_EQ(step_io_.drive(0).position(), 3);  // the table's 3 steps, no thermal term
}

// Deactivating the table fades the thermal correction out (never a jump); the outputs return to
// the commanded position.
TEST_F(ThermalBench, DeactivationFadesTheThermalCorrectionOut) {
  BootWithCanChannels();
  io_.SetInput(InputLine::kWriteEnable, true);
  ASSERT_TRUE(Upload(ThermalImage(Model(), 32)).ok());
  ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok());
  Feed(400);
  ASSERT_TRUE(Command(TableCommand::kActivate).ok());
  Feed(2000);
  ASSERT_EQ(step_io_.drive(0).position(), 13);
  ASSERT_TRUE(Command(TableCommand::kDeactivate).ok());
  Feed(2000);
  EXPECT_EQ(step_io_.drive(0).position(), 0);
  EXPECT_EQ(static_cast<int32_t>(Read(ObjectId::kThermalOffset1)), 0);
  EXPECT_EQ(Read(ObjectId::kThermalStatus) & canopen::kThermalActive, 0u);
}

// The channels' configuration objects: each field range-checked at the write (as every setting:
// 0x06090030 for a source that does not exist, 0x06090032 below a limit), the channel as a whole
// at the store (0x1010 refuses an inconsistent set with 0x06090030; 0x2123 names the rule and the
// channel before), in force from the next reset node (until then 0x2122 says settings pending and
// the channel runs as it started).
TEST_F(ThermalBench, TheChannelObjectsAreCheckedStoredAndTakenAtResetNode) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  using canopen::SdoAbort;
  using canopen_client::AbortOf;
  EXPECT_EQ(Read(ObjectId::kChannelSource1), 0u);  // factory: unused, 1.5 s, -20..+90 C, 1 K/s
  EXPECT_EQ(Read(ObjectId::kChannelTimeout1), 1500u);
  EXPECT_EQ(static_cast<int16_t>(Read(ObjectId::kChannelLow1)), -2000);
  EXPECT_EQ(Read(ObjectId::kChannelHigh1), 9000u);
  EXPECT_EQ(Read(ObjectId::kChannelMaxRate1), 100u);
  EXPECT_EQ(AbortOf(Write(ObjectId::kChannelSource1, 6)), SdoAbort::kInvalidValue);
  EXPECT_EQ(AbortOf(Write(ObjectId::kChannelTimeout1, 99)), SdoAbort::kValueTooLow);
  EXPECT_EQ(AbortOf(Write(ObjectId::kChannelTimeout1, 60001)), SdoAbort::kValueTooHigh);
  EXPECT_EQ(AbortOf(Write(ObjectId::kChannelMaxRate1, 0)), SdoAbort::kValueTooLow);
  ASSERT_TRUE(Write(ObjectId::kChannelSource1, 1).ok());  // the CAN object
  ASSERT_TRUE(Write(ObjectId::kChannelTimeout1, 5000).ok());
  ASSERT_TRUE(Write(ObjectId::kChannelLow1, static_cast<uint16_t>(-500)).ok());  // -5 C
  EXPECT_EQ(Read(ObjectId::kChannelSource1), 1u);
  EXPECT_EQ(static_cast<int16_t>(Read(ObjectId::kChannelLow1)), -500);
  EXPECT_TRUE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).settings_pending);
  EXPECT_EQ(Read(ObjectId::kTemperatureState1), 0u);  // not in force: still unused
  EXPECT_EQ(AbortOf(Write(ObjectId::kTemperature1, 2500)), SdoAbort::kReadOnly);

  // Channel 2: each field in range, low above high together: the store refuses the set.
  ASSERT_TRUE(Write(ObjectId::kChannelSource2, 2).ok());  // NTC
  ASSERT_TRUE(Write(ObjectId::kChannelLow2, 5000).ok());
  ASSERT_TRUE(Write(ObjectId::kChannelHigh2, 4000).ok());
  const canopen::SettingsCheck check = canopen::DecodeSettingsCheck(Read(ObjectId::kSettingsCheck));
  EXPECT_EQ(check.finding.rule, ConfigRule::kTemperatureChannel);
  EXPECT_EQ(check.finding.axis, 2);  // the channel
  EXPECT_EQ(AbortOf(Write(ObjectId::kStoreAll, canopen::kSaveSignature)), SdoAbort::kInvalidValue);
  ASSERT_TRUE(Write(ObjectId::kChannelSource2, 0).ok());  // unused: its limits are not checked
  EXPECT_EQ(canopen::DecodeSettingsCheck(Read(ObjectId::kSettingsCheck)).finding.rule,
            ConfigRule::kNone);
  ASSERT_TRUE(Write(ObjectId::kStoreAll, canopen::kSaveSignature).ok());
  EXPECT_EQ(Read(ObjectId::kTemperatureState1), 0u);  // stored, not yet in force

  EXPECT_TRUE(Contains(Nmt(0x81), "710#00"));  // reset node: the stored settings in force
  EXPECT_FALSE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).settings_pending);
  EXPECT_EQ(Read(ObjectId::kTemperatureState1), 1u);                              // waiting
  ASSERT_TRUE(Write(ObjectId::kTemperature1, static_cast<uint16_t>(-400)).ok());  // -4 C
  EXPECT_EQ(Read(ObjectId::kTemperatureState1), 2u);                              // valid
  ASSERT_TRUE(Write(ObjectId::kTemperature1, static_cast<uint16_t>(-600)).ok());  // below -5 C
  EXPECT_EQ(Read(ObjectId::kTemperatureState1), 4u);                              // out of range
  EXPECT_EQ(static_cast<int16_t>(Read(ObjectId::kTemperature1)), -400);           // held
  EXPECT_EQ(Read(ObjectId::kTemperatureState2), 0u);
}

// RPDO2 (0x300 + node-ID) carries channels 1-4, RPDO3 (0x400 + node-ID) channels 5-8, four I16
// each (CiA 301 pre-defined connection set, valid from the factory, acted on in operational only).
// Each temperature is a write of 0x2150:n with the SDO write's rules: taken for a channel fed by
// the CAN object, refused (EMCY 0xFF10, bytes 3-6 0x06010002, counted in 0x2140:9) for a channel
// with another source or none, except 0x8000 ("no reading"), which such a channel ignores: what a
// sender puts in the slots of channels it does not feed.
TEST_F(ThermalBench, Rpdo2And3CarryTheTemperatures) {
  BoardSettings s;
  s.board = config_;
  s.temperature[0].source = thermal::ChannelSource::kCanObject;
  s.temperature[1].source = thermal::ChannelSource::kCanObject;
  s.temperature[2].source = thermal::ChannelSource::kBoardPt1000;  // channel 4 unused
  s.temperature[5].source = thermal::ChannelSource::kCanObject;
  Boot(s);
  const auto frame = [](uint32_t id, std::initializer_list<int16_t> t, uint8_t dlc = 8) {
    CanFrame f{id, false, false, dlc, {}};
    int k = 0;
    for (int16_t v : t) {
      f.data[k++] = static_cast<uint8_t>(v);
      f.data[k++] = static_cast<uint8_t>(static_cast<uint16_t>(v) >> 8);
    }
    return f;
  };
  const auto send = [this](const CanFrame& f) {
    can_.Inject(f);
    Step(1500);  // 30 ms: past the EMCY inhibit time
    std::vector<canopen::Emcy> out;
    for (const CanFrame& r : can_.TakeSent()) {
      canopen::Emcy e;
      if (canopen::DecodeEmcy(r, kNode, &e) && e.code != canopen::kEmcyErrorReset) out.push_back(e);
    }
    return out;
  };
  constexpr int16_t kNone = thermal::kNoReading_cC;
  EXPECT_EQ(Read(ObjectId::kRpdo2CobId), 0x300u + kNode);
  EXPECT_EQ(Read(ObjectId::kRpdo3CobId), 0x400u + kNode);
  EXPECT_EQ(Read(ObjectId::kRpdo2Mapped), 4u);
  EXPECT_EQ(Read(ObjectId::kRpdo2Mapping1), 0x21500110u);  // 0x2150:1, 16 bits
  EXPECT_EQ(Read(ObjectId::kRpdo3Mapping4), 0x21500810u);  // 0x2150:8

  // Pre-operational: not processed.
  EXPECT_TRUE(send(frame(0x300 + kNode, {2345, -150, kNone, kNone})).empty());
  EXPECT_EQ(Read(ObjectId::kTemperatureState1), 1u);  // waiting
  Nmt(0x01);
  const uint32_t refused = app_.objects().refused_actions();
  EXPECT_TRUE(send(frame(0x300 + kNode, {2345, -150, kNone, kNone})).empty());
  EXPECT_EQ(Read(ObjectId::kTemperature1), 2345u);
  EXPECT_EQ(static_cast<int16_t>(Read(ObjectId::kTemperature2)), -150);
  EXPECT_EQ(Read(ObjectId::kTemperatureState1), 2u);  // valid
  EXPECT_EQ(Read(ObjectId::kTemperatureState2), 2u);
  EXPECT_EQ(Read(ObjectId::kTemperatureState3), 1u);  // the PT1000's: untouched
  EXPECT_EQ(app_.objects().refused_actions(), refused);
  EXPECT_EQ(app_.node().rpdo_received(), 1u);

  // A temperature for the unused channel 4: refused as its SDO write is; the others are taken.
  std::vector<canopen::Emcy> e = send(frame(0x300 + kNode, {2350, -140, kNone, 2000}));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].code, canopen::kEmcyRefused);
  EXPECT_EQ(LoadLe32(e[0].data), 0x06010002u);
  EXPECT_EQ(app_.objects().refused_actions(), refused + 1);
  EXPECT_EQ(Read(ObjectId::kTemperature1), 2350u);
  EXPECT_EQ(Read(ObjectId::kTemperatureState4), 0u);

  // RPDO3: channel 6 is its second slot.
  EXPECT_TRUE(send(frame(0x400 + kNode, {kNone, 3000, kNone, kNone})).empty());
  EXPECT_EQ(Read(ObjectId::kTemperature6), 3000u);
  EXPECT_EQ(Read(ObjectId::kTemperatureState6), 2u);

  // The wrong length: not processed (CiA 301: EMCY 0x8210 shorter, byte 3 = the DLC).
  e = send(frame(0x300 + kNode, {2400, -140, kNone}, 6));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].code, canopen::kEmcyPdoLength);
  EXPECT_EQ(e[0].data[0], 6);
  EXPECT_EQ(Read(ObjectId::kTemperature1), 2350u);

  // Disabled (bit 31, CiA 301): frames on its CAN-ID are not processed.
  io_.SetInput(InputLine::kWriteEnable, true);
  ASSERT_TRUE(Write(ObjectId::kRpdo2CobId, 0x80000000u | (0x300 + kNode)).ok());
  const uint32_t received = app_.node().rpdo_received();
  EXPECT_TRUE(send(frame(0x300 + kNode, {2500, -140, kNone, kNone})).empty());
  EXPECT_EQ(app_.node().rpdo_received(), received);
  EXPECT_EQ(Read(ObjectId::kTemperature1), 2350u);
}

}  // namespace
}  // namespace volcomp
