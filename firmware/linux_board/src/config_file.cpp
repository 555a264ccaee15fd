// volcomp-fw-linux configuration file: the board's settings through the one settings codec, the
// Linux board's own keys and sections here.
#include "volcomp/linux_board/config_file.hpp"

#include <cctype>
#include <utility>
#include <vector>

#include "volcomp/hosted/settings_ini.hpp"

namespace volcomp::linux_board {
namespace {

namespace lb = hal::linux_board;
using hosted::IniDocument;
using hosted::IniEntry;
using hosted::IniExpected;
using hosted::IniKey;
using hosted::IniOutcome;
using hosted::IniSection;
using hosted::IniWriter;
using hosted::ReadBool;
using hosted::ReadChoice;
using hosted::ReadInteger;
using hosted::Trim;

// An integer key within [low, high] into *out.
template <typename T>
IniKey Number(const IniDocument& doc, const char* key, int64_t low, int64_t high, T* out) {
  return {key, [&doc, low, high, out](const IniEntry& e) -> IniOutcome {
            VOLCOMP_TRY_ASSIGN(const int64_t v, ReadInteger(doc, e, low, high));
            *out = static_cast<T>(v);
            return IniOutcome::Ok();
          }};
}

IniKey Bool(const IniDocument& doc, const char* key, bool* out) {
  return {key, [&doc, out](const IniEntry& e) -> IniOutcome {
            VOLCOMP_TRY_ASSIGN(*out, ReadBool(doc, e));
            return IniOutcome::Ok();
          }};
}

// A key whose value is kept as written (an interface or file name).
IniKey Text(const char* key, std::string* out) {
  return {key, [out](const IniEntry& e) -> IniOutcome {
            *out = e.value;
            return IniOutcome::Ok();
          }};
}

std::string OnOff(bool v) { return v ? "true" : "false"; }

// "temperature_file.N" for channel ch (N = ch + 1, the sub-index of 0x2150).
const char* TemperatureFileKey(uint8_t ch) {
  static const char* const kKeys[thermal::kMaxChannels] = {
      "temperature_file.1", "temperature_file.2", "temperature_file.3", "temperature_file.4",
      "temperature_file.5", "temperature_file.6", "temperature_file.7", "temperature_file.8"};
  return kKeys[ch];
}

// Reads one configuration text. Each step reads a part into config_ and stops at the first
// mistake; Parse() runs them in a file-independent order, so the same mistake always gives the
// same message.
class ConfigParser {
 public:
  explicit ConfigParser(const IniDocument& doc) : doc_(doc) {}

  IniExpected<LinuxBoardConfig> Parse() {
    VOLCOMP_TRY(doc_.CheckSections({"board", "axis NAME", "temperature N", "can", "gateway", "gpio",
                                    "flash", "sensors", "process"}));
    VOLCOMP_TRY(Settings());
    VOLCOMP_TRY(Can());
    VOLCOMP_TRY(Gateway());
    VOLCOMP_TRY(Gpio());
    VOLCOMP_TRY(Flash());
    VOLCOMP_TRY(Sensors());
    VOLCOMP_TRY(Process());
    VOLCOMP_TRY(CheckFlash());
    VOLCOMP_TRY(CheckMapping());
    return config_;
  }

 private:
  // "0x201:2" -> COB-ID, offset.
  IniOutcome Pdo(const IniEntry& e, uint16_t* cob, uint8_t* offset) const {
    const size_t colon = e.value.find(':');
    if (colon == std::string::npos) {
      return doc_.FailKey(e, "expected COB-ID:OFFSET (e.g. 0x201:2), got '" + e.value + "'");
    }
    IniEntry c = e, o = e;
    c.key += " COB-ID";
    c.value = Trim(e.value.substr(0, colon));
    o.key += " offset";
    o.value = Trim(e.value.substr(colon + 1));
    VOLCOMP_TRY_ASSIGN(const int64_t id, ReadInteger(doc_, c, 1, 0x7FF));
    VOLCOMP_TRY_ASSIGN(const int64_t at, ReadInteger(doc_, o, 0, 4));
    *cob = static_cast<uint16_t>(id);
    *offset = static_cast<uint8_t>(at);
    return IniOutcome::Ok();
  }

