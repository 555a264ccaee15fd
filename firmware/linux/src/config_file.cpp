// volcomp-fw-linux configuration file.
#include "volcomp/fw_linux/config_file.hpp"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <vector>

#include "volcomp/correction_limiter.hpp"

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

class Parser {
 public:
  explicit Parser(std::string source) : source_(std::move(source)) {}

  std::string Where(int line) const { return source_ + ":" + std::to_string(line) + ": "; }

  bool Unsigned(const Entry& e, uint64_t max, uint64_t* out, std::string* err) const {
    const std::string& v = e.value;
    uint64_t x = 0;
    size_t i = 0;
    int base = 10;
    if (v.size() > 2 && v[0] == '0' && (v[1] == 'x' || v[1] == 'X')) {
      base = 16;
      i = 2;
    }
    if (i == v.size()) return Fail(e, "expected a number", err);
    for (; i < v.size(); ++i) {
      const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(v[i])));
      int d = -1;
      if (c >= '0' && c <= '9') d = c - '0';
      if (base == 16 && c >= 'a' && c <= 'f') d = c - 'a' + 10;
      if (d < 0) return Fail(e, "expected a number, got '" + v + "'", err);
      x = x * static_cast<uint64_t>(base) + static_cast<uint64_t>(d);
      if (x > max) return Fail(e, "value above " + std::to_string(max), err);
    }
    *out = x;
    return true;
  }

  template <typename T>
  bool U(const Entry& e, uint64_t min, uint64_t max, T* out, std::string* err) const {
    uint64_t x = 0;
    if (!Unsigned(e, max, &x, err)) return false;
    if (x < min) return Fail(e, "value below " + std::to_string(min), err);
    *out = static_cast<T>(x);
    return true;
  }

  bool Signed(const Entry& e, int32_t* out, std::string* err) const {
    Entry abs = e;
    const bool neg = !e.value.empty() && e.value[0] == '-';
    if (neg) abs.value = e.value.substr(1);
    uint64_t x = 0;
    if (!Unsigned(abs, neg ? 2147483648u : 2147483647u, &x, err)) return false;
    *out = neg ? static_cast<int32_t>(-static_cast<int64_t>(x)) : static_cast<int32_t>(x);
    return true;
  }

  bool Bool(const Entry& e, bool* out, std::string* err) const {
    std::string v;
    for (char c : e.value) v += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (v == "true" || v == "yes" || v == "on" || v == "1") {
      *out = true;
    } else if (v == "false" || v == "no" || v == "off" || v == "0") {
      *out = false;
    } else {
      return Fail(e, "expected true or false, got '" + e.value + "'", err);
    }
    return true;
  }

  // "0.0001" -> 100000 (units x 1e9), exactly.
  bool Decimal_e9(const Entry& e, uint32_t* out, std::string* err) const {
    const std::string& v = e.value;
    const size_t dot = v.find('.');
    const std::string whole = v.substr(0, dot);
    std::string frac = dot == std::string::npos ? "" : v.substr(dot + 1);
    if ((whole.empty() && frac.empty()) || frac.size() > 9) {
      return Fail(e, "expected a decimal with at most 9 decimals, got '" + v + "'", err);
    }
    uint64_t x = 0;
    for (char c : whole + frac + std::string(9 - frac.size(), '0')) {
      if (c < '0' || c > '9') return Fail(e, "expected a decimal, got '" + v + "'", err);
      x = x * 10 + static_cast<uint64_t>(c - '0');
      if (x > 0xFFFFFFFFu) return Fail(e, "value too large", err);
    }
    if (x == 0) return Fail(e, "must be above zero", err);
    *out = static_cast<uint32_t>(x);
    return true;
  }

  // "0x201:2" -> COB-ID, offset.
  bool Pdo(const Entry& e, uint16_t* cob, uint8_t* offset, std::string* err) const {
    const size_t colon = e.value.find(':');
    if (colon == std::string::npos) {
      return Fail(e, "expected COB-ID:OFFSET (e.g. 0x201:2), got '" + e.value + "'", err);
    }
    Entry c = e, o = e;
    c.value = Trim(e.value.substr(0, colon));
    o.value = Trim(e.value.substr(colon + 1));
    return U(c, 1, 0x7FF, cob, err) && U(o, 0, 4, offset, err);
  }

  bool Fail(const Entry& e, const std::string& what, std::string* err) const {
    *err = Where(e.line) + e.key + ": " + what;
    return false;
  }

 private:
  std::string source_;
};

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string ParseConfig(const std::string& text, const std::string& source, LinuxBoardConfig* out) {
  Parser p(source);
  // ---- Split into sections.
  std::vector<Section> sections;
  {
    std::istringstream in(text);
    std::string raw;
    int number = 0;
    while (std::getline(in, raw)) {
      ++number;
      const std::string line = Trim(StripComment(raw));
      if (line.empty()) continue;
      if (line.front() == '[') {
        if (line.back() != ']') return p.Where(number) + "expected [section]";
        std::istringstream head(line.substr(1, line.size() - 2));
        Section s;
        s.line = number;
        head >> s.name >> s.arg;
        std::string extra;
        if (s.name.empty() || (head >> extra)) return p.Where(number) + "bad section header";
        s.name = Lower(s.name);
        for (const Section& o : sections) {
          if (o.name == s.name && o.arg == s.arg) {
            return p.Where(number) + "section [" + line.substr(1, line.size() - 2) +
                   "] appears twice (first at line " + std::to_string(o.line) + ")";
          }
        }
        sections.push_back(s);
        continue;
      }
      const size_t eq = line.find('=');
      if (eq == std::string::npos) return p.Where(number) + "expected key = value";
      if (sections.empty()) return p.Where(number) + "key outside a [section]";
      Entry e{Lower(Trim(line.substr(0, eq))), Trim(line.substr(eq + 1)), number};
      for (const Entry& o : sections.back().entries) {
        if (o.key == e.key) return p.Where(number) + e.key + ": given twice";
      }
      sections.back().entries.push_back(e);
    }
  }

  LinuxBoardConfig c;
  c.settings.board.tick_hz = 1000;
  std::string err;
  bool enable_input_given = false;
  std::vector<std::string> axis_names = {"X", "Y", "Z"};

  auto find = [&](const std::string& name, const std::string& arg) -> const Section* {
    for (const Section& s : sections) {
      if (s.name == name && s.arg == arg) return &s;
    }
    return nullptr;
  };
  using Handler = std::function<bool(const Entry&)>;
  auto apply = [&](const Section* s, const std::map<std::string, Handler>& keys) -> bool {
    if (s == nullptr) return true;
    for (const Entry& e : s->entries) {
      const auto it = keys.find(e.key);
      if (it == keys.end()) {
        std::string known;
        for (const auto& k : keys) known += (known.empty() ? "" : ", ") + k.first;
        err = p.Where(e.line) + "unknown key '" + e.key + "' in [" + s->name +
              (s->arg.empty() ? "" : " " + s->arg) + "] (known: " + known + ")";
        return false;
      }
      if (!it->second(e)) return false;
    }
    return true;
  };

  // ---- Sections must be known.
  for (const Section& s : sections) {
    const bool known =
        (s.arg.empty() && (s.name == "board" || s.name == "can" || s.name == "gateway" ||
                           s.name == "gpio" || s.name == "flash" || s.name == "process")) ||
        (s.name == "axis" && !s.arg.empty());
    if (!known) {
      return p.Where(s.line) + "unknown section [" + s.name + (s.arg.empty() ? "" : " " + s.arg) +
             "] (expected board, can, gateway, axis NAME, gpio, flash, process)";
    }
  }

  // ---- [board]
  firmware::BoardSettings& st = c.settings;
  if (!apply(find("board", ""),
             {{"node_id", [&](const Entry& e) { return p.U(e, 1, 127, &st.node_id, &err); }},
              {"heartbeat_ms",
               [&](const Entry& e) { return p.U(e, 0, 65535, &st.heartbeat_ms, &err); }},
              {"bitrate_kbit",
               [&](const Entry& e) { return p.U(e, 10, 1000, &st.bitrate_kbit, &err); }},
              {"tick_hz",
               [&](const Entry& e) { return p.U(e, 1000, 200000, &st.board.tick_hz, &err); }},
              {"serial_number",
               [&](const Entry& e) { return p.U(e, 0, 0xFFFFFFFFu, &c.serial_number, &err); }},
              {"enable_input",
               [&](const Entry& e) {
                 enable_input_given = true;
                 return p.Bool(e, &c.enable_input, &err);
               }},
              {"axes", [&](const Entry& e) {
                 axis_names.clear();
                 std::istringstream in(e.value);
                 std::string n;
                 while (in >> n) {
                   const std::string names = table::kAxisNames;
                   if (n.size() != 1 || names.find(n[0]) == std::string::npos) {
                     return p.Fail(e, "axis name '" + n + "' is not one of " + names, &err);
                   }
                   for (const std::string& o : axis_names) {
                     if (o == n) return p.Fail(e, "axis " + n + " given twice", &err);
                   }
                   axis_names.push_back(n);
                 }
                 if (axis_names.empty() || axis_names.size() > table::kMaxAxes) {
                   return p.Fail(e, "expected 1 to 6 axis names, e.g. X Y Z", &err);
                 }
                 return true;
               }}})) {
    return err;
  }
  st.board.axis_count = static_cast<uint8_t>(axis_names.size());

  // ---- [axis NAME]
  gateway::GatewayConfig& gw = c.gateway;
  gw.map_count = 0;
  for (uint8_t a = 0; a < st.board.axis_count; ++a) {
    AxisConfig& ax = st.board.axis[a];
    ax = DefaultBoardConfig().axis[0];
    ax.name = axis_names[a][0];
    const Section* s = find("axis", axis_names[a]);
    if (s == nullptr) {
      return source + ": no [axis " + axis_names[a] + "] section (units_per_step is required)";
    }
    bool have_units = false;
    auto add_map = [&](const Entry& e, gateway::PdoField field) {
      if (gw.map_count == gateway::kMaxPdoMaps) return p.Fail(e, "too many mapped PDOs", &err);
      gateway::PdoMap& m = gw.map[gw.map_count];
      m.field = field;
      m.axis = a;
      if (!p.Pdo(e, &m.cob_id, &m.offset, &err)) return false;
      ++gw.map_count;
      return true;
    };
    if (!apply(s, {{"kind",
                    [&](const Entry& e) {
                      const std::string v = Lower(e.value);
                      if (v != "linear" && v != "rotary") {
                        return p.Fail(e, "expected linear or rotary", &err);
                      }
                      ax.kind = v == "linear" ? table::AxisKind::kLinear : table::AxisKind::kRotary;
                      return true;
                    }},
                   {"units_per_step",
                    [&](const Entry& e) {
                      have_units = true;
                      return p.Decimal_e9(e, &ax.resolution_e9, &err);
                    }},
                   {"invert", [&](const Entry& e) { return p.Bool(e, &gw.invert[a], &err); }},
                   {"target_pdo",
                    [&](const Entry& e) { return add_map(e, gateway::PdoField::kTargetPosition); }},
                   {"actual_pdo",
                    [&](const Entry& e) { return add_map(e, gateway::PdoField::kActualPosition); }},
                   {"max_correction",
                    [&](const Entry& e) {
                      return p.U(e, 0, table::kMaxCorrectionSteps, &ax.max_correction_steps, &err);
                    }},
                   {"max_rate",
                    [&](const Entry& e) {
                      return p.U(e, 1, 0xFFFFFFFFu, &ax.max_correction_rate_steps_s, &err);
                    }},
                   {"max_accel",
                    [&](const Entry& e) {
                      return p.U(e, 1, 0xFFFFFFFFu, &ax.max_correction_accel_steps_s2, &err);
                    }},
                   {"home_position",
                    [&](const Entry& e) { return p.Signed(e, &ax.home_position_steps, &err); }}})) {
      return err;
    }
    if (!have_units) return p.Where(s->line) + "[axis " + axis_names[a] + "] needs units_per_step";
    if (static_cast<uint64_t>(ax.max_input_rate_hz) + ax.max_correction_rate_steps_s >
        ax.drive.max_rate_hz) {
      ax.drive.max_rate_hz = ax.max_input_rate_hz + ax.max_correction_rate_steps_s;
    }
    if (!CorrectionLimiter::MakeParams(st.board.tick_hz, ax.max_correction_rate_steps_s,
                                       ax.max_correction_accel_steps_s2)
             .ok()) {
      return p.Where(s->line) + "[axis " + axis_names[a] + "]: max_rate / max_accel do not fit " +
             "tick_hz " + std::to_string(st.board.tick_hz) +
             " (the acceleration must be at least tick_hz^2 / 2^32 and below tick_hz^2 "
             "steps/s2, " +
             "and max_rate at least max_accel / tick_hz)";
    }
  }
  for (const Section& s : sections) {
    if (s.name != "axis") continue;
    bool listed = false;
    for (const std::string& n : axis_names) listed = listed || n == s.arg;
    if (!listed) return p.Where(s.line) + "[axis " + s.arg + "] is not in [board] axes";
  }

  // ---- [can]
  if (!apply(find("can", ""),
             {{"controller",
               [&](const Entry& e) {
                 c.controller_iface = e.value;
                 return true;
               }},
              {"drives",
               [&](const Entry& e) {
                 c.drives_iface = e.value;
                 return true;
               }},
              {"tx_queue", [&](const Entry& e) { return p.U(e, 16, 100000, &c.tx_queue, &err); }},
              {"restart_on_bus_off",
               [&](const Entry& e) { return p.Bool(e, &c.restart_on_bus_off, &err); }}})) {
    return err;
  }
  if (c.controller_iface.empty()) return source + ": [can] controller = IFACE is required";
  if (c.drives_iface == c.controller_iface) {
    return source + ": [can] controller and drives must be different interfaces";
  }

  // ---- [gateway]
  if (!apply(
          find("gateway", ""),
          {{"sync_cob_id", [&](const Entry& e) { return p.U(e, 1, 0x7FF, &gw.sync_cob_id, &err); }},
           {"feedback", [&](const Entry& e) {
              const std::string v = Lower(e.value);
              if (v == "sync") {
                gw.feedback = gateway::FeedbackMode::kAtSync;
              } else if (v == "latest") {
                gw.feedback = gateway::FeedbackMode::kLatest;
              } else {
                return p.Fail(e, "expected sync or latest", &err);
              }
              return true;
            }}})) {
    return err;
  }

  // ---- [gpio]
  std::map<std::string, Handler> gpio_keys = {
      {"backend",
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
           return p.Fail(e, "expected gpiod, fake, fake:STATE_FILE or none", &err);
         }
         return true;
       }},
      {"consumer",
       [&](const Entry& e) {
         c.gpio.consumer = e.value;
         return true;
       }},
      {"debounce_ms", [&](const Entry& e) { return p.U(e, 0, 1000, &c.debounce_ms, &err); }},
      {"poll_ms", [&](const Entry& e) { return p.U(e, 1, 1000, &c.io_poll_ms, &err); }}};
  for (int i = 0; i < lb::kInputLineCount; ++i) {
    lb::GpioLineSpec* spec = &c.gpio.input[i];
    gpio_keys[lb::InputLineName(static_cast<hal::InputLine>(i))] = [&, spec](const Entry& e) {
      const std::string why = lb::ParseGpioLineSpec(e.value, spec);
      return why.empty() || p.Fail(e, why, &err);
    };
  }
  for (int i = 0; i < lb::kOutputLineCount; ++i) {
    lb::GpioLineSpec* spec = &c.gpio.output[i];
    gpio_keys[lb::OutputLineName(static_cast<hal::OutputLine>(i))] = [&, spec](const Entry& e) {
      const std::string why = lb::ParseGpioLineSpec(e.value, spec);
      return why.empty() || p.Fail(e, why, &err);
    };
  }
  if (!apply(find("gpio", ""), gpio_keys)) return err;
  for (uint32_t i = st.board.axis_count; i < table::kMaxAxes; ++i) {
    if (c.gpio.input[i].used) {
      return source + ": [gpio] home" + std::to_string(i) + " is wired but the board has only " +
             std::to_string(st.board.axis_count) + " axes";
    }
  }
  if (!enable_input_given) {
    c.enable_input = c.gpio_backend != GpioBackendKind::kNone &&
                     (c.gpio.input[static_cast<int>(hal::InputLine::kEnable)].used ||
                      c.gpio_backend == GpioBackendKind::kFake);
  }

  // ---- [flash]
  uint32_t bank_kib = c.table_bank_bytes / 1024;
  if (!apply(
          find("flash", ""),
          {{"tables",
            [&](const Entry& e) {
              c.table_file = e.value;
              return true;
            }},
           {"settings",
            [&](const Entry& e) {
              c.settings_file = e.value;
              return true;
            }},
           {"table_bank_kib", [&](const Entry& e) { return p.U(e, 16, 65536, &bank_kib, &err); }},
           {"sector_bytes",
            [&](const Entry& e) { return p.U(e, 256, 1u << 20, &c.sector_bytes, &err); }},
           {"sync", [&](const Entry& e) { return p.Bool(e, &c.flash_sync, &err); }},
           {"write_behind",
            [&](const Entry& e) { return p.Bool(e, &c.flash_write_behind, &err); }}})) {
    return err;
  }

  // ---- [process]
  if (!apply(find("process", ""),
             {{"realtime_priority",
               [&](const Entry& e) { return p.U(e, 0, 99, &c.realtime_priority, &err); }},
              {"lock_memory", [&](const Entry& e) { return p.Bool(e, &c.lock_memory, &err); }}})) {
    return err;
  }
  c.table_bank_bytes = bank_kib * 1024u;
  if (c.table_file.empty()) return source + ": [flash] tables = FILE is required";
  if (c.table_bank_bytes % c.sector_bytes != 0) {
    return source + ": [flash] table_bank_kib must be a multiple of sector_bytes";
  }
  if (!c.settings_file.empty() && c.settings_file == c.table_file) {
    return source + ": [flash] tables and settings must be different files";
  }

  // ---- Whole checks.
  if (!firmware::ValidateSettings(st).ok()) {
    return source + ": the board settings are inconsistent (ValidateBoardConfig)";
  }
  gw.own_node_id = st.node_id;
  if (!gateway::ValidateGatewayConfig(gw, st.board.axis_count).ok()) {
    return source + ": the PDO mapping is invalid: COB-IDs must not be 0x000, the SYNC COB-ID " +
           "or one of the board's own (0x580/0x600/0x700/0x080 + node_id); at most one " +
           "target_pdo and one actual_pdo per axis; fields in one PDO must not overlap";
  }
  *out = c;
  return "";
}

std::string LoadConfigFile(const std::string& path, LinuxBoardConfig* out) {
  std::ifstream in(path);
  if (!in) return path + ": cannot read the configuration file";
  std::ostringstream text;
  text << in.rdbuf();
  return ParseConfig(text.str(), path, out);
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
