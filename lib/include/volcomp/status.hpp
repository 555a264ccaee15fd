// Status and Result<T>: the error type of every volcomp API (no exceptions anywhere in lib/).
//
// Modelled on pw::Status / pw::Result: small, constexpr, [[nodiscard]]. Status wraps one Error code
// from error_codes.def; Result<T> is a value or an Error. Both are trivially copyable when T is.
#pragma once

#include <cstdint>
#include <type_traits>

namespace volcomp {

enum class Error : uint16_t {
#define X(name, value, text) name = value,
#include "volcomp/error_codes.def"
#undef X
};

/// Readable name of an error, e.g. "kImageBadCrc". Never null; unknown codes give "kUnknown".
const char* ErrorName(Error e);
/// One-line description, e.g. "image CRC-32 does not match". Never null.
const char* ErrorText(Error e);

class [[nodiscard]] Status {
 public:
  constexpr Status() = default;
  constexpr Status(Error e) : error_(e) {}  // NOLINT: implicit by design, `return Error::kX;`
  static constexpr Status Ok() { return Status(); }

  constexpr bool ok() const { return error_ == Error::kOk; }
  constexpr Error error() const { return error_; }
  const char* name() const { return ErrorName(error_); }
  constexpr bool operator==(Status o) const { return error_ == o.error_; }
  constexpr bool operator!=(Status o) const { return error_ != o.error_; }
  /// Explicitly ignore a status (use sparingly, with a comment saying why).
  constexpr void IgnoreError() const {}

 private:
  Error error_ = Error::kOk;
};

/// A value of T, or an Error. T must be default-constructible (fixed-size embedded types are).
template <typename T>
class [[nodiscard]] Result {
  static_assert(std::is_default_constructible<T>::value, "Result<T> needs a default T");

 public:
  constexpr Result(const T& value) : value_(value) {}  // NOLINT: implicit like pw::Result
  constexpr Result(Error e) : status_(e) {}            // NOLINT
  constexpr Result(Status s) : status_(s) {}           // NOLINT

  constexpr bool ok() const { return status_.ok(); }
  constexpr Status status() const { return status_; }
  constexpr Error error() const { return status_.error(); }
  /// The value; only meaningful when ok().
  constexpr const T& value() const { return value_; }
  constexpr T& value() { return value_; }
  constexpr const T& operator*() const { return value_; }
  constexpr const T* operator->() const { return &value_; }

 private:
  T value_{};
  Status status_;
};

}  // namespace volcomp

/// Return early from the enclosing function when `expr` (a Status) is not ok.
#define VOLCOMP_TRY(expr)                          \
  do {                                             \
    const ::volcomp::Status volcomp_try_ = (expr); \
    if (!volcomp_try_.ok()) return volcomp_try_;   \
  } while (0)