  // [board] and [axis NAME]: the settings (the one codec) and this board's keys in them.
  IniOutcome Settings() {
    BoardSettings& st = config_.settings;
    gateway::GatewayConfig& gw = config_.gateway;
    gw.map_count = 0;
    hosted::SettingsIniExtras extras;
    extras.board = {Bool(doc_, "enable_input", &config_.enable_input),
                    Number(doc_, "serial_number", 0, 0xFFFFFFFFll, &config_.serial_number)};
    extras.axis = [this, &gw](uint8_t a) {
      auto add_map = [this, &gw, a](const IniEntry& e, gateway::PdoField field) -> IniOutcome {
        if (gw.map_count == gateway::kMaxPdoMaps) return doc_.FailKey(e, "too many mapped PDOs");
        gateway::PdoMap& m = gw.map[gw.map_count];
        m.field = field;
        m.axis = a;
        VOLCOMP_TRY(Pdo(e, &m.cob_id, &m.offset));
        ++gw.map_count;
        return IniOutcome::Ok();
      };
      return std::vector<IniKey>{
          Bool(doc_, "invert", &gw.invert[a]),
          {"target_pdo",
           [add_map](const IniEntry& e) { return add_map(e, gateway::PdoField::kTargetPosition); }},
          {"actual_pdo", [add_map](const IniEntry& e) {
             return add_map(e, gateway::PdoField::kActualPosition);
           }}};
    };
    VOLCOMP_TRY(hosted::ReadSettings(doc_, &st, extras));
    const IniSection* board = doc_.Find("board");
    enable_input_given_ = board != nullptr && board->Find("enable_input") != nullptr;
    for (uint8_t a = 0; a < st.board.axis_count; ++a) {
      AxisConfig& ax = st.board.axis[a];
      const IniSection* s = doc_.Find("axis", std::string(1, ax.name));
      // A drive increment is this board's step: there is no sensible default.
      if (s->Find("units_per_step") == nullptr && s->Find("steps_per_unit") == nullptr) {
        return doc_.FailAt(s->line, s->Title() + " needs units_per_step (or steps_per_unit)");
      }
      // No step output: the drive's rate only has to cover the input and the correction.
      const uint64_t needed = uint64_t{ax.max_input_rate_hz} + ax.max_correction_rate_steps_s;
      if (s->Find("drive_max_rate_hz") == nullptr && needed > ax.drive.max_rate_hz &&
          needed <= 0xFFFFFFFFu) {
        ax.drive.max_rate_hz = static_cast<uint32_t>(needed);
      }
    }
    return hosted::CheckSettings(doc_, st);
  }

  // [can]
  IniOutcome Can() {
    LinuxBoardConfig& c = config_;
    VOLCOMP_TRY(
        hosted::ReadKeys(doc_, doc_.Find("can"),
                         {Text("controller", &c.controller_iface), Text("drives", &c.drives_iface),
                          Number(doc_, "tx_queue", 16, 100000, &c.tx_queue),
                          Bool(doc_, "restart_on_bus_off", &c.restart_on_bus_off)}));
    if (c.controller_iface.empty()) return doc_.FailAt(0, "[can] controller = IFACE is required");
    if (c.drives_iface == c.controller_iface) {
      return doc_.FailAt(0, "[can] controller and drives must be different interfaces");
    }
    return IniOutcome::Ok();
  }

  // [gateway]
  IniOutcome Gateway() {
    gateway::GatewayConfig& gw = config_.gateway;
    return hosted::ReadKeys(
        doc_, doc_.Find("gateway"),
        {Number(doc_, "sync_cob_id", 1, 0x7FF, &gw.sync_cob_id),
         {"feedback", [this, &gw](const IniEntry& e) -> IniOutcome {
            VOLCOMP_TRY_ASSIGN(const size_t i, ReadChoice(doc_, e, {"sync", "latest"}));
            gw.feedback = i == 0 ? gateway::FeedbackMode::kAtSync : gateway::FeedbackMode::kLatest;
            return IniOutcome::Ok();
          }}});
  }

