// `volcomp-sim run`: a part program on the simulated installation.
#include "volcomp/sim/program_run.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "volcomp/hosted/settings_ini.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/report/xy_chart.hpp"
#include "volcomp/sim/ballbar.hpp"
#include "volcomp/sim/board_session.hpp"
#include "volcomp/sim/gcode.hpp"
#include "volcomp/sim/world.hpp"
#include "volcomp/sim/worn_profile.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::sim {
namespace {

constexpr uint64_t kSecond_ns = 1000000000ull;

Point3 ToPoint(const model::Vec3& v) { return {v.x, v.y, v.z}; }

double Distance(const Point3& a, const Point3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

Expected<std::unique_ptr<World>> MakeWorld(const ProgramRunOptions& o) {
  WorldOptions wo;
  VOLCOMP_TRY_ASSIGN(wo.machine.model, LoadMachineModel(o.model_spec));
  if (o.worn) wo.machine.wear = DefaultWornProfile(o.seed ^ 0x6d616368696e65ull);
  {
    VOLCOMP_TRY_ASSIGN(const Machine machine, Machine::Create(wo.machine));
    wo.board = BoardSettingsFor(machine);
  }
  if (!o.settings_ini.empty()) {
    const auto doc = hosted::IniDocument::Parse(o.settings_ini, o.settings_source);
    if (!doc.ok()) return Unexpected<Failure>{doc.error().ToFailure()};
    const auto read = hosted::ReadSettings(*doc, &wo.board);
    if (!read.ok()) return Unexpected<Failure>{read.error().ToFailure()};
    const auto checked = hosted::CheckSettings(*doc, wo.board);
    if (!checked.ok()) return Unexpected<Failure>{checked.error().ToFailure()};
  }
  wo.cnc.accel_mm_s2 = o.accel_mm_s2;
  return World::Create(wo);
}

Outcome PrepareBoard(World& world,
                     const ProgramRunOptions& o,
                     ProgramRunResult& r,
                     std::ostream& log) {
  VOLCOMP_TRY(world.Start());
  world.cnc().QueueHome(7);
  if (!world.RunUntilCncIdle(120 * kSecond_ns)) {
    return Fail(Error::kNotReady, "homing did not finish within 120 s");
  }
  world.RunFor(20000000);
  log << "homed; the board referenced X, Y, Z on the switches\n";
  if (o.table_image.empty()) return {};
  VOLCOMP_TRY_ASSIGN(const UploadReport up, UploadTable(world, o.table_image, log));
  world.RunFor(150000000);  // activation needs 100 ms without input steps
  VOLCOMP_TRY_ASSIGN(const ActivationReport act, ActivateTable(world, up.image_crc));
  world.RunFor(500000000);  // the correction ramps in within the rate limits
  r.table_crc = act.active_crc;
  char b[96];
  std::snprintf(b, sizeof b, "table CRC-32 0x%08X uploaded and active\n", act.active_crc);
  log << b;
  return {};
}

// Moves to the touch-off point and returns the tool point's offset from the command there.
Expected<Point3> TouchOff(World& world,
                          const Program& program,
                          const Point3& start_mm,
                          const Point3& step_mm,
                          const ProgramInWorldOptions& o,
                          ProgramRunResult& r) {
  Point3 at = start_mm;
  if (o.touch_off_mm) {
    at = *o.touch_off_mm;
  } else {
    for (const ProgramBlock& b : program) {
      if (b.kind == ProgramBlock::Kind::kDwell) continue;
      at = RequestOf(b, start_mm, step_mm).end_mm;
      break;
    }
  }
  std::array<int64_t, 3> target;
  for (size_t a = 0; a < 3; ++a) target[a] = std::llround(at[a] / step_mm[a]);
  world.cnc().QueueRapid(target);
  if (!world.RunUntilCncIdle(600 * kSecond_ns)) {
    return Fail(Error::kNotReady, "the move to the touch-off point did not finish");
  }
  world.RunFor(100000000);  // settled
  world.CheckAtRest();
  const Point3 tool = ToPoint(world.machine().ToolPoint_mm(world.AxisPositions_mm()));
  const Point3 cmd = ToPoint(world.CommandedPoint_mm());
  Point3 offset;
  for (size_t a = 0; a < 3; ++a) {
    offset[a] = tool[a] - cmd[a];
    r.touch_off_mm[a] = cmd[a];
    r.work_offset_um[a] = 1e3 * offset[a];
  }
  return offset;
}

}  // namespace

const char* SampleKindName(SampleKind k) {
  switch (k) {
    case SampleKind::kCutting:
      return "cutting";
    case SampleKind::kRapid:
      return "rapid";
    case SampleKind::kRest:
      break;
  }
  return "rest";
}

Expected<ProgramRunResult> RunProgramOnMachine(const ProgramRunOptions& o, std::ostream& log) {
  ProgramRunResult r;
  r.program = o.program_name;
  r.machine = o.worn ? "worn" : "ideal";
  VOLCOMP_TRY_ASSIGN(const Program program, ParseGcode(o.program_text, o.program_name));
  VOLCOMP_TRY_ASSIGN(const std::unique_ptr<World> installation, MakeWorld(o));
  World& world = *installation;
  VOLCOMP_TRY(PrepareBoard(world, o, r, log));
  ProgramInWorldOptions p;
  p.program_name = o.program_name;
  p.touch_off_mm = o.touch_off_mm;
  p.ballbar_pivot_mm = o.ballbar_pivot_mm;
  p.ballbar_seed = o.seed ^ 0x62616c6c626172ull;
  p.sample_period_s = o.sample_period_s;
  p.limit_s = o.limit_s;
  VOLCOMP_TRY(RunProgramInWorld(world, program, p, r));
  const StepAudit audit = world.Audit();
  r.lost_steps = audit.lost_steps;
  r.timing_violations = audit.timing_violations;
  r.rest_checks = audit.rest_checks;
  return r;
}

Outcome RunProgramInWorld(World& world,
                          const Program& program,
                          const ProgramInWorldOptions& o,
                          ProgramRunResult& r) {
  Cnc& cnc = world.cnc();
  Point3 step_mm, start_mm;
  for (int a = 0; a < 3; ++a) {
    step_mm[static_cast<size_t>(a)] = world.machine().step_mm(a);
    start_mm[static_cast<size_t>(a)] =
        static_cast<double>(cnc.position(a)) * step_mm[static_cast<size_t>(a)];
  }
  VOLCOMP_TRY(CheckProgramPaths(program, start_mm, step_mm, o.program_name));
  VOLCOMP_TRY_ASSIGN(const Point3 offset_mm, TouchOff(world, program, start_mm, step_mm, o, r));
  cnc.set_dwell_handler([&world](uint64_t) { world.CheckAtRest(); });
  cnc.QueueProgram(program);

  std::optional<Ballbar> ballbar;
  if (o.ballbar_pivot_mm) {
    const Point3& p = *o.ballbar_pivot_mm;
    ballbar.emplace(&world.machine(), model::Vec3{p[0], p[1], p[2]}, BallbarOptions{},
                    o.ballbar_seed);
  }
  const model::Vec3 work_offset{offset_mm[0], offset_mm[1], offset_mm[2]};
  int last_degree[2] = {-1, -1};  // per direction: the last whole degree read
  auto read_ballbar = [&](const PathSegment& arc, const model::Vec3& q_mm, const Point3& tool) {
    const Point3 c = arc.centre_mm();
    if (!arc.full_circle() || Distance(c, *o.ballbar_pivot_mm) > 1e-3) return;
    const auto& ax = arc.plane_axes();
    const size_t f = static_cast<size_t>(ax[0]), g = static_cast<size_t>(ax[1]);
    double angle = std::atan2(tool[g] - c[g], tool[f] - c[f]) * 180 / 3.14159265358979323846;
    if (angle < 0) angle += 360;
    const bool cw = arc.sweep_rad() < 0;
    const int degree = static_cast<int>(angle);
    if (degree == last_degree[cw]) return;
    last_degree[cw] = degree;
    BallbarReading b;
    b.cw = cw;
    b.angle_deg = angle;
    b.deviation_um = ballbar->Deviation_um(q_mm, work_offset, arc.radius_mm());
    b.plane = ax[0] == 0 ? 17 : ax[0] == 2 ? 18 : 19;
    b.radius_mm = arc.radius_mm();
    r.ballbar.push_back(b);
  };
  const uint64_t period_ns = static_cast<uint64_t>(std::llround(o.sample_period_s * 1e9));
  const uint64_t t0 = world.now_ns();
  double cutting_sum2 = 0;
  auto sample = [&](bool running) {
    PathSample s;
    s.t_s = static_cast<double>(world.now_ns() - t0) * 1e-9;
    s.line = running ? cnc.active_line() : 0;
    const Cnc::Activity act = running ? cnc.activity() : Cnc::Activity::kIdle;
    s.kind = act == Cnc::Activity::kFeed    ? SampleKind::kCutting
             : act == Cnc::Activity::kRapid ? SampleKind::kRapid
                                            : SampleKind::kRest;
    s.commanded_mm = ToPoint(world.CommandedPoint_mm());
    const model::Vec3 q = world.AxisPositions_mm();
    s.tool_mm = ToPoint(world.machine().ToolPoint_mm(q));
    for (size_t a = 0; a < 3; ++a) s.tool_mm[a] -= offset_mm[a];
    const std::optional<PathSegment> path = cnc.active_segment();
    const double error_mm = s.kind != SampleKind::kRest && path
                                ? path->DistanceTo(s.tool_mm)
                                : Distance(s.tool_mm, s.commanded_mm);
    s.error_um = 1e3 * error_mm;
    if (ballbar && s.kind == SampleKind::kCutting && path && path->arc()) {
      read_ballbar(*path, q, s.tool_mm);
    }
    if (s.kind == SampleKind::kCutting) {
      r.cutting_max_error_um = std::max(r.cutting_max_error_um, s.error_um);
      cutting_sum2 += s.error_um * s.error_um;
      ++r.cutting_samples;
    } else if (s.kind == SampleKind::kRapid) {
      r.rapid_max_error_um = std::max(r.rapid_max_error_um, s.error_um);
    } else {
      r.rest_max_error_um = std::max(r.rest_max_error_um, s.error_um);
    }
    auto it = std::find_if(r.lines.begin(), r.lines.end(), [&](const LineFigures& l) {
      return l.line == s.line && l.kind == s.kind;
    });
    if (it == r.lines.end()) it = r.lines.insert(r.lines.end(), LineFigures{s.line, s.kind});
    ++it->samples;
    it->max_error_um = std::max(it->max_error_um, s.error_um);
    if (o.keep_samples) r.samples.push_back(s);
  };
  while (!cnc.idle()) {
    if (world.now_ns() - t0 > o.limit_s * kSecond_ns) {
      return Fail(Error::kNotReady, o.program_name + ": the program did not finish within " +
                                        std::to_string(o.limit_s) + " s of virtual time");
    }
    world.RunFor(period_ns);
    sample(!cnc.idle());
  }
  cnc.set_dwell_handler({});
  r.duration_s = static_cast<double>(world.now_ns() - t0) * 1e-9;
  world.RunFor(20000000);  // the last correction settles; then the end point at rest
  world.CheckAtRest();
  sample(false);
  if (r.cutting_samples > 0) {
    r.cutting_rms_error_um = std::sqrt(cutting_sum2 / static_cast<double>(r.cutting_samples));
  }
  if (o.ballbar_pivot_mm) {
    metrology::CircularData data;
    data.source = o.program_name + " (ballbar)";
    for (const BallbarReading& b : r.ballbar) {
      metrology::CircularPath& path = b.cw ? data.cw : data.ccw;
      path.angle_deg.push_back(b.angle_deg);
      path.deviation_um.push_back(b.deviation_um);
    }
    if (r.ballbar.empty()) {
      return Fail(Error::kInputInvalid, o.program_name +
                                            ": the ballbar read nothing: no full circle about "
                                            "its pivot (give the circle's centre)");
    }
    VOLCOMP_TRY_ASSIGN(r.circular, metrology::EvaluateCircular(data));
  }
  return Outcome::Ok();
}

Outcome WriteProgramRunReport(const ProgramRunResult& r, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return Fail(Error::kIoError, dir + ": cannot create the report folder: " + ec.message());
  std::ostringstream csv;
  csv << "t_s,line,kind,x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm,error_um\n";
  report::XySeries cutting, rapid, rest;
  cutting.label = "cutting (G1/G2/G3)";
  cutting.color = "#d62728";
  rapid.label = "rapid (G0)";
  rest.label = "rest";
  rest.color = "#2ca02c";
  for (report::XySeries* s : {&cutting, &rapid, &rest}) {
    s->marker = report::Marker::kNone;
  }
  for (const PathSample& s : r.samples) {
    csv << report::FormatNumber(s.t_s, 9) << ',' << s.line << ',' << SampleKindName(s.kind);
    for (double v : s.commanded_mm) csv << ',' << report::FormatFixed(v, 6);
    for (double v : s.tool_mm) csv << ',' << report::FormatFixed(v, 6);
    csv << ',' << report::FormatFixed(s.error_um, 4) << '\n';
    for (report::XySeries* series : {&cutting, &rapid, &rest}) {
      const bool mine = (series == &cutting && s.kind == SampleKind::kCutting) ||
                        (series == &rapid && s.kind == SampleKind::kRapid) ||
                        (series == &rest && s.kind == SampleKind::kRest);
      series->x.push_back(s.t_s);
      series->y.push_back(mine ? s.error_um : NAN);
    }
  }
  VOLCOMP_TRY(tools::WriteTextFile(dir + "/samples.csv", csv.str()));
  if (!r.ballbar.empty()) {
    std::ostringstream bar;
    bar << "direction,angle_deg,deviation_um\n";
    for (const BallbarReading& b : r.ballbar) {
      bar << (b.cw ? "cw," : "ccw,") << report::FormatFixed(b.angle_deg, 3) << ','
          << report::FormatFixed(b.deviation_um, 2) << '\n';
    }
    VOLCOMP_TRY(tools::WriteTextFile(dir + "/ballbar.csv", bar.str()));
  }
  report::XyChart chart;
  chart.title = r.program + " on the " + r.machine + " machine";
  chart.x_label = "time since the program started, s";
  chart.y_label = "tool point error against the programmed path, µm";
  chart.series = {cutting, rapid, rest};
  report::HtmlPage page("volcomp-sim run: " + r.program);
  page.Heading(1, "volcomp-sim run: " + r.program);
  page.Paragraph("Machine: " + r.machine + "; table CRC-32: " +
                 (r.table_crc == 0 ? std::string("none") : report::FormatNumber(r.table_crc)) +
                 "; cutting max " + report::FormatFixed(r.cutting_max_error_um, 2) + " µm, rms " +
                 report::FormatFixed(r.cutting_rms_error_um, 2) + " µm; rapid max " +
                 report::FormatFixed(r.rapid_max_error_um, 2) + " µm; at rest max " +
                 report::FormatFixed(r.rest_max_error_um, 2) + " µm. Samples: samples.csv.");
  page.Figure(chart.Render(), "The error along the program (one sample per sample period).");
  return page.WriteFile(dir + "/index.html");
}

}  // namespace volcomp::sim
