// Number formatting and escaping (format.hpp).
#include "volcomp/report/format.hpp"

#include <gtest/gtest.h>

namespace volcomp::report {
namespace {

TEST(ReportFormat, FixedAndSigned) {
  EXPECT_EQ(FormatFixed(18.00395, 2), "18.00");
  EXPECT_EQ(FormatFixed(-0.001, 2), "0.00");
  EXPECT_EQ(FormatFixed(-1.5, 1), "-1.5");
  EXPECT_EQ(FormatFixed(1.0 / 0.0, 2), "n/a");
  EXPECT_EQ(FormatSigned(0.5, 1), "+0.5");
  EXPECT_EQ(FormatSigned(-0.5, 1), "-0.5");
}

TEST(ReportFormat, EscapeXml) {
  EXPECT_EQ(EscapeXml("a<b & \"c\"'"), "a&lt;b &amp; &quot;c&quot;&#39;");
}

}  // namespace
}  // namespace volcomp::report