  // [gpio]: the backend, timing and one line spec per wired line.
  IniOutcome Gpio() {
    LinuxBoardConfig& c = config_;
    std::vector<IniKey> keys = {
        {"backend",
         [this, &c](const IniEntry& e) -> IniOutcome {
           const std::string& v = e.value;
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
             return doc_.FailKey(e,
                                 "expected gpiod | fake | fake:STATE_FILE | none, got '" + v + "'");
           }
           return IniOutcome::Ok();
         }},
        Text("consumer", &c.gpio.consumer),
        Number(doc_, "debounce_ms", 0, 1000, &c.debounce_ms),
        Number(doc_, "poll_ms", 1, 1000, &c.io_poll_ms)};
    const auto line = [this](const char* name, lb::GpioLineSpec* spec) -> IniKey {
      return {name, [this, spec](const IniEntry& e) -> IniOutcome {
                const Expected<lb::GpioLineSpec> parsed = lb::ParseGpioLineSpec(e.value);
                if (!parsed.ok()) return doc_.FailKey(e, parsed.error().message);
                *spec = *parsed;
                return IniOutcome::Ok();
              }};
    };
    for (int i = 0; i < lb::kInputLineCount; ++i) {
      keys.push_back(line(lb::InputLineName(static_cast<hal::InputLine>(i)), &c.gpio.input[i]));
    }
    for (int i = 0; i < lb::kOutputLineCount; ++i) {
      keys.push_back(line(lb::OutputLineName(static_cast<hal::OutputLine>(i)), &c.gpio.output[i]));
    }
    VOLCOMP_TRY(hosted::ReadKeys(doc_, doc_.Find("gpio"), keys));
    const uint8_t axes = c.settings.board.axis_count;
    for (uint32_t i = axes; i < table::kMaxAxes; ++i) {
      if (c.gpio.input[i].used) {
        return doc_.FailAt(0, "[gpio] home" + std::to_string(i) +
                                  " is wired but the board has only " + std::to_string(axes) +
                                  " axes");
      }
    }
    if (!enable_input_given_) {
      c.enable_input = c.gpio_backend != GpioBackendKind::kNone &&
                       (c.gpio.input[static_cast<int>(hal::InputLine::kEnable)].used ||
                        c.gpio_backend == GpioBackendKind::kFake);
    }
    return IniOutcome::Ok();
  }

  // [flash] (checked by CheckFlash once every section is read)
  IniOutcome Flash() {
    LinuxBoardConfig& c = config_;
    bank_kib_ = c.table_bank_bytes / 1024;
    return hosted::ReadKeys(
        doc_, doc_.Find("flash"),
        {Text("tables", &c.table_file), Text("settings", &c.settings_file),
         Number(doc_, "table_bank_kib", 16, 65536, &bank_kib_),
         Number(doc_, "sector_bytes", 256, 1 << 20, &c.sector_bytes),
         Bool(doc_, "sync", &c.flash_sync), Bool(doc_, "write_behind", &c.flash_write_behind)});
  }

  // [sensors]: temperature_file.1 .. temperature_file.8, temperature_period_ms.
  IniOutcome Sensors() {
    LinuxBoardConfig& c = config_;
    std::vector<IniKey> keys = {
        Number(doc_, "temperature_period_ms", 100, 60000, &c.temperature_period_ms)};
    for (uint8_t ch = 0; ch < thermal::kMaxChannels; ++ch) {
      keys.push_back({TemperatureFileKey(ch), [this, &c, ch](const IniEntry& e) -> IniOutcome {
                        if (e.value.empty() || e.value[0] != '/') {
                          return doc_.FailKey(
                              e, "expected an absolute file path, got '" + e.value + "'");
                        }
                        c.temperature_files[ch] = e.value;
                        return IniOutcome::Ok();
                      }});
    }
    return hosted::ReadKeys(doc_, doc_.Find("sensors"), keys);
  }
  // [process]
  IniOutcome Process() {
    LinuxBoardConfig& c = config_;
    return hosted::ReadKeys(doc_, doc_.Find("process"),
                            {Number(doc_, "realtime_priority", 0, 99, &c.realtime_priority),
                             Bool(doc_, "lock_memory", &c.lock_memory)});
  }

  IniOutcome CheckFlash() {
    LinuxBoardConfig& c = config_;
    c.table_bank_bytes = bank_kib_ * 1024u;
    if (c.table_file.empty()) return doc_.FailAt(0, "[flash] tables = FILE is required");
    if (c.table_bank_bytes % c.sector_bytes != 0) {
      return doc_.FailAt(0, "[flash] table_bank_kib must be a multiple of sector_bytes");
    }
    if (!c.settings_file.empty() && c.settings_file == c.table_file) {
      return doc_.FailAt(0, "[flash] tables and settings must be different files");
    }
    return IniOutcome::Ok();
  }

  // The PDO mapping for the settings read.
  IniOutcome CheckMapping() {
    gateway::GatewayConfig& gw = config_.gateway;
    gw.own_node_id = config_.settings.node_id;
    if (!gateway::ValidateGatewayConfig(gw, config_.settings.board.axis_count).ok()) {
      return doc_.FailAt(
          0,
          "the PDO mapping is invalid: COB-IDs must not be 0x000, the SYNC COB-ID or one of the "
          "board's own (0x580/0x600/0x700/0x080 + node_id); at most one target_pdo and one "
          "actual_pdo per axis; fields in one PDO must not overlap");
    }
    return IniOutcome::Ok();
  }

