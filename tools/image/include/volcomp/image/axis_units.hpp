// Axis names, units per step and unit conversions for the PC tool's options and CSV columns.
//
// Step sizes come from option values: `--resolution-nm X=1000,Z=500` (nm per step; µ° per step
// on the rotary axes A, B, C) or `--steps-per-unit X=1000,A=100` (steps per mm or per degree).
// Either must give a whole number of 1e-9 units per step (pm or nano-degrees), as the image
// stores it. The parsers read option values, so their failures are kUsage and name the option.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/image/image_builder.hpp"

namespace volcomp::image {

/// Parses "X=1,Y=2" into {'X':"1", 'Y':"2"}; kUsage on bad syntax, a bad or repeated axis name.
Expected<std::map<char, std::string>> ParseAxisAssignments(const std::string& text,
                                                           const std::string& option);

/// Parses "X,Y,Z" into names; kUsage on bad syntax, a bad or repeated axis name.
Expected<std::vector<char>> ParseAxisList(const std::string& text, const std::string& option);

/// Rotary axes by ISO 841 convention: A, B, C.
bool IsRotaryName(char name);

/// AxisDefs for `names` from the --resolution-nm / --steps-per-unit values (exactly one of them
/// non-empty; it must name every axis); kUsage otherwise, or for a step that is not a whole
/// number of 1e-9 units.
Expected<std::vector<AxisDef>> MakeAxisDefs(const std::vector<char>& names,
                                            const std::string& resolution_nm,
                                            const std::string& steps_per_unit);

/// A step size as the shop says it, steps per unit first: "400 steps/mm (2500 nm/step)", on a
/// rotary axis "1000 steps/deg (1000 µ°/step)". `resolution_e9` is units (mm or degrees) per step
/// x 1e9 as object 0x2012 and the image store it (pm or nano-degrees per step); both figures are
/// printed to 9 significant digits; 0 (no resolution) gives "0 nm/step" / "0 µ°/step".
std::string ResolutionText(uint32_t resolution_e9, bool rotary);

/// Lower-case column prefix of an axis ("x" for 'X').
std::string ColumnName(char axis);

}  // namespace volcomp::image
