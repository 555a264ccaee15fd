// Compensator behaviour: pass-through until referenced, ramps, clamp, table changes, directions.
#include "volcomp/compensator.hpp"

#include <gtest/gtest.h>

#include "test_tables.hpp"

namespace volcomp {
namespace {

constexpr double kQ8 = 256.0;

// A uniform grid correction (every node the same vector) plus an optional X AXIS1D table.
struct TableFixture {
  std::vector<int32_t> values;
  std::vector<int32_t> x_fwd, x_rev;
  testing::AlignedBytes img;
  table::TableView view;

  TableFixture(double cx, double cy, double cz, bool x_table = false) {
    values.assign(2 * 2 * 2 * 3, 0);
    for (size_t i = 0; i < values.size(); i += 3) {
      values[i] = static_cast<int32_t>(cx * kQ8);
      values[i + 1] = static_cast<int32_t>(cy * kQ8);
      values[i + 2] = static_cast<int32_t>(cz * kQ8);
    }
    table::GridSpec g;
    g.frac_bits = 8;
    for (auto& d : g.dim) d = {2, -100000, 200000};
    g.values.type = table::ElementType::kInt32;
    g.values.i32 = values.data();
    table::ImageSpec s;
    s.table_id = 42;
    s.axis_count = 3;
    s.axes[0] = testing::LinearAxis('X');
    s.axes[1] = testing::LinearAxis('Y');
    s.axes[2] = testing::LinearAxis('Z');
    s.grid = &g;
    if (x_table) {
      x_fwd = {0, 0};
      x_rev = {static_cast<int32_t>(3 * kQ8), static_cast<int32_t>(3 * kQ8)};  // +3 steps reversing
      table::Axis1dSpec& a = s.axis1d[0];
      a.axis = 0;
      a.frac_bits = 8;
      a.dim = {2, -100000, 200000};
      a.forward.type = a.reverse.type = table::ElementType::kInt32;
      a.forward.i32 = x_fwd.data();
      a.has_reverse = true;
      a.reverse.i32 = x_rev.data();
      s.axis1d_count = 1;
    }
    img = testing::AlignedBytes(*table::ImageSize(s));
    EXPECT_TRUE(table::WriteImage(s, img.data(), img.size()).ok());
    view = *table::ParseImage(img.data(), img.size());
  }
};

class CompensatorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    config_ = DefaultBoardConfig();
    for (int a = 0; a < 3; ++a) {
      config_.axis[a].max_correction_steps = 100;
      config_.axis[a].max_correction_rate_steps_s = 1000;
      config_.axis[a].max_correction_accel_steps_s2 = 100000;
    }
    ASSERT_TRUE(comp_.Configure(config_).ok());
  }
  // Ticks with the axes at `pos_`; returns the last correction of axis 0.
  int32_t TickN(int n) {
    for (int i = 0; i < n; ++i) {
      comp_.Tick(pos_, corr_);
      for (int a = 0; a < 3; ++a) {
        const double applied = comp_.applied_q8(a) / kQ8;
        max_rate_ = std::max(max_rate_, std::fabs(applied - last_[a]));
        last_[a] = applied;
      }
    }
    return corr_[0];
  }
  PreparedTable Prepare(const TableFixture& f) {
    PreparedTable t;
    EXPECT_TRUE(t.Prepare(f.view, config_).ok());
    return t;
  }

  BoardConfig config_;
  Compensator comp_;
  int32_t pos_[3] = {0, 0, 0};
  int32_t corr_[3] = {};
  double last_[3] = {};
  double max_rate_ = 0;  // steps per tick
};

TEST_F(CompensatorTest, PassThroughUntilReferenced) {
  TableFixture f(10, -20, 30);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetEnabled(true);
  TickN(20000);
  EXPECT_EQ(corr_[0], 0);
  EXPECT_EQ(corr_[1], 0);
  EXPECT_TRUE(comp_.passthrough());
  EXPECT_FALSE(comp_.engaged());
  comp_.SetReferenced(true);
  EXPECT_TRUE(comp_.engaged());
  TickN(20000);
  EXPECT_EQ(corr_[0], 10);
  EXPECT_EQ(corr_[1], -20);
  EXPECT_EQ(corr_[2], 30);
  EXPECT_FALSE(comp_.passthrough());
}

