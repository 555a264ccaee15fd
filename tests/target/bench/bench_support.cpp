// The cycle benches' shared pieces.
#include "bench_support.hpp"

#include "semihost.hpp"

extern "C" __attribute__((noinline, section(".text.volcomp_bench_mark"))) void
volcomp_bench_mark() {
  __asm volatile("" ::: "memory");
}

namespace volcomp::target {

void Scenario(const char* name, const char* symbol) {
  semihost::Write("SCENARIO ");
  semihost::Write(name);
  semihost::Write(" ");
  semihost::Write(symbol);
  semihost::Write("\n");
  volcomp_bench_mark();
}

Status BenchFlash::DoErase(uint32_t offset) {
  for (uint32_t i = 0; i < kSectorBytes / 4; ++i) words_[offset / 4 + i] = ~0u;
  return Status::Ok();
}

Status BenchFlash::DoProgram(uint32_t offset, const uint8_t* data, uint32_t n) {
  for (uint32_t i = 0; i < n; i += 8) {
    uint32_t lo, hi;
    __builtin_memcpy(&lo, data + i, 4);
    __builtin_memcpy(&hi, data + i + 4, 4);
    words_[(offset + i) / 4] &= lo;
    words_[(offset + i) / 4 + 1] &= hi;
  }
  return Status::Ok();
}

}  // namespace volcomp::target
