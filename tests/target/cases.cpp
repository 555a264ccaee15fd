// Deterministic inputs shared by host and target (see cases.hpp).
#include "cases.hpp"

namespace volcomp::target {
namespace {

// Element storage for the case being built (static: freestanding, no heap).
alignas(4) int16_t g_i16[kMaxCaseNodes * 3];
alignas(4) int32_t g_i32[kMaxCaseNodes * 3];
alignas(4) float g_f32[kMaxCaseNodes * 3];

table::AxisInfo Linear(char name) { return {name, table::AxisKind::kLinear, 1000000}; }

}  // namespace

uint32_t BuildGridImage(const GridCaseSpec& c, uint8_t* out, uint32_t capacity) {
  const uint32_t n = c.dim[0].nodes * c.dim[1].nodes * c.dim[2].nodes * 3;
  if (n > kMaxCaseNodes * 3) return 0;
  Rng rng(c.seed);
  for (uint32_t i = 0; i < n; ++i) {
    // Every 5th value at the extreme, so the largest corner differences occur.
    const int32_t v = (i % 5 == 0) ? ((rng.Next() & 1u) ? c.amplitude : -c.amplitude)
                                   : rng.Range(-c.amplitude, c.amplitude);
    g_i16[i] = static_cast<int16_t>(v);
    g_i32[i] = v;
    // float32: a value with a fraction (v + k/64), exactly representable.
    g_f32[i] = static_cast<float>(v) + static_cast<float>(rng.Next() & 63u) * (1.0f / 64.0f);
  }
  table::GridSpec g;
  g.frac_bits = c.frac_bits;
  for (int d = 0; d < 3; ++d) g.dim[d] = c.dim[d];
  g.values.type = c.type;
  g.values.i16 = g_i16;
  g.values.i32 = g_i32;
  g.values.f32 = g_f32;
  table::ImageSpec s;
  s.table_id = c.seed;
  s.axis_count = 3;
  s.axes[0] = Linear('X');
  s.axes[1] = Linear('Y');
  s.axes[2] = Linear('Z');
  s.grid = &g;
  const Result<uint32_t> w = table::WriteImage(s, out, capacity);
  return w.ok() ? *w : 0;
}

uint32_t CoordinateCount(const table::Dimension& dim) { return 8 + 3 * dim.nodes; }

int32_t Coordinate(const table::Dimension& dim, uint32_t k, Rng& rng) {
  const int64_t lo = dim.origin_steps;
  const int64_t hi = lo + int64_t{dim.nodes - 1} * dim.spacing_steps;
  auto clamp32 = [](int64_t v) {
    return static_cast<int32_t>(v < INT32_MIN ? INT32_MIN : (v > INT32_MAX ? INT32_MAX : v));
  };
  switch (k) {
    case 0:
      return INT32_MIN;
    case 1:
      return INT32_MAX;
    case 2:
      return clamp32(lo - 1);
    case 3:
      return clamp32(hi + 1);
    case 4:
      return clamp32(lo - 1 - static_cast<int64_t>(rng.Next() % 100000u));
    case 5:
      return clamp32(hi + 1 + static_cast<int64_t>(rng.Next() % 100000u));
    case 6:
    case 7: {
      const uint64_t span = static_cast<uint64_t>(hi - lo) + 1u;
      return clamp32(lo + static_cast<int64_t>(
                              ((static_cast<uint64_t>(rng.Next()) << 32) | rng.Next()) % span));
    }
    default: {
      const uint32_t node = (k - 8) / 3;
      const int64_t p = lo + int64_t{node} * dim.spacing_steps + int64_t((k - 8) % 3) - 1;
      return clamp32(p);
    }
  }
}

BoardConfig TickBoardConfig() {
  BoardConfig c = DefaultBoardConfig();
  c.tick_hz = 50000;
  c.pulse_clock_hz = 170000000;
  for (uint8_t a = 0; a < 3; ++a) {
    c.axis[a].max_correction_steps = 500;
    c.axis[a].max_correction_rate_steps_s = 20000;
    c.axis[a].max_correction_accel_steps_s2 = 2000000;
  }
  return c;
}

uint32_t BuildTickImage(uint8_t* out, uint32_t capacity) {
  static int16_t grid[5 * 5 * 5 * 3];
  static int16_t x_fwd[6], x_rev[6], y_fwd[4], z_fwd[5];
  Rng rng(77);
  for (auto& v : grid) v = static_cast<int16_t>(rng.Range(-32767, 32767));  // +/-2047 steps
  for (int i = 0; i < 6; ++i) {
    x_fwd[i] = static_cast<int16_t>(rng.Range(-8000, 8000));
    x_rev[i] = static_cast<int16_t>(rng.Range(-8000, 8000));
  }
  for (auto& v : y_fwd) v = static_cast<int16_t>(rng.Range(-8000, 8000));
  for (auto& v : z_fwd) v = static_cast<int16_t>(rng.Range(-8000, 8000));
  z_fwd[4] = z_fwd[0];  // wrap tables are continuous across the seam
  table::GridSpec g;
  g.frac_bits = 4;
  g.dim[0] = {5, -20000, 10000};
  g.dim[1] = {5, -15000, 7500};
  g.dim[2] = {5, -1000, 3333};
  g.values.type = table::ElementType::kInt16;
  g.values.i16 = grid;
  table::ImageSpec s;
  s.table_id = 4711;
  s.axis_count = 3;
  s.axes[0] = Linear('X');
  s.axes[1] = Linear('Y');
  s.axes[2] = Linear('Z');
  s.grid = &g;
  table::Axis1dSpec& x = s.axis1d[0];
  x.axis = 0;
  x.frac_bits = 4;
  x.dim = {6, -25000, 10001};
  x.backlash_q8 = 3 * 256;
  x.forward = {table::ElementType::kInt16, x_fwd, nullptr, nullptr};
  x.has_reverse = true;
  x.reverse = {table::ElementType::kInt16, x_rev, nullptr, nullptr};
  table::Axis1dSpec& y = s.axis1d[1];
  y.axis = 1;
  y.frac_bits = 4;
  y.dim = {4, -16000, 11000};
  y.forward = {table::ElementType::kInt16, y_fwd, nullptr, nullptr};
  table::Axis1dSpec& z = s.axis1d[2];
  z.axis = 2;
  z.frac_bits = 4;
  z.dim = {5, 0, 2500};
  z.period_steps = 10000;
  z.forward = {table::ElementType::kInt16, z_fwd, nullptr, nullptr};
  s.axis1d_count = 3;
  const Result<uint32_t> w = table::WriteImage(s, out, capacity);
  return w.ok() ? *w : 0;
}

bool StartTickEngine(uint8_t* image,
                     uint32_t capacity,
                     ControlTick& engine,
                     StepOutput& output,
                     PreparedTable& table) {
  const uint32_t size = BuildTickImage(image, capacity);
  const Result<table::TableView> view = table::ParseImage(image, size);
  const BoardConfig cfg = TickBoardConfig();
  if (size == 0 || !view.ok() || !engine.Configure(cfg).ok() || !output.Configure(cfg).ok() ||
      !table.Prepare(*view, cfg).ok()) {
    return false;
  }
  const int32_t zero[3] = {0, 0, 0};
  engine.compensator().SetTable(table, zero);
  engine.compensator().SetEnabled(true);
  for (uint8_t a = 0; a < 3; ++a) engine.Reference(a);
  return true;
}

uint32_t TickCounterDelta(uint32_t i, uint32_t axis) {
  // Phases of 40 ticks; axes are offset so they do different things at once.
  const uint32_t phase = ((i / 40) + axis) % 10;
  switch (phase) {
    case 0:
      return 0;  // standstill
    case 1:
      return 20;  // 1 MHz input at 50 kHz
    case 2:
      return static_cast<uint32_t>(-20);  // 1 MHz the other way
    case 3:
      return (i & 1) ? 20 : static_cast<uint32_t>(-20);  // reversal every tick
    case 4:
      return (i % 7 == 0) ? 1 : 0;  // creeping
    case 5:
      return (i % 3 == 0) ? 5000 : 0;  // jumps across cells (beyond the input rate: stress only)
    case 6:
      return static_cast<uint32_t>(-7);
    case 7:
      return (i % 2 == 0) ? 13 : 0;
    case 8:
      return static_cast<uint32_t>(-(i % 5 == 0 ? 2500 : 0));
    default:
      return 3;
  }
}

}  // namespace volcomp::target