  const IniDocument& doc_;
  LinuxBoardConfig config_;
  bool enable_input_given_ = false;
  uint32_t bank_kib_ = 0;
};

}  // namespace

BoardSettings LinuxBoardDefaults() {
  BoardSettings s;
  s.board.tick_hz = 1000;
  return s;
}

Expected<LinuxBoardConfig, ConfigError> ParseConfig(const std::string& text,
                                                    const std::string& source) {
  VOLCOMP_TRY_ASSIGN(const IniDocument doc, IniDocument::Parse(text, source));
  return ConfigParser(doc).Parse();
}

Expected<LinuxBoardConfig, ConfigError> LoadConfigFile(const std::string& path) {
  VOLCOMP_TRY_ASSIGN(const IniDocument doc, IniDocument::ReadFile(path));
  return ConfigParser(doc).Parse();
}

std::string FormatConfig(const LinuxBoardConfig& c) {
  IniWriter w;
  hosted::SettingsIniWriteExtras extras;
  extras.board = [&c](IniWriter& o) {
    o.Key("enable_input", OnOff(c.enable_input));
    o.Key("serial_number", std::to_string(c.serial_number));
  };
  extras.axis = [&c](IniWriter& o, uint8_t a) {
    o.Key("invert", OnOff(c.gateway.invert[a]));
    for (uint8_t i = 0; i < c.gateway.map_count; ++i) {
      const gateway::PdoMap& m = c.gateway.map[i];
      if (m.axis != a) continue;
      o.Key(m.field == gateway::PdoField::kTargetPosition ? "target_pdo" : "actual_pdo",
            hosted::FormatHex(m.cob_id, 3) + ":" + std::to_string(m.offset));
    }
  };
  hosted::WriteSettings(w, c.settings, extras);
  w.Section("can");
  w.Key("controller", c.controller_iface);
  w.Key("drives", c.drives_iface);
  w.Key("tx_queue", std::to_string(c.tx_queue));
  w.Key("restart_on_bus_off", OnOff(c.restart_on_bus_off));
  w.Section("gateway");
  w.Key("sync_cob_id", hosted::FormatHex(c.gateway.sync_cob_id, 3));
  w.Key("feedback", c.gateway.feedback == gateway::FeedbackMode::kAtSync ? "sync" : "latest");
  w.Section("gpio");
  switch (c.gpio_backend) {
    case GpioBackendKind::kNone:
      w.Key("backend", "none");
      break;
    case GpioBackendKind::kGpiod:
      w.Key("backend", "gpiod");
      break;
    case GpioBackendKind::kFake:
      w.Key("backend", "fake" + (c.fake_state_file.empty() ? "" : ":" + c.fake_state_file));
      break;
  }
  w.Key("consumer", c.gpio.consumer);
  w.Key("debounce_ms", std::to_string(c.debounce_ms));
  w.Key("poll_ms", std::to_string(c.io_poll_ms));
  for (int i = 0; i < lb::kInputLineCount; ++i) {
    if (c.gpio.input[i].used) {
      w.Key(lb::InputLineName(static_cast<hal::InputLine>(i)),
            lb::FormatGpioLineSpec(c.gpio.input[i]));
    }
  }
  for (int i = 0; i < lb::kOutputLineCount; ++i) {
    if (c.gpio.output[i].used) {
      w.Key(lb::OutputLineName(static_cast<hal::OutputLine>(i)),
            lb::FormatGpioLineSpec(c.gpio.output[i]));
    }
  }
  w.Section("flash");
  w.Key("tables", c.table_file);
  w.Key("settings", c.settings_file);
  w.Key("table_bank_kib", std::to_string(c.table_bank_bytes / 1024));
  w.Key("sector_bytes", std::to_string(c.sector_bytes));
  w.Key("sync", OnOff(c.flash_sync));
  w.Key("write_behind", OnOff(c.flash_write_behind));
  w.Section("sensors");
  for (uint8_t ch = 0; ch < thermal::kMaxChannels; ++ch) {
    if (!c.temperature_files[ch].empty()) w.Key(TemperatureFileKey(ch), c.temperature_files[ch]);
  }
  w.Key("temperature_period_ms", std::to_string(c.temperature_period_ms));
  w.Section("process");
  w.Key("realtime_priority", std::to_string(c.realtime_priority));
  w.Key("lock_memory", OnOff(c.lock_memory));
  return w.text();
}

}  // namespace volcomp::linux_board
