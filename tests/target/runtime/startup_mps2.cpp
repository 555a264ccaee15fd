// Reset and fault handling for the QEMU mps2-an386 test images: stack, FPU, memory, constructors,
// then main(); its return value is the emulator's exit code. A fault prints its name and exits 99.
#include <cstdint>

#include "cm4_runtime.hpp"
#include "semihost.hpp"

int main();

extern "C" {
extern uint32_t _stack_top[];

[[noreturn]] void volcomp_reset() {
  volcomp::runtime::EnableFpu();
  volcomp::runtime::InitMemory();
  volcomp::runtime::RunConstructors();
  volcomp::semihost::Exit(main());
}

[[noreturn]] static void Fault(const char* what) {
  volcomp::semihost::Write("\n*** ");
  volcomp::semihost::Write(what);
  volcomp::semihost::Write(" (CFSR ");
  volcomp::semihost::WriteHex(*reinterpret_cast<volatile uint32_t*>(0xE000ED28u));
  volcomp::semihost::Write(")\n");
  volcomp::semihost::Exit(99);
}

[[noreturn]] void volcomp_runtime_panic() { Fault("panic"); }
static void NmiHandler() { Fault("NMI"); }
static void HardFaultHandler() { Fault("HardFault"); }
static void MemManageHandler() { Fault("MemManage fault"); }
static void BusFaultHandler() { Fault("BusFault"); }
static void UsageFaultHandler() { Fault("UsageFault"); }
static void UnexpectedHandler() { Fault("unexpected exception"); }

using Handler = void (*)();
// Armv7-M vector table: initial SP, reset, then the system exceptions (ARM DDI 0403, B1.5.3).
__attribute__((section(".vectors"), used)) const Handler kVectors[16] = {
    reinterpret_cast<Handler>(_stack_top),
    volcomp_reset,
    NmiHandler,
    HardFaultHandler,
    MemManageHandler,
    BusFaultHandler,
    UsageFaultHandler,
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    UnexpectedHandler,  // SVCall
    UnexpectedHandler,  // DebugMonitor
    nullptr,
    UnexpectedHandler,  // PendSV
    UnexpectedHandler,  // SysTick
};
}
