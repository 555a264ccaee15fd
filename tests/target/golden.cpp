// Golden-vector stream (see golden.hpp).
#include "golden.hpp"

#include "cases.hpp"
#include "volcomp/base/byte_order.hpp"
#include "volcomp/base/crc32.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/limiter/correction_limiter.hpp"
#include "volcomp/lookup/axis_lookup.hpp"
#include "volcomp/lookup/grid_lookup.hpp"
#include "volcomp/output/step_generator.hpp"
#include "volcomp/output/step_output.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp::target {
namespace {

alignas(8) uint8_t g_image[kMaxCaseImage];
alignas(8) uint8_t g_broken[kMaxCaseImage];

void PutPlan(GoldenSink& sink, const PulsePlan& p) {
  sink.Put(p.count);
  sink.Put((p.negative ? 1u : 0u) | (p.dir_change ? 2u : 0u));
  sink.Put(p.dir_edge);
  sink.Put(p.first_rise);
  sink.Put(p.period);
  sink.Put(p.width);
}

void GridSection(GoldenSink& sink, uint32_t* mismatches) {
  for (const GridCaseSpec& c : kGridCases) {
    const uint32_t size = BuildGridImage(c, g_image, sizeof g_image);
    const Result<table::TableView> view = table::ParseImage(g_image, size);
    GridLookup lookup;
    if (size == 0 || !view.ok() || !lookup.Init(view->grid).ok()) {
      sink.Put(0xDEADu);
      continue;
    }
    Rng rng(c.seed);
    uint32_t n[3];
    for (int d = 0; d < 3; ++d) n[d] = CoordinateCount(c.dim[d]);
    const uint32_t total = n[0] * 3 + n[1] * 2 + n[2];
    for (uint32_t i = 0; i < total; ++i) {
      int32_t pos[3];
      for (int d = 0; d < 3; ++d) pos[d] = Coordinate(c.dim[d], (i * (d + 2) + d) % n[d], rng);
      int32_t out[3], ref[3];
      lookup.Lookup(pos, out);
      switch (c.type) {
        case table::ElementType::kInt16:
          lookup.Interpolate<LoadInt16>(pos, ref);
          break;
        case table::ElementType::kInt32:
          lookup.Interpolate<LoadInt32>(pos, ref);
          break;
        case table::ElementType::kFloat32:
          lookup.Interpolate<LoadFloat32>(pos, ref);
          break;
      }
      // The three-part form the control tick uses must agree too.
      GridLookup::Partial part;
      int32_t parts[3];
      lookup.Begin(pos, &part);
      lookup.AccumulateZ0(&part);
      lookup.FinishZ1(part, parts);
      for (int k = 0; k < 3; ++k) {
        if (out[k] != ref[k] || parts[k] != ref[k]) ++*mismatches;
        if (!sink.Put(static_cast<uint32_t>(out[k]))) return;
      }
    }
  }
}

void AxisSection(GoldenSink& sink) {
  const uint32_t size = BuildTickImage(g_image, sizeof g_image);
  const Result<table::TableView> view = table::ParseImage(g_image, size);
  if (size == 0 || !view.ok()) {
    sink.Put(0xDEADu);
    return;
  }
  for (uint8_t t = 0; t < view->axis1d_count; ++t) {
    AxisLookup lookup;
    if (!lookup.Init(view->axis1d[t]).ok()) {
      sink.Put(0xDEADu);
      continue;
    }
    Rng rng(100u + t);
    const table::Dimension& d = view->axis1d[t].dim;
    for (uint32_t k = 0; k < CoordinateCount(d); ++k) {
      const int32_t p = Coordinate(d, k, rng);
      sink.Put(static_cast<uint32_t>(lookup.Lookup(p, false)));
      if (!sink.Put(static_cast<uint32_t>(lookup.Lookup(p, true)))) return;
    }
  }
}

void CrcSection(GoldenSink& sink) {
  const char check[] = "123456789";
  sink.Put(ComputeCrc32(reinterpret_cast<const uint8_t*>(check), 9));
  for (const GridCaseSpec& c : kGridCases) {
    const uint32_t size = BuildGridImage(c, g_image, sizeof g_image);
    sink.Put(size);
    sink.Put(ComputeCrc32(g_image, size));
  }
  const uint32_t size = BuildTickImage(g_image, sizeof g_image);
  sink.Put(size);
  sink.Put(ComputeCrc32(g_image, size));
}

// Broken images: each edit must give its own error code (the host suite checks every field; here
// the same parser runs on the target and must agree).
void ImageErrorSection(GoldenSink& sink) {
  const uint32_t size = BuildGridImage(kGridCases[0], g_image, sizeof g_image);
  auto parse = [&](uint32_t len) {
    const Result<table::TableView> v = table::ParseImage(g_broken, len);
    return static_cast<uint32_t>(v.status().error());
  };
  auto fresh = [&] {
    for (uint32_t i = 0; i < size; ++i) g_broken[i] = g_image[i];
  };
  auto fix_crc = [&] { StoreLe32(g_broken + size - 4, ComputeCrc32(g_broken, size - 4)); };
  fresh();
  sink.Put(parse(size));  // valid: kOk
  g_broken[0] ^= 1u;
  sink.Put(parse(size));  // magic
  fresh();
  g_broken[size / 2] ^= 0x10u;
  sink.Put(parse(size));  // CRC
  fresh();
  sink.Put(parse(size - 4));  // truncated
  fresh();
  g_broken[4] = 2;  // major version
  fix_crc();
  sink.Put(parse(size));
  fresh();
  StoreLe32(g_broken + 8, size + 4);  // image size field
  fix_crc();
  sink.Put(parse(size));
  fresh();
  // First GRID3 spacing (AXES section: 8 + 4 + 3*8 bytes after the header) set to zero.
  const uint32_t grid_body = 24 + 8 + 4 + 3 * 8 + 8;
  StoreLe32(g_broken + grid_body + table::grid3::kSpacingOffset, 0);
  fix_crc();
  sink.Put(parse(size));
  fresh();
  g_broken[grid_body + table::grid3::kElementTypeOffset] = 9;
  fix_crc();
  sink.Put(parse(size));
  // The same image one byte off its 4-byte alignment.
  const Result<table::TableView> mis = table::ParseImage(g_image + 1, size - 1);
  sink.Put(static_cast<uint32_t>(mis.status().error()));
}

void LimiterSection(GoldenSink& sink) {
  const Result<LimiterParams> p = CorrectionLimiter::MakeParams(50000, 20000, 2000000);
  sink.Put(p.ok() ? p->accel_q32 : 0u);
  sink.Put(p.ok() ? p->max_k : 0u);
  if (!p.ok()) return;
  CorrectionLimiter lim(*p);
  const int64_t targets[] = {int64_t{500} << 32, -(int64_t{500} << 32), int64_t{3} << 31, 0,
                             int64_t{65536} << 32};
  for (int64_t t : targets) {
    for (int i = 0; i < 300; ++i) {
      const int64_t pos = lim.Step(t);
      sink.Put(static_cast<uint32_t>(pos));
      sink.Put(static_cast<uint32_t>(static_cast<uint64_t>(pos) >> 32));
      if (!sink.Put(static_cast<uint32_t>(lim.velocity_index()))) return;
    }
  }
}

void StepGeneratorSection(GoldenSink& sink) {
  const BoardConfig cfg = TickBoardConfig();
  const PulseFormat formats[] = {PulseFormat::kStepDir, PulseFormat::kQuadrature};
  for (PulseFormat f : formats) {
    AxisConfig ax = cfg.axis[0];
    ax.output_format = f;
    StepGenerator gen;
    sink.Put(static_cast<uint32_t>(gen.Configure(ax, cfg.tick_hz, cfg.pulse_clock_hz).error()));
    int32_t target = 0;
    for (uint32_t i = 0; i < kTickPatternLength; ++i) {
      target = static_cast<int32_t>(static_cast<uint32_t>(target) + TickCounterDelta(i, 1));
      const PulsePlan plan = gen.Plan(target);
      PutPlan(sink, plan);
      sink.Put(static_cast<uint32_t>(gen.position()));
    }
  }
}

void ControlTickSection(GoldenSink& sink) {
  static ControlTick engine;
  static StepOutput output;
  static PreparedTable table;
  if (!StartTickEngine(g_image, sizeof g_image, engine, output, table)) {
    sink.Put(0xDEADu);
    return;
  }
  uint32_t counters[3] = {0, 0, 0};
  PulsePlan plans[3];
  for (uint32_t i = 0; i < kTickPatternLength; ++i) {
    for (uint32_t a = 0; a < 3; ++a) counters[a] += TickCounterDelta(i, a);
    engine.Run(counters);
    output.Plan(engine.targets(), plans);
    for (uint8_t a = 0; a < 3; ++a) {
      PutPlan(sink, plans[a]);
      sink.Put(static_cast<uint32_t>(engine.correction_steps(a)));
      sink.Put(static_cast<uint32_t>(engine.compensator().target_q8(a)));
      sink.Put(static_cast<uint32_t>(engine.compensator().applied_q8(a)));
      sink.Put(static_cast<uint32_t>(output.position(a)));
    }
  }
}

}  // namespace

