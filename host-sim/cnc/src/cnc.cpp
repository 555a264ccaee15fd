// The simulated CNC controller.
#include "volcomp/sim/cnc.hpp"

#include <algorithm>
#include <cmath>

#include "volcomp/sim/contract.hpp"
#include "volcomp/sim/path_motion.hpp"

namespace volcomp::sim {

struct Cnc::Block {
  enum class Kind { kMove, kDwell, kHome };
  Kind kind = Kind::kMove;
  std::array<double, 3> value_steps = {0, 0, 0};  // absolute target or distance (incremental)
  std::array<bool, 3> has = {true, true, true};
  bool incremental = false;
  bool rapid = true;
  double feed_mm_s = 0;
  double dwell_s = 0;
  uint8_t mask = 0;
  bool arc = false;
  PathRequest arc_words;  // its end_mm is not used (TargetOf gives the end)
  int line = 0;
};

struct Cnc::Chain {
  std::unique_ptr<PathMotion> motion;
  std::vector<double> ends_mm;  // path length at the end of each block
  std::vector<int> lines;       // program line of each block
};

struct Cnc::Move {
  uint64_t start_ns = 0;
  uint64_t end_ns = 0;
  TrapezoidProfile profile{0, 1, 1};
  std::array<int64_t, 3> n = {0, 0, 0};
  std::array<int64_t, 3> done = {0, 0, 0};
  std::array<int, 3> dir = {1, 1, 1};
  std::array<uint64_t, 3> next_t = {0, 0, 0};
  std::array<double, 3> path_per_step_mm = {0, 0, 0};  // path length per step of each axis
  PathSegment path = PathSegment::Line({0, 0, 0}, {0, 0, 0});

