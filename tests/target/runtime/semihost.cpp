// Semihosting calls: BKPT 0xAB with the operation in r0 and the parameter block in r1.
#include "semihost.hpp"

namespace volcomp::semihost {
namespace {

constexpr uint32_t kSysWrite0 = 0x04;
constexpr uint32_t kSysGetCmdline = 0x15;
constexpr uint32_t kSysExitExtended = 0x20;
constexpr uint32_t kAdpStoppedApplicationExit = 0x20026;

uint32_t Call(uint32_t op, const void* arg) {
  register uint32_t r0 __asm("r0") = op;
  register const void* r1 __asm("r1") = arg;
  __asm volatile("bkpt #0xab" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

}  // namespace

void Write(const char* s) { Call(kSysWrite0, s); }

void WriteUint(uint64_t v) {
  char buf[24];
  char* p = buf + sizeof buf;
  *--p = '\0';
  do {
    *--p = static_cast<char>('0' + v % 10u);
    v /= 10u;
  } while (v != 0);
  Write(p);
}

void WriteInt(int64_t v) {
  if (v < 0) {
    Write("-");
    WriteUint(static_cast<uint64_t>(0) - static_cast<uint64_t>(v));
  } else {
    WriteUint(static_cast<uint64_t>(v));
  }
}

void WriteHex(uint32_t v) {
  char buf[11] = {'0', 'x'};
  for (int i = 0; i < 8; ++i) buf[2 + i] = "0123456789abcdef"[(v >> (28 - 4 * i)) & 0xFu];
  buf[10] = '\0';
  Write(buf);
}

void Exit(int code) {
  const uint32_t block[2] = {kAdpStoppedApplicationExit, static_cast<uint32_t>(code)};
  Call(kSysExitExtended, block);
  for (;;) {
  }
}

const char* CommandLine() {
  static char buf[256];
  struct {
    char* p;
    uint32_t len;
  } block = {buf, sizeof buf - 1};
  if (Call(kSysGetCmdline, &block) != 0) buf[0] = '\0';
  // QEMU passes "<kernel file> <-append text>": skip the first word.
  const char* p = buf;
  while (*p != '\0' && *p != ' ') ++p;
  while (*p == ' ') ++p;
  return p;
}

}  // namespace volcomp::semihost
