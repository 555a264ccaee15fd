// A duty cycle of hours with the real firmware in the loop.
#include "volcomp/sim/thermal_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "volcomp/sim/board_session.hpp"
#include "volcomp/sim/world.hpp"

namespace volcomp::sim {
namespace {

constexpr uint64_t kSecond_ns = 1000000000ull;

// The machine side of the loop: the heat balance, the sensors and the PLC that writes their
// readings to the board, stepped by the world's clock.
class ThermalPlant {
 public:
  ThermalPlant(const ThermalLoopOptions& o,
               const std::vector<ThermalSensorParams>& sensors,
               World* world)
      : o_(o), world_(world), heat_(o.run.machine, o.cycle.start_ambient_C) {
    for (size_t i = 0; i < sensors.size(); ++i) {
      sensors_.emplace_back(sensors[i], heat_, o.cycle.start_ambient_C, o.run.seed + 101 * i);
    }
    readings_cC_.assign(sensors.size(), 0);
    plc_ = &world->bus().Attach("plc");
    world_->machine().SetThermalDeformation(heat_.Deformation());
  }

  // The cycle's clock starts now (before: the machine stands at the start ambient).
  void StartCycle(uint64_t now_ns) {
    start_ns_ = now_ns;
    running_ = true;
  }
  double cycle_s(uint64_t now_ns) const {
    return running_ ? 1e-9 * static_cast<double>(now_ns - start_ns_) : 0;
  }

  // Every reading period: the loads up to now, the deformation, the sensors, the PLC's frame.
  void Clock(uint64_t now_ns) {
    const double t = cycle_s(now_ns);
    const double dt = t - last_s_;
    if (dt > 0) {
      heat_.Step(dt, o_.cycle.LoadAt(last_s_));
      for (ThermalSensor& s : sensors_) s.Step(dt, heat_, o_.cycle.LoadAt(t).ambient_C);
      last_s_ = t;
      world_->machine().SetThermalDeformation(heat_.Deformation());
    }
    for (ThermalSensor& s : sensors_) s.InjectFault(SensorFault::kNone);
    for (const SensorFaultInjection& f : o_.faults) {
      if (running_ && t >= f.at_s && t < f.at_s + f.for_s) {
        sensors_[static_cast<size_t>(f.sensor)].InjectFault(f.kind);
      }
    }
    for (size_t i = 0; i < sensors_.size(); ++i) readings_cC_[i] = sensors_[i].Read_cC();
    SendReadings();
  }

  const std::vector<int16_t>& readings_cC() const { return readings_cC_; }

  // The PLC is the NMT master: it starts the node (PDOs run in Operational only, CiA 301).
  void StartNode() {
    CanFrame f;
    f.id = 0;
    f.dlc = 2;
    f.data[0] = 0x01;  // start remote node
    f.data[1] = world_->node_id();
    plc_->Send(f);
  }

 private:
  // RPDO2: channels 1..4 as four int16, little-endian (docs/thermal.md "Configuration").
  void SendReadings() {
    CanFrame f;
    f.id = 0x300u + world_->node_id();
    f.dlc = 8;
    for (size_t i = 0; i < 4; ++i) {
      const int16_t v = i < readings_cC_.size() ? readings_cC_[i] : thermal::kNoReading_cC;
      f.data[2 * i] = static_cast<uint8_t>(static_cast<uint16_t>(v) & 0xFF);
      f.data[2 * i + 1] = static_cast<uint8_t>(static_cast<uint16_t>(v) >> 8);
    }
    plc_->Send(f);
  }

