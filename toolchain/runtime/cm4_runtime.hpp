// Bare-metal runtime for the Cortex-M4F images: startup helpers shared by the STM32G474 firmware
// and the QEMU mps2-an386 test images. The images' linker scripts define the symbols used here:
// __data_load/__data_start/__data_end (.data copy), __ccm_load/__ccm_start/__ccm_end (code and data
// copied into CCM SRAM, empty on QEMU), __ccm_bss_start/__ccm_bss_end (zeroed CCM data),
// __bss_start/__bss_end, __init_array_start/__init_array_end.
#pragma once

extern "C" [[noreturn]] void volcomp_runtime_panic();

namespace volcomp::runtime {

/// Enables the FPU (CP10/CP11 full access). Must run before any floating-point instruction.
void EnableFpu();
/// Copies .data (and the CCM SRAM image) from their load addresses and zeroes .bss.
void InitMemory();
/// Runs the static constructors (.init_array).
void RunConstructors();

}  // namespace volcomp::runtime
