// STM32G474 reset and vector table: FPU on, flash contents copied (.data, CCM SRAM tick path),
// .bss cleared, static constructors, then main(). Armv7-M system exceptions plus the 102 device
// interrupts of the STM32G474 (RM0440 §13.3, Table 97); unused ones stop in DefaultHandler.
#include <cstdint>

#include "cm4_runtime.hpp"

int main();
extern "C" void volcomp_tick_isr();

extern "C" {
extern uint32_t _stack_top[];

struct VectorTable;
void RelocateVectors();

[[noreturn]] void volcomp_reset() {
  volcomp::runtime::EnableFpu();
  volcomp::runtime::InitMemory();
  RelocateVectors();
  volcomp::runtime::RunConstructors();
  main();
  for (;;) {
  }
}

// An unexpected interrupt or fault: stop here (the watchdog then resets the board).
[[noreturn]] void DefaultHandler() { volcomp_runtime_panic(); }
// The compensation interrupt (a software interrupt the tick pends): only the step/dir image has
// one (main.cpp); elsewhere nothing pends it, and taking it stops like any unexpected interrupt.
[[noreturn]] void volcomp_compensation_isr() __attribute__((weak, alias("DefaultHandler")));

using Handler = void (*)();
constexpr int kSystemHandlers = 15;  // after the initial SP: reset .. SysTick
constexpr int kDeviceIrqs = 102;
constexpr int kTim6DacIrq = 54;
constexpr int kTim7DacIrq = 55;  // the compensation interrupt (a software interrupt)

struct Handlers {
  Handler h[kSystemHandlers + kDeviceIrqs];
};

constexpr Handlers MakeHandlers() {
  Handlers t{};
  for (Handler& h : t.h) h = DefaultHandler;
  t.h[0] = volcomp_reset;
  const int reserved[] = {6, 7, 8, 9, 12};  // vectors 7-10 and 13
  for (int r : reserved) t.h[r] = nullptr;
  t.h[kSystemHandlers + kTim6DacIrq] = volcomp_tick_isr;
  t.h[kSystemHandlers + kTim7DacIrq] = volcomp_compensation_isr;
  return t;
}

struct VectorTable {
  uint32_t* initial_sp;
  Handlers handlers;
};

// Constant-initialised (the core reads it at reset, before any startup code runs).
__attribute__((section(".vectors"), used))
const VectorTable kVectors = {_stack_top, MakeHandlers()};

// Exceptions fetch their vector from SRAM, not flash: while the table store erases or programs
// flash bank 1, an interrupt must not wait for the flash (the tick code itself is in CCM SRAM).
// VTOR needs the table aligned to its size rounded up to a power of two (118 words -> 512 bytes).
alignas(512) VectorTable g_ram_vectors;

void RelocateVectors() {
  g_ram_vectors = kVectors;
  *reinterpret_cast<volatile uint32_t*>(0xE000ED08u) = reinterpret_cast<uint32_t>(&g_ram_vectors);
  __asm volatile("dsb\n\tisb" ::: "memory");
}
}
