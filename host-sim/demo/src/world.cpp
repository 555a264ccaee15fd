// The simulated installation in virtual time.
#include "volcomp/sim/world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

namespace volcomp::sim {

BoardSettings BoardSettingsFor(const Machine& machine) {
  BoardSettings s;
  s.board = DefaultBoardConfig();
  for (int a = 0; a < 3; ++a) {
    AxisConfig& ax = s.board.axis[a];
    ax.resolution_e9 = static_cast<uint32_t>(std::llround(machine.step_mm(a) * 1e9));
    ax.home_position_steps =
        static_cast<int32_t>(std::llround(machine.home_switch_mm(a) / machine.step_mm(a)));
  }
  return s;
}

Expected<std::unique_ptr<World>> World::Create(const WorldOptions& options) {
  VOLCOMP_TRY_ASSIGN(Machine machine, Machine::Create(options.machine));
  return std::unique_ptr<World>(new World(options, std::move(machine)));
}

World::World(const WorldOptions& options, Machine machine)
    : options_(options), bus_(options.can_bitrate), latency_(20000) {
  machine_ = std::make_unique<Machine>(std::move(machine));
  SimulatedBoardOptions bo;
  bo.settings = options_.board;
  bo.poll_period_ns = options_.poll_period_ns;
  board_ = std::make_unique<SimulatedBoard>(bus_, bo);
  pc_ = &bus_.Attach("pc");
  tick_ns_ = 1000000000ull / options_.board.board.tick_hz;
  pulse_clock_hz_ = options_.board.board.pulse_clock_hz;
  latency_ = LatencyMeter(tick_ns_);
  CncConfig cc = options_.cnc;
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    cc.step_mm[i] = machine_->step_mm(a);
    cc.home_position_steps[i] = options_.board.board.axis[a].home_position_steps;
  }
  cnc_ = std::make_unique<Cnc>(cc, static_cast<StepSink*>(this), [this](int axis) {
    return machine_->HomeSwitchClosed(
        axis, board_->step_io().drive(static_cast<uint8_t>(axis)).position());
  });

  link_.send = [this](const CanFrame& f) {
    bus_.RunUntil(now_ns_);
    pc_->Send(f);
    return Outcome::Ok();
  };
  link_.receive = [this](uint64_t timeout_us) -> Expected<std::optional<CanFrame>> {
    const uint64_t deadline = now_ns_ + timeout_us * 1000;
    CanFrame f;
    for (;;) {
      if (pc_->Receive(&f)) return std::optional<CanFrame>(f);
      if (now_ns_ >= deadline) return std::optional<CanFrame>();
      StepOnce(deadline);
    }
  };
  link_.now_us = [this] { return now_ns_ / 1000; };
}

World::~World() = default;

Outcome World::Start() { return board_->Start(); }

void World::OnStep(int axis, uint64_t t_ns, int dir) {
  board_->step_io().add_steps(static_cast<uint8_t>(axis), dir);
  latency_.OnInput(axis, t_ns, dir, cnc_->count(axis));
  ++audit_.input_steps;
}

void World::SetClocked(uint64_t period_ns, std::function<void(uint64_t now_ns)> fn) {
  clocked_ = std::move(fn);
  clocked_period_ns_ = period_ns;
  next_clocked_ns_ = now_ns_ + period_ns;
}

void World::StepOnce(uint64_t limit_ns) {
  StepEvent(limit_ns);
  if (clocked_ && now_ns_ >= next_clocked_ns_) {
    next_clocked_ns_ += clocked_period_ns_;
    if (next_clocked_ns_ <= now_ns_) next_clocked_ns_ = now_ns_ + clocked_period_ns_;
    clocked_(now_ns_);
  }
}

