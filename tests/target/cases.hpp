// Deterministic test and benchmark inputs shared by the host and the Cortex-M4F images
// (freestanding: no heap, no libc): table images built with the real writer from a fixed
// pseudo-random sequence, and adversarial positions (grid nodes, node +/- 1, cell interiors, the
// boundary, far outside). The host golden-vector generator and the QEMU images compute exactly the
// same inputs from these.
#pragma once

#include <cstddef>
#include <cstdint>

#include "volcomp/config/board_config.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/output/step_output.hpp"
#include "volcomp/table/table_format.hpp"
#include "volcomp/table/table_writer.hpp"

namespace volcomp::target {

/// xorshift32 (Marsaglia 2003): the same sequence everywhere.
class Rng {
 public:
  explicit Rng(uint32_t seed) : s_(seed != 0 ? seed : 1u) {}
  uint32_t Next() {
    s_ ^= s_ << 13;
    s_ ^= s_ >> 17;
    s_ ^= s_ << 5;
    return s_;
  }
  /// Uniform-ish in [lo, hi] (inclusive; modulo bias is irrelevant here).
  int32_t Range(int32_t lo, int32_t hi) {
    const uint32_t span = static_cast<uint32_t>(hi) - static_cast<uint32_t>(lo) + 1u;
    const uint32_t r = span == 0 ? Next() : Next() % span;
    return static_cast<int32_t>(static_cast<uint32_t>(lo) + r);
  }

 private:
  uint32_t s_;
};

/// Largest grid the cases use (storage is static, sized for it).
inline constexpr uint32_t kMaxCaseNodes = 7 * 6 * 5;
inline constexpr uint32_t kMaxCaseImage =
    24 + 8 + 4 + 8 * 6 + 8 + 44 + kMaxCaseNodes * 3 * 4 + 4 + 3 * (8 + 24 + 2 * 64 * 4) + 64;

/// A grid table case: element type, fraction bits, and the three lattice dimensions.
struct GridCaseSpec {
  table::ElementType type;
  uint8_t frac_bits;
  table::Dimension dim[3];
  uint32_t seed;
  int32_t amplitude;  // |value| bound in element LSB (int types) or steps (float32)
};

/// The grid cases every test/bench uses: non-power-of-two spacings, negative origins, full-range
/// values (int16 at its limit, int32 at +/-65536 steps, float32 up to 1000 steps).
inline constexpr GridCaseSpec kGridCases[] = {
    {table::ElementType::kInt16, 0, {{7, -30000, 10007}, {6, 5000, 777}, {5, -1, 3}}, 11, 32767},
    {table::ElementType::kInt16, 8, {{2, 0, 1}, {3, -7, 65536}, {4, 100, 99991}}, 12, 32767},
    {table::ElementType::kInt32,
     8,
     {{5, -1000000, 250001}, {4, 7, 33}, {6, 0, 1024}},
     13,
     65536 * 256},
    {table::ElementType::kInt32,
     0,
     {{3, -2147483647 - 1, 1073741823}, {5, 1, 5}, {2, -9, 2}},
     14,
     65536},
    {table::ElementType::kFloat32, 0, {{6, -123456, 4321}, {5, 0, 1000}, {4, -50, 37}}, 15, 1000},
    {table::ElementType::kFloat32, 0, {{4, 1 << 20, 15625}, {4, -3, 7}, {7, 0, 100}}, 16, 65535},
};
inline constexpr size_t kGridCaseCount = sizeof(kGridCases) / sizeof(kGridCases[0]);

/// Builds the image of grid case `c` into `out` (4-byte aligned, kMaxCaseImage bytes); returns its
/// size, or 0 on failure. Values are drawn from Rng(seed).
uint32_t BuildGridImage(const GridCaseSpec& c, uint8_t* out, uint32_t capacity);

/// Adversarial coordinate k (0 <= k < CoordinateCount(dim)) along one dimension: far outside on
/// both sides, the limits, every node and its neighbours, and interior points.
uint32_t CoordinateCount(const table::Dimension& dim);
int32_t Coordinate(const table::Dimension& dim, uint32_t k, Rng& rng);

/// Board used for the control-tick cases: three linear axes, default limits, a pulse clock of
/// 170 MHz (the STM32G474 timer clock) and a 50 kHz tick.
BoardConfig TickBoardConfig();

/// Image for the control-tick cases: an int16 GRID3 over X, Y, Z plus AXIS1D tables (X with a
/// reverse table and backlash, Y forward only, Z with rotary-style wrap). Values reach beyond the
/// board's maximum correction so the clamp engages.
uint32_t BuildTickImage(uint8_t* out, uint32_t capacity);

/// The control-tick case's engine: builds the tick image into `image` (4-byte aligned, `capacity`
/// bytes, kept: the table refers to it), configures `engine` and the step output stage `output`
/// for TickBoardConfig(), prepares `table`, sets it active and enabled, and references every
/// axis. False if any step fails.
bool StartTickEngine(uint8_t* image,
                     uint32_t capacity,
                     ControlTick& engine,
                     StepOutput& output,
                     PreparedTable& table);

/// Counter increment of tick `i` of the control-tick input pattern (per axis): standstill, steady
/// 1 MHz input, reversals, single steps and a jump across several cells.
uint32_t TickCounterDelta(uint32_t i, uint32_t axis);
inline constexpr uint32_t kTickPatternLength = 400;

}  // namespace volcomp::target
