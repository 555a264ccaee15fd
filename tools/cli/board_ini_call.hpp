// TRANSITION(H1): tools/board_ini still reports errors by throwing (tools::InputError,
// tools::CommunicationError); this is the one place the CAN commands catch them, as Failures
// (kInputInvalid: exit 1, kCommunication: exit 3). Goes when board_ini returns results.
#pragma once

#include <exception>
#include <type_traits>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/exit_codes.hpp"

namespace volcomp::cli {

/// The result of `call()` (a call into board_ini), or its exception as a Failure.
template <typename F, typename R = std::invoke_result_t<F&>>
Expected<R> CallBoardIni(F&& call) {
  try {
    if constexpr (std::is_void_v<R>) {
      call();
      return Expected<R>();
    } else {
      return call();
    }
  } catch (const tools::CommunicationError& e) {
    return Fail(Error::kCommunication, e.what());
  } catch (const std::exception& e) {
    return Fail(Error::kInputInvalid, e.what());
  }
}

}  // namespace volcomp::cli
