// volcomp-fw-linux configuration file.
#include "volcomp/fw_linux/config_file.hpp"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

namespace volcomp::fw_linux {
namespace {

namespace lb = hal::linux_board;

struct Entry {
  std::string key, value;
  int line = 0;
};
struct Section {
  std::string name, arg;  // "[axis X]" -> name "axis", arg "X"
  int line = 0;
  std::vector<Entry> entries;
};

std::string Trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

// A comment starts at '#' or ';' at the start of the line or after whitespace.
std::string StripComment(const std::string& s) {
  for (size_t i = 0; i < s.size(); ++i) {
    if ((s[i] == '#' || s[i] == ';') &&
        (i == 0 || std::isspace(static_cast<unsigned char>(s[i - 1])))) {
      return s.substr(0, i);
    }
  }
  return s;
}

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

using Handler = std::function<bool(const Entry&)>;
using Keys = std::map<std::string, Handler>;

// Reads one configuration text. Each step reads a part into config_ and returns false with
// error_ set at the first mistake; Parse() runs them in file-independent order, so the same
// mistake always gives the same message.
class ConfigParser {
 public:
  explicit ConfigParser(std::string source) : source_(std::move(source)) {}

  Expected<LinuxBoardConfig, ConfigError> Parse(const std::string& text) {
    config_.settings.board.tick_hz = 1000;
    const bool ok = Split(text) && CheckSectionNames() && Board() && Axes() && Can() && Gateway() &&
                    Gpio() && Flash() && Process() && CheckFlash() && CheckWhole();
    if (!ok) return Fail(*error_);
    return config_;
  }

 private:
  // ---- Errors.
  bool FailAt(int line, const std::string& message) {
    error_ = ConfigError{source_, line, message};
    return false;
  }
  bool FailFile(const std::string& message) { return FailAt(0, message); }
  bool FailKey(const Entry& e, const std::string& what) {
    return FailAt(e.line, e.key + ": " + what);
  }

  // ---- Values.
  bool Unsigned(const Entry& e, uint64_t max, uint64_t* out) {
    const std::string& v = e.value;
    uint64_t x = 0;
    size_t i = 0;
    int base = 10;
    if (v.size() > 2 && v[0] == '0' && (v[1] == 'x' || v[1] == 'X')) {
      base = 16;
      i = 2;
    }
    if (i == v.size()) return FailKey(e, "expected a number");
    for (; i < v.size(); ++i) {
      const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(v[i])));
      int d = -1;
      if (c >= '0' && c <= '9') d = c - '0';
      if (base == 16 && c >= 'a' && c <= 'f') d = c - 'a' + 10;
      if (d < 0) return FailKey(e, "expected a number, got '" + v + "'");
      x = x * static_cast<uint64_t>(base) + static_cast<uint64_t>(d);
      if (x > max) return FailKey(e, "value above " + std::to_string(max));
    }
    *out = x;
    return true;
  }

  template <typename T>
  bool U(const Entry& e, uint64_t min, uint64_t max, T* out) {
    uint64_t x = 0;
    if (!Unsigned(e, max, &x)) return false;
    if (x < min) return FailKey(e, "value below " + std::to_string(min));
    *out = static_cast<T>(x);
    return true;
  }

  bool Signed(const Entry& e, int32_t* out) {
    Entry abs = e;
    const bool neg = !e.value.empty() && e.value[0] == '-';
    if (neg) abs.value = e.value.substr(1);
    uint64_t x = 0;
    if (!Unsigned(abs, neg ? 2147483648u : 2147483647u, &x)) return false;
    *out = neg ? static_cast<int32_t>(-static_cast<int64_t>(x)) : static_cast<int32_t>(x);
    return true;
  }

  bool Bool(const Entry& e, bool* out) {
    const std::string v = Lower(e.value);
    if (v == "true" || v == "yes" || v == "on" || v == "1") {
      *out = true;
    } else if (v == "false" || v == "no" || v == "off" || v == "0") {
      *out = false;
    } else {
      return FailKey(e, "expected true or false, got '" + e.value + "'");
    }
    return true;
  }