void World::StepEvent(uint64_t limit_ns) {
  uint64_t t = board_->NextEventTime();
  if (const auto b = bus_.NextEventTime(); b && *b < t) {
    if (*b > limit_ns) {
      bus_.RunUntil(limit_ns);
      now_ns_ = std::max(now_ns_, limit_ns);
      return;
    }
    bus_.RunUntil(*b);
    now_ns_ = std::max(now_ns_, *b);
    return;
  }
  if (t > limit_ns) {
    bus_.RunUntil(limit_ns);
    now_ns_ = std::max(now_ns_, limit_ns);
    return;
  }
  cnc_->AdvanceTo(t);
  hal::mock::MockStepIo& io = board_->step_io();
  for (uint8_t a = 0; a < 3; ++a) {
    board_->io().SetInput(hal::HomeLine(a), machine_->HomeSwitchClosed(a, io.drive(a).position()));
  }
  bus_.RunUntil(t);
  const uint64_t ticks = io.ticks_applied();
  board_->AdvanceTo(t);
  now_ns_ = t;
  if (io.ticks_applied() != ticks) AfterTick(t);
}

void World::AfterTick(uint64_t t_ns) {
  ++audit_.ticks;
  if (machine_->wear().any()) machine_->OnDriveTick(DriveSteps(), t_ns);
  const auto& plans = board_->step_io().last_plans();
  const ControlTick& engine = board_->app().control_tick();
  for (uint8_t a = 0; a < 3; ++a) {
    const PulsePlan& p = plans[a];
    const int64_t correction = engine.correction_steps(a);
    const int dir = p.negative ? -1 : 1;
    for (uint32_t j = 0; j < p.count; ++j) {
      const uint64_t units = p.first_rise + static_cast<uint64_t>(j) * p.period;
      const uint64_t t = t_ns + units * 1000000000ull / pulse_clock_hz_;
      output_[a] += dir;
      latency_.OnOutput(a, t, output_[a] - correction);
    }
    audit_.output_steps += p.count;
    latency_.EndOfTick(a, t_ns, output_[a] - correction);
    const int64_t drive = board_->step_io().drive(a).position();
    if (drive != output_[a] || drive != static_cast<int64_t>(board_->output().position(a))) {
      ++audit_.tick_mismatches;
    }
  }
}

bool World::RunUntilCncIdle(uint64_t limit_ns) {
  const uint64_t end = now_ns_ + limit_ns;
  while (!cnc_->idle()) {
    if (now_ns_ >= end) return false;
    StepOnce(std::numeric_limits<uint64_t>::max());
  }
  return true;
}

void World::RunFor(uint64_t duration_ns) {
  const uint64_t end = now_ns_ + duration_ns;
  while (now_ns_ < end) StepOnce(end);
}

std::array<int64_t, 3> World::DriveSteps() const {
  std::array<int64_t, 3> d;
  for (uint8_t a = 0; a < 3; ++a) d[a] = board_->step_io().drive(a).position();
  return d;
}

model::Vec3 World::AxisPositions_mm() const { return machine_->AxisPositions_mm(DriveSteps()); }

model::Vec3 World::CommandedPoint_mm() const {
  model::Vec3 p;
  for (int a = 0; a < 3; ++a) {
    p[a] = static_cast<double>(cnc_->position(a)) * machine_->step_mm(a);
  }
  return p;
}

bool World::CheckAtRest() {
  const ControlTick& engine = board_->app().control_tick();
  bool ok = true;
  for (uint8_t a = 0; a < 3; ++a) {
    const int64_t expected = cnc_->count(a) + engine.correction_steps(a);
    const int64_t drive = board_->step_io().drive(a).position();
    const int64_t owed = board_->output().backlog(a, engine.target(a));
    audit_.lost_steps += static_cast<uint64_t>(std::llabs(drive - expected));
    audit_.owed_at_rest += static_cast<uint64_t>(std::llabs(owed));
    ok = ok && drive == expected;
  }
  ++audit_.rest_checks;
  return ok;
}

StepAudit World::Audit() const {
  StepAudit a = audit_;
  const StepOutput& output = board_->output();
  a.timing_violations = 0;
  a.max_backlog = 0;
  for (uint8_t i = 0; i < 3; ++i) {
    a.timing_violations += board_->step_io().drive(i).violations();
    a.max_backlog = std::max(a.max_backlog, output.max_backlog(i));
  }
  a.overruns = output.overruns();
  return a;
}

}  // namespace volcomp::sim
