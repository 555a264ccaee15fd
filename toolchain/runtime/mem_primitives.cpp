// The four memory primitives a freestanding compiler may call even without a C library (struct
// copies, zeroing): linked into the Cortex-M4F images (volcomp_cm4_runtime) and into the host's
// no-runtime link check (firmware/freestanding_check). Build with
// -fno-tree-loop-distribute-patterns (GCC; clang with -ffreestanding needs nothing), or the
// compiler turns these loops into calls to themselves.
#include <cstddef>
#include <cstdint>

extern "C" {

void* memcpy(void* d, const void* s, size_t n) {
  auto* dp = static_cast<unsigned char*>(d);
  const auto* sp = static_cast<const unsigned char*>(s);
  if (((reinterpret_cast<uintptr_t>(dp) | reinterpret_cast<uintptr_t>(sp)) & 3u) == 0) {
    for (; n >= 4; n -= 4, dp += 4, sp += 4) {
      *reinterpret_cast<uint32_t*>(dp) = *reinterpret_cast<const uint32_t*>(sp);
    }
  }
  while (n-- != 0) *dp++ = *sp++;
  return d;
}

void* memmove(void* d, const void* s, size_t n) {
  auto* dp = static_cast<unsigned char*>(d);
  const auto* sp = static_cast<const unsigned char*>(s);
  if (dp < sp) {
    while (n-- != 0) *dp++ = *sp++;
  } else {
    while (n-- != 0) dp[n] = sp[n];
  }
  return d;
}

void* memset(void* d, int c, size_t n) {
  auto* dp = static_cast<unsigned char*>(d);
  const auto byte = static_cast<unsigned char>(c);
  // Word stores once aligned (a structure zero-fill is usually word aligned throughout).
  for (; n != 0 && (reinterpret_cast<uintptr_t>(dp) & 3u) != 0; --n) *dp++ = byte;
  const uint32_t word = byte * 0x01010101u;
  for (; n >= 4; n -= 4, dp += 4) *reinterpret_cast<uint32_t*>(dp) = word;
  while (n-- != 0) *dp++ = byte;
  return d;
}

int memcmp(const void* a, const void* b, size_t n) {
  const auto* x = static_cast<const unsigned char*>(a);
  const auto* y = static_cast<const unsigned char*>(b);
  for (; n != 0; --n, ++x, ++y) {
    if (*x != *y) return *x < *y ? -1 : 1;
  }
  return 0;
}

}  // extern "C"