  // "0.0001" -> 100000 (units x 1e9), exactly.
  bool Decimal_e9(const Entry& e, uint32_t* out) {
    const std::string& v = e.value;
    const size_t dot = v.find('.');
    const std::string whole = v.substr(0, dot);
    std::string frac = dot == std::string::npos ? "" : v.substr(dot + 1);
    if ((whole.empty() && frac.empty()) || frac.size() > 9) {
      return FailKey(e, "expected a decimal with at most 9 decimals, got '" + v + "'");
    }
    uint64_t x = 0;
    for (char c : whole + frac + std::string(9 - frac.size(), '0')) {
      if (c < '0' || c > '9') return FailKey(e, "expected a decimal, got '" + v + "'");
      x = x * 10 + static_cast<uint64_t>(c - '0');
      if (x > 0xFFFFFFFFu) return FailKey(e, "value too large");
    }
    if (x == 0) return FailKey(e, "must be above zero");
    *out = static_cast<uint32_t>(x);
    return true;
  }

  // "0x201:2" -> COB-ID, offset.
  bool Pdo(const Entry& e, uint16_t* cob, uint8_t* offset) {
    const size_t colon = e.value.find(':');
    if (colon == std::string::npos) {
      return FailKey(e, "expected COB-ID:OFFSET (e.g. 0x201:2), got '" + e.value + "'");
    }
    Entry c = e, o = e;
    c.value = Trim(e.value.substr(0, colon));
    o.value = Trim(e.value.substr(colon + 1));
    return U(c, 1, 0x7FF, cob) && U(o, 0, 4, offset);
  }

  bool GpioLine(const Entry& e, lb::GpioLineSpec* spec) {
    const Expected<lb::GpioLineSpec> parsed = lb::ParseGpioLineSpec(e.value);
    if (!parsed.ok()) return FailKey(e, parsed.error().message);
    *spec = *parsed;
    return true;
  }

  // A key whose value is kept as written (an interface or file name).
  static Handler Text(std::string* out) {
    return [out](const Entry& e) {
      *out = e.value;
      return true;
    };
  }

  // ---- Sections.
  const Section* Find(const std::string& name, const std::string& arg) const {
    for (const Section& s : sections_) {
      if (s.name == name && s.arg == arg) return &s;
    }
    return nullptr;
  }

  // Runs each entry of `s` (may be null: nothing to do) through its key's handler.
  bool Apply(const Section* s, const Keys& keys) {
    if (s == nullptr) return true;
    for (const Entry& e : s->entries) {
      const auto it = keys.find(e.key);
      if (it == keys.end()) {
        std::string known;
        for (const auto& k : keys) known += (known.empty() ? "" : ", ") + k.first;
        return FailAt(e.line, "unknown key '" + e.key + "' in [" + s->name +
                                  (s->arg.empty() ? "" : " " + s->arg) + "] (known: " + known +
                                  ")");
      }
      if (!it->second(e)) return false;
    }
    return true;
  }

  // The text into sections of key = value entries.
  bool Split(const std::string& text) {
    std::istringstream in(text);
    std::string raw;
    int number = 0;
    while (std::getline(in, raw)) {
      ++number;
      const std::string line = Trim(StripComment(raw));
      if (line.empty()) continue;
      if (line.front() == '[') {
        if (line.back() != ']') return FailAt(number, "expected [section]");
        std::istringstream head(line.substr(1, line.size() - 2));
        Section s;
        s.line = number;
        head >> s.name >> s.arg;
        std::string extra;
        if (s.name.empty() || (head >> extra)) return FailAt(number, "bad section header");
        s.name = Lower(s.name);
        for (const Section& o : sections_) {
          if (o.name == s.name && o.arg == s.arg) {
            return FailAt(number, "section [" + line.substr(1, line.size() - 2) +
                                      "] appears twice (first at line " + std::to_string(o.line) +
                                      ")");
          }
        }
        sections_.push_back(s);
        continue;
      }
      const size_t eq = line.find('=');
      if (eq == std::string::npos) return FailAt(number, "expected key = value");
      if (sections_.empty()) return FailAt(number, "key outside a [section]");
      Entry e{Lower(Trim(line.substr(0, eq))), Trim(line.substr(eq + 1)), number};
      for (const Entry& o : sections_.back().entries) {
        if (o.key == e.key) return FailAt(number, e.key + ": given twice");
      }
      sections_.back().entries.push_back(e);
    }
    return true;
  }

  bool CheckSectionNames() {
    for (const Section& s : sections_) {
      const bool known =
          (s.arg.empty() && (s.name == "board" || s.name == "can" || s.name == "gateway" ||
                             s.name == "gpio" || s.name == "flash" || s.name == "process")) ||
          (s.name == "axis" && !s.arg.empty());
      if (!known) {
        return FailAt(s.line, "unknown section [" + s.name + (s.arg.empty() ? "" : " " + s.arg) +
                                  "] (expected board, can, gateway, axis NAME, gpio, flash, "
                                  "process)");
      }
    }
    return true;
  }

