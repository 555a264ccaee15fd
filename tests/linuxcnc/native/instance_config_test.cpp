// The native component's load parameters: instances as halcompile components name them, linear
// units as [TRAJ]LINEAR_UNITS writes them, joint channels on table axes (a gantry's two joints on
// one axis; every table axis needs a joint).
#include "native/instance_config.hpp"

#include <gtest/gtest.h>

#include "native_tables.hpp"

namespace volcomp::linuxcnc {
namespace {

TEST(InstanceConfig, NamesInstancesAsHalcompileDoes) {
  auto n = InstanceNames(0, {});
  ASSERT_TRUE(n.ok());
  EXPECT_EQ(*n, std::vector<std::string>({"volcomp.0"}));
  n = InstanceNames(3, {});
  ASSERT_TRUE(n.ok());
  EXPECT_EQ(*n, std::vector<std::string>({"volcomp.0", "volcomp.1", "volcomp.2"}));
  n = InstanceNames(0, {"vc-head", "vc-table"});
  ASSERT_TRUE(n.ok());
  EXPECT_EQ(*n, std::vector<std::string>({"vc-head", "vc-table"}));
  EXPECT_EQ(InstanceNames(2, {"a"}).error().message, "count= and names= cannot be used together");
  EXPECT_EQ(InstanceNames(9, {}).error().message, "at most 8 instances (count=/names=)");
  EXPECT_EQ(InstanceNames(0, {"a", "a"}).error().message, "names=: \"a\" given twice");
  EXPECT_FALSE(InstanceNames(0, {std::string(30, 'x')}).ok());
  EXPECT_FALSE(InstanceNames(0, {"two words"}).ok());
}

TEST(InstanceConfig, ReadsLinuxcncLinearUnits) {
  for (const char* mm : {"", "mm", "MM", "metric", "millimeter", "1.0"})
    EXPECT_EQ(*ParseLinearUnits(mm), 1.0) << mm;
  for (const char* in : {"inch", "in", "Inch", "imperial", "0.03937"})
    EXPECT_EQ(*ParseLinearUnits(in), 25.4) << in;
  const auto bad = ParseLinearUnits("cm");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().message,
            "units=cm: not a linear unit LinuxCNC uses (mm or inch, as [TRAJ]LINEAR_UNITS)");
}

TEST(InstanceConfig, MapsJointChannelsOnTableAxes) {
  const auto t = testing::Load(testing::XyzaImage(testing::Grid(1, 5.0)));
  ASSERT_NE(t, nullptr);
  // Default: one channel per table axis, in order.
  auto m = MapChannels("", *t);
  ASSERT_TRUE(m.ok());
  ASSERT_EQ(m->count, 4u);
  for (uint8_t j = 0; j < 4; ++j) EXPECT_EQ(m->axis_of[j], j);
  // A gantry: joints 1 and 2 are both Y; Y's position is joint 1's.
  m = MapChannels("XYyZA", *t);
  ASSERT_TRUE(m.ok());
  ASSERT_EQ(m->count, 5u);
  const uint8_t axis_of[5] = {0, 1, 1, 2, 3};
  for (uint8_t j = 0; j < 5; ++j) EXPECT_EQ(m->axis_of[j], axis_of[j]) << int(j);
  EXPECT_EQ(m->position_channel[1], 1u);
  EXPECT_EQ(m->position_channel[2], 3u);
  EXPECT_EQ(m->position_channel[3], 4u);
  EXPECT_EQ(MapChannels("XYZB", *t).error().message,
            "axes=XYZB: joint 3 is 'B', which is not an axis of the table (X Y Z A)");
  EXPECT_EQ(MapChannels("XYZ", *t).error().message,
            "axes=XYZ: the table's axis A has no joint (the table needs its position)");
  EXPECT_FALSE(MapChannels("XYZAXXXXXX", *t).ok());
}

}  // namespace
}  // namespace volcomp::linuxcnc
