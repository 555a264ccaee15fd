// The hand-worked inputs of the hobby writers' tests (marlin_test, reprap_test, grblhal_test):
// a squareness C0Y = −500, B0Z = 200, A0Z = −300 µrad and a two-direction test whose reverse
// minus forward deviations are 18, 20, 21, 18, 20 µm (backlash 97 / 5 = 19.4 µm, B̄ = −19.4 µm,
// max |B_j| = 21 µm; a constant 19.4 leaves up to |21 − 19.4| = 1.6 µm).
#pragma once

#include <string>

#include "expected_value.hpp"
#include "volcomp/exporters/hobby_common.hpp"

namespace volcomp::exporters::test_data {

inline HobbySquareness Square() {
  HobbySquareness s;
  s.xy = PlaneSquareness{-500, "--squareness-xy-urad"};
  s.xz = PlaneSquareness{200, "--squareness-xz-urad"};
  s.yz = PlaneSquareness{-300, "--squareness-yz-urad"};
  return s;
}

inline model::PositioningData LostMotionTest(bool rotary = false) {
  model::PositioningData d;
  d.rotary = rotary;
  d.position = {0, 50, 100, 150, 200};
  d.dev_forward = {0, 6, 10, 12, 9};
  d.dev_reverse = {18, 26, 31, 30, 29};
  return d;
}

inline AxisBacklash Backlash(char axis, bool rotary = false, bool negate_test = false) {
  return testing::ValueOf(
      BacklashFromTest(axis, std::string(1, axis) + ".csv", LostMotionTest(rotary), negate_test));
}

}  // namespace volcomp::exporters::test_data
