// The board configuration file: keys, parser, writer.
#include "volcomp/board_ini/board_ini.hpp"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "volcomp/table/table_format.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::board_ini {
namespace {

using canopen::ObjectId;
using firmware::BoardSettings;
using tools::InputError;

const char* const kPulseFormats[] = {"step_dir", "cw_ccw", "quadrature"};
const char* const kAxisKinds[] = {"linear", "rotary"};

std::string Trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A comment starts at '#' or ';' at the start of the line or after white space.
std::string StripComment(const std::string& s) {
  for (size_t i = 0; i < s.size(); ++i) {
    if ((s[i] == '#' || s[i] == ';') &&
        (i == 0 || std::isspace(static_cast<unsigned char>(s[i - 1])))) {
      return s.substr(0, i);
    }
  }
  return s;
}

ObjectId AxisId(ObjectId first, uint32_t axis) {
  return static_cast<ObjectId>(static_cast<uint16_t>(first) + axis);
}

// The axis-1 entries of the per-axis arrays, for KeyOf().
bool InAxisArray(ObjectId id, ObjectId first) {
  const int d = static_cast<int>(id) - static_cast<int>(first);
  return d >= 0 && d < static_cast<int>(table::kMaxAxes);
}

struct Line {
  int number = 0;
  std::string key, value;
};

struct Section {
  std::string name, arg;  // "[axis X]": "axis", "X"
  int number = 0;
  std::vector<Line> lines;
};

class Parser {
 public:
  explicit Parser(std::string source) : source_(std::move(source)) {}

  BoardSettings Parse(const std::string& text) {
    Split(text);
    BoardSettings s = FactorySettings();
    const Section* board = nullptr;
    for (const Section& sec : sections_) {
      if (sec.name == "board") board = &sec;
    }
    std::vector<char> names = {'X', 'Y', 'Z'};
    int names_line = 0;
    if (board != nullptr) {
      for (const Line& l : board->lines) {
        const IniKey& k = Key(*board, l);
        if (k.form == ValueForm::kAxisNames) {
          names = AxisNames(l);
          names_line = l.number;
        } else {
          Set(&s, k.id, l, Number(l, canopen::Entry(k.id)));
        }
      }
    }
    s.board.axis_count = static_cast<uint8_t>(names.size());
    const canopen::ObjectEntry& count = canopen::Entry(ObjectId::kAxisCountConfig);
    if (const std::string why = LimitViolation(count, s.board.axis_count); !why.empty()) {
      Fail(names_line, "axes: " + std::to_string(names.size()) + " axes, " + why);
    }
    for (const Section& sec : sections_) {
      if (sec.name != "axis") continue;
      bool listed = false;
      for (char n : names) listed = listed || sec.arg == std::string(1, n);
      if (!listed) Fail(sec.number, "[axis " + sec.arg + "] is not one of [board] axes");
    }
    for (uint32_t a = 0; a < names.size(); ++a) {
      const Section* sec = nullptr;
      for (const Section& x : sections_) {
        if (x.name == "axis" && x.arg == std::string(1, names[a])) sec = &x;
      }
      if (sec == nullptr) {
        Fail(names_line, std::string("axes: no [axis ") + names[a] + "] section");
      }
      s.board.axis[a].name = names[a];
      for (const Line& l : sec->lines) {
        const IniKey& k = Key(*sec, l);
        const ObjectId id = AxisId(k.id, a);
        Set(&s, id, l, Value(k, l, canopen::Entry(id)));
      }
      axis_lines_.push_back(sec->number);
    }
    if (const std::string why = ConsistencyProblem(s); !why.empty()) {
      Fail(WhyLine(s), why);
    }
    return s;
  }

 private:
  [[noreturn]] void Fail(int line, const std::string& message) const {
    throw InputError(source_ + (line > 0 ? ":" + std::to_string(line) : "") + ": " + message);
  }

  // The [axis] section line of the axis the consistency rules stop at (0 if none).
  int WhyLine(const BoardSettings& s) const {
    for (uint8_t n = 1; n <= s.board.axis_count && n <= axis_lines_.size(); ++n) {
      BoardSettings first = s;
      first.board.axis_count = n;
      if (!firmware::ValidateSettings(first).ok()) return axis_lines_[n - 1];
    }
    return 0;
  }