  bool AxisNames(const Entry& e) {
    axis_names_.clear();
    std::istringstream in(e.value);
    std::string n;
    while (in >> n) {
      const std::string names = table::kAxisNames;
      if (n.size() != 1 || names.find(n[0]) == std::string::npos) {
        return FailKey(e, "axis name '" + n + "' is not one of " + names);
      }
      for (const std::string& o : axis_names_) {
        if (o == n) return FailKey(e, "axis " + n + " given twice");
      }
      axis_names_.push_back(n);
    }
    if (axis_names_.empty() || axis_names_.size() > table::kMaxAxes) {
      return FailKey(e, "expected 1 to 6 axis names, e.g. X Y Z");
    }
    return true;
  }

  // [board]
  bool Board() {
    firmware::BoardSettings& st = config_.settings;
    if (!Apply(Find("board", ""),
               {{"node_id", [&](const Entry& e) { return U(e, 1, 127, &st.node_id); }},
                {"heartbeat_ms", [&](const Entry& e) { return U(e, 0, 65535, &st.heartbeat_ms); }},
                {"bitrate_kbit", [&](const Entry& e) { return U(e, 10, 1000, &st.bitrate_kbit); }},
                {"tick_hz", [&](const Entry& e) { return U(e, 1000, 200000, &st.board.tick_hz); }},
                {"serial_number",
                 [&](const Entry& e) { return U(e, 0, 0xFFFFFFFFu, &config_.serial_number); }},
                {"enable_input",
                 [&](const Entry& e) {
                   enable_input_given_ = true;
                   return Bool(e, &config_.enable_input);
                 }},
                {"axes", [&](const Entry& e) { return AxisNames(e); }}})) {
      return false;
    }
    st.board.axis_count = static_cast<uint8_t>(axis_names_.size());
    return true;
  }

  // One [axis NAME] section: the axis's configuration and its PDO fields.
  bool Axis(uint8_t a) {
    firmware::BoardSettings& st = config_.settings;
    gateway::GatewayConfig& gw = config_.gateway;
    AxisConfig& ax = st.board.axis[a];
    ax = DefaultBoardConfig().axis[0];
    ax.name = axis_names_[a][0];
    const Section* s = Find("axis", axis_names_[a]);
    if (s == nullptr) {
      return FailFile("no [axis " + axis_names_[a] + "] section (units_per_step is required)");
    }
    bool have_units = false;
    auto add_map = [&](const Entry& e, gateway::PdoField field) {
      if (gw.map_count == gateway::kMaxPdoMaps) return FailKey(e, "too many mapped PDOs");
      gateway::PdoMap& m = gw.map[gw.map_count];
      m.field = field;
      m.axis = a;
      if (!Pdo(e, &m.cob_id, &m.offset)) return false;
      ++gw.map_count;
      return true;
    };
    if (!Apply(s, {{"kind",
                    [&](const Entry& e) {
                      const std::string v = Lower(e.value);
                      if (v != "linear" && v != "rotary") {
                        return FailKey(e, "expected linear or rotary");
                      }
                      ax.kind = v == "linear" ? table::AxisKind::kLinear : table::AxisKind::kRotary;
                      return true;
                    }},
                   {"units_per_step",
                    [&](const Entry& e) {
                      have_units = true;
                      return Decimal_e9(e, &ax.resolution_e9);
                    }},
                   {"invert", [&](const Entry& e) { return Bool(e, &gw.invert[a]); }},
                   {"target_pdo",
                    [&](const Entry& e) { return add_map(e, gateway::PdoField::kTargetPosition); }},
                   {"actual_pdo",
                    [&](const Entry& e) { return add_map(e, gateway::PdoField::kActualPosition); }},
                   {"max_correction",
                    [&](const Entry& e) {
                      return U(e, 0, table::kMaxCorrectionSteps, &ax.max_correction_steps);
                    }},
                   {"max_rate",
                    [&](const Entry& e) {
                      return U(e, 1, 0xFFFFFFFFu, &ax.max_correction_rate_steps_s);
                    }},
                   {"max_accel",
                    [&](const Entry& e) {
                      return U(e, 1, 0xFFFFFFFFu, &ax.max_correction_accel_steps_s2);
                    }},
                   {"home_position",
                    [&](const Entry& e) { return Signed(e, &ax.home_position_steps); }}})) {
      return false;
    }
    if (!have_units) return FailAt(s->line, "[axis " + axis_names_[a] + "] needs units_per_step");
    if (static_cast<uint64_t>(ax.max_input_rate_hz) + ax.max_correction_rate_steps_s >
        ax.drive.max_rate_hz) {
      ax.drive.max_rate_hz = ax.max_input_rate_hz + ax.max_correction_rate_steps_s;
    }
    const uint32_t divider = CompensationDivider(st.board.tick_hz);
    if (!AxisLimiterParams(ax, st.board.tick_hz).ok()) {
      const std::string f = "f = tick_hz / " + std::to_string(divider);
      return FailAt(s->line, "[axis " + axis_names_[a] + "]: max_rate / max_accel do not fit " +
                                 "tick_hz " + std::to_string(st.board.tick_hz) +
                                 " (the compensation rate " + f +
                                 ": the acceleration must be at least f^2 / 2^32 and below f^2 "
                                 "steps/s2, and max_rate at least max_accel / f)");
    }
    return true;
  }