  const ThermalLoopOptions& o_;
  World* world_;
  HeatBalance heat_;
  std::vector<ThermalSensor> sensors_;
  std::vector<int16_t> readings_cC_;
  Endpoint* plc_ = nullptr;
  uint64_t start_ns_ = 0;
  bool running_ = false;
  double last_s_ = 0;
};

Expected<std::unique_ptr<World>> MakeWorld(const ThermalLoopOptions& o, size_t channels) {
  WorldOptions wo;
  VOLCOMP_TRY_ASSIGN(wo.machine.model, LoadMachineModel(o.model_spec));
  if (o.wear.thermal) {
    return Fail(Error::kInvalidArgument,
                "the thermal loop's machine warms by its heat balance: the closed-form warm-up "
                "(WornMachineProfile::thermal) must be off");
  }
  wo.machine.wear = o.wear;
  {
    VOLCOMP_TRY_ASSIGN(const Machine machine, Machine::Create(wo.machine));
    wo.board = BoardSettingsFor(machine);
  }
  wo.board.board.tick_hz = o.tick_hz;
  for (size_t i = 0; i < channels; ++i) {
    thermal::ChannelConfig& c = wo.board.temperature[i];
    c.source = thermal::ChannelSource::kCanObject;
    c.stuck_readings = o.stuck_readings;
  }
  wo.poll_period_ns = o.poll_period_ns;
  return World::Create(wo);
}

// The board's applied correction at `q_mm` along `axis`, um.
double AppliedAt_um(World& world, int axis, const model::Vec3& q_mm) {
  const auto& c = world.board().app().thermal().correction();
  return c.CorrectionAt_um(static_cast<uint8_t>(axis), static_cast<float>(q_mm[axis]));
}

}  // namespace

Expected<ThermalLoopResult> RunThermalLoop(const ThermalLoopOptions& o, std::ostream& log) {
  const auto wall0 = std::chrono::steady_clock::now();
  std::vector<ThermalSensorParams> sensors = o.run.sensors;
  if (sensors.empty()) {
    for (const ThermalSensorParams& s : WornMachineSensors()) sensors.push_back(s);
  }
  VOLCOMP_TRY_ASSIGN(std::unique_ptr<World> world_ptr, MakeWorld(o, sensors.size()));
  World& world = *world_ptr;
  ThermalPlant plant(o, sensors, &world);
  const uint64_t period_ns = static_cast<uint64_t>(std::llround(o.reading_period_s * 1e9));
  ThermalLoopResult r;
  r.run.cycle = o.cycle.name;
  for (const ThermalSensorParams& s : sensors) r.run.channel_names.push_back(s.name);
  const std::vector<DriftCheckPoint> points =
      o.run.points.empty() ? DefaultDriftCheckPoints(world.machine()) : o.run.points;

  uint64_t next_rate_ns = 0;
  std::vector<double> last_c(points.size(), 0);
  double last_rate_s = -1;
  r.faults.resize(o.faults.size());
  for (size_t i = 0; i < o.faults.size(); ++i) r.faults[i].injected = o.faults[i];
  std::vector<std::vector<double>> held_at(o.faults.size());
  // The board's applied correction at every check point now.
  auto applied = [&]() {
    std::vector<double> c(points.size());
    for (size_t k = 0; k < points.size(); ++k)
      c[k] = AppliedAt_um(world, points[k].axis, points[k].q_mm);
    return c;
  };
  // Every reading period: the plant, then the fault watch; every second: the rate.
  world.SetClocked(period_ns, [&](uint64_t now_ns) {
    plant.Clock(now_ns);
    const double t = plant.cycle_s(now_ns);
    const auto& th = world.board().app().thermal();
    for (size_t i = 0; i < o.faults.size(); ++i) {
      const SensorFaultInjection& f = o.faults[i];
      FaultOutcome& out = r.faults[i];
      if (t < f.at_s || t >= f.at_s + f.for_s) continue;
      if (out.detected_after_s < 0 && ((th.channel_fault_mask() >> f.sensor) & 1u)) {
        out.detected_after_s = t - f.at_s;
        held_at[i] = applied();
      }
      if (held_at[i].empty()) continue;
      const std::vector<double> c = applied();
      for (size_t k = 0; k < c.size(); ++k) {
        out.change_while_held_um =
            std::max(out.change_while_held_um, std::fabs(c[k] - held_at[i][k]));
      }
    }
    if (now_ns < next_rate_ns) return;
    next_rate_ns = now_ns + kSecond_ns;
    // The rate in the world's time: the activation's ramp-in before the cycle counts too.
    const std::vector<double> c = applied();
    const double w = 1e-9 * static_cast<double>(now_ns);
    if (last_rate_s >= 0) {
      for (size_t k = 0; k < points.size(); ++k) {
        double& m = r.max_rate_um_s[points[k].axis];
        m = std::max(m, std::fabs(c[k] - last_c[k]) / (w - last_rate_s));
      }
    }
    last_c = c;
    last_rate_s = w;
  });

  VOLCOMP_TRY(world.Start());
  plant.StartNode();
  world.cnc().QueueHome(7);
  if (!world.RunUntilCncIdle(300 * kSecond_ns)) {
    return Fail(Error::kNotReady, "homing did not finish within 300 s");
  }
  world.RunFor(kSecond_ns / 10);
  if (!o.image.empty()) {
    VOLCOMP_TRY_ASSIGN(const UploadReport up, UploadTable(world, o.image, log));
    world.RunFor(kSecond_ns / 5);  // activation needs 100 ms without input steps
    VOLCOMP_TRY(ActivateTable(world, up.image_crc));
  }
  // The cycle starts with the correction settled on the cold machine.
  world.RunFor(30 * kSecond_ns);
  plant.StartCycle(world.now_ns());
  const uint64_t start_ns = world.now_ns();
  const double step_mm[3] = {world.machine().step_mm(0), world.machine().step_mm(1),
                             world.machine().step_mm(2)};
  const double end_s = o.cycle.duration_s();
  for (double check_s = 0; check_s <= end_s + 1e-9; check_s += o.run.check_interval_s) {
    const uint64_t due_ns = start_ns + static_cast<uint64_t>(std::llround(check_s * 1e9));
    if (world.now_ns() < due_ns) world.RunFor(due_ns - world.now_ns());
    for (const DriftCheckPoint& p : points) {
      double sum_um = 0;
      for (int k = 0; k < o.approaches; ++k) {
        for (const double below_mm : {o.approach_mm, 0.0}) {
          std::array<int64_t, 3> target;
          for (int a = 0; a < 3; ++a) {
            target[static_cast<size_t>(a)] = std::llround((p.q_mm[a] - below_mm) / step_mm[a]);
          }
          world.cnc().QueueLinear(target, o.check_feed_mm_s);
          if (!world.RunUntilCncIdle(600 * kSecond_ns)) {
            return Fail(Error::kNotReady, "a move to a check point did not finish within 600 s");
          }
        }
        world.RunFor(static_cast<uint64_t>(o.settle_s * 1e9));
        world.CheckAtRest();
        const model::Vec3 tool = world.machine().ToolPoint_mm(world.AxisPositions_mm());
        sum_um += 1e3 * (tool[p.axis] - world.CommandedPoint_mm()[p.axis]);
      }
      r.run.readings.push_back({plant.cycle_s(world.now_ns()), p.axis, p.q_mm[p.axis],
                                sum_um / std::max(1, o.approaches), plant.readings_cC()});
    }
  }
  world.SetClocked(0, nullptr);
  const StepAudit audit = world.Audit();
  r.ticks = audit.ticks;
  r.lost_steps = audit.lost_steps;
  r.overruns = audit.overruns;
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  char line[160];
  std::snprintf(line, sizeof line,
                "thermal loop (%s): %.1f h of machine time, %llu ticks at %u Hz, %.1f s wall\n",
                o.cycle.name.c_str(), end_s / 3600, static_cast<unsigned long long>(r.ticks),
                o.tick_hz, r.wall_s);
  log << line;
  return r;
}

}  // namespace volcomp::sim
