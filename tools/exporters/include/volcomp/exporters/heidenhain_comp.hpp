// HEIDENHAIN TNC nonlinear axis-error compensation tables from error tables (error_table.hpp):
// one .COM table per axis (TNC 640 / MANUALplus 620 layout: "BEGIN AXIS_X.COM MM", the columns
// NR, AXISPOS, BACKLASH and the compensated axis, "[END]") and the .CMA configuration table that
// names the .COM files (ACTIVE "*" marks the active line). Each .COM compensates its axis as a
// function of itself (X = F(X)).
// Values: the measured error, actual − nominal, in mm, 4 decimals (0.1 µm): HEIDENHAIN's own
// example plots the table as "Error in Z" and the public writer (Paolico/AxisCorection) writes
// the mean deviation / 1000 without a change of sign — unconfirmed against a machine (--negate).
// The axis column holds the error moving positive; BACKLASH the extra error moving negative
// (reverse − forward) at that position, 0 for a one-direction test — our reading of "the values
// measured in the negative direction", unconfirmed. AXISPOS is the position from the machine
// datum, mm, 6 decimals. TNC tables have no comment line, so the sign rule and its sources go
// into the notes file the command writes next to them (HeidenhainNotes).
// Limits: TNC 640: any positions (the test's own, or a --spacing grid); the legacy TNC 4xx:
// spacing a power of two times 0.1 µm and at most 256 points. Linear axes only (the table's
// unit for a rotary axis is not in volcomp's sources).
// Sources: MANUALplus 620 manual pp. 716/718; TNC 407 technical manual pp. 153/156/622; iTNC 530
// HSCI manual p. 680 (shared reference §B5).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "volcomp/exporters/error_table.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::exporters {

enum class HeidenhainControl { kTnc6xx, kTnc4xx };

/// TNC 407/415/425: at most 256 points per .COM table.
inline constexpr std::size_t kHeidenhainLegacyMaxPoints = 256;

struct HeidenhainAxis {
  char axis = 'X';     // the table's axis and column name
  std::string source;  // the test file, for the notes
  ErrorTable table;
};

struct HeidenhainTable {
  std::string file_name;  // "AXIS_X.COM"
  std::string text;
  double largest_mm = 0;           // the largest |axis value|, mm
  double largest_backlash_mm = 0;  // the largest |BACKLASH|, mm
};

/// kInvalidArgument naming the axis, the value, the limit and the fix: a rotary axis; for
/// kTnc4xx unequal spacing, a spacing that is not 2^n × 0.1 µm, more than 256 points.
Expected<HeidenhainTable> BuildHeidenhainCom(const HeidenhainAxis& axis, HeidenhainControl control);

/// The .CMA table "BEGIN <cma_name> ..." with one column per axis naming its .COM file on line 0,
/// marked active.
std::string HeidenhainCma(const std::string& cma_name,
                          const std::vector<char>& axes,
                          const std::vector<std::string>& com_files);

/// The notes file: what each file is, the sign rule with its sources, the zeroing and --negate.
std::string HeidenhainNotes(const std::vector<HeidenhainAxis>& axes,
                            const std::vector<HeidenhainTable>& tables,
                            const std::string& cma_name);

}  // namespace volcomp::exporters
