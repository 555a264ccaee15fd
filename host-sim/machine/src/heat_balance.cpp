#include "volcomp/sim/heat_balance.hpp"

#include <algorithm>
#include <cmath>

namespace volcomp::sim {
namespace {

constexpr int kSpindle = static_cast<int>(ThermalBody::kSpindle);
constexpr int kHead = static_cast<int>(ThermalBody::kHead);
constexpr int kScrew = static_cast<int>(ThermalBody::kXScrew);
constexpr int kStructure = static_cast<int>(ThermalBody::kStructure);

}  // namespace

HeatBalance::HeatBalance(const HeatBalanceParams& params, double start_C)
    : p_(params), start_C_(start_C) {
  t_C_.fill(start_C);
}

void HeatBalance::Rates(const std::array<double, kThermalBodies>& t,
                        const ThermalLoad& load,
                        std::array<double, kThermalBodies>* dt_dt,
                        double* power_in_W,
                        double* power_to_air_W) const {
  std::array<double, kThermalBodies> q = {};  // net power into each body, W
  q[kSpindle] = p_.spindle_power_W * load.spindle_fraction;
  q[kScrew] = p_.screw_W_per_m_min * std::fabs(load.x_speed_m_min);
  *power_in_W = q[kSpindle] + q[kScrew];
  const double sh = p_.spindle_to_head_W_K * (t[kSpindle] - t[kHead]);
  const double hs = p_.head_to_structure_W_K * (t[kHead] - t[kStructure]);
  q[kSpindle] -= sh;
  q[kHead] += sh - hs;
  q[kStructure] += hs;
  *power_to_air_W = 0;
  for (int i = 0; i < kThermalBodies; ++i) {
    const double loss = p_.to_air_W_K[static_cast<size_t>(i)] * (t[i] - load.ambient_C);
    q[i] -= loss;
    *power_to_air_W += loss;
    (*dt_dt)[i] = q[i] / p_.capacity_J_K[static_cast<size_t>(i)];
  }
}

void HeatBalance::Step(double dt_s, const ThermalLoad& load) {
  while (dt_s > 0) {
    const double h = std::min(dt_s, p_.max_substep_s);
    std::array<double, kThermalBodies> k1, k2, mid;
    double in1, in2, air1, air2;
    Rates(t_C_, load, &k1, &in1, &air1);
    for (int i = 0; i < kThermalBodies; ++i) mid[i] = t_C_[i] + h * k1[i];
    Rates(mid, load, &k2, &in2, &air2);
    for (int i = 0; i < kThermalBodies; ++i) t_C_[i] += 0.5 * h * (k1[i] + k2[i]);
    heat_in_J_ += 0.5 * h * (in1 + in2);
    heat_to_air_J_ += 0.5 * h * (air1 + air2);
    time_s_ += h;
    dt_s -= h;
  }
}

double HeatBalance::heat_stored_J() const {
  double e = 0;
  for (int i = 0; i < kThermalBodies; ++i) {
    e += p_.capacity_J_K[static_cast<size_t>(i)] * (t_C_[i] - start_C_);
  }
  return e;
}

ThermalDeformation HeatBalance::Deformation() const {
  const double a_um = p_.alpha_per_K * 1e3;  // um per (K mm)
  const double d_spindle = t_C_[kSpindle] - p_.reference_C;
  const double d_head = t_C_[kHead] - p_.reference_C;
  const double d_structure = t_C_[kStructure] - p_.reference_C;
  ThermalDeformation d;
  d.x_screw_ppm = p_.alpha_per_K * 1e6 * (t_C_[kScrew] - p_.reference_C);
  d.x_screw_fixed_end_mm = p_.screw_fixed_end_mm;
  // The head's path from the column's guideways to the spindle bore: the casting, and near the
  // bore the wall the cartridge heats.
  d.tool_um.y =
      a_um * p_.head_y_mm * ((1 - p_.bore_wall_share) * d_head + p_.bore_wall_share * d_spindle);
  d.tool_um.z =
      -a_um * (p_.quill_mm * d_spindle + p_.head_mm * d_head) + a_um * p_.column_mm * d_structure;
  return d;
}

}  // namespace volcomp::sim
