// Direction and unit names.
#include "volcomp/metrology/direction.hpp"

#include <algorithm>
#include <cctype>

namespace volcomp::metrology {

const char* DirectionSymbol(Direction d) { return d == Direction::kUp ? "↑" : "↓"; }

const char* DirectionName(Direction d) { return d == Direction::kUp ? "up" : "down"; }

std::optional<Direction> ParseDirection(const std::string& text) {
  std::string t;
  for (char c : text) {
    if (c != ' ' && c != '\t') t += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  if (t == "+" || t == "up" || t == "pos" || t == "positive" || t == "\xE2\x86\x91") {
    return Direction::kUp;
  }
  if (t == "-" || t == "down" || t == "neg" || t == "negative" || t == "\xE2\x86\x93") {
    return Direction::kDown;
  }
  return std::nullopt;
}

const char* TargetUnit(AxisKind kind) { return kind == AxisKind::kLinear ? "mm" : "deg"; }

const char* DeviationUnit(AxisKind kind) {
  return kind == AxisKind::kLinear ? "µm" : "\xE2\x80\xB3";
}

const char* DeviationUnitAscii(AxisKind kind) {
  return kind == AxisKind::kLinear ? "um" : "arcsec";
}

}  // namespace volcomp::metrology
