// The result type of hosted code (hal/linux, firmware/linux_board, tools/, host-sim/, linuxcnc/): a
// value or a Failure, as Status / Result<T> are in lib/ and with the same error codes, plus what an
// operator needs to act on the failure in words (file, line, interface, errno text, object).
//
//   Expected<T>        a T, or a Failure;
//   Expected<void>     success, or a Failure;
//   Expected<T, E>     a T, or an E (a typed error of its own, e.g. a configuration file's line).
//
//   return Fail(Error::kIoError, "tables.bin: cannot open: Permission denied");
//   VOLCOMP_TRY_ASSIGN(const CsvTable table, ReadCsvFile(path));   // returns the failure
//   VOLCOMP_TRY(WriteFile(path, text));
//
// Libraries return these and never throw; the command layer (tools/cli, host-sim/app) turns a
// failure into a message and an exit code. value() of a failure, or error() of a value, is a
// programming error: checked in checked builds (VOLCOMP_CHECKED_RESULTS), where it aborts with
// the failure's message.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

#include "volcomp/base/status.hpp"

namespace volcomp {

/// What went wrong: one of the project's error codes and the readable detail.
struct Failure {
  Error code = Error::kIoError;
  std::string message;

  /// `context: message`, e.g. Failure{..., "line 4: bad number"}.Prefixed("x.csv").
  Failure Prefixed(const std::string& context) const {
    return Failure{code, message.empty() ? context : context + ": " + message};
  }
};

/// An error on its way into an Expected (keeps T and E apart even when they are one type).
template <typename E>
struct Unexpected {
  E error;
};

template <typename E>
Unexpected<E> Fail(E error) {
  return Unexpected<E>{std::move(error)};
}
inline Unexpected<Failure> Fail(Error code, std::string message) {
  return Unexpected<Failure>{Failure{code, std::move(message)}};
}
/// A core Status as a failure; the message is `context` followed by the error's description.
inline Unexpected<Failure> Fail(Status status, const std::string& context = "") {
  std::string text = ErrorText(status.error());
  return Fail(status.error(), context.empty() ? text : context + ": " + text);
}

namespace internal {
[[noreturn]] inline void BadAccess(const char* what, const std::string& detail) {
  std::fprintf(stderr, "volcomp: %s %s\n", what, detail.c_str());
  std::abort();
}
inline std::string Describe(const Failure& f) { return f.message; }
template <typename E>
std::string Describe(const E&) {
  return "(typed error)";
}
}  // namespace internal

/// A value of T, or an error E.
template <typename T, typename E = Failure>
class [[nodiscard]] Expected {
 public:
  Expected(T value) : value_(std::move(value)) {}                    // NOLINT: implicit by design
  Expected(Unexpected<E> error) : error_(std::move(error.error)) {}  // NOLINT
  /// A failed core Status (Failure only): the error's code and description.
  template <typename F = E, typename = std::enable_if_t<std::is_same<F, Failure>::value>>
  Expected(Status status) : Expected(Fail(status)) {}  // NOLINT: VOLCOMP_TRY of a core call

  bool ok() const { return !error_.has_value(); }
  /// The value; only when ok().
  const T& value() const& { return CheckValue(), *value_; }
  T& value() & { return CheckValue(), *value_; }
  T&& value() && { return CheckValue(), std::move(*value_); }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }
  /// The error; only when !ok().
  const E& error() const { return CheckError(), *error_; }

 private:
  void CheckValue() const {
#if defined(VOLCOMP_CHECKED_RESULTS)
    if (!ok()) internal::BadAccess("value() of a failure:", internal::Describe(*error_));
#endif
  }
  void CheckError() const {
#if defined(VOLCOMP_CHECKED_RESULTS)
    if (ok()) internal::BadAccess("error() of a value", "");
#endif
  }

  std::optional<T> value_;
  std::optional<E> error_;
};

/// Success, or an error E.
template <typename E>
class [[nodiscard]] Expected<void, E> {
 public:
  Expected() = default;
  Expected(Unexpected<E> error) : error_(std::move(error.error)) {}  // NOLINT
  template <typename F = E, typename = std::enable_if_t<std::is_same<F, Failure>::value>>
  Expected(Status status) {  // NOLINT: VOLCOMP_TRY of a core call
    if (!status.ok()) error_ = Fail(status).error;
  }
  static Expected Ok() { return Expected(); }

  bool ok() const { return !error_.has_value(); }
  /// The error; only when !ok().
  const E& error() const {
#if defined(VOLCOMP_CHECKED_RESULTS)
    if (ok()) internal::BadAccess("error() of a success", "");
#endif
    return *error_;
  }

 private:
  std::optional<E> error_;
};

/// Success or a Failure (the hosted Status).
using Outcome = Expected<void>;

namespace internal {
// VOLCOMP_TRY / VOLCOMP_TRY_ASSIGN (status.hpp) on an Expected: its error, moved on.
template <typename T, typename E>
Unexpected<E> TryFailure(const Expected<T, E>& r) {
  return Unexpected<E>{r.error()};
}
template <typename T, typename E>
T TakeValue(Expected<T, E>& r) {
  return std::move(r).value();
}
}  // namespace internal

}  // namespace volcomp
