// Helpers for the metrology tests: repository paths and checks of returned failures.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology::testing {

/// The repository root: $VOLCOMP_SOURCE_DIR (set by ctest), else the configure-time path.
inline std::string SourceDir() {
  if (const char* env = std::getenv("VOLCOMP_SOURCE_DIR")) return env;
#ifdef VOLCOMP_TEST_SOURCE_DIR
  return VOLCOMP_TEST_SOURCE_DIR;
#else
  return ".";
#endif
}

inline std::string RepoPath(const std::string& relative) { return SourceDir() + "/" + relative; }

/// The value of `r`; an unexpected failure ends the test with its message.
template <typename T>
T Must(Expected<T> r) {
  if (!r.ok()) throw std::runtime_error("unexpected failure: " + r.error().message);
  return std::move(r).value();
}

/// The CSV table of `text`, named `source` in messages.
inline tools::CsvTable Csv(const std::string& text, const std::string& source) {
  return Must(tools::CsvTable::ReadString(text, source));
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

}  // namespace volcomp::metrology::testing
