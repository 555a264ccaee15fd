// Status and Result<T>: the error type of every volcomp API (no exceptions anywhere in lib/).
//
// Modelled on pw::Status / pw::Result: small, constexpr, [[nodiscard]]. Status wraps one Error code
// from error_codes.def; Result<T> is a value or an Error. Both are trivially copyable when T is.
// Result<T>::value() of an error traps in checked builds (VOLCOMP_CHECKED_RESULTS: Debug and the
// sanitizer build). VOLCOMP_TRY / VOLCOMP_TRY_ASSIGN return early on an error; they also take the
// hosted Expected<T> (hosted/include/volcomp/hosted/expected.hpp).
#pragma once

#include <cstdint>
#include <type_traits>

namespace volcomp {

enum class Error : uint16_t {
#define X(name, value, text) name = value,
#include "volcomp/base/error_codes.def"
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
  /// The value; only when ok() (traps otherwise in checked builds).
  constexpr const T& value() const { return Checked(), value_; }
  constexpr T& value() { return Checked(), value_; }
  constexpr const T& operator*() const { return value(); }
  constexpr const T* operator->() const { return &value(); }
  /// The value, or `fallback` when not ok().
  constexpr T value_or(const T& fallback) const { return ok() ? value_ : fallback; }

 private:
  constexpr void Checked() const {
#if defined(VOLCOMP_CHECKED_RESULTS)
    if (!status_.ok()) __builtin_trap();  // value() of an error: a programming error
#endif
  }

  T value_{};
  Status status_;
};

namespace internal {
// What VOLCOMP_TRY / VOLCOMP_TRY_ASSIGN return for a failed expression (overloaded for the hosted
// Expected<T> in hosted/include/volcomp/hosted/expected.hpp).
constexpr Status TryFailure(Status s) { return s; }
template <typename T>
constexpr Status TryFailure(const Result<T>& r) {
  return r.status();
}
template <typename T>
constexpr T TakeValue(Result<T>& r) {
  return r.value();
}
}  // namespace internal

}  // namespace volcomp

#define VOLCOMP_CONCAT_INNER(a, b) a##b
#define VOLCOMP_CONCAT(a, b) VOLCOMP_CONCAT_INNER(a, b)

/// Returns early from the enclosing function when `expr` (a Status, Result<T> or hosted Expected)
/// is not ok, with its error.
#define VOLCOMP_TRY(expr)                                                         \
  do {                                                                            \
    auto&& volcomp_try_ = (expr);                                                 \
    if (!volcomp_try_.ok()) return ::volcomp::internal::TryFailure(volcomp_try_); \
  } while (0)

/// `lhs = the value of expr` (a Result<T> or hosted Expected<T>), or returns its error, as
/// PW_TRY_ASSIGN: `VOLCOMP_TRY_ASSIGN(const auto view, ParseImage(data, size));`.
#define VOLCOMP_TRY_ASSIGN(lhs, expr) \
  VOLCOMP_TRY_ASSIGN_IMPL(VOLCOMP_CONCAT(volcomp_try_assign_, __LINE__), lhs, expr)
#define VOLCOMP_TRY_ASSIGN_IMPL(tmp, lhs, expr)               \
  auto tmp = (expr);                                          \
  if (!tmp.ok()) return ::volcomp::internal::TryFailure(tmp); \
  lhs = ::volcomp::internal::TakeValue(tmp)