  void Split(const std::string& text) {
    std::istringstream in(text);
    std::string raw;
    int number = 0;
    while (std::getline(in, raw)) {
      ++number;
      const std::string line = Trim(StripComment(raw));
      if (line.empty()) continue;
      if (line.front() == '[') {
        if (line.back() != ']') Fail(number, "expected [section]");
        std::istringstream head(line.substr(1, line.size() - 2));
        Section s;
        s.number = number;
        std::string extra;
        head >> s.name >> s.arg;
        if (s.name.empty() || (head >> extra)) Fail(number, "bad section header " + line);
        s.name = Lower(s.name);
        if (s.name == "axis" && s.arg.size() == 1) {
          s.arg[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(s.arg[0])));
        }
        const bool known =
            (s.name == "board" && s.arg.empty()) || (s.name == "axis" && !s.arg.empty());
        if (!known) Fail(number, "unknown section " + line + " (expected [board] or [axis NAME])");
        for (const Section& o : sections_) {
          if (o.name == s.name && o.arg == s.arg) {
            Fail(number, "section " + line + " appears twice (first at line " +
                             std::to_string(o.number) + ")");
          }
        }
        sections_.push_back(s);
        continue;
      }
      const size_t eq = line.find('=');
      if (eq == std::string::npos) Fail(number, "expected key = value, got '" + line + "'");
      if (sections_.empty()) Fail(number, "key outside a section ([board] or [axis NAME])");
      Line l{number, Lower(Trim(line.substr(0, eq))), Trim(line.substr(eq + 1))};
      for (const Line& o : sections_.back().lines) {
        if (o.key == l.key) {
          Fail(number, l.key + ": given twice (first at line " + std::to_string(o.number) + ")");
        }
      }
      sections_.back().lines.push_back(l);
    }
  }

  const IniKey& Key(const Section& sec, const Line& l) const {
    const bool axis = sec.name == "axis";
    std::string known;
    for (const IniKey& k : IniKeys()) {
      if (k.per_axis != axis) continue;
      if (l.key == k.key) return k;
      known += (known.empty() ? "" : ", ") + std::string(k.key);
    }
    Fail(l.number, "unknown key '" + l.key + "' in [" + sec.name + (axis ? " " + sec.arg : "") +
                       "] (known: " + known + ")");
  }

  int64_t Number(const Line& l, const canopen::ObjectEntry& e) const {
    const std::string& v = l.value;
    size_t i = 0;
    const bool negative = !v.empty() && v[0] == '-';
    if (negative) i = 1;
    int base = 10;
    if (v.size() > i + 2 && v[i] == '0' && (v[i + 1] == 'x' || v[i + 1] == 'X')) {
      base = 16;
      i += 2;
    }
    if (i == v.size()) Fail(l.number, l.key + ": expected a number, got '" + v + "'");
    int64_t x = 0;
    for (; i < v.size(); ++i) {
      const int c = std::tolower(static_cast<unsigned char>(v[i]));
      int d = -1;
      if (c >= '0' && c <= '9') d = c - '0';
      if (base == 16 && c >= 'a' && c <= 'f') d = c - 'a' + 10;
      if (d < 0) Fail(l.number, l.key + ": expected a number, got '" + v + "'");
      x = x * base + d;
      if (x > (int64_t{1} << 40)) Fail(l.number, l.key + ": " + v + " is out of range");
    }
    if (negative) x = -x;
    if (const std::string why = LimitViolation(e, x); !why.empty()) {
      Fail(l.number, l.key + " = " + v + ": " + why + " of " + ObjectName(e));
    }
    return x;
  }

  static std::string ObjectName(const canopen::ObjectEntry& e) {
    return ObjectAddress(e) + " (" + e.name + ")";
  }

  // Exact decimal to units x 1e9: "0.001" -> 1000000.
  int64_t UnitsPerStep(const Line& l, const canopen::ObjectEntry& e) const {
    const std::string& v = l.value;
    const size_t dot = v.find('.');
    const std::string whole = v.substr(0, dot);
    const std::string frac = dot == std::string::npos ? "" : v.substr(dot + 1);
    if ((whole.empty() && frac.empty()) || frac.size() > 9) {
      Fail(l.number, l.key + ": expected a decimal with at most 9 decimals, got '" + v + "'");
    }
    int64_t x = 0;
    for (char c : whole + frac + std::string(9 - frac.size(), '0')) {
      if (c < '0' || c > '9') Fail(l.number, l.key + ": expected a decimal, got '" + v + "'");
      x = x * 10 + (c - '0');
      if (x > (int64_t{1} << 40)) Fail(l.number, l.key + ": " + v + " is out of range");
    }
    if (const std::string why = LimitViolation(e, x); !why.empty()) {
      Fail(l.number, l.key + " = " + v + ": " + why + " (x 1e-9) of " + ObjectName(e));
    }
    return x;
  }