  // [axis NAME] for each axis of [board] axes, and no other.
  bool Axes() {
    config_.gateway.map_count = 0;
    for (uint8_t a = 0; a < config_.settings.board.axis_count; ++a) {
      if (!Axis(a)) return false;
    }
    for (const Section& s : sections_) {
      if (s.name != "axis") continue;
      bool listed = false;
      for (const std::string& n : axis_names_) listed = listed || n == s.arg;
      if (!listed) return FailAt(s.line, "[axis " + s.arg + "] is not in [board] axes");
    }
    return true;
  }

  // [can]
  bool Can() {
    LinuxBoardConfig& c = config_;
    if (!Apply(Find("can", ""),
               {{"controller", Text(&c.controller_iface)},
                {"drives", Text(&c.drives_iface)},
                {"tx_queue", [&](const Entry& e) { return U(e, 16, 100000, &c.tx_queue); }},
                {"restart_on_bus_off",
                 [&](const Entry& e) { return Bool(e, &c.restart_on_bus_off); }}})) {
      return false;
    }
    if (c.controller_iface.empty()) return FailFile("[can] controller = IFACE is required");
    if (c.drives_iface == c.controller_iface) {
      return FailFile("[can] controller and drives must be different interfaces");
    }
    return true;
  }

  // [gateway]
  bool Gateway() {
    gateway::GatewayConfig& gw = config_.gateway;
    return Apply(Find("gateway", ""),
                 {{"sync_cob_id", [&](const Entry& e) { return U(e, 1, 0x7FF, &gw.sync_cob_id); }},
                  {"feedback", [&](const Entry& e) {
                     const std::string v = Lower(e.value);
                     if (v == "sync") {
                       gw.feedback = gateway::FeedbackMode::kAtSync;
                     } else if (v == "latest") {
                       gw.feedback = gateway::FeedbackMode::kLatest;
                     } else {
                       return FailKey(e, "expected sync or latest");
                     }
                     return true;
                   }}});
  }

  // [gpio]: the backend, timing and one line spec per wired line.
  bool Gpio() {
    LinuxBoardConfig& c = config_;
    Keys keys = {{"backend",
                  [&](const Entry& e) {
                    const std::string v = e.value;
                    if (v == "none") {
                      c.gpio_backend = GpioBackendKind::kNone;
                    } else if (v == "gpiod") {
                      c.gpio_backend = GpioBackendKind::kGpiod;
                    } else if (v == "fake") {
                      c.gpio_backend = GpioBackendKind::kFake;
                    } else if (v.rfind("fake:", 0) == 0 && v.size() > 5) {
                      c.gpio_backend = GpioBackendKind::kFake;
                      c.fake_state_file = v.substr(5);
                    } else {
                      return FailKey(e, "expected gpiod, fake, fake:STATE_FILE or none");
                    }
                    return true;
                  }},
                 {"consumer", Text(&c.gpio.consumer)},
                 {"debounce_ms", [&](const Entry& e) { return U(e, 0, 1000, &c.debounce_ms); }},
                 {"poll_ms", [&](const Entry& e) { return U(e, 1, 1000, &c.io_poll_ms); }}};
    for (int i = 0; i < lb::kInputLineCount; ++i) {
      lb::GpioLineSpec* spec = &c.gpio.input[i];
      keys[lb::InputLineName(static_cast<hal::InputLine>(i))] = [this, spec](const Entry& e) {
        return GpioLine(e, spec);
      };
    }
    for (int i = 0; i < lb::kOutputLineCount; ++i) {
      lb::GpioLineSpec* spec = &c.gpio.output[i];
      keys[lb::OutputLineName(static_cast<hal::OutputLine>(i))] = [this, spec](const Entry& e) {
        return GpioLine(e, spec);
      };
    }
    if (!Apply(Find("gpio", ""), keys)) return false;
    const uint8_t axes = c.settings.board.axis_count;
    for (uint32_t i = axes; i < table::kMaxAxes; ++i) {
      if (c.gpio.input[i].used) {
        return FailFile("[gpio] home" + std::to_string(i) + " is wired but the board has only " +
                        std::to_string(axes) + " axes");
      }
    }
    if (!enable_input_given_) {
      c.enable_input = c.gpio_backend != GpioBackendKind::kNone &&
                       (c.gpio.input[static_cast<int>(hal::InputLine::kEnable)].used ||
                        c.gpio_backend == GpioBackendKind::kFake);
    }
    return true;
  }

