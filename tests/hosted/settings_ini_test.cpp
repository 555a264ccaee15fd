// The board's settings as INI sections (the PC tool's board file): what a hand-written file means
// (values stated here, in the objects' own units), every refusal with its line, every setting row
// with its key, and the written form reading back as itself.
#include "volcomp/hosted/settings_ini.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "volcomp/canopen/setting_objects.hpp"

namespace volcomp::hosted {
namespace {

using canopen::SettingObject;
using canopen::SettingObjects;

BoardSettings ParseBoardIni(const std::string& text, const std::string& source) {
  const IniExpected<BoardSettings> r = ParseSettingsIni(text, source);
  EXPECT_TRUE(r.ok()) << r.error().ToString();
  return r.ok() ? *r : BoardSettings();
}

// The stored configuration objects whose values differ between `a` and `b`.
std::vector<canopen::ObjectId> Differences(const BoardSettings& a, const BoardSettings& b) {
  std::vector<canopen::ObjectId> out;
  for (const SettingObject& o : SettingObjects()) {
    if (o.get(a) != o.get(b)) out.push_back(o.id);
  }
  return out;
}

const char* const kMachine =
    "# a four-axis mill\n"
    "[board]\n"
    "node_id = 0x11            ; hex is fine\n"
    "tick_hz = 25000\n"
    "heartbeat_ms = 500\n"
    "axes = X Y Z C\n"
    "\n"
    "[axis X]\n"
    "units_per_step = 0.0005   # 0.5 um per step\n"
    "home_position = -5000\n"
    "max_correction = 800\n"
    "max_rate = 1500\n"
    "pulse_width_ns = 2500\n"
    "drive_max_rate_hz = 200000\n"
    "max_input_rate_hz = 150000\n"
    "[Axis Y]\n"
    "[axis Z]\n"
    "output_format = cw_ccw\n"
    "[axis C]\n"
    "kind = rotary\n"
    "units_per_step = 0.001\n"
    "input_format = quadrature\n";

// The message `text` is refused with ("" when it is accepted).
std::string Refusal(const std::string& text) {
  const IniExpected<BoardSettings> r = ParseSettingsIni(text, "m.ini");
  return r.ok() ? "" : r.error().ToString();
}

TEST(BoardIni, AHandWrittenFileMeansWhatItSays) {
  const BoardSettings s = ParseBoardIni(kMachine, "m.ini");
  EXPECT_EQ(s.node_id, 17);
  EXPECT_EQ(s.board.tick_hz, 25000u);
  EXPECT_EQ(s.heartbeat_ms, 500);
  EXPECT_EQ(s.board.axis_count, 4);
  EXPECT_EQ(s.board.axis[0].name, 'X');
  EXPECT_EQ(s.board.axis[0].resolution_e9, 500000u);
  EXPECT_EQ(s.board.axis[0].home_position_steps, -5000);
  EXPECT_EQ(s.board.axis[0].max_correction_steps, 800);
  EXPECT_EQ(s.board.axis[0].max_correction_rate_steps_s, 1500u);
  EXPECT_EQ(s.board.axis[0].drive.pulse_width_ns, 2500u);
  EXPECT_EQ(s.board.axis[0].drive.max_rate_hz, 200000u);
  EXPECT_EQ(s.board.axis[0].max_input_rate_hz, 150000u);
  EXPECT_EQ(s.board.axis[1].name, 'Y');  // "[Axis Y]": section names are case-insensitive
  EXPECT_EQ(s.board.axis[2].output_format, PulseFormat::kCwCcw);
  EXPECT_EQ(s.board.axis[3].name, 'C');
  EXPECT_EQ(s.board.axis[3].kind, table::AxisKind::kRotary);
  EXPECT_EQ(s.board.axis[3].resolution_e9, 1000000u);
  EXPECT_EQ(s.board.axis[3].input_format, PulseFormat::kQuadrature);
  // Keys left out: the factory values (1 um/step, 1000 steps, 200 ns, 1000 kbit/s, ...).
  EXPECT_EQ(s.bitrate_kbit, 1000);
  EXPECT_EQ(s.emcy_inhibit_100us, 100);
  EXPECT_EQ(s.board.axis[1].resolution_e9, 1000000u);
  EXPECT_EQ(s.board.axis[1].max_correction_steps, 1000);
  EXPECT_EQ(s.board.axis[1].drive.pulse_width_ns, 200u);
  EXPECT_EQ(s.board.axis[3].home_position_steps, 0);
  // The axes the board has beyond the four: factory values.
  EXPECT_EQ(s.board.axis[4].max_correction_steps, 1000);
}

TEST(BoardIni, EveryStoredObjectHasItsKey) {
  // 0x1015, 0x1017, 0x2000:1-4, seventeen per-axis arrays of six, six per-channel arrays of eight.
  EXPECT_EQ(SettingObjects().size(), 2u + 4u + 17u * 6u + 6u * 8u);
  for (const SettingObject& o : SettingObjects()) {
    EXPECT_NE(SettingKeyOf(o.id), nullptr) << canopen::Entry(o.id).name;
  }
}

TEST(BoardIni, RefusalsNameTheLineAndTheLimit) {
  const std::string base = "[board]\naxes = X\n[axis X]\n";
  // An unknown key (a typo must not silently leave a value as it was).
  std::string r = Refusal(base + "max_rte = 10\n");
  EXPECT_NE(r.find("m.ini:4: unknown key 'max_rte' in [axis X]"), std::string::npos) << r;
  // Outside the object's limits (od_entries.def: 0x2015 is 0..65536, node-ID 1..127).
  r = Refusal(base + "max_correction = 70000\n");
  EXPECT_NE(r.find("m.ini:4: max_correction = 70000: above the highest value 65536"),
            std::string::npos)
      << r;
  r = Refusal("[board]\nnode_id = 0\n[axis X]\n[axis Y]\n[axis Z]\n");
  EXPECT_NE(r.find("m.ini:2: node_id = 0: below the lowest value 1"), std::string::npos) << r;
  // Outside the type of an object without limits (0x2016 is U32): never truncated on the way.
  r = Refusal(base + "max_rate = 4294967296\n");
  EXPECT_NE(r.find("m.ini:4: max_rate = 4294967296: above the highest value 4294967295"),
            std::string::npos)
      << r;
  r = Refusal(base + "max_rate = -1\n");
  EXPECT_NE(r.find("m.ini:4: max_rate = -1: below the lowest value 0"), std::string::npos) << r;
  r = Refusal(base + "home_position = 2147483648\n");
  EXPECT_NE(r.find("m.ini:4:"), std::string::npos) << r;
  // Names and numbers.
  EXPECT_NE(Refusal(base + "kind = round\n").find("m.ini:4: kind: expected linear | rotary"),
            std::string::npos);
  EXPECT_NE(Refusal(base + "max_accel = 1e5\n").find("m.ini:4: max_accel: expected a number"),
            std::string::npos);
  EXPECT_NE(Refusal(base + "units_per_step = 0.0000000001\n").find("m.ini:4: units_per_step"),
            std::string::npos);
  EXPECT_NE(Refusal(base + "units_per_step = 0\n").find("below the lowest value 1"),
            std::string::npos);
  // Structure.
  EXPECT_NE(Refusal(base + "kind = linear\nkind = rotary\n").find("m.ini:5: kind: given twice"),
            std::string::npos);
  EXPECT_NE(Refusal("[board]\naxes = X Y\n[axis X]\n").find("m.ini:2: axes: no [axis Y]"),
            std::string::npos);
  EXPECT_NE(Refusal(base + "[axis Q]\n").find("m.ini:4: [axis Q] is not one of [board] axes"),
            std::string::npos);
  EXPECT_NE(Refusal("[drives]\n").find("m.ini:1: unknown section [drives]"), std::string::npos);
  EXPECT_NE(Refusal("axes = X\n").find("m.ini:1: key outside a [section]"), std::string::npos);
  EXPECT_NE(Refusal("[board]\naxes = X X\n").find("m.ini:2: axes: X given twice"),
            std::string::npos);
  EXPECT_NE(Refusal("[board]\naxes = X Q\n").find("m.ini:2: axes: 'Q' is not an axis name"),
            std::string::npos);
  EXPECT_NE(Refusal("[board]\naxes = X Y Z A B C U\n").find("above the highest value 6"),
            std::string::npos);
}

TEST(BoardIni, TheFirmwaresConsistencyRulesNameTheAxis) {
  // 0x201D must cover 0x201E + 0x2016 (1 000 000 + 2000 Hz by default): 1 001 000 does not.
  const std::string bad_rate =
      "[board]\naxes = X Y\n[axis X]\n[axis Y]\ndrive_max_rate_hz = 1001000\n";
  std::string r = Refusal(bad_rate);
  EXPECT_NE(r.find("m.ini:4: [axis Y]: drive_max_rate_hz 1001000 is below max_input_rate_hz + "
                   "max_rate = 1002000"),
            std::string::npos)
      << r;
  EXPECT_EQ(Refusal("[board]\naxes = X Y\n[axis X]\n[axis Y]\ndrive_max_rate_hz = 1002000\n"), "");
  // An acceleration of 0 leaves the correction limiter nothing to work with.
  r = Refusal("[board]\naxes = X\n[axis X]\nmax_accel = 0\n");
  EXPECT_NE(r.find("m.ini:3: [axis X]: max_rate 2000 and max_accel 0 do not fit tick_hz 50000"),
            std::string::npos)
      << r;
}

// A temperature channel's rule names the channel by its section, not an axis of the same number,
// with the keys and values that break it.
TEST(BoardIni, ATemperatureChannelFindingNamesTheChannel) {
  BoardSettings s;
  s.temperature[1].source = thermal::ChannelSource::kCanObject;
  s.temperature[1].low_cC = 5000;
  s.temperature[1].high_cC = 4000;
  ConfigFinding f;
  ASSERT_FALSE(ValidateSettings(s, &f).ok());
  EXPECT_EQ(hosted::FindingText(s, f),
            "[temperature 2]: low_C 50.00 is not below high_C 40.00 (rule 18)");
  s.temperature[1].high_cC = 6000;
  s.temperature[1].stuck_readings = 1;
  ASSERT_FALSE(ValidateSettings(s, &f).ok());
  EXPECT_EQ(hosted::FindingText(s, f),
            "[temperature 2]: stuck_readings 1 must be 0 (off) or 2..255 (rule 18)");
  // With an axis rule broken too, the axis is named for the axis's rule (the channel does not
  // make every axis look broken).
  s.board.axis[0].max_correction_accel_steps_s2 = 0;
  EXPECT_NE(ConsistencyProblem(s).find("[axis X]: max_rate 2000 and max_accel 0"),
            std::string::npos)
      << ConsistencyProblem(s);
}

// [temperature N]: the channel's source and limits in the file's units (C, K/s), N the
// sub-index of 0x2158-0x215D; a section names what feeds its channel.
TEST(BoardIni, TemperatureSectionsConfigureTheChannels) {
  const std::string head = "[board]\naxes = X\n[axis X]\n";
  const BoardSettings s = ParseBoardIni(head +
                                            "[temperature 1]\n"
                                            "source = can\n"
                                            "timeout_ms = 5000\n"
                                            "low_C = -5.5\n"
                                            "high_C = 60\n"
                                            "max_rate_K_s = 0.25\n"
                                            "[temperature 8]\n"
                                            "source = PT1000\n"
                                            "stuck_readings = 20\n",
                                        "m.ini");
  const thermal::ChannelConfig& c1 = s.temperature[0];
  EXPECT_EQ(c1.source, thermal::ChannelSource::kCanObject);
  EXPECT_EQ(c1.timeout_ms, 5000);
  EXPECT_EQ(c1.low_cC, -550);
  EXPECT_EQ(c1.high_cC, 6000);
  EXPECT_EQ(c1.max_rate_cC_s, 25);
  const thermal::ChannelConfig& c8 = s.temperature[7];
  EXPECT_EQ(c8.source, thermal::ChannelSource::kBoardPt1000);
  EXPECT_EQ(c8.stuck_readings, 20);
  EXPECT_EQ(c8.timeout_ms, 1500);  // left out: the factory value
  EXPECT_EQ(c8.low_cC, -2000);
  for (int ch = 1; ch < 7; ++ch) {
    EXPECT_EQ(s.temperature[ch].source, thermal::ChannelSource::kNone) << ch;
  }
  // Written back: the two channels in use, in the file's units, nothing for the unused ones.
  const std::string text = FormatSettingsIni(s, {});
  EXPECT_NE(text.find("\n[temperature 1]\nsource = can "), std::string::npos) << text;
  EXPECT_NE(text.find("\nlow_C = -5.50 "), std::string::npos) << text;
  EXPECT_NE(text.find("# 215A:1 C, lowest plausible reading"), std::string::npos) << text;
  EXPECT_NE(text.find("\nmax_rate_K_s = 0.25 "), std::string::npos) << text;
  EXPECT_NE(text.find("\n[temperature 8]\nsource = pt1000 "), std::string::npos) << text;
  EXPECT_NE(text.find("# 2158:8 none | can | ntc | pt1000 | linux_file | simulated"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("[temperature 2]"), std::string::npos) << text;
  const BoardSettings back = ParseBoardIni(text, "saved.ini");
  EXPECT_TRUE(Differences(back, s).empty());
  EXPECT_EQ(FormatSettingsIni(BoardSettings(), {}).find("[temperature"), std::string::npos);

  // Refusals name the section, the key and the value.
  EXPECT_EQ(Refusal(head + "[temperature 3]\nsource = thermocouple\n"),
            "m.ini:5: [temperature 3] source: expected none | can | ntc | pt1000 | linux_file | "
            "simulated, got 'thermocouple'");
  EXPECT_EQ(Refusal(head + "[temperature 3]\nsource = can\nlow_C = 20.005\n"),
            "m.ini:6: [temperature 3] low_C: expected a decimal with at most 2 decimals, got "
            "'20.005'");
  EXPECT_EQ(Refusal(head + "[temperature 3]\nsource = can\nhigh_C = 400\n"),
            "m.ini:6: [temperature 3] high_C = 400: above the highest value 32767 (x 0.01) of "
            "215B:3 (Temperature high 0.01 C channel 3)");
  EXPECT_EQ(Refusal(head + "[temperature 3]\nsource = can\ntimeout_ms = 50\n"),
            "m.ini:6: [temperature 3] timeout_ms = 50: below the lowest value 100 of 2159:3 "
            "(Temperature timeout ms channel 3)");
  EXPECT_EQ(Refusal(head + "[temperature 3]\nsource = can\nmax_rate = 1\n")
                .rfind("m.ini:6: unknown key 'max_rate' in [temperature 3]", 0),
            0u);
  EXPECT_EQ(Refusal(head + "[temperature 9]\nsource = can\n"),
            "m.ini:4: [temperature 9] is not a channel: N must be 1..8 (the sub-index of "
            "2158-215D)");
  EXPECT_EQ(Refusal(head + "[temperature 2]\ntimeout_ms = 5000\n"),
            "m.ini:4: [temperature 2] gives no source (none | can | ntc | pt1000 | linux_file | "
            "simulated)");
  // The firmware's rule (0x1010 would refuse it), at the section's line.
  EXPECT_EQ(Refusal(head + "[temperature 2]\nsource = ntc\nlow_C = 30\nhigh_C = 30\n"),
            "m.ini:4: [temperature 2]: low_C 30.00 is not below high_C 30.00 (rule 18)");
}

// Steps per mm (per degree), as datasheets and controllers give the resolution: stored exactly as
// units per step x 1e9, refused where that is not exact, never beside units_per_step.
TEST(BoardIni, StepsPerUnitIsTheResolutionTheOtherWayRound) {
  const std::string head = "[board]\naxes = X C\n[axis X]\n";
  const BoardSettings s = ParseBoardIni(
      head + "steps_per_unit = 400\n[axis C]\nkind = rotary\nsteps_per_unit = 1000.0\n", "m.ini");
  EXPECT_EQ(s.board.axis[0].resolution_e9, 2500000u);  // 1 / 400 mm = 0.0025 mm
  EXPECT_EQ(s.board.axis[1].resolution_e9, 1000000u);  // 0.001 degree
  EXPECT_EQ(Refusal(head + "steps_per_unit = 3\n[axis C]\n"),
            "m.ini:4: steps_per_unit: 1 / 3 units per step is not exact to 1e-9 (0x2012 stores "
            "units per step x 1e9): give units_per_step = 0.333333333 (or a rounder step count)");
  EXPECT_EQ(Refusal(head + "units_per_step = 0.0025\nsteps_per_unit = 400\n[axis C]\n"),
            "m.ini:5: give units_per_step (line 4) or steps_per_unit (line 5), not both");
  EXPECT_NE(Refusal(head + "steps_per_unit = 0\n[axis C]\n").find("m.ini:4: steps_per_unit"),
            std::string::npos);
  // The saved file keeps units_per_step and says the steps per unit beside it.
  const std::string text = FormatSettingsIni(s, {});
  EXPECT_NE(text.find("\nunits_per_step = 0.0025 "), std::string::npos) << text;
  EXPECT_NE(text.find("mm per step (degrees on a rotary axis) (400 steps per mm)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("(1000 steps per degree)\n"), std::string::npos) << text;
}

// The max correction in the table's units (µm, arcsec), as the integrator thinks of it: a whole
// number of steps of the axis, never beside the steps, and the right unit for the axis's kind.
TEST(BoardIni, MaxCorrectionInMicrometresOrArcseconds) {
  const std::string head = "[board]\naxes = X C\n[axis X]\nunits_per_step = 0.0025\n";
  const std::string rotary = "[axis C]\nkind = rotary\nunits_per_step = 0.001\n";
  const BoardSettings s = ParseBoardIni(
      head + "max_correction_um = 50\n" + rotary + "max_correction_arcsec = 36\n", "m.ini");
  EXPECT_EQ(s.board.axis[0].max_correction_steps, 20);  // 50 um / 2.5 um
  EXPECT_EQ(s.board.axis[1].max_correction_steps, 10);  // 36 arcsec / 3.6 arcsec
  EXPECT_EQ(Refusal(head + "max_correction_um = 51\n" + rotary),
            "m.ini:5: max_correction_um: not a whole number of steps of 2.5 um: give 50 or 52.5 "
            "(20 or 21 steps), or max_correction in steps");
  EXPECT_EQ(Refusal(head + "max_correction = 20\nmax_correction_um = 50\n" + rotary),
            "m.ini:6: give max_correction (line 5) or max_correction_um (line 6), not both");
  EXPECT_EQ(Refusal(head + "max_correction_arcsec = 36\n" + rotary),
            "m.ini:5: max_correction_arcsec: the axis is linear: give max_correction_um");
  const std::string text = FormatSettingsIni(s, {});
  EXPECT_NE(text.find("max_correction = 20 "), std::string::npos) << text;
  EXPECT_NE(text.find("# 2015:1 steps (50 um)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("# 2015:2 steps (36 arcsec)\n"), std::string::npos) << text;
  EXPECT_NE(Refusal(head + "max_correction_um = 1000000\n" + rotary)
                .find("m.ini:5: max_correction_um: 400000 steps: above the highest value 65536"),
            std::string::npos);
}

TEST(BoardIni, TheWrittenFileReadsBackAsItself) {
  const BoardSettings s = ParseBoardIni(kMachine, "m.ini");
  const std::string text = FormatSettingsIni(s, {"header line"});
  EXPECT_EQ(text.rfind("# header line\n", 0), 0u);
  // Spot checks of the form, in the file's own units.
  EXPECT_NE(text.find("\naxes = X Y Z C "), std::string::npos) << text;
  EXPECT_NE(text.find("\nnode_id = 17 "), std::string::npos) << text;
  EXPECT_NE(text.find("\nunits_per_step = 0.0005 "), std::string::npos) << text;
  EXPECT_NE(text.find("\nhome_position = -5000 "), std::string::npos) << text;
  EXPECT_NE(text.find("\n[axis C]\nkind = rotary "), std::string::npos) << text;
  EXPECT_NE(text.find("# 2015:1 steps ("), std::string::npos) << text;
  const BoardSettings back = ParseBoardIni(text, "saved.ini");
  for (const SettingObject& o : SettingObjects()) {
    EXPECT_EQ(o.get(back), o.get(s)) << canopen::Entry(o.id).name;
  }
  EXPECT_EQ(FormatSettingsIni(back, {"header line"}), text);
  // The factory settings too.
  const std::string factory = FormatSettingsIni(BoardSettings(), {});
  EXPECT_TRUE(Differences(ParseBoardIni(factory, "f.ini"), BoardSettings()).empty());
}

// One row, one object, one key: every setting row of od_entries.def has its key, a [board] key
// once or an [axis NAME] key on every axis, and no two rows of a section share one (the axis
// names are the one exception: they make up `axes`, with the axis count).
TEST(SettingsIni, EveryRowHasOneKeyInItsSection) {
  std::set<std::string> board, axis, channel;
  for (const SettingKey& k : SettingKeys()) {
    EXPECT_FALSE(k.per_axis && k.per_channel) << k.key;
    EXPECT_TRUE((k.per_axis      ? axis
                 : k.per_channel ? channel
                                 : board)
                    .insert(k.key)
                    .second)
        << k.key << " twice";
    EXPECT_NE(std::string(k.unit), "") << k.key;
  }
  size_t axis_elements = 0, channel_elements = 0;
  for (const SettingObject& o : SettingObjects()) {
    const SettingKey* k = SettingKeyOf(o.id);
    ASSERT_NE(k, nullptr) << canopen::Entry(o.id).name;
    if (k->per_axis) {
      ++axis_elements;
      EXPECT_NE(o.axis, canopen::kBoardSetting);
      // The key names the array; the element's sub-index is its axis.
      EXPECT_EQ(canopen::Entry(o.id).sub, o.axis + 1);
      EXPECT_EQ(canopen::Entry(k->id).index, canopen::Entry(o.id).index);
    } else if (k->per_channel) {
      ++channel_elements;
      // The key names the array; the element's sub-index is its [temperature N].
      EXPECT_EQ(canopen::Entry(o.id).sub, o.channel + 1);
      EXPECT_EQ(canopen::Entry(k->id).index, canopen::Entry(o.id).index);
    } else if (o.axis == canopen::kBoardSetting) {
      EXPECT_EQ(k->id, o.id) << k->key;
    }
  }
  EXPECT_EQ(axis_elements, axis.size() * table::kMaxAxes);
  EXPECT_EQ(channel_elements, channel.size() * thermal::kMaxChannels);
  EXPECT_EQ(channel, (std::set<std::string>{"source", "timeout_ms", "low_C", "high_C",
                                            "max_rate_K_s", "stuck_readings"}));
  EXPECT_EQ(SettingKeys().size(), board.size() + axis.size() + channel.size());
  EXPECT_EQ(std::string(SettingKeyOf(canopen::ObjectId::kAxisName4)->key), "axes");
  EXPECT_EQ(SettingKeyOf(canopen::ObjectId::kAxisCountConfig),
            SettingKeyOf(canopen::ObjectId::kAxisName1));
  EXPECT_EQ(SettingKeyOf(canopen::ObjectId::kDeviceState), nullptr);
}

// Every object of every row, set away from its factory value (within its limits), goes through
// the one writer and the one reader unchanged.
TEST(SettingsIni, EveryObjectRoundTripsThroughTheWriterAndTheReader) {
  BoardSettings s;
  s.board.axis_count = table::kMaxAxes;
  const char names[] = {'C', 'A', 'Z', 'U', 'X', 'W'};
  int n = 0;
  // The axis names (0x2010) are written within `axes`, the count (0x2000:4) is theirs.
  const auto is_names = [](const SettingObject& o) {
    return o.id == canopen::ObjectId::kAxisCountConfig ||
           SettingKeyOf(o.id)->form == SettingForm::kAxisNames;
  };
  for (const SettingObject& o : SettingObjects()) {
    const canopen::ObjectEntry& e = canopen::Entry(o.id);
    const canopen::ValueRange r = canopen::EntryRange(e);
    if (o.id == canopen::ObjectId::kAxisCountConfig) continue;
    int64_t v = 0;
    switch (SettingKeyOf(o.id)->form) {
      case SettingForm::kAxisNames:
        v = names[o.axis];
        break;
      case SettingForm::kAxisKind:
        v = 1;
        break;
      case SettingForm::kPulseFormat:
        v = 1 + (o.axis % 2);
        break;
      default:
        // Distinct per object, inside the object's range, never the factory value.
        v = r.low + 7 + (++n) % 97;
        if (v == o.get(BoardSettings())) ++v;
        if (v > r.high) v = r.high;
        break;
    }
    o.set(s, v);
  }
  for (const SettingObject& o : SettingObjects()) {
    if (is_names(o)) continue;
    EXPECT_NE(o.get(s), o.get(BoardSettings())) << canopen::Entry(o.id).name;
  }
  IniWriter w;
  WriteSettings(w, s);
  const IniExpected<IniDocument> doc = IniDocument::Parse(w.text(), "all.ini");
  ASSERT_TRUE(doc.ok()) << doc.error().ToString();
  BoardSettings back;
  const IniOutcome read = ReadSettings(*doc, &back);
  ASSERT_TRUE(read.ok()) << read.error().ToString() << "\n" << w.text();
  for (const SettingObject& o : SettingObjects()) {
    EXPECT_EQ(o.get(back), o.get(s)) << canopen::Entry(o.id).name;
  }
  // Every object's line carries its address and unit (`axes`: the count's address).
  for (const SettingObject& o : SettingObjects()) {
    if (is_names(o) && o.id != canopen::ObjectId::kAxisCountConfig) continue;
    const SettingKey& k = *SettingKeyOf(o.id);
    EXPECT_NE(w.text().find("# " + ObjectAddress(canopen::Entry(o.id)) + " " + k.unit),
              std::string::npos)
        << canopen::Entry(o.id).name;
  }
}

TEST(SettingsIni, ExtraKeysAreReadAndWrittenBesideTheSettings) {
  std::string board_extra, axis_extra[table::kMaxAxes];
  SettingsIniExtras extras;
  extras.board = {{"site", [&](const IniEntry& e) -> IniOutcome {
                     board_extra = e.value;
                     return IniOutcome::Ok();
                   }}};
  extras.axis = [&](uint8_t a) {
    return std::vector<IniKey>{{"note", [&axis_extra, a](const IniEntry& e) -> IniOutcome {
                                  axis_extra[a] = e.value;
                                  return IniOutcome::Ok();
                                }}};
  };
  const std::string text =
      "[board]\nsite = hall 2\naxes = X Y\n[axis X]\nnote = the long one\n[axis Y]\n"
      "max_rate = 1500\n";
  const IniExpected<IniDocument> doc = IniDocument::Parse(text, "x.ini");
  ASSERT_TRUE(doc.ok());
  BoardSettings s;
  ASSERT_TRUE(ReadSettings(*doc, &s, extras).ok());
  EXPECT_EQ(board_extra, "hall 2");
  EXPECT_EQ(axis_extra[0], "the long one");
  EXPECT_EQ(s.board.axis[1].max_correction_rate_steps_s, 1500u);
  // Without the extras the same keys are unknown, and the message lists the known ones.
  const IniOutcome plain = ReadSettings(*doc, &s);
  ASSERT_FALSE(plain.ok());
  EXPECT_EQ(plain.error().line, 2);
  EXPECT_NE(plain.error().message.find("unknown key 'site' in [board] (known: emcy_inhibit_100us, "
                                       "heartbeat_ms, node_id, bitrate_kbit, tick_hz, axes)"),
            std::string::npos)
      << plain.error().message;
  SettingsIniWriteExtras out;
  out.board = [](IniWriter& o) { o.Key("site", "hall 2"); };
  out.axis = [](IniWriter& o, uint8_t a) { o.Key("note", a == 0 ? "x" : "y"); };
  IniWriter w;
  WriteSettings(w, s, out);
  EXPECT_NE(w.text().find("\nsite = hall 2\n\n[axis X]\n"), std::string::npos) << w.text();
  EXPECT_NE(w.text().find("\nnote = y\n"), std::string::npos) << w.text();
}

}  // namespace
}  // namespace volcomp::hosted
