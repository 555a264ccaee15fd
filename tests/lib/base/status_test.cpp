// Status, Result<T>, the error names and texts, and the early-return macros VOLCOMP_TRY /
// VOLCOMP_TRY_ASSIGN on core types.
#include "volcomp/base/status.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>

namespace volcomp {
namespace {

TEST(ErrorName, NamesAndTextsOfKnownCodes) {
  EXPECT_STREQ(ErrorName(Error::kOk), "kOk");
  EXPECT_STREQ(ErrorText(Error::kOk), "ok");
  EXPECT_STREQ(ErrorName(Error::kImageBadCrc), "kImageBadCrc");
  EXPECT_STREQ(ErrorText(Error::kImageBadCrc), "image CRC-32 does not match");
  EXPECT_STREQ(ErrorName(Error::kConfigInvalid), "kConfigInvalid");
  EXPECT_STREQ(ErrorText(Error::kIoError), "I/O error");
  EXPECT_STREQ(Status(Error::kImageBadMagic).name(), "kImageBadMagic");
}

TEST(ErrorName, UnknownCodesGetAPlaceholderNeverNull) {
  const Error unknown = static_cast<Error>(0xFFFF);
  EXPECT_STREQ(ErrorName(unknown), "kUnknown");
  EXPECT_STREQ(ErrorText(unknown), "unknown error");
}

// Every row of error_codes.def: its name is the enumerator's, its value unique (codes are sent over
// CAN and documented), its text non-empty; the values written in the file are the enum's.
TEST(ErrorName, EveryCodeHasItsOwnValueNameAndText) {
  std::set<int> values;
  int rows = 0;
#define X(name, value, text)                                         \
  ++rows;                                                            \
  EXPECT_EQ(static_cast<int>(Error::name), value) << #name;          \
  EXPECT_TRUE(values.insert(value).second) << "duplicate " << #name; \
  EXPECT_STREQ(ErrorName(Error::name), #name);                       \
  EXPECT_STREQ(ErrorText(Error::name), text);                        \
  EXPECT_GT(std::strlen(text), 0u) << #name;
#include "volcomp/base/error_codes.def"
#undef X
  EXPECT_GT(rows, 40);
}

TEST(Status, OkByDefaultAndComparable) {
  constexpr Status ok;
  static_assert(ok.ok(), "a default Status is ok");
  static_assert(Status::Ok() == ok, "Ok() equals the default");
  const Status bad = Error::kBusy;
  EXPECT_FALSE(bad.ok());
  EXPECT_EQ(bad.error(), Error::kBusy);
  EXPECT_NE(bad, ok);
  EXPECT_EQ(bad, Status(Error::kBusy));
}

TEST(Result, ValueOrError) {
  const Result<int> seven = 7;
  ASSERT_TRUE(seven.ok());
  EXPECT_EQ(seven.value(), 7);
  EXPECT_EQ(*seven, 7);
  EXPECT_EQ(seven.status(), Status::Ok());
  const Result<int> bad = Error::kOutOfRange;
  EXPECT_FALSE(bad.ok());
  EXPECT_EQ(bad.error(), Error::kOutOfRange);
  EXPECT_EQ(bad.status(), Status(Error::kOutOfRange));
  const Result<int> from_status = Status(Error::kFull);
  EXPECT_EQ(from_status.error(), Error::kFull);
}

TEST(Result, ValueOrGivesTheFallbackOnlyOnError) {
  EXPECT_EQ(Result<int>(5).value_or(-1), 5);
  EXPECT_EQ(Result<int>(Error::kBusy).value_or(-1), -1);
  constexpr Result<uint32_t> c = Error::kNotReady;
  static_assert(c.value_or(42u) == 42u, "value_or is constexpr");
}

struct Point {
  int x = 0;
  int y = 0;
};

TEST(Result, ArrowReachesTheValue) {
  const Result<Point> p = Point{3, 4};
  EXPECT_EQ(p->x, 3);
  EXPECT_EQ(p->y, 4);
}

// ---- VOLCOMP_TRY / VOLCOMP_TRY_ASSIGN ----------------------------------------------------------

int g_evaluations = 0;

Status Step(Error e) {
  ++g_evaluations;
  return e;
}
Result<int> Number(int v, Error e = Error::kOk) {
  ++g_evaluations;
  if (e != Error::kOk) return e;
  return v;
}

// Runs three steps; `reached` counts the lines after each TRY that ran.
Status ThreeSteps(Error first, Error second, int* reached) {
  VOLCOMP_TRY(Step(first));
  ++*reached;
  VOLCOMP_TRY(Number(1, second));  // a Result works as well
  ++*reached;
  return Status::Ok();
}

TEST(VolcompTry, ReturnsTheFirstErrorAndEvaluatesOnce) {
  int reached = 0;
  g_evaluations = 0;
  EXPECT_EQ(ThreeSteps(Error::kOk, Error::kOk, &reached), Status::Ok());
  EXPECT_EQ(reached, 2);
  EXPECT_EQ(g_evaluations, 2);

  reached = 0;
  g_evaluations = 0;
  EXPECT_EQ(ThreeSteps(Error::kBusy, Error::kOk, &reached).error(), Error::kBusy);
  EXPECT_EQ(reached, 0);
  EXPECT_EQ(g_evaluations, 1);

  reached = 0;
  EXPECT_EQ(ThreeSteps(Error::kOk, Error::kIoError, &reached).error(), Error::kIoError);
  EXPECT_EQ(reached, 1);
}

// Sum of two numbers through TRY_ASSIGN: a declaration and an existing variable as lhs.
Result<int> Sum(Error first, Error second) {
  VOLCOMP_TRY_ASSIGN(const int a, Number(20, first));
  int b = -1;
  VOLCOMP_TRY_ASSIGN(b, Number(22, second));
  return a + b;
}

TEST(VolcompTryAssign, AssignsTheValueOrReturnsTheError) {
  g_evaluations = 0;
  const Result<int> ok = Sum(Error::kOk, Error::kOk);
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(*ok, 42);
  EXPECT_EQ(g_evaluations, 2);

  g_evaluations = 0;
  EXPECT_EQ(Sum(Error::kNotFound, Error::kOk).error(), Error::kNotFound);
  EXPECT_EQ(g_evaluations, 1);  // the second call never ran
  EXPECT_EQ(Sum(Error::kOk, Error::kFull).error(), Error::kFull);
}

// TRY_ASSIGN twice in a function returning Status (each temporary has its own name).
Status Check(int* out) {
  VOLCOMP_TRY_ASSIGN(const int a, Number(2));
  VOLCOMP_TRY_ASSIGN(const int b, Number(3));
  *out = a * b;
  return Status::Ok();
}

TEST(VolcompTryAssign, WorksInAStatusFunction) {
  int v = 0;
  EXPECT_TRUE(Check(&v).ok());
  EXPECT_EQ(v, 6);
}

}  // namespace
}  // namespace volcomp
