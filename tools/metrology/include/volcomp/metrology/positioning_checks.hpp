// Plan checks of a positioning test that do not stop the evaluation; each returns warnings.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/metrology/positioning_eval.hpp"

namespace volcomp::metrology {

/// Number of target positions against the axis length (linear axes only):
///  - GOST 27843-88 §2.7: at least 11 positions on any 2 m of travel (checked for every 2 m
///    window starting at a target; an axis of up to 2 m needs 11 in total);
///  - ISO 230-2:2014: at least 5 per metre and at least 5 in total for axes up to 2000 mm, and
///    an average interval of at most 250 mm beyond that.
/// `axis_length_mm` defaults to the span of the targets.
std::vector<std::string> CheckPositionCount(const PositioningSet& set,
                                            Standard standard,
                                            std::optional<double> axis_length_mm);

/// GOST 27843-88 §2.8: an angular positioning test must include 0°, 90°, 180° and 270° (those
/// within the tested range for an axis of less than a full turn). Targets are compared modulo
/// 360° within 0.001°. Returns one warning naming the missing angles, or nothing.
std::vector<std::string> CheckCardinalAngles(const PositioningSet& set);

}  // namespace volcomp::metrology