  // [flash] (checked by CheckFlash once every section is read)
  bool Flash() {
    LinuxBoardConfig& c = config_;
    bank_kib_ = c.table_bank_bytes / 1024;
    return Apply(
        Find("flash", ""),
        {{"tables", Text(&c.table_file)},
         {"settings", Text(&c.settings_file)},
         {"table_bank_kib", [&](const Entry& e) { return U(e, 16, 65536, &bank_kib_); }},
         {"sector_bytes", [&](const Entry& e) { return U(e, 256, 1u << 20, &c.sector_bytes); }},
         {"sync", [&](const Entry& e) { return Bool(e, &c.flash_sync); }},
         {"write_behind", [&](const Entry& e) { return Bool(e, &c.flash_write_behind); }}});
  }

  // [process]
  bool Process() {
    LinuxBoardConfig& c = config_;
    return Apply(
        Find("process", ""),
        {{"realtime_priority", [&](const Entry& e) { return U(e, 0, 99, &c.realtime_priority); }},
         {"lock_memory", [&](const Entry& e) { return Bool(e, &c.lock_memory); }}});
  }

  bool CheckFlash() {
    LinuxBoardConfig& c = config_;
    c.table_bank_bytes = bank_kib_ * 1024u;
    if (c.table_file.empty()) return FailFile("[flash] tables = FILE is required");
    if (c.table_bank_bytes % c.sector_bytes != 0) {
      return FailFile("[flash] table_bank_kib must be a multiple of sector_bytes");
    }
    if (!c.settings_file.empty() && c.settings_file == c.table_file) {
      return FailFile("[flash] tables and settings must be different files");
    }
    return true;
  }

  // The settings and the PDO mapping as a whole.
  bool CheckWhole() {
    const firmware::BoardSettings& st = config_.settings;
    if (!firmware::ValidateSettings(st).ok()) {
      return FailFile("the board settings are inconsistent (ValidateBoardConfig)");
    }
    gateway::GatewayConfig& gw = config_.gateway;
    gw.own_node_id = st.node_id;
    if (!gateway::ValidateGatewayConfig(gw, st.board.axis_count).ok()) {
      return FailFile(
          "the PDO mapping is invalid: COB-IDs must not be 0x000, the SYNC COB-ID or one of the "
          "board's own (0x580/0x600/0x700/0x080 + node_id); at most one target_pdo and one "
          "actual_pdo per axis; fields in one PDO must not overlap");
    }
    return true;
  }

  std::string source_;
  std::vector<Section> sections_;
  LinuxBoardConfig config_;
  std::vector<std::string> axis_names_ = {"X", "Y", "Z"};
  bool enable_input_given_ = false;
  uint32_t bank_kib_ = 0;
  std::optional<ConfigError> error_;
};

}  // namespace

std::string ConfigError::ToString() const {
  return line > 0 ? source + ":" + std::to_string(line) + ": " + message : source + ": " + message;
}

Expected<LinuxBoardConfig, ConfigError> ParseConfig(const std::string& text,
                                                    const std::string& source) {
  return ConfigParser(source).Parse(text);
}

Expected<LinuxBoardConfig, ConfigError> LoadConfigFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Fail(ConfigError{path, 0, "cannot read the configuration file"});
  std::ostringstream text;
  text << in.rdbuf();
  return ParseConfig(text.str(), path);
}

