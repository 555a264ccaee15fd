// The thermal correction on the board end to end (docs/thermal.md): temperature channels written
// over CAN (0x2150), the active image's THERMAL model applied to the drive outputs, a channel that
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

}  // namespace
}  // namespace volcomp
