// Direction of approach to a target position (GOST 27843-88 §1.4, ISO 230-2): ↑ is an approach
// moving in the positive direction of the axis, ↓ in the negative direction.
#pragma once

#include <optional>
#include <string>

namespace volcomp::metrology {

enum class Direction { kUp, kDown };

/// "↑" or "↓".
const char* DirectionSymbol(Direction d);
/// "up" or "down" (JSON, CSV output).
const char* DirectionName(Direction d);
/// Accepts "+", "-", "up", "down", "pos", "neg", "positive", "negative", "↑", "↓"
/// (case-insensitive); nullopt otherwise.
std::optional<Direction> ParseDirection(const std::string& text);

/// Linear axes: targets in mm, deviations in µm. Rotary axes: targets in degrees, deviations in
/// arc-seconds.
enum class AxisKind { kLinear, kRotary };

/// "mm" or "deg".
const char* TargetUnit(AxisKind kind);
/// "µm" or "″" (arc-seconds), for human output.
const char* DeviationUnit(AxisKind kind);
/// "um" or "arcsec", for JSON keys and CSV headers.
const char* DeviationUnitAscii(AxisKind kind);

}  // namespace volcomp::metrology