std::string FormatConfig(const LinuxBoardConfig& c) {
  std::ostringstream o;
  const firmware::BoardSettings& st = c.settings;
  char hex[16];
  o << "[board]\nnode_id = " << int{st.node_id} << "\nheartbeat_ms = " << st.heartbeat_ms
    << "\nbitrate_kbit = " << st.bitrate_kbit << "\ntick_hz = " << st.board.tick_hz << "\naxes =";
  for (uint8_t a = 0; a < st.board.axis_count; ++a) o << " " << st.board.axis[a].name;
  o << "\nenable_input = " << (c.enable_input ? "true" : "false")
    << "\nserial_number = " << c.serial_number << "\n\n[can]\ncontroller = " << c.controller_iface
    << "\ndrives = " << c.drives_iface << "\ntx_queue = " << c.tx_queue
    << "\nrestart_on_bus_off = " << (c.restart_on_bus_off ? "true" : "false") << "\n\n[gateway]\n";
  std::snprintf(hex, sizeof hex, "0x%03X", c.gateway.sync_cob_id);
  o << "sync_cob_id = " << hex
    << "\nfeedback = " << (c.gateway.feedback == gateway::FeedbackMode::kAtSync ? "sync" : "latest")
    << "\n";
  for (uint8_t a = 0; a < st.board.axis_count; ++a) {
    const AxisConfig& ax = st.board.axis[a];
    const uint32_t r = ax.resolution_e9;
    char units[32];
    std::snprintf(units, sizeof units, "%u.%09u", r / 1000000000u, r % 1000000000u);
    std::string u = units;
    while (u.back() == '0') u.pop_back();
    if (u.back() == '.') u.pop_back();
    o << "\n[axis " << ax.name
      << "]\nkind = " << (ax.kind == table::AxisKind::kLinear ? "linear" : "rotary")
      << "\nunits_per_step = " << u << "\ninvert = " << (c.gateway.invert[a] ? "true" : "false")
      << "\n";
    for (uint8_t i = 0; i < c.gateway.map_count; ++i) {
      const gateway::PdoMap& m = c.gateway.map[i];
      if (m.axis != a) continue;
      std::snprintf(hex, sizeof hex, "0x%03X:%u", m.cob_id, m.offset);
      o << (m.field == gateway::PdoField::kTargetPosition ? "target_pdo = " : "actual_pdo = ")
        << hex << "\n";
    }
    o << "max_correction = " << ax.max_correction_steps
      << "\nmax_rate = " << ax.max_correction_rate_steps_s
      << "\nmax_accel = " << ax.max_correction_accel_steps_s2
      << "\nhome_position = " << ax.home_position_steps << "\n";
  }
  o << "\n[gpio]\nbackend = ";
  switch (c.gpio_backend) {
    case GpioBackendKind::kNone:
      o << "none";
      break;
    case GpioBackendKind::kGpiod:
      o << "gpiod";
      break;
    case GpioBackendKind::kFake:
      o << "fake" << (c.fake_state_file.empty() ? "" : ":" + c.fake_state_file);
      break;
  }
  o << "\nconsumer = " << c.gpio.consumer << "\ndebounce_ms = " << c.debounce_ms
    << "\npoll_ms = " << c.io_poll_ms << "\n";
  for (int i = 0; i < lb::kInputLineCount; ++i) {
    if (c.gpio.input[i].used) {
      o << lb::InputLineName(static_cast<hal::InputLine>(i)) << " = "
        << lb::FormatGpioLineSpec(c.gpio.input[i]) << "\n";
    }
  }
  for (int i = 0; i < lb::kOutputLineCount; ++i) {
    if (c.gpio.output[i].used) {
      o << lb::OutputLineName(static_cast<hal::OutputLine>(i)) << " = "
        << lb::FormatGpioLineSpec(c.gpio.output[i]) << "\n";
    }
  }
  o << "\n[flash]\ntables = " << c.table_file << "\nsettings = " << c.settings_file
    << "\ntable_bank_kib = " << c.table_bank_bytes / 1024 << "\nsector_bytes = " << c.sector_bytes
    << "\nsync = " << (c.flash_sync ? "true" : "false")
    << "\nwrite_behind = " << (c.flash_write_behind ? "true" : "false")
    << "\n\n[process]\nrealtime_priority = " << c.realtime_priority
    << "\nlock_memory = " << (c.lock_memory ? "true" : "false") << "\n";
  return o.str();
}

}  // namespace volcomp::fw_linux