  int64_t Named(const Line& l, const char* const* names, size_t count) const {
    const std::string v = Lower(l.value);
    std::string known;
    for (size_t i = 0; i < count; ++i) {
      if (v == names[i]) return static_cast<int64_t>(i);
      known += (i == 0 ? "" : " | ") + std::string(names[i]);
    }
    Fail(l.number, l.key + ": expected " + known + ", got '" + l.value + "'");
  }

  int64_t Value(const IniKey& k, const Line& l, const canopen::ObjectEntry& e) const {
    switch (k.form) {
      case ValueForm::kUnitsPerStep:
        return UnitsPerStep(l, e);
      case ValueForm::kAxisKind:
        return Named(l, kAxisKinds, 2);
      case ValueForm::kPulseFormat:
        return Named(l, kPulseFormats, 3);
      default:
        return Number(l, e);
    }
  }

  std::vector<char> AxisNames(const Line& l) const {
    std::vector<char> out;
    std::istringstream in(l.value);
    const std::string valid = table::kAxisNames;
    for (std::string n; in >> n;) {
      if (n.size() == 1) n[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(n[0])));
      if (n.size() != 1 || valid.find(n[0]) == std::string::npos) {
        Fail(l.number, "axes: '" + n + "' is not an axis name (" + valid + ")");
      }
      for (char o : out) {
        if (o == n[0]) Fail(l.number, "axes: " + n + " given twice");
      }
      out.push_back(n[0]);
    }
    if (out.empty()) Fail(l.number, "axes: expected the axis names in board order, e.g. X Y Z");
    return out;
  }

  void Set(BoardSettings* s, ObjectId id, const Line& l, int64_t v) const {
    const SettingObject* o = FindSettingObject(id);
    if (o == nullptr) Fail(l.number, l.key + ": not a stored configuration object");
    o->set(*s, v);
  }

  std::string source_;
  std::vector<Section> sections_;
  std::vector<int> axis_lines_;
};

}  // namespace

const std::vector<IniKey>& IniKeys() {
  static const std::vector<IniKey> kKeys = {
      {"node_id", false, ObjectId::kNodeIdConfig, ValueForm::kInteger, "CAN node-ID, 1..127"},
      {"bitrate_kbit", false, ObjectId::kBitrateConfig, ValueForm::kInteger, "kbit/s"},
      {"tick_hz", false, ObjectId::kTickRateConfig, ValueForm::kInteger, "Hz, control tick rate"},
      {"heartbeat_ms", false, ObjectId::kHeartbeatTime, ValueForm::kInteger, "ms, 0 = off"},
      {"emcy_inhibit_100us", false, ObjectId::kEmcyInhibitTime, ValueForm::kInteger,
       "x 100 us between two EMCYs, 0 = none"},
      {"axes", false, ObjectId::kAxisName1, ValueForm::kAxisNames,
       "axis count; 2010:n the names, in board order (X Y Z A B C U V W)"},
      {"kind", true, ObjectId::kAxisKind1, ValueForm::kAxisKind, "linear | rotary"},
      {"units_per_step", true, ObjectId::kAxisResolution1, ValueForm::kUnitsPerStep,
       "mm per step (degrees on a rotary axis)"},
      {"input_format", true, ObjectId::kAxisInputFormat1, ValueForm::kPulseFormat,
       "step_dir | cw_ccw | quadrature, from the CNC"},
      {"output_format", true, ObjectId::kAxisOutputFormat1, ValueForm::kPulseFormat,
       "step_dir | cw_ccw | quadrature, to the drive"},
      {"max_correction", true, ObjectId::kAxisMaxCorrection1, ValueForm::kInteger, "steps"},
      {"max_rate", true, ObjectId::kAxisMaxRate1, ValueForm::kInteger,
       "steps/s, fastest correction change"},
      {"max_accel", true, ObjectId::kAxisMaxAccel1, ValueForm::kInteger, "steps/s2"},
      {"home_position", true, ObjectId::kAxisHome1, ValueForm::kInteger,
       "steps, machine position at the home switch"},
      {"pulse_width_ns", true, ObjectId::kAxisPulseWidth1, ValueForm::kInteger,
       "ns, drive's minimum step pulse"},
      {"step_space_ns", true, ObjectId::kAxisStepSpace1, ValueForm::kInteger,
       "ns, drive's minimum step space"},
      {"dir_setup_ns", true, ObjectId::kAxisDirSetup1, ValueForm::kInteger,
       "ns, direction change to step edge"},
      {"dir_hold_ns", true, ObjectId::kAxisDirHold1, ValueForm::kInteger,
       "ns, step edge to direction change"},
      {"drive_max_rate_hz", true, ObjectId::kAxisDriveMaxRate1, ValueForm::kInteger,
       "Hz, fastest step rate the drive takes"},
      {"max_input_rate_hz", true, ObjectId::kAxisInputMaxRate1, ValueForm::kInteger,
       "Hz, fastest step rate from the CNC"},
  };
  return kKeys;
}

