// The board's settings as INI sections: keys from the setting rows, reader, writer.
#include "volcomp/hosted/settings_ini.hpp"

#include <cctype>
#include <cstdio>
#include <sstream>

#include "volcomp/table/table_format.hpp"

namespace volcomp::hosted {
namespace {

using canopen::ObjectEntry;
using canopen::ObjectId;

// The rows' file keys (their VOLCOMP_OD_KEY), expanded from od_entries.def: one per [board]
// setting, one per axis array (its axis-1 element) and one per channel array (its channel-1
// element). Here rather than in lib/canopen's setting table so the firmware images do not carry
// the texts.
struct KeyRow {
  ObjectId id;
  const char* key;
  SettingForm form;
  const char* unit;
  bool per_axis;
  bool per_channel;
};
// clang-format off
#define VOLCOMP_OD_KEY(key, form, unit) (key, form, unit)
#define VOLCOMP_OD_KEY_FIELDS(key, form, unit) key, SettingForm::form, unit
#define VOLCOMP_OD_OBJECT(index, kind, name)
#define VOLCOMP_OD_ENTRY(id, index, sub, type, access, def, name)
#define VOLCOMP_OD_SETTING(id, index, sub, type, limits, def, field, key, name)                \
  {ObjectId::id, VOLCOMP_OD_KEY_FIELDS key, false, false},
#define VOLCOMP_OD_AXIS_SETTING(id, index, type, limits, field, key, name)                     \
  {ObjectId::id##1, VOLCOMP_OD_KEY_FIELDS key, true, false},
#define VOLCOMP_OD_CHANNEL_SETTING(id, index, type, limits, field, key, name)                  \
  {ObjectId::id##1, VOLCOMP_OD_KEY_FIELDS key, false, true},
const KeyRow kKeyRows[] = {
#include "volcomp/canopen/od_entries.def"  // NOLINT(build/include)
};
#undef VOLCOMP_OD_OBJECT
#undef VOLCOMP_OD_ENTRY
#undef VOLCOMP_OD_SETTING
#undef VOLCOMP_OD_AXIS_SETTING
#undef VOLCOMP_OD_CHANNEL_SETTING
#undef VOLCOMP_OD_KEY_FIELDS
#undef VOLCOMP_OD_KEY
// clang-format on

const std::vector<std::string> kAxisKinds = {"linear", "rotary"};
const std::vector<std::string> kPulseFormats = {"step_dir", "cw_ccw", "quadrature"};
// thermal::ChannelSource in enumerator order.
const std::vector<std::string> kChannelSources = {"none",   "can",        "ntc",
                                                  "pt1000", "linux_file", "simulated"};
static_assert(thermal::kLastChannelSource == 5, "a name per channel source");
constexpr const char* kTemperatureSection = "temperature";

ObjectId AxisId(ObjectId first, uint32_t axis) {
  return static_cast<ObjectId>(static_cast<uint16_t>(first) + axis);
}

// A decimal with up to 2 decimals, optionally negative, as an exact integer x 100 ("-20.5" ->
// -2050), within [low, high] of that integer.
IniExpected<int64_t> ReadCenti(
    const IniDocument& doc, const IniEntry& e, int64_t low, int64_t high, const std::string& of) {
  const std::string& v = e.value;
  const bool negative = !v.empty() && v[0] == '-';
  const std::string digits = negative ? v.substr(1) : v;
  const size_t dot = digits.find('.');
  const std::string whole = digits.substr(0, dot);
  const std::string frac = dot == std::string::npos ? "" : digits.substr(dot + 1);
  if ((whole.empty() && frac.empty()) || frac.size() > 2) {
    return doc.FailKey(e, "expected a decimal with at most 2 decimals, got '" + v + "'");
  }
  int64_t x = 0;
  for (char c : whole + frac + std::string(2 - frac.size(), '0')) {
    if (c < '0' || c > '9' || x > 1000000000) {
      return doc.FailKey(e, "expected a decimal, got '" + v + "'");
    }
    x = x * 10 + (c - '0');
  }
  if (negative) x = -x;
  if (const std::string why = RangeViolation(x, low, high); !why.empty()) {
    return doc.FailAt(e.line, e.key + " = " + v + ": " + why + " (x 0.01)" + of);
  }
  return x;
}

// "-20.00" for -2000.
std::string FormatCenti(int64_t v) {
  char text[32];
  std::snprintf(text, sizeof text, "%s%lld.%02lld", v < 0 ? "-" : "",
                static_cast<long long>((v < 0 ? -v : v) / 100),
                static_cast<long long>((v < 0 ? -v : v) % 100));
  return text;
}

// " of 2015:1 (Max correction steps axis 1)": whose limit a value broke.
std::string OfObject(const ObjectEntry& e) {
  return " of " + ObjectAddress(e) + " (" + e.name + ")";
}

void Set(BoardSettings* s, ObjectId id, int64_t v) { canopen::FindSetting(id)->set(*s, v); }

IniExpected<int64_t> ReadValue(const IniDocument& doc,
                               const IniEntry& e,
                               const SettingKey& k,
                               const ObjectEntry& object) {
  const canopen::ValueRange r = canopen::EntryRange(object);
  switch (k.form) {
    case SettingForm::kUnitsPerStep:
      return ReadDecimalE9(doc, e, r.low, r.high, OfObject(object));
    case SettingForm::kAxisKind: {
      VOLCOMP_TRY_ASSIGN(const size_t i, ReadChoice(doc, e, kAxisKinds));
      return static_cast<int64_t>(i);
    }
    case SettingForm::kPulseFormat: {
      VOLCOMP_TRY_ASSIGN(const size_t i, ReadChoice(doc, e, kPulseFormats));
      return static_cast<int64_t>(i);
    }
    case SettingForm::kChannelSource: {
      VOLCOMP_TRY_ASSIGN(const size_t i, ReadChoice(doc, e, kChannelSources));
      return static_cast<int64_t>(i);
    }
    case SettingForm::kCentiDegrees:
      return ReadCenti(doc, e, r.low, r.high, OfObject(object));
    default:
      return ReadInteger(doc, e, r.low, r.high, OfObject(object));
  }
}

// `steps_per_unit` (steps per mm, or per degree): the resolution as the drive's datasheet and
// most controllers give it, stored as units per step x 1e9 (0x2012), which must be exact.
IniExpected<int64_t> ReadStepsPerUnit(const IniDocument& doc, const IniEntry& e) {
  VOLCOMP_TRY_ASSIGN(const int64_t steps_e9, ReadDecimalE9(doc, e, 1, INT64_MAX));
  constexpr int64_t kE18 = 1000000000000000000;
  const int64_t per_step_e9 = kE18 / steps_e9;
  if (per_step_e9 < 1 || per_step_e9 > 0xFFFFFFFF) {
    return doc.FailKey(e, "a step of " + std::to_string(per_step_e9) +
                              "e-9 units is outside 0x2012's range (1e-9 .. 4.29 units)");
  }
  if (kE18 % steps_e9 != 0) {
    return doc.FailKey(e, "1 / " + e.value +
                              " units per step is not exact to 1e-9 (0x2012 stores "
                              "units per step x 1e9): give units_per_step = " +
                              FormatDecimalE9(per_step_e9) + " (or a rounder step count)");
  }
  return per_step_e9;
}

// `max_correction_um` (`max_correction_arcsec` on a rotary axis): the max correction (0x2015, in
// steps) in the units of the table, read after the section's other keys (it needs the axis's kind
// and units per step); it must be a whole number of steps, and is never given beside the steps.
IniOutcome ReadMaxCorrectionInUnits(const IniDocument& doc,
                                    const IniSection& sec,
                                    ObjectId id,
                                    BoardSettings* s,
                                    const AxisConfig* axis) {
  const bool rotary = axis->kind == table::AxisKind::kRotary;
  const char* key = rotary ? "max_correction_arcsec" : "max_correction_um";
  const char* other = rotary ? "max_correction_um" : "max_correction_arcsec";
  if (const IniEntry* wrong = sec.Find(other)) {
    return doc.FailKey(
        *wrong, std::string("the axis is ") + (rotary ? "rotary" : "linear") + ": give " + key);
  }
  const IniEntry* e = sec.Find(key);
  if (e == nullptr) return IniOutcome::Ok();
  const SettingKey& steps_key = *SettingKeyOf(id);
  if (const IniEntry* steps = sec.Find(steps_key.key)) {
    return doc.FailAt(std::max(steps->line, e->line), std::string("give ") + steps_key.key +
                                                          " (line " + std::to_string(steps->line) +
                                                          ") or " + key + " (line " +
                                                          std::to_string(e->line) + "), not both");
  }
  VOLCOMP_TRY_ASSIGN(const int64_t value_e9, ReadDecimalE9(doc, *e, 0, INT64_MAX));
  // One step in the key's unit x 1e9: units per step x 1e9 (mm, degrees) x 1000 um or 3600 arcsec.
  const int64_t step_e9 = int64_t{axis->resolution_e9} * (rotary ? 3600 : 1000);
  const int64_t steps = value_e9 / step_e9;
  if (value_e9 % step_e9 != 0) {
    return doc.FailKey(
        *e, "not a whole number of steps of " + FormatDecimalE9(step_e9) + " " +
                (rotary ? "arcsec" : "um") + ": give " + FormatDecimalE9(steps * step_e9) + " or " +
                FormatDecimalE9((steps + 1) * step_e9) + " (" + std::to_string(steps) + " or " +
                std::to_string(steps + 1) + " steps), or " + steps_key.key + " in steps");
  }
  const ObjectEntry& object = canopen::Entry(id);
  if (const std::string why = LimitViolation(object, steps); !why.empty()) {
    return doc.FailKey(*e, std::to_string(steps) + " steps: " + why + OfObject(object));
  }
  Set(s, id, steps);
  return IniOutcome::Ok();
}

// [board] axes: the axis names in board order.
IniExpected<std::vector<char>> ReadAxisNames(const IniDocument& doc, const IniEntry& e) {
  std::vector<char> out;
  std::istringstream in(e.value);
  const std::string valid = table::kAxisNames;
  for (std::string n; in >> n;) {
    if (n.size() == 1) n[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(n[0])));
    if (n.size() != 1 || valid.find(n[0]) == std::string::npos) {
      return doc.FailKey(e, "'" + n + "' is not an axis name (" + valid + ")");
    }
    for (char o : out) {
      if (o == n[0]) return doc.FailKey(e, n + " given twice");
    }
    out.push_back(n[0]);
  }
  if (out.empty()) return doc.FailKey(e, "expected the axis names in board order, e.g. X Y Z");
  return out;
}

// The [axis] section of the axis `name`.
const IniSection* AxisSection(const IniDocument& doc, char name) {
  return doc.Find("axis", std::string(1, name));
}

// A [temperature N] section into s->temperature[N - 1]: N is the channel, 1..8 (the sub-index
// of its objects); `source` is required (a section says what feeds the channel).
IniOutcome ReadChannelSection(const IniDocument& doc, const IniSection& sec, BoardSettings* s);

std::vector<SettingKey> MakeKeys() {
  std::vector<SettingKey> keys;
  for (const KeyRow& r : kKeyRows) {
    if (r.form == SettingForm::kAxisName) continue;  // the names are part of `axes`
    keys.push_back({r.key, r.per_axis, r.id, r.form, r.unit, r.per_channel});
  }
  return keys;
}

}  // namespace

const std::vector<SettingKey>& SettingKeys() {
  static const std::vector<SettingKey> kKeys = MakeKeys();
  return kKeys;
}

const SettingKey* SettingKeyOf(ObjectId id) {
  const canopen::SettingObject* s = canopen::FindSetting(id);
  if (s == nullptr) return nullptr;
  // An array element: its array's key, found by the axis-1 (channel-1) element.
  const uint8_t element = s->axis != canopen::kBoardSetting   ? s->axis
                          : s->channel != canopen::kNoChannel ? s->channel
                                                              : 0;
  const ObjectId first = static_cast<ObjectId>(static_cast<uint16_t>(id) - element);
  for (const KeyRow& r : kKeyRows) {
    if (r.id != first) continue;
    for (const SettingKey& k : SettingKeys()) {
      if (r.form == SettingForm::kAxisName ? k.form == SettingForm::kAxisNames : k.id == first) {
        return &k;
      }
    }
  }
  return nullptr;
}

std::string FormatSettingValue(const SettingKey& key, int64_t v) {
  switch (key.form) {
    case SettingForm::kAxisNames:
    case SettingForm::kAxisName:
      return v > 32 && v < 127 ? std::string(1, static_cast<char>(v)) : "#" + std::to_string(v);
    case SettingForm::kUnitsPerStep:
      return FormatDecimalE9(v);
    case SettingForm::kAxisKind:
      return v >= 0 && v < 2 ? kAxisKinds[static_cast<size_t>(v)] : std::to_string(v);
    case SettingForm::kPulseFormat:
      return v >= 0 && v < 3 ? kPulseFormats[static_cast<size_t>(v)] : std::to_string(v);
    case SettingForm::kChannelSource:
      return v >= 0 && static_cast<size_t>(v) < kChannelSources.size()
                 ? kChannelSources[static_cast<size_t>(v)]
                 : std::to_string(v);
    case SettingForm::kCentiDegrees:
      return FormatCenti(v);
    default:
      return std::to_string(v);
  }
}

// The resolution as steps per unit: read in place of units_per_step, never written.
constexpr const char* kStepsPerUnitKey = "steps_per_unit";

std::string ObjectAddress(const ObjectEntry& e) {
  char text[16];
  std::snprintf(text, sizeof text, "%04X:%u", e.index, e.sub);
  return text;
}

std::string LimitViolation(const ObjectEntry& e, int64_t v) {
  const canopen::ValueRange r = canopen::EntryRange(e);
  return RangeViolation(v, r.low, r.high);
}

IniOutcome ReadSettings(const IniDocument& doc, BoardSettings* s, const SettingsIniExtras& extras) {
  std::vector<char> names = {'X', 'Y', 'Z'};
  int names_line = 0;
  std::vector<IniKey> board_keys;
  for (const SettingKey& k : SettingKeys()) {
    if (k.per_axis || k.per_channel) continue;
    if (k.form == SettingForm::kAxisNames) {
      board_keys.push_back({k.key, [&](const IniEntry& e) -> IniOutcome {
                              VOLCOMP_TRY_ASSIGN(names, ReadAxisNames(doc, e));
                              names_line = e.line;
                              return IniOutcome::Ok();
                            }});
      continue;
    }
    board_keys.push_back({k.key, [&doc, s, k](const IniEntry& e) -> IniOutcome {
                            VOLCOMP_TRY_ASSIGN(const int64_t v,
                                               ReadValue(doc, e, k, canopen::Entry(k.id)));
                            Set(s, k.id, v);
                            return IniOutcome::Ok();
                          }});
  }
  board_keys.insert(board_keys.end(), extras.board.begin(), extras.board.end());
  VOLCOMP_TRY(ReadKeys(doc, doc.Find("board"), board_keys));

  const ObjectEntry& count = canopen::Entry(ObjectId::kAxisCountConfig);
  if (const std::string why = LimitViolation(count, static_cast<int64_t>(names.size()));
      !why.empty()) {
    return doc.FailAt(names_line, "axes: " + std::to_string(names.size()) + " axes, " + why);
  }
  Set(s, ObjectId::kAxisCountConfig, static_cast<int64_t>(names.size()));
  for (const IniSection& sec : doc.sections()) {
    if (sec.name != "axis") continue;
    bool listed = false;
    for (char n : names) listed = listed || AxisSection(doc, n) == &sec;
    if (!listed) return doc.FailAt(sec.line, sec.Title() + " is not one of [board] axes");
  }
  for (uint8_t a = 0; a < names.size(); ++a) {
    const IniSection* sec = AxisSection(doc, names[a]);
    if (sec == nullptr) {
      return doc.FailAt(names_line, std::string("axes: no [axis ") + names[a] + "] section");
    }
    Set(s, AxisId(ObjectId::kAxisName1, a), names[a]);
    std::vector<IniKey> keys;
    for (const SettingKey& k : SettingKeys()) {
      if (!k.per_axis) continue;
      const ObjectId id = AxisId(k.id, a);
      keys.push_back({k.key, [&doc, s, k, id](const IniEntry& e) -> IniOutcome {
                        VOLCOMP_TRY_ASSIGN(const int64_t v,
                                           ReadValue(doc, e, k, canopen::Entry(id)));
                        Set(s, id, v);
                        return IniOutcome::Ok();
                      }});
    }
    const ObjectId resolution = AxisId(ObjectId::kAxisResolution1, a);
    keys.push_back({kStepsPerUnitKey, [&doc, s, resolution](const IniEntry& e) -> IniOutcome {
                      VOLCOMP_TRY_ASSIGN(const int64_t v, ReadStepsPerUnit(doc, e));
                      Set(s, resolution, v);
                      return IniOutcome::Ok();
                    }});
    for (const char* later : {"max_correction_um", "max_correction_arcsec"}) {  // below
      keys.push_back({later, [](const IniEntry&) { return IniOutcome::Ok(); }});
    }
    if (extras.axis) {
      const std::vector<IniKey> more = extras.axis(a);
      keys.insert(keys.end(), more.begin(), more.end());
    }
    VOLCOMP_TRY(ReadKeys(doc, sec, keys));
    VOLCOMP_TRY(ReadMaxCorrectionInUnits(doc, *sec, AxisId(ObjectId::kAxisMaxCorrection1, a), s,
                                         &s->board.axis[a]));
    const IniEntry* per_step = sec->Find(SettingKeyOf(resolution)->key);
    const IniEntry* per_unit = sec->Find(kStepsPerUnitKey);
    if (per_step != nullptr && per_unit != nullptr) {
      return doc.FailAt(std::max(per_step->line, per_unit->line),
                        "give units_per_step (line " + std::to_string(per_step->line) +
                            ") or steps_per_unit (line " + std::to_string(per_unit->line) +
                            "), not both");
    }
  }
  for (const IniSection& sec : doc.sections()) {
    if (sec.name != kTemperatureSection) continue;
    const IniOutcome read = ReadChannelSection(doc, sec, s);
    if (!read.ok()) {  // the section's title before what the key's reader says (if it does not)
      IniError e = read.error();
      if (e.message.find(sec.Title()) == std::string::npos)
        e.message = sec.Title() + " " + e.message;
      return Fail(e);
    }
  }
  return IniOutcome::Ok();
}

std::string ChannelSectionName(uint8_t ch) {
  return std::string(kTemperatureSection) + " " + std::to_string(ch + 1);
}

namespace {

IniOutcome ReadChannelSection(const IniDocument& doc, const IniSection& sec, BoardSettings* s) {
  const std::string& n = sec.arg;
  if (n.size() != 1 || n[0] < '1' || n[0] > static_cast<char>('0' + thermal::kMaxChannels)) {
    return doc.FailAt(sec.line, "is not a channel: N must be 1.." +
                                    std::to_string(thermal::kMaxChannels) +
                                    " (the sub-index of 2158-215D)");
  }
  const uint8_t ch = static_cast<uint8_t>(n[0] - '1');
  std::vector<IniKey> keys;
  for (const SettingKey& k : SettingKeys()) {
    if (!k.per_channel) continue;
    const ObjectId id = AxisId(k.id, ch);
    keys.push_back({k.key, [&doc, s, k, id](const IniEntry& e) -> IniOutcome {
                      IniEntry named = e;  // refusals name the key as it is written: "low_C"
                      named.key = k.key;
                      VOLCOMP_TRY_ASSIGN(const int64_t v,
                                         ReadValue(doc, named, k, canopen::Entry(id)));
                      Set(s, id, v);
                      return IniOutcome::Ok();
                    }});
  }
  if (sec.Find(keys.front().key) == nullptr) {
    return doc.FailAt(sec.line, "gives no " + keys.front().key + " (" +
                                    SettingKeyOf(ObjectId::kChannelSource1)->unit + ")");
  }
  return ReadKeys(doc, &sec, keys);
}

// `s` with every temperature channel unused: the axis rules alone.
BoardSettings WithoutChannels(BoardSettings s) {
  for (thermal::ChannelConfig& c : s.temperature) c = thermal::ChannelConfig();
  return s;
}

// Why thermal::ValidateChannelConfig refuses channel `ch` (0-based), in its keys and values.
std::string ChannelProblem(const BoardSettings& s, uint8_t ch) {
  const thermal::ChannelConfig& c = s.temperature[ch];
  const std::string where = "[" + ChannelSectionName(ch) + "]: ";
  const auto text = [&](ObjectId first, int64_t v) {
    const SettingKey& k = *SettingKeyOf(first);
    return std::string(k.key) + " " + FormatSettingValue(k, v);
  };
  std::string why;
  if (static_cast<uint8_t>(c.source) > thermal::kLastChannelSource) {
    why = text(ObjectId::kChannelSource1, static_cast<int64_t>(c.source)) + " is not a source (" +
          SettingKeyOf(ObjectId::kChannelSource1)->unit + ")";
  } else if (c.timeout_ms < 100 || c.timeout_ms > 60000) {
    why = text(ObjectId::kChannelTimeout1, c.timeout_ms) + " is outside 100..60000";
  } else if (c.low_cC == thermal::kNoReading_cC) {
    why = text(ObjectId::kChannelLow1, c.low_cC) + " is the \"no reading\" value";
  } else if (c.low_cC >= c.high_cC) {
    why = text(ObjectId::kChannelLow1, c.low_cC) + " is not below " +
          text(ObjectId::kChannelHigh1, c.high_cC);
  } else if (c.max_rate_cC_s < 1) {
    why = text(ObjectId::kChannelMaxRate1, c.max_rate_cC_s) + " is below 0.01";
  } else if (c.stuck_readings == 1) {
    why = text(ObjectId::kChannelStuck1, c.stuck_readings) + " must be 0 (off) or 2..255";
  } else {
    return where + ConfigRuleText(ConfigRule::kTemperatureChannel);
  }
  return where + why + " (rule " +
         std::to_string(static_cast<int>(ConfigRule::kTemperatureChannel)) + ")";
}

}  // namespace

std::string ConsistencyProblem(const BoardSettings& all) {
  ConfigFinding f;
  if (ValidateSettings(all, &f).ok()) return "";
  if (f.rule == ConfigRule::kTemperatureChannel && f.axis >= 1 && f.axis <= thermal::kMaxChannels) {
    return ChannelProblem(all, static_cast<uint8_t>(f.axis - 1));
  }
  const BoardSettings s = WithoutChannels(all);
  if (ValidateSettings(s).ok()) return "";
  for (uint8_t n = 1; n <= s.board.axis_count && n <= table::kMaxAxes; ++n) {
    BoardSettings first = s;
    first.board.axis_count = n;
    if (ValidateSettings(first).ok()) continue;
    const AxisConfig& ax = s.board.axis[n - 1];
    const std::string axis = std::string("[axis ") + ax.name + "]";
    const uint32_t divider = CompensationDivider(s.board.tick_hz);
    if (!AxisLimiterParams(ax, s.board.tick_hz).ok()) {
      return axis + ": max_rate " + std::to_string(ax.max_correction_rate_steps_s) +
             " and max_accel " + std::to_string(ax.max_correction_accel_steps_s2) +
             " do not fit tick_hz " + std::to_string(s.board.tick_hz) +
             " (the compensation rate f = tick_hz / " + std::to_string(divider) +
             ": both above 0, max_accel at least f^2 / 2^32 and below f^2 steps/s2, max_rate at "
             "least max_accel / f)";
    }
    BoardSettings faster = first;
    faster.board.axis[n - 1].drive.max_rate_hz = 0xFFFFFFFFu;
    if (ValidateSettings(faster).ok()) {
      return axis + ": drive_max_rate_hz " + std::to_string(ax.drive.max_rate_hz) +
             " is below max_input_rate_hz + max_rate = " +
             std::to_string(uint64_t{ax.max_input_rate_hz} + ax.max_correction_rate_steps_s) +
             " (the output must keep up with the fastest input plus the fastest correction)";
    }
    return axis + ": refused by the board's consistency rules (ValidateSettings)";
  }
  return "the [board] values are refused by the board's consistency rules (ValidateSettings)";
}

std::string FindingText(const BoardSettings& s, const ConfigFinding& f) {
  if (f.rule == ConfigRule::kNone) return "";
  std::string where;
  if (f.rule == ConfigRule::kTemperatureChannel) {  // `axis` is the channel, 1-based
    if (f.axis >= 1 && f.axis <= thermal::kMaxChannels) {
      return ChannelProblem(s, static_cast<uint8_t>(f.axis - 1));
    }
    where = "temperature channel " + std::to_string(f.axis) + ": ";
  } else if (f.axis >= 1 && f.axis <= s.board.axis_count && f.axis <= table::kMaxAxes) {
    where = std::string("[axis ") + s.board.axis[f.axis - 1].name + "]: ";
  } else if (f.axis != 0) {
    where = "axis " + std::to_string(f.axis) + ": ";
  }
  const std::string rule =
      "(rule " + std::to_string(static_cast<int>(f.rule)) + ": " + ConfigRuleText(f.rule) + ")";
  if (f.rule == ConfigRule::kPulseTiming && !where.empty() && f.axis <= s.board.axis_count) {
    const AxisConfig& ax = s.board.axis[f.axis - 1];
    const uint32_t rate = PulseTimingRateHz(ax);
    return where + "drive_max_rate_hz " + std::to_string(ax.drive.max_rate_hz) +
           " is more than the pulse timing allows: pulse_width_ns " +
           std::to_string(ax.drive.pulse_width_ns) + " + step_space_ns " +
           std::to_string(ax.drive.step_space_ns) + " = " +
           std::to_string(uint64_t{ax.drive.pulse_width_ns} + ax.drive.step_space_ns) +
           " ns a step, at most " + std::to_string(rate) +
           " Hz; set drive_max_rate_hz to at most " + std::to_string(rate) +
           " (and max_input_rate_hz + max_rate within it), or the shorter pulse times the drive's "
           "datasheet gives for its rate " +
           rule;
  }
  return where + ConfigRuleText(f.rule);
}

IniOutcome CheckSettings(const IniDocument& doc, const BoardSettings& all) {
  const std::string why = ConsistencyProblem(all);
  if (why.empty()) return IniOutcome::Ok();
  ConfigFinding f;
  (void)ValidateSettings(all, &f);
  if (f.rule == ConfigRule::kTemperatureChannel) {  // at the channel's section (if it has one)
    const IniSection* sec = doc.Find(kTemperatureSection, std::to_string(f.axis));
    return doc.FailAt(sec != nullptr ? sec->line : 0, why);
  }
  const BoardSettings s = WithoutChannels(all);
  // The [axis] section of the axis the rules stop at (the file as a whole if none).
  int line = 0;
  for (uint8_t n = 1; n <= s.board.axis_count && n <= table::kMaxAxes && line == 0; ++n) {
    BoardSettings first = s;
    first.board.axis_count = n;
    if (ValidateSettings(first).ok()) continue;
    const IniSection* sec = AxisSection(doc, s.board.axis[n - 1].name);
    line = sec != nullptr ? sec->line : 0;
    break;
  }
  return doc.FailAt(line, why);
}

IniExpected<BoardSettings> ParseSettingsIni(const std::string& text, const std::string& source) {
  VOLCOMP_TRY_ASSIGN(const IniDocument doc, IniDocument::Parse(text, source));
  VOLCOMP_TRY(doc.CheckSections({"board", "axis NAME", "temperature N"}));
  BoardSettings s;  // the factory settings
  VOLCOMP_TRY(ReadSettings(doc, &s));
  VOLCOMP_TRY(CheckSettings(doc, s));
  return s;
}

IniExpected<BoardSettings> ReadSettingsIniFile(const std::string& path) {
  VOLCOMP_TRY_ASSIGN(const IniDocument doc, IniDocument::ReadFile(path));
  VOLCOMP_TRY(doc.CheckSections({"board", "axis NAME", "temperature N"}));
  BoardSettings s;
  VOLCOMP_TRY(ReadSettings(doc, &s));
  VOLCOMP_TRY(CheckSettings(doc, s));
  return s;
}

void WriteSettings(IniWriter& w, const BoardSettings& s, const SettingsIniWriteExtras& extras) {
  const auto comment = [](ObjectId id, const SettingKey& k) {
    return ObjectAddress(canopen::Entry(id)) + " " + k.unit;
  };
  w.Section("board");
  for (const SettingKey& k : SettingKeys()) {
    if (k.per_axis || k.per_channel) continue;
    if (k.form == SettingForm::kAxisNames) {
      std::string names;
      for (uint8_t a = 0; a < s.board.axis_count; ++a) {
        names += (a == 0 ? "" : " ") + FormatSettingValue(k, s.board.axis[a].name);
      }
      w.Key(k.key, names, comment(k.id, k));
      continue;
    }
    w.Key(k.key, FormatSettingValue(k, canopen::FindSetting(k.id)->get(s)), comment(k.id, k));
  }
  if (extras.board) extras.board(w);
  for (uint8_t a = 0; a < s.board.axis_count; ++a) {
    w.Section(std::string("axis ") + s.board.axis[a].name);
    for (const SettingKey& k : SettingKeys()) {
      if (!k.per_axis) continue;
      const ObjectId id = AxisId(k.id, a);
      const int64_t v = canopen::FindSetting(id)->get(s);
      std::string note = comment(id, k);
      if (k.form == SettingForm::kUnitsPerStep && v > 0) {  // what the datasheet says
        char steps[48];
        std::snprintf(steps, sizeof steps, " (%.9g steps per %s)", 1e9 / static_cast<double>(v),
                      s.board.axis[a].kind == table::AxisKind::kRotary ? "degree" : "mm");
        note += steps;
      }
      if (k.id == ObjectId::kAxisMaxCorrection1) {  // in the table's units too
        const bool rotary = s.board.axis[a].kind == table::AxisKind::kRotary;
        note += " (" + FormatDecimalE9(v * s.board.axis[a].resolution_e9 * (rotary ? 3600 : 1000)) +
                (rotary ? " arcsec)" : " um)");
      }
      w.Key(k.key, FormatSettingValue(k, v), note);
    }
    if (extras.axis) extras.axis(w, a);
  }
  for (uint8_t ch = 0; ch < thermal::kMaxChannels; ++ch) {
    if (s.temperature[ch].source == thermal::ChannelSource::kNone) continue;  // unused
    w.Section(ChannelSectionName(ch));
    for (const SettingKey& k : SettingKeys()) {
      if (!k.per_channel) continue;
      const ObjectId id = AxisId(k.id, ch);
      w.Key(k.key, FormatSettingValue(k, canopen::FindSetting(id)->get(s)), comment(id, k));
    }
  }
}

std::string FormatSettingsIni(const BoardSettings& s, const std::vector<std::string>& header) {
  IniWriter w;
  for (const std::string& h : header) w.Comment(h);
  WriteSettings(w, s);
  return w.text();
}

}  // namespace volcomp::hosted
