// Whether the test binary runs under a sanitizer (the slower runs then use smaller workloads).
#pragma once

namespace volcomp::testing {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

}  // namespace volcomp::testing
