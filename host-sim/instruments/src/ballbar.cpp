// The virtual ballbar.
#include "volcomp/sim/ballbar.hpp"

namespace volcomp::sim {

Ballbar::Ballbar(const Machine* machine,
                 const model::Vec3& pivot_mm,
                 const BallbarOptions& options,
                 uint64_t seed)
    : machine_(machine), pivot_mm_(pivot_mm), options_(options), rng_(seed) {}

double Ballbar::TrueDeviation_um(const model::Vec3& q_mm,
                                 const model::Vec3& work_offset_mm,
                                 double nominal_mm) const {
  const model::Vec3 bar = machine_->ToolPoint_mm(q_mm) - work_offset_mm - pivot_mm_;
  return 1e3 * (model::Norm(bar) - nominal_mm);
}

double Ballbar::Deviation_um(const model::Vec3& q_mm,
                             const model::Vec3& work_offset_mm,
                             double nominal_mm) {
  return ApplyChannelErrors(options_.length_um, TrueDeviation_um(q_mm, work_offset_mm, nominal_mm),
                            rng_);
}

}  // namespace volcomp::sim
