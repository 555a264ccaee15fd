// ARM semihosting (Arm "Semihosting for AArch32 and AArch64", v2.0) for the QEMU test images:
// console output and the exit code. QEMU runs with -semihosting-config enable=on,target=native.
#pragma once

#include <cstdint>

namespace volcomp::semihost {

/// Writes a NUL-terminated string to the host console (SYS_WRITE0).
void Write(const char* s);
/// Writes a signed / unsigned decimal or a 0x-prefixed hexadecimal number.
void WriteInt(int64_t v);
void WriteUint(uint64_t v);
void WriteHex(uint32_t v);
/// Ends the emulation; `code` becomes QEMU's exit status (SYS_EXIT_EXTENDED, 0x20026).
[[noreturn]] void Exit(int code);
/// The text given to QEMU with -append (SYS_GET_CMDLINE without the image name); "" if none.
const char* CommandLine();

}  // namespace volcomp::semihost
