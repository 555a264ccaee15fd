// Host benchmarks of the hot paths (not in the pass/fail path):
// `build/host/tests/bench/core_bench`. The Cortex-M4 cycle budgets are measured separately on the
// target model (toolchain/).
#include <benchmark/benchmark.h>

#include <array>
#include <random>

#include "test_tables.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/lookup/grid_lookup.hpp"
#include "volcomp/output/step_output.hpp"

namespace volcomp {
namespace {

// A 33x33x33 grid (the reference upload size) of the given element type.
struct Grid33 {
  testing::GridCase g;
  testing::AlignedBytes img;
  GridLookup lookup;
  std::vector<std::array<int32_t, 3>> points;
  explicit Grid33(table::ElementType type) {
    std::mt19937_64 rng(1);
    g.type = type;
    g.frac_bits = type == table::ElementType::kFloat32 ? 0 : 4;
    for (auto& d : g.dim) d = {33, 0, 15625};
    for (size_t i = 0; i < g.count(); ++i) {
      const int v = static_cast<int>(rng() % 4001) - 2000;
      g.i16.push_back(static_cast<int16_t>(v));
      g.i32.push_back(v);
      g.f32.push_back(v / 16.0f);
      g.steps.push_back(v / 16.0);
    }
    img = testing::WriteGridImage(g);
    lookup.Init(table::ParseImage(img.data(), img.size())->grid).IgnoreError();
    for (int i = 0; i < 4096; ++i) {
      points.push_back({static_cast<int32_t>(rng() % 520000) - 10000,
                        static_cast<int32_t>(rng() % 520000) - 10000,
                        static_cast<int32_t>(rng() % 520000) - 10000});
    }
  }
};

void BM_GridLookup(benchmark::State& state, table::ElementType type) {
  Grid33 grid(type);
  size_t i = 0;
  int32_t out[3];
  for (auto _ : state) {
    grid.lookup.Lookup(grid.points[i++ & 4095].data(), out);
    benchmark::DoNotOptimize(out);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(BM_GridLookup, int16, table::ElementType::kInt16);
BENCHMARK_CAPTURE(BM_GridLookup, int32, table::ElementType::kInt32);
BENCHMARK_CAPTURE(BM_GridLookup, float32, table::ElementType::kFloat32);

void BM_ControlTick3Axes(benchmark::State& state) {
  Grid33 grid(table::ElementType::kInt16);
  ControlTick engine;
  StepOutput output;
  BoardConfig cfg = DefaultBoardConfig();
  engine.Configure(cfg).IgnoreError();
  output.Configure(cfg).IgnoreError();
  PreparedTable t;
  t.Prepare(*table::ParseImage(grid.img.data(), grid.img.size()), cfg).IgnoreError();
  int32_t zero[3] = {0, 0, 0};
  engine.compensator().SetTable(t, zero);
  engine.compensator().SetEnabled(true);
  for (uint8_t a = 0; a < 3; ++a) engine.Reference(a);
  uint32_t counters[3] = {0, 0, 0};
  PulsePlan plans[3];
  uint32_t k = 0;
  for (auto _ : state) {
    // 10 input steps per tick per axis (500 kHz), reversing every 10000 ticks.
    const uint32_t d = ((++k / 10000) & 1) ? 0xFFFFFFF6u : 10u;
    for (auto& c : counters) c += d;
    engine.Run(counters);
    output.Plan(engine.targets(), plans);
    benchmark::DoNotOptimize(plans);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ControlTick3Axes);

void BM_ParseImage33(benchmark::State& state) {
  Grid33 grid(table::ElementType::kInt16);
  for (auto _ : state) {
    auto v = table::ParseImage(grid.img.data(), grid.img.size());
    benchmark::DoNotOptimize(v);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * grid.img.size()));
}
BENCHMARK(BM_ParseImage33);

}  // namespace
}  // namespace volcomp

BENCHMARK_MAIN();
