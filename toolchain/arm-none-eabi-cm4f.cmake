# CMake toolchain file: Cortex-M4F (STM32G474, QEMU mps2-an386) with Debian's arm-none-eabi GCC 12.
#
#   cmake --preset arm-m4f      (or: cmake -DCMAKE_TOOLCHAIN_FILE=toolchain/arm-none-eabi-cm4f.cmake)
#
# Packages: scripts/setup-deps.sh arm. Executables are bare-metal images; ctest runs the ones that
# register tests under QEMU's mps2-an386 machine (Cortex-M4 + FPv4-SP) through
# CMAKE_CROSSCOMPILING_EMULATOR (toolchain/qemu/run-mps2-an386.sh: semihosting, exit code, timeout).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(VOLCOMP_ARM_PREFIX arm-none-eabi- CACHE STRING "Cross tool prefix")
set(CMAKE_C_COMPILER ${VOLCOMP_ARM_PREFIX}gcc)
set(CMAKE_CXX_COMPILER ${VOLCOMP_ARM_PREFIX}g++)
set(CMAKE_ASM_COMPILER ${VOLCOMP_ARM_PREFIX}gcc)
set(CMAKE_OBJCOPY ${VOLCOMP_ARM_PREFIX}objcopy CACHE FILEPATH "")
set(CMAKE_OBJDUMP ${VOLCOMP_ARM_PREFIX}objdump CACHE FILEPATH "")
set(CMAKE_SIZE ${VOLCOMP_ARM_PREFIX}size CACHE FILEPATH "")
set(CMAKE_NM ${VOLCOMP_ARM_PREFIX}nm CACHE FILEPATH "")

# Compiler checks build a static library: there is no startup code to link an executable with yet.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Cortex-M4 with the single-precision FPU, hard-float ABI (the same code runs on the STM32G474 and
# on QEMU's mps2-an386). Sections per function/object so the linker drops what is unused.
set(VOLCOMP_CM4F_FLAGS "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
set(CMAKE_C_FLAGS_INIT "${VOLCOMP_CM4F_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${VOLCOMP_CM4F_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${VOLCOMP_CM4F_FLAGS}")
# The arm-m4f preset builds RelWithDebInfo (-O2 -g): the cycle figures in docs/mcu-target.md are
# for -O2; -g only adds debug sections (the code is the same).
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostartfiles -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# add_test(NAME x COMMAND <image target>) runs the image under QEMU.
set(CMAKE_CROSSCOMPILING_EMULATOR ${CMAKE_CURRENT_LIST_DIR}/qemu/run-mps2-an386.sh)

# The top-level CMakeLists.txt skips tests/ in cross builds; this file (included at the end of the
# top-level project() call) turns ctest on so that the QEMU images' tests are found from the top.
set(CMAKE_PROJECT_volcomp_INCLUDE ${CMAKE_CURRENT_LIST_DIR}/arm-m4f-project.cmake)
