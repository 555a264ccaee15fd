// Helpers for the metrology tests: repository paths and exception-message checks.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <string>

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

/// Runs `f`, expects an exception of type E whose message contains every one of `parts`.
template <typename E>
void ExpectThrowWith(const std::function<void()>& f, std::initializer_list<std::string> parts) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one containing \"" << *parts.begin() << "\"";
  } catch (const E& e) {
    const std::string msg = e.what();
    for (const auto& p : parts) {
      EXPECT_NE(msg.find(p), std::string::npos)
          << "message \"" << msg << "\" lacks \"" << p << "\"";
    }
  }
}

}  // namespace volcomp::metrology::testing
