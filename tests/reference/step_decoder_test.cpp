// Input decoders for step+dir, CW/CCW and quadrature.
#include "volcomp/reference/step_decoder.hpp"

#include <gtest/gtest.h>

namespace volcomp {
namespace {

TEST(StepDecoder, StepDirCountsRisingEdgesByDirection) {
  StepDecoder d(PulseFormat::kStepDir);
  d.Reset(false, true);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(d.Sample(true, true), 1);
    EXPECT_EQ(d.Sample(false, true), 0);
  }
  d.Sample(false, false);  // direction change alone counts nothing
  for (int i = 0; i < 3; ++i) {
    d.Sample(true, false);
    d.Sample(false, false);
  }
  EXPECT_EQ(d.count(), 2);
  StepDecoder inv(PulseFormat::kStepDir, /*invert_dir=*/true);
  inv.Sample(true, true);
  EXPECT_EQ(inv.count(), -1);
}

TEST(StepDecoder, CwCcwCountsEachLine) {
  StepDecoder d(PulseFormat::kCwCcw);
  d.Sample(true, false);
  d.Sample(false, false);
  d.Sample(false, true);
  d.Sample(false, false);
  d.Sample(false, true);
  EXPECT_EQ(d.count(), -1);
}

TEST(StepDecoder, QuadratureCountsEveryEdgeAndFlagsSkips) {
  StepDecoder d(PulseFormat::kQuadrature);
  const bool seq[4][2] = {{true, false}, {true, true}, {false, true}, {false, false}};
  for (int cycle = 0; cycle < 10; ++cycle) {
    for (const auto& s : seq) d.Sample(s[0], s[1]);
  }
  EXPECT_EQ(d.count(), 40);
  for (int cycle = 0; cycle < 3; ++cycle) {
    for (int i = 3; i >= 0; --i) d.Sample(seq[(i + 3) % 4][0], seq[(i + 3) % 4][1]);
  }
  EXPECT_EQ(d.count(), 28);
  EXPECT_EQ(d.errors(), 0u);
  d.Sample(true, true);  // from 00 both lines at once: a decoding error, no count
  EXPECT_EQ(d.errors(), 1u);
  EXPECT_EQ(d.count(), 28);
}

}  // namespace
}  // namespace volcomp
