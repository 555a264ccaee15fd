// How the CAN commands report a failed object access: the client's SdoFailure as the tool's
// Failure (kCommunication when nothing answered or the link failed: exit 3; a refusal: exit 1),
// explained by the step that failed.
#pragma once

#include <string>
#include <type_traits>
#include <utility>

#include "command.hpp"
#include "volcomp/canopen_client/node_objects.hpp"
#include "volcomp/canopen_client/table_staging.hpp"

namespace volcomp::cli {

/// The Failure part of `f` (its code and message).
inline Failure ToFailure(const canopen_client::SdoFailure& f) { return Failure{f.code, f.message}; }

/// The value of `r`, or its failure as the tool reports it (already explained by the library).
template <typename T>
Expected<T> Required(canopen_client::SdoExpected<T> r) {
  if (!r.ok()) return Fail(ToFailure(r.error()));
  if constexpr (std::is_void_v<T>) {
    return Outcome::Ok();
  } else {
    return std::move(r).value();
  }
}

/// The value of `r`, or its failure explained by `step` ("step: reason; what to do").
template <typename T>
Expected<T> Checked(canopen_client::SdoExpected<T> r, const std::string& step) {
  return Required(canopen_client::Explain(std::move(r), step));
}

/// A numeric object of `node`; a failure reads "reading WHAT: ...".
inline Expected<uint32_t> ReadNumber(canopen_client::NodeObjects& node,
                                     canopen::ObjectId id,
                                     const std::string& what) {
  return Checked(node.Read(id), "reading " + what);
}

}  // namespace volcomp::cli