  uint64_t StepTime(size_t a, int64_t k) const {
    const double s = k == n[a] ? profile.length_mm() : path_per_step_mm[a] * static_cast<double>(k);
    return start_ns + static_cast<uint64_t>(std::ceil(profile.TimeAt(s) * 1e9));
  }
};

struct Cnc::Homing {
  enum class Phase { kLeave, kFast, kPause1, kBackoff, kPause2, kSlow, kDone };
  struct Axis {
    Phase phase = Phase::kDone;
    uint64_t phase_start = 0;
    uint64_t period_ns = 0;
    int dir = -1;
    int64_t k = 0;
    int64_t backoff_left = -1;  // steps still to go after the switch opened (-1: not open yet)
  };
  std::array<Axis, 3> axis;
};

Cnc::Cnc(const CncConfig& config, StepSink* sink, SwitchReader home_switch)
    : config_(config), sink_(sink), switch_(std::move(home_switch)) {
  for (double s : config_.step_mm) VOLCOMP_SIM_EXPECT(s > 0, "cnc: step length must be > 0");
  VOLCOMP_SIM_EXPECT(config_.max_step_rate_hz > 0 && config_.accel_mm_s2 > 0,
                     "cnc: step rate and acceleration must be > 0");
}

Cnc::~Cnc() = default;

void Cnc::QueueRapid(const std::array<int64_t, 3>& target_steps) {
  Block b;
  for (size_t a = 0; a < 3; ++a) b.value_steps[a] = static_cast<double>(target_steps[a]);
  queue_.push_back(b);
}

void Cnc::QueueLinear(const std::array<int64_t, 3>& target_steps, double feed_mm_s) {
  VOLCOMP_SIM_EXPECT(feed_mm_s > 0, "cnc: feed must be > 0");
  Block b;
  for (size_t a = 0; a < 3; ++a) b.value_steps[a] = static_cast<double>(target_steps[a]);
  b.rapid = false;
  b.feed_mm_s = feed_mm_s;
  queue_.push_back(b);
}

void Cnc::QueueDwell(double seconds) {
  VOLCOMP_SIM_EXPECT(seconds >= 0, "cnc: dwell must be >= 0");
  Block b;
  b.kind = Block::Kind::kDwell;
  b.dwell_s = seconds;
  queue_.push_back(b);
}

void Cnc::QueueHome(uint8_t mask) {
  Block b;
  b.kind = Block::Kind::kHome;
  b.mask = static_cast<uint8_t>(mask & 7u);
  queue_.push_back(b);
}

void Cnc::QueueProgram(const Program& program) {
  for (const ProgramBlock& p : program) {
    Block b;
    if (p.kind == ProgramBlock::Kind::kDwell) {
      b.kind = Block::Kind::kDwell;
      b.dwell_s = p.dwell_s;
    } else {
      b.rapid = p.kind == ProgramBlock::Kind::kRapid;
      b.feed_mm_s = p.feed_mm_s;
      b.incremental = p.incremental;
      b.arc = p.kind == ProgramBlock::Kind::kArc;
      b.arc_words = RequestOf(p, {0, 0, 0}, config_.step_mm);
      for (size_t a = 0; a < 3; ++a) {
        b.has[a] = p.has[a];
        b.value_steps[a] = p.value_mm[a] / config_.step_mm[a];
      }
    }
    b.line = p.line;
    queue_.push_back(b);
  }
}

std::array<int64_t, 3> Cnc::TargetOf(const Block& b, const std::array<int64_t, 3>& from) const {
  std::array<int64_t, 3> target = from;
  for (size_t a = 0; a < 3; ++a) {
    if (!b.has[a]) continue;
    const int64_t v = std::llround(b.value_steps[a]);
    target[a] = b.incremental ? from[a] + v : v;
  }
  return target;
}

bool Cnc::StartChain(const Block& b, uint64_t t0) {
  if (b.rapid) return false;
  std::array<int64_t, 3> from = {position(0), position(1), position(2)};
  auto mm = [&](const std::array<int64_t, 3>& steps) {
    Point3 p;
    for (size_t a = 0; a < 3; ++a) p[a] = static_cast<double>(steps[a]) * config_.step_mm[a];
    return p;
  };
  auto segment = [&](const Block& x, const std::array<int64_t, 3>& start) {
    PathRequest r = x.arc_words;
    r.arc = x.arc;
    r.end_mm = mm(TargetOf(x, start));
    Expected<PathSegment> s = PathSegment::Resolve(mm(start), r);
    VOLCOMP_SIM_EXPECT(s.ok(), "cnc: an arc the program check should have refused");
    return *s;
  };
  std::vector<PathSegment> segments = {segment(b, from)};
  auto chain = std::make_unique<Chain>();
  chain->ends_mm.push_back(segments.back().length_mm());
  chain->lines.push_back(b.line);
  std::array<int64_t, 3> end = TargetOf(b, from);
  const double kJoinCos = std::cos(3.14159265358979323846 / 180);
  while (!queue_.empty()) {
    const Block& next = queue_.front();
    if (next.kind != Block::Kind::kMove || next.rapid || next.feed_mm_s != b.feed_mm_s) break;
    const PathSegment s = segment(next, end);
    const PathSegment& last = segments.back();
    const Point3 t0v = last.TangentAt(last.length_mm()), t1v = s.TangentAt(0);
    const double dot = t0v[0] * t1v[0] + t0v[1] * t1v[1] + t0v[2] * t1v[2];
    if (!(last.arc() || s.arc()) || dot < kJoinCos) break;
    segments.push_back(s);
    chain->ends_mm.push_back(chain->ends_mm.back() + s.length_mm());
    chain->lines.push_back(next.line);
    end = TargetOf(next, end);
    queue_.pop_front();
  }
  if (segments.size() == 1 && !segments[0].arc()) return false;
  Point3 axis_speed;
  for (size_t a = 0; a < 3; ++a) axis_speed[a] = config_.max_step_rate_hz * config_.step_mm[a];
  std::array<bool, 3> moves = {false, false, false};
  for (const PathSegment& s : segments) {
    const Point3 e = s.end_mm();
    for (size_t a = 0; a < 3; ++a) moves[a] = moves[a] || e[a] != s.start_mm()[a];
    if (s.arc())
      moves[static_cast<size_t>(s.plane_axes()[0])] =
          moves[static_cast<size_t>(s.plane_axes()[1])] = true;
  }
  double speed = b.feed_mm_s;
  for (const PathSegment& s : segments) {
    speed = std::min(speed, s.SpeedLimit(axis_speed, config_.accel_mm_s2));
  }
  chain->motion = std::make_unique<PathMotion>(std::move(segments), from, end, config_.step_mm,
                                               speed, config_.accel_mm_s2, t0);
  // An axis moves at most at the path speed; only the axes the chain moves count.
  for (size_t a = 0; a < 3; ++a) {
    if (!moves[a]) continue;
    peak_rate_hz_ = std::max(peak_rate_hz_, chain->motion->peak_speed_mm_s() / config_.step_mm[a]);
  }
  chain_ = std::move(chain);
  return true;
}

int Cnc::active_line() const {
  if (!active_) return 0;
  if (!chain_) return active_->line;
  const double s = chain_->motion->PathLengthAt(now_ns_);
  size_t i = 0;
  while (i + 1 < chain_->lines.size() && chain_->ends_mm[i] < s) ++i;
  return chain_->lines[i];
}

Cnc::Activity Cnc::activity() const {
  if (!active_) return Activity::kIdle;
  switch (active_->kind) {
    case Block::Kind::kDwell:
      return Activity::kDwell;
    case Block::Kind::kHome:
      return Activity::kHome;
    case Block::Kind::kMove:
      break;
  }
  return active_->rapid ? Activity::kRapid : Activity::kFeed;
}

std::optional<PathSegment> Cnc::active_segment() const {
  if (!active_ || active_->kind != Block::Kind::kMove) return std::nullopt;
  if (chain_) return chain_->motion->SegmentAt(now_ns_);
  if (move_) return move_->path;
  return std::nullopt;
}

double Cnc::RapidSpeed_mm_s(const std::array<int64_t, 3>& delta_steps) const {
  double len2 = 0;
  for (size_t a = 0; a < 3; ++a) {
    const double d = static_cast<double>(delta_steps[a]) * config_.step_mm[a];
    len2 += d * d;
  }
  const double length = std::sqrt(len2);
  double v = INFINITY;
  for (size_t a = 0; a < 3; ++a) {
    if (delta_steps[a] == 0) continue;
    v = std::min(
        v, config_.max_step_rate_hz * length / std::fabs(static_cast<double>(delta_steps[a])));
  }
  return v;
}

void Cnc::Emit(int axis, uint64_t t, int dir) {
  count_[static_cast<size_t>(axis)] += dir;
  ++steps_;
  if (sink_ != nullptr) sink_->OnStep(axis, t, dir);
}

void Cnc::Start(const Block& b, uint64_t t0) {
  active_ = std::make_unique<Block>(b);
  if (b.kind == Block::Kind::kDwell) {
    dwell_end_ns_ = t0 + static_cast<uint64_t>(std::llround(b.dwell_s * 1e9));
    return;
  }
  if (b.kind == Block::Kind::kHome) {
    homing_ = std::make_unique<Homing>();
    for (size_t a = 0; a < 3; ++a) {
      if ((b.mask & (1u << a)) == 0) continue;
      Homing::Axis& h = homing_->axis[a];
      h.phase = Homing::Phase::kLeave;
      h.phase_start = t0;
    }
    return;
  }
  if (StartChain(b, t0)) return;
  auto m = std::make_unique<Move>();
  m->start_ns = t0;
  std::array<int64_t, 3> delta = {0, 0, 0};
  double len2 = 0;
  for (size_t a = 0; a < 3; ++a) {
    int64_t target = position(static_cast<int>(a));
    if (b.has[a]) {
      const int64_t v = std::llround(b.value_steps[a]);
      target = b.incremental ? target + v : v;
    }
    delta[a] = target - position(static_cast<int>(a));
    m->n[a] = std::llabs(delta[a]);
    m->dir[a] = delta[a] < 0 ? -1 : 1;
    const double d = static_cast<double>(delta[a]) * config_.step_mm[a];
    len2 += d * d;
  }
  const double length = std::sqrt(len2);
  {
    Point3 from, to;
    for (size_t a = 0; a < 3; ++a) {
      from[a] = static_cast<double>(position(static_cast<int>(a))) * config_.step_mm[a];
      to[a] = from[a] + static_cast<double>(delta[a]) * config_.step_mm[a];
    }
    m->path = PathSegment::Line(from, to);
  }
  if (length == 0) {
    m->end_ns = t0;
    move_ = std::move(m);
    return;
  }
  double speed = RapidSpeed_mm_s(delta);
  if (!b.rapid) speed = std::min(speed, b.feed_mm_s);
  m->profile = TrapezoidProfile(length, speed, config_.accel_mm_s2);
  m->end_ns = t0 + static_cast<uint64_t>(std::ceil(m->profile.duration_s() * 1e9));
  for (size_t a = 0; a < 3; ++a) {
    if (m->n[a] == 0) continue;
    const double rate = m->profile.peak_speed_mm_s() * static_cast<double>(m->n[a]) / length;
    peak_rate_hz_ = std::max(peak_rate_hz_, rate);
    m->path_per_step_mm[a] = length / static_cast<double>(m->n[a]);
    m->next_t[a] = m->StepTime(a, 1);
  }
  move_ = std::move(m);
}

bool Cnc::RunMove(uint64_t t_ns) {
  if (chain_) {
    PathMotion& p = *chain_->motion;
    const bool emitted = p.EmitUntil(t_ns, [this](int a, uint64_t t, int dir) { Emit(a, t, dir); });
    if (!emitted || p.end_ns() > t_ns) return false;
    cursor_ns_ = p.end_ns();
    return true;
  }
  Move& m = *move_;
  for (size_t a = 0; a < 3; ++a) {
    while (m.done[a] < m.n[a] && m.next_t[a] <= t_ns) {
      Emit(static_cast<int>(a), m.next_t[a], m.dir[a]);
      ++m.done[a];
      if (m.done[a] < m.n[a]) m.next_t[a] = m.StepTime(a, m.done[a] + 1);
    }
  }
  for (size_t a = 0; a < 3; ++a) {
    if (m.done[a] < m.n[a]) return false;
  }
  if (m.end_ns > t_ns) return false;
  cursor_ns_ = m.end_ns;
  return true;
}

bool Cnc::RunHoming(uint64_t t_ns) {
  using Phase = Homing::Phase;
  bool all_done = true;
  for (size_t a = 0; a < 3; ++a) {
    Homing::Axis& h = homing_->axis[a];
    const int axis = static_cast<int>(a);
    auto jog = [&](Phase p, int dir, double speed_mm_s) {
      h.phase = p;
      h.phase_start = t_ns;
      h.dir = dir;
      h.k = 0;
      h.period_ns = static_cast<uint64_t>(std::llround(1e9 * config_.step_mm[a] / speed_mm_s));
    };
    // Phase changes on what the switch shows now (the drives' state before this instant).
    const bool closed = h.phase != Phase::kDone && switch_(axis);
    switch (h.phase) {
      case Phase::kLeave:
        if (!closed) {
          jog(Phase::kFast, -1, config_.home_fast_mm_s);
        } else if (h.k == 0 && h.dir != 1) {
          jog(Phase::kLeave, 1, config_.home_fast_mm_s);
        }
        break;
      case Phase::kFast:
        if (closed) {
          h.phase = Phase::kPause1;
          h.phase_start = t_ns;
        }
        break;
      case Phase::kPause1:
        if (t_ns >= h.phase_start + static_cast<uint64_t>(config_.home_pause_s * 1e9)) {
          jog(Phase::kBackoff, 1, config_.home_fast_mm_s / 4);
          h.backoff_left = -1;
        }
        break;
      case Phase::kBackoff:
        if (!closed && h.backoff_left < 0) {
          h.backoff_left = std::llround(config_.home_backoff_mm / config_.step_mm[a]);
        }
        if (h.backoff_left == 0) {
          h.phase = Phase::kPause2;
          h.phase_start = t_ns;
        }
        break;
      case Phase::kPause2:
        if (t_ns >= h.phase_start + static_cast<uint64_t>(config_.home_pause_s * 1e9)) {
          jog(Phase::kSlow, -1, config_.home_slow_mm_s);
        }
        break;
      case Phase::kSlow:
        if (closed) {
          offset_[a] = config_.home_position_steps[a] - count_[a];
          homed_[a] = true;
          h.phase = Phase::kDone;
        }
        break;
      case Phase::kDone:
        break;
    }
    const bool jogging = h.phase == Phase::kLeave || h.phase == Phase::kFast ||
                         h.phase == Phase::kBackoff || h.phase == Phase::kSlow;
    if (jogging && h.period_ns > 0) {
      while (h.phase_start + static_cast<uint64_t>(h.k + 1) * h.period_ns <= t_ns) {
        if (h.phase == Phase::kBackoff && h.backoff_left == 0) break;
        ++h.k;
        Emit(axis, h.phase_start + static_cast<uint64_t>(h.k) * h.period_ns, h.dir);
        if (h.phase == Phase::kBackoff && h.backoff_left > 0) --h.backoff_left;
      }
    }
    all_done = all_done && h.phase == Phase::kDone;
  }
  if (all_done) cursor_ns_ = t_ns;
  return all_done;
}

void Cnc::AdvanceTo(uint64_t t_ns) {
  for (;;) {
    if (!active_) {
      if (queue_.empty()) break;
      const Block b = queue_.front();
      queue_.pop_front();
      Start(b, std::max(cursor_ns_, now_ns_));
    }
    bool finished = false;
    switch (active_->kind) {
      case Block::Kind::kMove:
        finished = RunMove(t_ns);
        break;
      case Block::Kind::kDwell:
        if (dwell_end_ns_ <= t_ns) {
          cursor_ns_ = dwell_end_ns_;
          if (on_dwell_) on_dwell_(dwell_end_ns_);
          finished = true;
        }
        break;
      case Block::Kind::kHome:
        finished = RunHoming(t_ns);
        break;
    }
    if (!finished) break;
    active_.reset();
    move_.reset();
    homing_.reset();
    chain_.reset();
  }
  now_ns_ = std::max(now_ns_, t_ns);
}

}  // namespace volcomp::sim
