// The board's settings (BoardSettings) as INI sections: the codec of the PC tool's board file
// (`volcomp config save|apply`, docs/user-guide.md) and of the [board] / [axis NAME] sections of
// volcomp-fw-linux's configuration file (docs/linux-board.md), which adds keys and sections of its
// own. The keys are those of the VOLCOMP_OD_SETTING rows (lib/canopen od_entries.def, their
// VOLCOMP_OD_KEY): one object, one key, in dictionary order.
//
//   [board]      node_id, bitrate_kbit, tick_hz, heartbeat_ms, emcy_inhibit_100us, ...; axes = the
//                axis names in board order ("X Y Z": the axis count 0x2000:4 and names 0x2010)
//   [axis NAME]  one per axis of `axes`: kind, units_per_step, input_format, max_correction, ...
//   [temperature N]  one per temperature channel in use, N = 1..8 (the sub-index of 0x2158-0x215D):
//                source (required), timeout_ms, low_C, high_C, max_rate_K_s, stuck_readings
//
// A key left out keeps the value read into (the factory value for the PC tool's file), the axes
// beyond `axes` too, and a channel without its section (the factory: unused; the writer leaves
// the unused channels out). Refused, with the file and line (IniError, ini.hpp): unknown keys, a
// value that is not a number or name, a value outside its object's limits or type (the limits the
// board checks before a write), an [axis] not in `axes` or an axis of `axes` without its section,
// a [temperature N] with N outside 1..8 or without `source` (a [temperature] key's refusal names
// its section), and (CheckSettings) a set the firmware's rules (ValidateSettings) refuse, named by
// its axis or channel section.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen/setting_objects.hpp"
#include "volcomp/config/board_settings.hpp"
#include "volcomp/hosted/ini.hpp"

namespace volcomp::hosted {

/// How a setting's value is written in the file (the `form` of a row's VOLCOMP_OD_KEY).
enum class SettingForm : uint8_t {
  kInteger,        // the object's number (decimal or 0x hex, negative where signed)
  kUnitsPerStep,   // 0x2012: a decimal in mm (degrees) with up to 9 decimals, exactly (x 1e9)
  kAxisKind,       // linear | rotary
  kPulseFormat,    // step_dir | cw_ccw | quadrature
  kAxisNames,      // 0x2000:4 as [board] axes: the configured axes' names; the count is theirs
  kAxisName,       // 0x2010: one axis's name, written within [board] axes (no key of its own)
  kChannelSource,  // 0x2158: none | can | ntc | pt1000 | linux_file | simulated
  kCentiDegrees,   // 0x215A-0x215C: a decimal with up to 2 decimals, C (K/s), stored x 100
};

/// One key of the file, from its setting row (per-axis keys from the axis-1 element, per-channel
/// keys from the channel-1 element).
struct SettingKey {
  const char* key;       // "max_correction"
  bool per_axis;         // in [axis NAME] (object sub-index = axis number) or [board]
  canopen::ObjectId id;  // the object ([axis]: its axis-1 entry; `axes`: 0x2000:4)
  SettingForm form;
  const char* unit;          // for the comment: "steps/s", "mm per step (degrees on a rotary axis)"
  bool per_channel = false;  // in [temperature N] (object sub-index = N)
};

/// The section of temperature channel `ch` (0-based): "temperature 3" for ch 2.
std::string ChannelSectionName(uint8_t ch);

/// Every key: [board] keys first, then [axis], then [temperature], in file (dictionary) order.
const std::vector<SettingKey>& SettingKeys();
/// The key of a stored configuration object (an axis object: its array's), or null; the axis
/// names (0x2010) give the `axes` key.
const SettingKey* SettingKeyOf(canopen::ObjectId id);

/// `value` of an object of `key` as the file writes it ("linear", "0.001", "-5000"); for `axes`
/// the name of one axis ("X").
std::string FormatSettingValue(const SettingKey& key, int64_t value);
/// "2015:1": an object's index (hex) and sub-index, as `volcomp sdo` takes it.
std::string ObjectAddress(const canopen::ObjectEntry& e);
/// Why `value` cannot be written to `e` ("above the highest value 127"), or "" when it can: the
/// entry's limits and the range of its type (canopen::EntryRange).
std::string LimitViolation(const canopen::ObjectEntry& e, int64_t value);

/// Keys a file has beyond the settings in [board] and in each [axis NAME] (for that axis, 0-based).
struct SettingsIniExtras {
  std::vector<IniKey> board;
  std::function<std::vector<IniKey>(uint8_t axis)> axis;
};

/// Reads [board], the [axis NAME] and the [temperature N] sections of `doc` into *s, which holds
/// the values of keys left out. Checks each value and the sections against `axes`, not the set as
/// a whole.
IniOutcome ReadSettings(const IniDocument& doc,
                        BoardSettings* s,
                        const SettingsIniExtras& extras = SettingsIniExtras());
/// The set against the firmware's rules (ValidateSettings), refused at the [axis] or
/// [temperature] section line of the axis or channel it stops at (ConsistencyProblem()).
IniOutcome CheckSettings(const IniDocument& doc, const BoardSettings& s);
/// Why the firmware refuses `s` as a whole ("" when ValidateSettings accepts it): the axis it stops
/// at (found by validating the first n axes) and, where trying the rules tells, the rule in keys;
/// or the temperature channel, its keys and values ("[temperature 2]: low_C 50.00 is not below
/// high_C 40.00").
std::string ConsistencyProblem(const BoardSettings& s);
/// A board's finding on `s` (ValidateSettings(), the settings check 0x2123) in words: the axis by
/// its section ("[axis X]: ") or the channel by its ("[temperature N]: "), the rule, and where the
/// rule has figures (kPulseTiming, kTemperatureChannel) the values, the limit and the fix in keys.
/// "" for kNone.
std::string FindingText(const BoardSettings& s, const ConfigFinding& f);

/// The PC tool's board file: [board], [axis NAME] and [temperature N] only, from the factory
/// settings, checked.
IniExpected<BoardSettings> ParseSettingsIni(const std::string& text, const std::string& source);
IniExpected<BoardSettings> ReadSettingsIniFile(const std::string& path);

/// Lines a file writes beyond the settings, at the end of [board] and of each [axis NAME].
struct SettingsIniWriteExtras {
  std::function<void(IniWriter& w)> board;
  std::function<void(IniWriter& w, uint8_t axis)> axis;
};

/// [board], then one [axis NAME] per configured axis, then one [temperature N] per channel in use
/// (source not none), every key with a comment naming its object and unit. ReadSettings() gives
/// `s` back (for the fields with an object, when the axes beyond the configured ones and the
/// unused channels hold what was read into).
void WriteSettings(IniWriter& w,
                   const BoardSettings& s,
                   const SettingsIniWriteExtras& extras = SettingsIniWriteExtras());
/// The PC tool's board file: `header` lines as comments, then WriteSettings().
std::string FormatSettingsIni(const BoardSettings& s, const std::vector<std::string>& header);

}  // namespace volcomp::hosted
