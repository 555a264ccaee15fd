# Included at the end of the top-level project() in cross builds (CMAKE_PROJECT_volcomp_INCLUDE,
# set by toolchain/arm-none-eabi-cm4f.cmake): enables ctest from the top build directory, where the
# QEMU test images (tests/target/) and the cycle-budget checks register their tests.
enable_testing()
