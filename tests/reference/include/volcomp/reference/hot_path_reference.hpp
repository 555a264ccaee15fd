// The clear versions of the tick's optimised routines, kept as executable specifications (the
// reference library, tests/reference; not linked into the product): the host tests
// (tests/lib/hot_path_reference_test.cpp) drive each optimised routine and its reference with the
// same random and adversarial inputs and require identical results, bit for bit.
//
//   StepGeneratorReference     StepGenerator::Plan() with int64 times relative to the tick (the
//                              optimised one keeps int32 times floored at -2^30)
//   LimiterStepReference()     CorrectionLimiter::Step() in its direct form (64-bit distances,
//                              division-free but unfused)
//   (GridLookup::Interpolate<Loader> and LatticeLocator::Locate are the lookup references; they
//   stay in grid_lookup.hpp and cell_locator.hpp next to the kernels.)
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/limiter/correction_limiter.hpp"
#include "volcomp/output/step_generator.hpp"

namespace volcomp {

/// Output pulse planning in its direct form (see step_generator.hpp for the rules).
class StepGeneratorReference {
 public:
  Status Configure(const AxisConfig& axis, uint32_t tick_hz, uint32_t pulse_clock_hz);
  PulsePlan Plan(int32_t target_steps);
  int32_t position() const { return position_; }
  void Reset(int32_t position_steps) { position_ = position_steps; }

 private:
  PulseTiming t_;  // the same conversion as StepGenerator (not what the comparison checks)
  int32_t position_ = 0;
  bool negative_ = false;
  int64_t last_rise_ = -(int64_t{1} << 40);  // relative to the current tick start
  int64_t last_fall_ = -(int64_t{1} << 40);
};

/// One tick of the correction limiter in its direct form: moves (pos, k) toward `target_q32`.
int64_t LimiterStepReference(const LimiterParams& p,
                             int64_t& pos_q32,
                             int32_t& k,
                             int64_t target_q32);

}  // namespace volcomp
