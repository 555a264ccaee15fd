// SimStatus and SimResult<T>: the error type of the simulator's sessions (hosted code). The same
// shape as volcomp::Status / Result<T> (lib/base/include/volcomp/base/status.hpp), plus the reason in words,
// because a session's failures need them: an SDO abort with its object, a program that did not
// finish, a board that refused to activate. Errors are returned, never thrown; the command line
// (demo_cli.cpp) is where they are printed.
#pragma once

#include <string>
#include <utility>

#include "volcomp/base/status.hpp"

namespace volcomp::sim {

class [[nodiscard]] SimStatus {
 public:
  SimStatus() = default;
  SimStatus(Error code, std::string reason) : code_(code), reason_(std::move(reason)) {}
  static SimStatus Ok() { return SimStatus(); }

  bool ok() const { return code_ == Error::kOk; }
  Error code() const { return code_; }
  /// What failed, in words (empty when ok()).
  const std::string& reason() const { return reason_; }

 private:
  Error code_ = Error::kOk;
  std::string reason_;
};

/// A value of T or a failed SimStatus.
template <typename T>
class [[nodiscard]] SimResult {
 public:
  SimResult(T value) : value_(std::move(value)) {}             // NOLINT: implicit like Result<T>
  SimResult(SimStatus status) : status_(std::move(status)) {}  // NOLINT

  bool ok() const { return status_.ok(); }
  const SimStatus& status() const { return status_; }
  /// The value; only meaningful when ok().
  const T& value() const { return value_; }
  T& value() { return value_; }
  const T& operator*() const { return value_; }
  const T* operator->() const { return &value_; }
  T* operator->() { return &value_; }

 private:
  T value_{};
  SimStatus status_;
};

}  // namespace volcomp::sim

/// Returns the enclosing function's failure when `expr` (a SimStatus) is not ok.
#define VOLCOMP_SIM_TRY(expr)                            \
  do {                                                   \
    ::volcomp::sim::SimStatus volcomp_sim_try_ = (expr); \
    if (!volcomp_sim_try_.ok()) return volcomp_sim_try_; \
  } while (0)

/// `lhs = value of expr` (a SimResult), or returns its failure.
#define VOLCOMP_SIM_ASSIGN(lhs, expr)                                   \
  do {                                                                  \
    auto volcomp_sim_result_ = (expr);                                  \
    if (!volcomp_sim_result_.ok()) return volcomp_sim_result_.status(); \
    lhs = std::move(volcomp_sim_result_.value());                       \
  } while (0)