const char* GoldenSectionName(GoldenSection s) {
  switch (s) {
    case GoldenSection::kGridLookup:
      return "grid_lookup";
    case GoldenSection::kAxisLookup:
      return "axis_lookup";
    case GoldenSection::kCrc:
      return "crc32";
    case GoldenSection::kImageErrors:
      return "image_validation";
    case GoldenSection::kLimiter:
      return "limiter";
    case GoldenSection::kStepGenerator:
      return "step_generator";
    case GoldenSection::kControlTick:
      return "control_tick";
    case GoldenSection::kCount:
      break;
  }
  return "?";
}

void ComputeGolden(GoldenSection s, GoldenSink& sink, uint32_t* mismatches) {
  sink.Begin(s);
  switch (s) {
    case GoldenSection::kGridLookup:
      GridSection(sink, mismatches);
      break;
    case GoldenSection::kAxisLookup:
      AxisSection(sink);
      break;
    case GoldenSection::kCrc:
      CrcSection(sink);
      break;
    case GoldenSection::kImageErrors:
      ImageErrorSection(sink);
      break;
    case GoldenSection::kLimiter:
      LimiterSection(sink);
      break;
    case GoldenSection::kStepGenerator:
      StepGeneratorSection(sink);
      break;
    case GoldenSection::kControlTick:
      ControlTickSection(sink);
      break;
    case GoldenSection::kCount:
      break;
  }
}

}  // namespace volcomp::target
