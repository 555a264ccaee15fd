// The inputs the exports from positioning tests share (`export linuxcnc`, `export isg`): the axis
// files of PositioningFileOptions() and a per-axis integer option such as --joints X=N,...
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "command.hpp"

namespace volcomp::cli {

/// The axis letters of PositioningFileOptions(), in their order.
inline constexpr const char* kPositioningAxes = "XYZABCUVW";

/// (axis, file) of each --x ... --w given, in the order X Y Z A B C U V W; a usage failure when
/// none is.
Expected<std::vector<std::pair<char, std::string>>> PositioningFiles(Args& args);

/// `option`'s "X=N,..." (absent: nullopt text): each axis's whole number in [min, max]; an axis not
/// named keeps `first` + its place in kPositioningAxes. Usage failure "OPTION: WHAT of X must be
/// MIN..MAX" otherwise.
Expected<std::map<char, int>> ParseAxisNumberMap(const std::optional<std::string>& text,
                                                 const std::string& option,
                                                 const std::string& what,
                                                 int first,
                                                 int min,
                                                 int max);

}  // namespace volcomp::cli
