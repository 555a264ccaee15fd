// The demo's ISO 230-4 circular tests: the program `volcomp program circular` writes, run through
// the board on the demo's installation as `volcomp-sim run --ballbar` runs it, and its readings
// evaluated with the PC tool's evaluation.
#include <cstdio>

#include "demo_session.hpp"
#include "volcomp/metrology/circular_program.hpp"
#include "volcomp/sim/gcode.hpp"
#include "volcomp/sim/program_run.hpp"

namespace volcomp::sim::demo {

Expected<std::vector<CircularTestResult>> MeasureCircularTests(Session& s) {
  std::vector<CircularTestResult> tests;
  const metrology::CircularPlane planes[] = {
      metrology::CircularPlane::kXY, metrology::CircularPlane::kZX, metrology::CircularPlane::kYZ};
  for (size_t k = 0; k < 3; ++k) {
    const auto t0 = Clock::now();
    CircularTestResult t;
    t.plane = metrology::CircularPlaneName(planes[k]);
    metrology::CircularProgramOptions c;
    c.plane = planes[k];
    c.centre_mm = {s.layout.centre[0], s.layout.centre[1], s.layout.centre[2]};
    c.radius_mm = s.o.circle_radius_mm;
    c.feed_mm_min = s.o.circle_feed_mm_min;
    VOLCOMP_TRY_ASSIGN(t.gcode, metrology::EmitCircularProgram(c));
    const std::string name = "circle_" + t.plane + ".ngc";
    VOLCOMP_TRY_ASSIGN(const Program program, ParseGcode(t.gcode, name));
    ProgramInWorldOptions o;
    o.program_name = name;
    o.ballbar_pivot_mm = s.layout.centre;
    // Its own noise in every phase and plane.
    o.ballbar_seed = (s.o.seed ^ 0x62616c6c626172ull) +
                     0x9E3779B97F4A7C15ull * (3 * static_cast<uint64_t>(s.epoch) + k + 1);
    o.keep_samples = false;
    ProgramRunResult run;
    VOLCOMP_TRY(RunProgramInWorld(s.world, program, o, run));
    for (const BallbarReading& b : run.ballbar) {
      metrology::CircularPath& path = b.cw ? t.data.cw : t.data.ccw;
      path.angle_deg.push_back(b.angle_deg);
      path.deviation_um.push_back(b.deviation_um);
    }
    t.data.source = name + " (ballbar)";
    t.result = *run.circular;
    t.cutting_max_error_um = run.cutting_max_error_um;
    char line[300];
    std::snprintf(line, sizeof line,
                  "ISO 230-4 circular test %s (r %.0f mm, %.0f mm/min, ballbar): G(b) %.2f um, "
                  "H %.2f um (G cw %.2f, ccw %.2f; F %.2f / %.2f um)   (%.1f s)",
                  t.plane.c_str(), c.radius_mm, c.feed_mm_min, t.result.G_b_um, t.result.H_um,
                  t.result.G_cw_um, t.result.G_ccw_um, t.result.F_max_um, t.result.F_min_um,
                  Since(t0));
    s.progress.Line(line);
    tests.push_back(std::move(t));
  }
  return tests;
}

}  // namespace volcomp::sim::demo
