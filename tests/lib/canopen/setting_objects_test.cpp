// The stored configuration objects (setting_objects.hpp), expanded from od_entries.def: one per
// VOLCOMP_OD_SETTING row in dictionary order, each bound to its field (the default a board without
// stored settings reports is its field's factory value), found by id in constant time.
#include "volcomp/canopen/setting_objects.hpp"

#include <gtest/gtest.h>

#include <string>

namespace volcomp::canopen {
namespace {

TEST(SettingObjects, OneObjectPerSettingRowInDictionaryOrder) {
  // 0x1015, 0x1017, 0x2000:1-4, seventeen per-axis arrays of six and six per-channel arrays of
  // eight (0x2158-0x215D).
  ASSERT_EQ(kSettingObjectCount, 2u + 4u + 17u * 6u + 6u * 8u);
  EXPECT_EQ(SettingObjects().size(), kSettingObjectCount);
  const SettingObject* previous = nullptr;
  for (const SettingObject& s : SettingObjects()) {
    const ObjectEntry& e = Entry(s.id);
    EXPECT_EQ(e.access, Access::kRw) << e.name;
    EXPECT_NE(FixedSize(e.type), 0u) << e.name;
    EXPECT_EQ(FindSetting(s.id), &s) << e.name;
    if (previous != nullptr) {
      EXPECT_LT(previous->id, s.id);
    }
    previous = &s;
    if (s.axis != kBoardSetting) {
      EXPECT_EQ(e.sub, s.axis + 1) << e.name;
      EXPECT_GE(e.index, 0x2010);
      EXPECT_EQ(s.channel, kNoChannel) << e.name;
    }
    if (s.channel != kNoChannel) {
      EXPECT_EQ(e.sub, s.channel + 1) << e.name;
      EXPECT_GE(e.index, 0x2158);
      EXPECT_LE(e.index, 0x215D);
      EXPECT_EQ(s.axis, kBoardSetting) << e.name;
    }
  }
  EXPECT_EQ(FindSetting(ObjectId::kChannelLow5)->channel, 4);
  EXPECT_EQ(FindSetting(ObjectId::kChannelSourceCount), nullptr);
  EXPECT_EQ(FindSetting(ObjectId::kDeviceState), nullptr);
  EXPECT_EQ(FindSetting(ObjectId::kAxisNameCount), nullptr);  // sub 0 of an array
  EXPECT_EQ(FindSetting(ObjectId::kHeartbeatTime)->axis, kBoardSetting);
  EXPECT_EQ(FindSetting(ObjectId::kAxisMaxCorrection3)->axis, 2);
}

TEST(SettingObjects, EachReadsAndWritesItsFieldAndItsDefaultIsTheFactoryValue) {
  const BoardSettings factory;
  for (const SettingObject& s : SettingObjects()) {
    const ObjectEntry& e = Entry(s.id);
    EXPECT_EQ(s.get(factory), e.default_value) << e.name;
    BoardSettings x;
    const ValueRange r = EntryRange(e);
    const int64_t v = s.get(factory) == r.high ? r.high - 1 : s.get(factory) + 1;
    s.set(x, v);
    EXPECT_EQ(s.get(x), v) << e.name;
    // Only that field changed.
    for (const SettingObject& other : SettingObjects()) {
      if (&other != &s) {
        EXPECT_EQ(other.get(x), other.get(factory)) << Entry(other.id).name;
      }
    }
  }
  BoardSettings x;
  FindSetting(ObjectId::kAxisKind2)->set(x, 1);
  EXPECT_EQ(x.board.axis[1].kind, table::AxisKind::kRotary);
  EXPECT_TRUE(FindSetting(ObjectId::kAxisKind2)->enumerated);
  EXPECT_FALSE(FindSetting(ObjectId::kAxisHome2)->enumerated);
  FindSetting(ObjectId::kAxisHome2)->set(x, -5);
  EXPECT_EQ(x.board.axis[1].home_position_steps, -5);
  // The channels' objects: channel n's fields, 0x2158 an enumeration (ChannelSource).
  EXPECT_TRUE(FindSetting(ObjectId::kChannelSource3)->enumerated);
  FindSetting(ObjectId::kChannelSource3)->set(x, 3);
  EXPECT_EQ(x.temperature[2].source, thermal::ChannelSource::kBoardPt1000);
  FindSetting(ObjectId::kChannelLow8)->set(x, -1234);
  EXPECT_EQ(x.temperature[7].low_cC, -1234);
  FindSetting(ObjectId::kChannelMaxRate1)->set(x, 40);
  EXPECT_EQ(x.temperature[0].max_rate_cC_s, 40);
  // Defaults as thermal::ChannelConfig documents them: unused, 1.5 s, -20..+90 C, 1 K/s, off.
  EXPECT_EQ(Entry(ObjectId::kChannelSource1).default_value, 0);
  EXPECT_EQ(Entry(ObjectId::kChannelTimeout4).default_value, 1500);
  EXPECT_EQ(Entry(ObjectId::kChannelLow2).default_value, -2000);
  EXPECT_EQ(Entry(ObjectId::kChannelHigh2).default_value, 9000);
  EXPECT_EQ(Entry(ObjectId::kChannelMaxRate6).default_value, 100);
  EXPECT_EQ(Entry(ObjectId::kChannelStuck7).default_value, 0);
}

TEST(SettingObjects, ValueRangesAndRawValuesFollowTheEntrysType) {
  EXPECT_EQ(EntryRange(Entry(ObjectId::kNodeIdConfig)).low, 1);  // the entry's limits
  EXPECT_EQ(EntryRange(Entry(ObjectId::kNodeIdConfig)).high, 127);
  EXPECT_EQ(EntryRange(Entry(ObjectId::kAxisHome1)).low, -2147483648ll);  // INTEGER32
  EXPECT_EQ(EntryRange(Entry(ObjectId::kAxisMaxRate1)).high, 0xFFFFFFFFll);
  EXPECT_EQ(EntryRange(Entry(ObjectId::kHeartbeatTime)).high, 0xFFFF);
  EXPECT_EQ(EntryValue(Entry(ObjectId::kAxisHome1), 0xFFFFEC78u), -5000);
  EXPECT_EQ(EntryValue(Entry(ObjectId::kAxisKind1), 0x101u), 1);  // masked to UNSIGNED8
  EXPECT_EQ(EntryValue(Entry(ObjectId::kAxisMaxRate1), 0xFFFFFFFFu), 0xFFFFFFFFll);
}

}  // namespace
}  // namespace volcomp::canopen
