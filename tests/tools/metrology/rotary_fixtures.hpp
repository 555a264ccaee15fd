// Synthetic ISO 230-7 records for the error-motion and rotary-evaluation tests.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "volcomp/metrology/error_motion.hpp"
#include "volcomp/metrology/rotary_data.hpp"

namespace volcomp::metrology::testing {

constexpr double kPi = 3.14159265358979323846;

inline std::vector<double> Angles(int n) {
  std::vector<double> a(n);
  for (int j = 0; j < n; ++j) a[j] = 360.0 * j / n;
  return a;
}

// u[k][j] = f(θ_total) with θ_total = θ_j + 360°·k in radians.
template <typename F>
Revolutions Make(int n, int k_revs, F f) {
  Revolutions u(k_revs, std::vector<double>(n));
  for (int k = 0; k < k_revs; ++k) {
    for (int j = 0; j < n; ++j) u[k][j] = f(2 * kPi * (j / static_cast<double>(n) + k));
  }
  return u;
}

// A record with the given channels, sampled at n angles over k revolutions.
inline RotaryRecord Record(int n, int k_revs, const std::map<std::string, Revolutions>& channels) {
  RotaryRecord r;
  r.source = "synthetic";
  r.angle_deg = Angles(n);
  for (int k = 0; k < k_revs; ++k) r.revs.push_back(k + 1);
  r.rev_sense.assign(k_revs, RotationSense::kUnstated);
  r.channels = channels;
  return r;
}

}  // namespace volcomp::metrology::testing
