// Golden vectors: every result the core computes for the deterministic inputs of cases.hpp,
// flattened into one stream of 32-bit words, grouped in sections. The host computes the stream
// (golden_gen writes it to golden_vectors.inc, checked in; golden_host_test re-checks it on every
// host build) and the Cortex-M4F image computes it again under QEMU and compares word by word:
// fixed-point results are bit-identical on host and target when both streams equal the file.
// Freestanding (no heap, no libc): the same source runs on both.
#pragma once

#include <cstdint>

namespace volcomp::target {

enum class GoldenSection : uint32_t {
  kGridLookup = 1,     // per grid case and position: 3 components (hot path == reference checked)
  kAxisLookup = 2,     // AXIS1D lookups of the tick image, both directions
  kCrc = 3,            // CRC-32 of the case images and of the check string
  kImageErrors = 4,    // ParseImage error codes of deliberately broken images
  kLimiter = 5,        // correction limiter positions and velocities
  kStepGenerator = 6,  // pulse plans toward a target sequence
  kControlTick = 7,    // the full tick: plans, corrections, output positions
  kCount = 8,
};

const char* GoldenSectionName(GoldenSection s);

/// Receives the stream. Returns false to stop early (a mismatch was reported).
class GoldenSink {
 public:
  virtual void Begin(GoldenSection s) = 0;
  virtual bool Put(uint32_t word) = 0;

 protected:
  ~GoldenSink() = default;
};

/// Computes the stream of section `s` into `sink`. `mismatches` counts places where the hot path
/// differed from the clear reference (GridLookup::Lookup vs Interpolate<>); must stay 0.
void ComputeGolden(GoldenSection s, GoldenSink& sink, uint32_t* mismatches);

}  // namespace volcomp::target