const IniKey* KeyOf(ObjectId id) {
  for (const IniKey& k : IniKeys()) {
    if (id == ObjectId::kAxisCountConfig && k.form == ValueForm::kAxisNames) return &k;
    if (k.per_axis || k.form == ValueForm::kAxisNames ? InAxisArray(id, k.id) : id == k.id) {
      return &k;
    }
  }
  return nullptr;
}

std::string FormatValue(const IniKey& key, int64_t v) {
  switch (key.form) {
    case ValueForm::kAxisNames:
      return v > 32 && v < 127 ? std::string(1, static_cast<char>(v)) : "#" + std::to_string(v);
    case ValueForm::kUnitsPerStep: {
      char text[40];
      std::snprintf(text, sizeof text, "%lld.%09lld", static_cast<long long>(v / 1000000000),
                    static_cast<long long>(v % 1000000000));
      std::string u = text;
      while (u.back() == '0') u.pop_back();
      if (u.back() == '.') u.pop_back();
      return u;
    }
    case ValueForm::kAxisKind:
      return v >= 0 && v < 2 ? kAxisKinds[v] : std::to_string(v);
    case ValueForm::kPulseFormat:
      return v >= 0 && v < 3 ? kPulseFormats[v] : std::to_string(v);
    default:
      return std::to_string(v);
  }
}

BoardSettings ParseBoardIni(const std::string& text, const std::string& source) {
  return Parser(source).Parse(text);
}

BoardSettings LoadBoardIni(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot read the configuration file");
  std::ostringstream text;
  text << in.rdbuf();
  return ParseBoardIni(text.str(), path);
}

std::string FormatBoardIni(const BoardSettings& s, const std::vector<std::string>& header) {
  std::ostringstream o;
  for (const std::string& h : header) o << "# " << h << "\n";
  auto line = [&](const IniKey& k, const std::string& value, ObjectId id) {
    std::string text = std::string(k.key) + " = " + value;
    if (text.size() < 32) text.resize(32, ' ');
    o << text << " # " << ObjectAddress(canopen::Entry(id)) << " " << k.unit << "\n";
  };
  o << "\n[board]\n";
  for (const IniKey& k : IniKeys()) {
    if (k.per_axis) continue;
    if (k.form == ValueForm::kAxisNames) {
      std::string names;
      for (uint8_t a = 0; a < s.board.axis_count; ++a) {
        names += (a == 0 ? "" : " ") + FormatValue(k, s.board.axis[a].name);
      }
      line(k, names, ObjectId::kAxisCountConfig);
      continue;
    }
    line(k, FormatValue(k, FindSettingObject(k.id)->get(s)), k.id);
  }
  for (uint8_t a = 0; a < s.board.axis_count; ++a) {
    o << "\n[axis " << s.board.axis[a].name << "]\n";
    for (const IniKey& k : IniKeys()) {
      if (!k.per_axis) continue;
      const ObjectId id = AxisId(k.id, a);
      line(k, FormatValue(k, FindSettingObject(id)->get(s)), id);
    }
  }
  return o.str();
}

std::string ConsistencyProblem(const BoardSettings& s) {
  if (firmware::ValidateSettings(s).ok()) return "";
  for (uint8_t n = 1; n <= s.board.axis_count; ++n) {
    BoardSettings first = s;
    first.board.axis_count = n;
    if (firmware::ValidateSettings(first).ok()) continue;
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
    if (firmware::ValidateSettings(faster).ok()) {
      return axis + ": drive_max_rate_hz " + std::to_string(ax.drive.max_rate_hz) +
             " is below max_input_rate_hz + max_rate = " +
             std::to_string(uint64_t{ax.max_input_rate_hz} + ax.max_correction_rate_steps_s) +
             " (the output must keep up with the fastest input plus the fastest correction)";
    }
    return axis + ": refused by the board's consistency rules (firmware ValidateSettings)";
  }
  return "the [board] values are refused by the board's consistency rules (firmware "
         "ValidateSettings)";
}

}  // namespace volcomp::board_ini
