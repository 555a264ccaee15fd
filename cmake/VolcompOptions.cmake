# Shared compile options: one INTERFACE target per rule set.
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)

# Warnings for every project target.
add_library(volcomp_warnings INTERFACE)
target_compile_options(volcomp_warnings INTERFACE -Wall -Wextra -Wshadow -Wconversion
                                                  -Wno-sign-conversion)

# lib/ rules: freestanding C++17, no exceptions, no RTTI, warnings are errors.
set(VOLCOMP_FREESTANDING_FLAGS -ffreestanding -fno-exceptions -fno-rtti
    -fno-threadsafe-statics -Wall -Wextra -Werror -Wshadow -Wconversion -Wno-sign-conversion
    -Wdouble-promotion)
add_library(volcomp_freestanding INTERFACE)
target_compile_options(volcomp_freestanding INTERFACE ${VOLCOMP_FREESTANDING_FLAGS})

# Host floating point: no contraction, so host and target agree on float32 results.
add_library(volcomp_fp INTERFACE)
target_compile_options(volcomp_fp INTERFACE -ffp-contract=off)

# Checked results: Result<T>::value() / Expected<T>::value() of an error traps (lib/base status.hpp,
# hosted/ expected.hpp). On in Debug builds and in the sanitizer build (preset host-asan).
if(CMAKE_BUILD_TYPE STREQUAL "Debug")
  set(volcomp_checked_default ON)
else()
  set(volcomp_checked_default OFF)
endif()
option(VOLCOMP_CHECKED_RESULTS "value() of an error result traps" ${volcomp_checked_default})
if(VOLCOMP_CHECKED_RESULTS)
  add_compile_definitions(VOLCOMP_CHECKED_RESULTS=1)
endif()
