// TRANSITION(tools): the PC tool's libraries the simulator calls (tools/model, image, metrology,
// report, can_io) still throw. Every such call goes through FromTools, which returns the value,
// or the exception as a Failure (`code`, the exception's text):
//   VOLCOMP_TRY_ASSIGN(auto grid, FromTools([&] { return model::BuildGridSection(...); }));
// Goes, with its call sites, once those libraries return results.
#pragma once

#include <exception>
#include <type_traits>
#include <utility>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::sim {

template <typename Call, typename R = std::invoke_result_t<Call&>>
Expected<R> FromTools(Call&& call, Error code = Error::kInputInvalid) {
  try {
    if constexpr (std::is_void_v<R>) {
      call();
      return Outcome::Ok();
    } else {
      return call();
    }
  } catch (const std::exception& e) {
    return Fail(code, e.what());
  }
}

}  // namespace volcomp::sim
