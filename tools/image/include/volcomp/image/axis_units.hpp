// Axis names, units per step and unit conversions for the PC tool's options and CSV columns.
//
// Resolution options: `--resolution-nm X=1000,Y=1000,Z=500` (nm per step for linear axes; for
// rotary axes A/B/C the value is micro-degrees per step) or
// `--steps-per-unit X=1000,A=100` (steps per mm, or per degree). Either must give a whole number
// of 1e-9 units (pm or nano-degrees) per step, which is how the image stores it.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "volcomp/image/image_builder.hpp"

namespace volcomp::image {

/// Parses "X=1,Y=2" into {'X':"1", 'Y':"2"}; throws UsageError on bad syntax or axis names.
std::map<char, std::string> ParseAxisAssignments(const std::string& text,
                                                 const std::string& option);

/// Parses "X,Y,Z" into names; throws UsageError.
std::vector<char> ParseAxisList(const std::string& text, const std::string& option);

/// Rotary axes by ISO 841 convention: A, B, C.
bool IsRotaryName(char name);

/// Builds AxisDefs for `names` from --resolution-nm / --steps-per-unit strings (exactly one of
/// them non-empty; it must name every axis). Throws UsageError, also when both are given.
std::vector<AxisDef> MakeAxisDefs(const std::vector<char>& names,
                                  const std::string& resolution_nm,
                                  const std::string& steps_per_unit);

/// Lower-case column prefix of an axis ("x" for 'X').
std::string ColumnName(char axis);

}  // namespace volcomp::image
