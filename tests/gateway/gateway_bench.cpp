// Host benchmarks of the gateway's per-frame work (Google Benchmark; figures, not pass/fail):
// the pure logic (lib/csp_gateway) on a mapped RPDO, a mapped TPDO and an unmapped frame, and the
// whole application path (GatewayApp::OnControllerFrame: gateway, routing, port queue) on the
// mock HAL. The SocketCAN path around it is measured by volcomp-fw-linux itself (--stats) and by
// tests/uml/run_uml_gateway.sh from candump timestamps.
#include <benchmark/benchmark.h>

#include "csp_drives.hpp"
#include "volcomp/firmware/gateway_app.hpp"
#include "volcomp/gateway/csp_gateway.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"

namespace volcomp {
namespace {

gateway::GatewayConfig Mapping(uint8_t axes) { return testing::CspDriveMapping(axes, 0x10); }

using testing::CspPdo;

void BM_GatewayTargetRpdo(benchmark::State& state) {
  gateway::CspGateway gw;
  if (!gw.Configure(Mapping(6), 6).ok()) state.SkipWithError("config");
  gw.SetCorrection(5, 17);
  CanFrame in = CspPdo(0x206, 1000), out;  // the last mapping: the longest scan
  for (auto _ : state) {
    in.data[2] = static_cast<uint8_t>(in.data[2] + 1);
    benchmark::DoNotOptimize(gw.FromController(in, &out));
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_GatewayTargetRpdo);

void BM_GatewayActualTpdo(benchmark::State& state) {
  gateway::CspGateway gw;
  if (!gw.Configure(Mapping(6), 6).ok()) state.SkipWithError("config");
  CanFrame in = CspPdo(0x186, 1000), out;
  for (auto _ : state) {
    in.data[2] = static_cast<uint8_t>(in.data[2] + 1);
    benchmark::DoNotOptimize(gw.FromDrive(in, &out));
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_GatewayActualTpdo);

void BM_GatewayUnmapped(benchmark::State& state) {
  gateway::CspGateway gw;
  if (!gw.Configure(Mapping(6), 6).ok()) state.SkipWithError("config");
  CanFrame in = CspPdo(0x381, 1000), out;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gw.FromController(in, &out));
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_GatewayUnmapped);

void BM_GatewayAppForward(benchmark::State& state) {
  hal::mock::MockClock clock;
  hal::mock::MockSlowIo io(&clock, nullptr);
  hal::mock::MockFlash tables(64 * 1024, 2048, 8, &clock, nullptr);
  hal::mock::MockCan cnc(&clock, nullptr, 1 << 20), drv(&clock, nullptr, 1 << 20);
  firmware::GatewayApp app({&cnc, &drv, &io, &tables, nullptr, &clock});
  BoardSettings s;
  s.board.tick_hz = 1000;
  if (!app.Start(s, Mapping(3)).ok()) state.SkipWithError("start");
  CanFrame in = CspPdo(0x201, 1000);
  uint32_t n = 0;
  for (auto _ : state) {
    in.data[2] = static_cast<uint8_t>(in.data[2] + 1);
    benchmark::DoNotOptimize(app.OnControllerFrame(in));
    if (++n == 65536) {  // keep the mock's record bounded
      state.PauseTiming();
      drv.TakeSent();
      n = 0;
      state.ResumeTiming();
    }
  }
}
BENCHMARK(BM_GatewayAppForward);

}  // namespace
}  // namespace volcomp

BENCHMARK_MAIN();
