// Bare-metal C/C++ runtime for the Cortex-M4F images (STM32G474 firmware, QEMU test images):
// .data/.bss initialisation, static constructors and the C++ ABI hooks (the memory primitives are
// in mem_primitives.cpp). No libc, no libstdc++: images link with -nostdlib and libgcc.
#include "cm4_runtime.hpp"

#include <cstddef>
#include <cstdint>

extern "C" {

// Linker-script symbols (see the images' .ld files).
extern uint32_t __data_load[];
extern uint32_t __data_start[];
extern uint32_t __data_end[];
extern uint32_t __bss_start[];
extern uint32_t __bss_end[];
extern uint32_t __ccm_load[];
extern uint32_t __ccm_start[];
extern uint32_t __ccm_end[];
extern uint32_t __ccm_bss_start[];
extern uint32_t __ccm_bss_end[];
using InitFn = void (*)();
extern InitFn __init_array_start[];
extern InitFn __init_array_end[];

// A pure virtual call is a bug: stop where a debugger sees it.
void __cxa_pure_virtual() { volcomp_runtime_panic(); }

// No atexit: firmware never returns from main, test images exit through semihosting.
int __aeabi_atexit(void*, void (*)(void*), void*) { return 0; }
void* __dso_handle = nullptr;

__attribute__((weak, noreturn)) void volcomp_runtime_panic() {
  for (;;) {
    __asm volatile("bkpt #0");
  }
}

}  // extern "C"

namespace volcomp::runtime {

static void Copy(uint32_t* dst, const uint32_t* src, const uint32_t* end) {
  while (dst < end) *dst++ = *src++;
}

void InitMemory() {
  Copy(__data_start, __data_load, __data_end);
  Copy(__ccm_start, __ccm_load, __ccm_end);
  for (uint32_t* p = __bss_start; p < __bss_end; ++p) *p = 0;
  for (uint32_t* p = __ccm_bss_start; p < __ccm_bss_end; ++p) *p = 0;
}

void RunConstructors() {
  for (InitFn* f = __init_array_start; f < __init_array_end; ++f) (*f)();
}

void EnableFpu() {
  // CPACR (Cortex-M4 Generic User Guide 4.6.1): full access to CP10 and CP11, then wait until the
  // write has taken effect before the first floating-point instruction.
  volatile uint32_t* const cpacr = reinterpret_cast<volatile uint32_t*>(0xE000ED88u);
  *cpacr = *cpacr | (0xFu << 20);
  __asm volatile("dsb\n\tisb" ::: "memory");
}

}  // namespace volcomp::runtime
