// Results of hosted code below the command line (hal/linux, firmware/linux): success or failure
// is typed, as Status / Result<T> are in lib/ (and with the same error codes), and a failure
// carries what an operator needs to act on it (file, interface, errno text, configuration line).
//
//   Expected<T>           a T, or a Failure;
//   Expected<void>        success, or a Failure;
//   Expected<T, E>        a T, or an E (a typed error of its own, e.g. a configuration file's
//                         line and reason).
//
//   return Fail(Error::kIoError, "tables.bin: cannot open: Permission denied");
//   if (!r.ok()) std::fprintf(stderr, "%s\n", r.error().message.c_str());
//
// No exceptions: the command line's main() decides how a failure ends the program.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "volcomp/status.hpp"

namespace volcomp {

/// What went wrong: one of the project's error codes and the readable detail.
struct Failure {
  Error code = Error::kIoError;
  std::string message;
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

/// A value of T, or an error E.
template <typename T, typename E = Failure>
class [[nodiscard]] Expected {
 public:
  Expected(T value) : value_(std::move(value)) {}                    // NOLINT: implicit by design
  Expected(Unexpected<E> error) : error_(std::move(error.error)) {}  // NOLINT

  bool ok() const { return !error_.has_value(); }
  /// The value; only when ok().
  const T& value() const { return *value_; }
  T& value() { return *value_; }
  const T& operator*() const { return *value_; }
  const T* operator->() const { return &*value_; }
  /// The error; only when !ok().
  const E& error() const { return *error_; }

 private:
  std::optional<T> value_;
  std::optional<E> error_;
};

/// Success, or an error E.
template <typename E>
class [[nodiscard]] Expected<void, E> {
 public:
  Expected() = default;
  Expected(Unexpected<E> error) : error_(std::move(error.error)) {}  // NOLINT
  static Expected Ok() { return Expected(); }

  bool ok() const { return !error_.has_value(); }
  /// The error; only when !ok().
  const E& error() const { return *error_; }

 private:
  std::optional<E> error_;
};

}  // namespace volcomp
