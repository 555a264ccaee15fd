// What a table asks of the board (largest correction, gradients) and the refusals of a table the
// board would refuse, clamp or rate-limit, against values worked out by hand from the nodes.
#include <gtest/gtest.h>

#include "board_fit.hpp"
#include "test_tables.hpp"
#include "volcomp/image/table_demands.hpp"

namespace volcomp::testing {
namespace {

// 3 x 2 x 2 nodes. X component along x: 0, 30, -10 steps (spacing 1000 steps): largest |X| 30,
// steepest 40 steps over 1000 = 0.04 per step. Z component along z: 0 then 5 (spacing 500):
// largest 5, gradient 0.01. Y component 0.
AlignedBytes HandTable() {
  GridCase g;
  g.frac_bits = 4;
  g.dim[0] = {3, 0, 1000};
  g.dim[1] = {2, 0, 2000};
  g.dim[2] = {2, 0, 500};
  const double xs[3] = {0, 30, -10};
  for (uint32_t k = 0; k < 2; ++k) {
    for (uint32_t j = 0; j < 2; ++j) {
      for (uint32_t i = 0; i < 3; ++i) {
        for (double v : {xs[i], 0.0, k == 1 ? 5.0 : 0.0}) {
          g.i16.push_back(static_cast<int16_t>(v * 16));
          g.steps.push_back(v);
        }
      }
    }
  }
  return WriteGridImage(g, 3);
}

cli::BoardInstallation Board(int32_t max_correction, uint32_t max_rate, uint32_t input_rate) {
  cli::BoardInstallation b;
  for (char name : {'X', 'Y', 'Z'}) {
    cli::BoardAxis a;
    a.name = name;
    a.resolution_e9 = 1000000;
    a.max_correction_steps = max_correction;
    a.max_rate_steps_s = max_rate;
    a.max_input_rate_hz = input_rate;
    b.axes.push_back(a);
  }
  return b;
}

TEST(TableDemands, LargestCorrectionAndGradientsFromTheNodes) {
  const AlignedBytes img = HandTable();
  const auto view = table::ParseImage(img.data(), img.size());
  ASSERT_TRUE(view.ok());
  const auto d = image::TableDemands(*view);
  ASSERT_EQ(d.size(), 3u);
  EXPECT_DOUBLE_EQ(d[0].max_correction_steps, 30);
  EXPECT_DOUBLE_EQ(d[0].gradient[0], 0.04);
  EXPECT_DOUBLE_EQ(d[0].gradient[1], 0);
  EXPECT_DOUBLE_EQ(d[0].gradient[2], 0);
  EXPECT_DOUBLE_EQ(d[1].max_correction_steps, 0);
  EXPECT_DOUBLE_EQ(d[2].max_correction_steps, 5);
  EXPECT_DOUBLE_EQ(d[2].gradient[2], 0.01);
  EXPECT_DOUBLE_EQ(d[2].gradient[0], 0);
}

TEST(TableFit, ATableWithinTheLimitsFits) {
  const AlignedBytes img = HandTable();
  const auto view = table::ParseImage(img.data(), img.size());
  ASSERT_TRUE(view.ok());
  // 0.04 x 50000 steps/s = 2000 steps/s: exactly the limit.
  EXPECT_TRUE(cli::CheckTableFits(*view, Board(30, 2000, 50000)).empty());
}

TEST(TableFit, ClampAndRateLimitNameTheAxisTheValueAndTheLimit) {
  const AlignedBytes img = HandTable();
  const auto view = table::ParseImage(img.data(), img.size());
  ASSERT_TRUE(view.ok());
  // Max correction 20 < 30 on X; 0.04 x 100000 = 4000 > 2000 steps/s on X; Z 0.01 x 100000 =
  // 1000 fits.
  const auto p = cli::CheckTableFits(*view, Board(20, 2000, 100000));
  ASSERT_EQ(p.size(), 2u);
  EXPECT_TRUE(p[0].limit);
  EXPECT_NE(p[0].message.find("axis 1 (X)"), std::string::npos) << p[0].message;
  EXPECT_NE(p[0].message.find("30.0 steps"), std::string::npos) << p[0].message;
  EXPECT_NE(p[0].message.find("(0x2015:1) is 20 steps"), std::string::npos) << p[0].message;
  EXPECT_TRUE(p[1].limit);
  EXPECT_NE(p[1].message.find("axis 1 (X)"), std::string::npos) << p[1].message;
  EXPECT_NE(p[1].message.find("4000 steps/s"), std::string::npos) << p[1].message;
  EXPECT_NE(p[1].message.find("(0x2016:1) is 2000 steps/s"), std::string::npos) << p[1].message;
}

TEST(TableFit, AnotherResolutionOrFewerAxesIsAMismatchNotALimit) {
  const AlignedBytes img = HandTable();
  const auto view = table::ParseImage(img.data(), img.size());
  ASSERT_TRUE(view.ok());
  cli::BoardInstallation b = Board(1000, 2000, 1000);
  b.axes[1].resolution_e9 = 500000;
  auto p = cli::CheckTableFits(*view, b);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_FALSE(p[0].limit);
  EXPECT_NE(p[0].message.find("axis 2 (Y)"), std::string::npos) << p[0].message;
  // 1 µm per step is 1000 steps/mm; 0.5 µm per step (500000 pm) is 2000 steps/mm.
  EXPECT_NE(p[0].message.find("the table was built for 1000 steps/mm (1000 nm/step), the board "
                              "runs 2000 steps/mm (500 nm/step) (0x2012:2)"),
            std::string::npos)
      << p[0].message;
  b = Board(1000, 2000, 1000);
  b.axes.pop_back();
  p = cli::CheckTableFits(*view, b);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_FALSE(p[0].limit);
  EXPECT_NE(p[0].message.find("the table has 3 axes, the board 2"), std::string::npos);
}

}  // namespace
}  // namespace volcomp::testing
