// The board configuration file: one INI text that documents a machine's installation, read and
// written by `volcomp config save|apply` (docs/user-guide.md "Configuring the board from a file").
//
//   [board]     node_id, bitrate_kbit, tick_hz, heartbeat_ms, emcy_inhibit_100us,
//               axes (the axis names in board order, e.g. "X Y Z": axis count 0x2000:4 and names
//               0x2010)
//   [axis X]    one per axis of `axes`: kind, units_per_step, input_format, output_format,
//               max_correction, max_rate, max_accel, home_position, pulse_width_ns,
//               step_space_ns, dir_setup_ns, dir_hold_ns, drive_max_rate_hz, max_input_rate_hz
//
// Every key is one configuration object (IniKeys(): its object, unit and meaning); the names the
// two files share are those of volcomp-fw-linux's configuration file (docs/linux-board.md).
// '#' and ';' start comments (at the start of a line or after white space); keys and section
// names are case-insensitive; numbers are decimal or 0x-hex, negative where the object is signed.
// A key left out takes the factory value (so the file alone decides the board's configuration);
// axes the board has beyond `axes` get the factory values too.
//
// Refused, with the file and line: unknown sections and keys, a key given twice, a value that is
// not a number or name, a value outside the object's limits or type (the board's own limits from
// od_entries.def), an [axis] not in `axes` or an axis of `axes` without its section, and a set the
// firmware's consistency rules (firmware::ValidateSettings) refuse, named by its axis.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/board_ini/setting_objects.hpp"
#include "volcomp/firmware/settings.hpp"

namespace volcomp::board_ini {

/// How a key's value is written in the file.
enum class ValueForm : uint8_t {
  kInteger,       // the object's number
  kAxisNames,     // [board] axes: names of the configured axes (count and 0x2010)
  kUnitsPerStep,  // 0x2012 as a decimal in mm (degrees) with up to 9 decimals, exactly
  kAxisKind,      // linear | rotary
  kPulseFormat,   // step_dir | cw_ccw | quadrature
};

struct IniKey {
  const char* key;       // "max_correction"
  bool per_axis;         // in [axis NAME] (object sub-index = axis number) or [board]
  canopen::ObjectId id;  // the object ([axis]: its axis-1 entry)
  ValueForm form;
  const char* unit;  // for the comment: "steps/s", "mm per step (degrees on a rotary axis)"
};

/// Every key, [board] keys first, in file order.
const std::vector<IniKey>& IniKeys();

/// The key of a stored configuration object (for axis objects: the key of its array), or null.
/// 0x2010 (axis names) gives the `axes` key.
const IniKey* KeyOf(canopen::ObjectId id);

/// `value` of the object of `key` as the file writes it ("linear", "0.001", "-5000"); for
/// kAxisNames the name of one axis ("X").
std::string FormatValue(const IniKey& key, int64_t value);

/// Parses a configuration text (named `source` in messages) into settings, starting from
/// FactorySettings(). Throws tools::InputError "SOURCE:LINE: message" (line 0 omitted) at the
/// first mistake; nothing else happens on error.
firmware::BoardSettings ParseBoardIni(const std::string& text, const std::string& source);

/// Reads and parses a file (InputError when it cannot be read).
firmware::BoardSettings LoadBoardIni(const std::string& path);

/// The file text of `s`: `header` lines as comments, [board], then one [axis] per configured
/// axis, every key with a comment naming its object and unit. ParseBoardIni gives `s` back
/// (for the fields with an object, when the axes beyond the configured ones are factory values).
std::string FormatBoardIni(const firmware::BoardSettings& s,
                           const std::vector<std::string>& header);

/// Why the firmware refuses `s` as a whole ("" when firmware::ValidateSettings accepts it): the
/// axis it stops at (found by validating the first n axes) and, where it can be told by trying
/// the firmware's rules, the rule.
std::string ConsistencyProblem(const firmware::BoardSettings& s);

}  // namespace volcomp::board_ini
