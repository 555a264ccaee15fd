// Tests of code that returns Expected<T>: the value, or the test fails with the failure's message
// (thrown as an exception the test framework reports), for tests whose subject is the value.
#pragma once

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

}  // namespace volcomp::testing
