// Tests of code that returns Expected<T>: the value, or the test fails with the failure's message
// (thrown as an exception the test framework reports), for tests whose subject is the value; and
// the check of a failure's code and message, for tests whose subject is the refusal.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::testing {

template <typename T>
T ValueOf(Expected<T> r) {
  if (!r.ok()) throw std::runtime_error("unexpected failure: " + r.error().message);
  return std::move(r).value();
}

inline void CheckOk(const Outcome& r) {
  if (!r.ok()) throw std::runtime_error("unexpected failure: " + r.error().message);
}

/// Expects `r` to be a failure with `code` whose message contains every one of `parts`.
template <typename T>
void ExpectFailure(const Expected<T>& r, Error code, std::initializer_list<std::string> parts) {
  ASSERT_FALSE(r.ok()) << "no failure; expected one containing \"" << *parts.begin() << "\"";
  const std::string& msg = r.error().message;
  EXPECT_EQ(r.error().code, code) << "code " << ErrorText(r.error().code) << ": " << msg;
  for (const auto& p : parts) {
    EXPECT_NE(msg.find(p), std::string::npos) << "message \"" << msg << "\" lacks \"" << p << "\"";
  }
}

}  // namespace volcomp::testing