TEST_F(CompensatorTest, EnableRampsInAndDisableRampsOutWithinLimits) {
  TableFixture f(50, 0, 0);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  std::vector<int32_t> ramp;
  for (int i = 0; i < 10000; ++i) {
    comp_.Tick(pos_, corr_);
    ramp.push_back(comp_.applied_q8(0));
  }
  EXPECT_EQ(ramp.back(), 50 * 256);
  // Monotonic ramp, each step within the rate limit (1000 steps/s at 50 kHz = 0.02 step/tick).
  for (size_t i = 1; i < ramp.size(); ++i) {
    ASSERT_GE(ramp[i], ramp[i - 1]);
    ASSERT_LE(ramp[i] - ramp[i - 1], 0.02 * 256 + 1);
  }
  const auto ticks_to_full = std::find(ramp.begin(), ramp.end(), 50 * 256) - ramp.begin();
  EXPECT_GT(ticks_to_full, 2500);  // 50 steps at 0.02 steps/tick takes >= 2500 ticks
  last_[0] = comp_.applied_q8(0) / kQ8;
  comp_.SetEnabled(false);
  TickN(10000);
  EXPECT_TRUE(comp_.passthrough());
  EXPECT_EQ(corr_[0], 0);
  EXPECT_LE(max_rate_, 0.02 + 1.0 / 256);
}

TEST_F(CompensatorTest, FaultRampsOut) {
  TableFixture f(0, 40, 0);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  TickN(10000);
  EXPECT_EQ(corr_[1], 40);
  comp_.SetFault(true);
  comp_.Tick(pos_, corr_);
  EXPECT_GE(corr_[1], 39);  // no jump
  TickN(10000);
  EXPECT_EQ(corr_[1], 0);
  EXPECT_TRUE(comp_.passthrough());
}

TEST_F(CompensatorTest, ClampHoldsTheConfiguredMaximum) {
  TableFixture f(5000, -5000, 99.5);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  TickN(30000);
  EXPECT_EQ(corr_[0], 100);
  EXPECT_EQ(corr_[1], -100);
  EXPECT_EQ(corr_[2], 100);  // 99.5 rounds half up
  EXPECT_EQ(comp_.target_q8(0), 100 * 256);
}

TEST_F(CompensatorTest, TableChangeIsSpreadWithinLimits) {
  TableFixture a(-30, 0, 0), b(30, 0, 0);
  comp_.SetTable(Prepare(a), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  TickN(10000);
  ASSERT_EQ(corr_[0], -30);
  max_rate_ = 0;
  comp_.SetTable(Prepare(b), pos_);
  EXPECT_EQ(comp_.table_id(), 42u);
  TickN(10000);
  EXPECT_EQ(corr_[0], 30);
  EXPECT_LE(max_rate_, 0.02 + 1.0 / 256);  // applied_q8() truncates to 1/256 step
}

TEST_F(CompensatorTest, ReverseDirectionSelectsTheReverseTable) {
  TableFixture f(0, 0, 0, /*x_table=*/true);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  pos_[0] = 100;
  TickN(5000);
  EXPECT_EQ(corr_[0], 0);
  EXPECT_FALSE(comp_.reverse(0));
  pos_[0] = 99;  // one step back: reversal
  TickN(5000);
  EXPECT_TRUE(comp_.reverse(0));
  EXPECT_EQ(corr_[0], 3);
  pos_[0] = 99;  // standing still keeps the direction
  TickN(100);
  EXPECT_TRUE(comp_.reverse(0));
  pos_[0] = 150;
  TickN(5000);
  EXPECT_FALSE(comp_.reverse(0));
  EXPECT_EQ(corr_[0], 0);
}

TEST_F(CompensatorTest, ImageForAnotherBoardIsRefusedAndNothingChanges) {
  TableFixture f(1, 2, 3);
  PreparedTable t;
  BoardConfig other = config_;
  other.axis[1].resolution_e9 = 500000;  // a different steps/mm on Y
  t.table_id = 99;
  EXPECT_EQ(t.Prepare(f.view, other).error(), Error::kConfigResolutionMismatch);
  EXPECT_EQ(t.table_id, 99u);
  other = config_;
  other.axis[2].name = 'W';
  EXPECT_EQ(t.Prepare(f.view, other).error(), Error::kConfigAxisMismatch);
  other.axis_count = 2;
  EXPECT_EQ(t.Prepare(f.view, other).error(), Error::kConfigTooManyAxes);
}

}  // namespace
}  // namespace volcomp
