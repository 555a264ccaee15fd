// Nice ticks and linear scales (scale.hpp).
#include "volcomp/report/scale.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace volcomp::report {
namespace {

TEST(ReportScale, NiceTicks) {
  EXPECT_EQ(NiceTicks(0.0, 10.0, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(NiceTicks(-11.12, 6.88, 6), (std::vector<double>{-10, -8, -6, -4, -2, 0, 2, 4, 6}));
  double lo = -11.12, hi = 6.88;
  ExpandToNice(&lo, &hi, 6);
  EXPECT_DOUBLE_EQ(lo, -12.0);
  EXPECT_DOUBLE_EQ(hi, 8.0);
  const LinearScale s(0.0, 10.0, 100.0, 0.0);
  EXPECT_DOUBLE_EQ(s(2.5), 75.0);
}

}  // namespace
}  // namespace volcomp::report
