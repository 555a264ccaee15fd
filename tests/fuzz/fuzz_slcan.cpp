// Fuzz target: the SLCAN decoder in both roles. Invariants: no over-read or UB on any byte stream;
// every frame it decodes is valid and survives an encode/decode round trip unchanged.
#include <cstdint>
#include <cstdlib>

#include "volcomp/can/slcan.hpp"

namespace {
void Check(volcomp::slcan::Role role, const uint8_t* data, size_t size) {
  using namespace volcomp::slcan;
  Decoder d(role);
  Message m;
  for (size_t i = 0; i < size; ++i) {
    if (!d.Feed(data[i], &m) || m.kind != Kind::kFrame) continue;
    if (!m.frame.valid()) std::abort();
    char line[kMaxEncodedLength];
    const size_t n = EncodeFrame(m.frame, line, sizeof line);
    if (n == 0) std::abort();
    const Message back = ParseLine(role, line, n - 1);
    if (back.kind != Kind::kFrame || !(back.frame == m.frame)) std::abort();
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Check(volcomp::slcan::Role::kDevice, data, size);
  Check(volcomp::slcan::Role::kHost, data, size);
  return 0;
}
