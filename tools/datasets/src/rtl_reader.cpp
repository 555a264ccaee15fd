// Renishaw .rtl linear data files (see rtl_reader.hpp for the syntax, units, sign and sources).
#include "volcomp/datasets/rtl_reader.hpp"

#include <cctype>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include "environment_units.hpp"
#include "trim.hpp"
#include "volcomp/metrology/inch.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::datasets {
namespace {

using metrology::Direction;

struct Line {
  std::size_t number = 0;  // 1-based
  std::string text;        // trimmed
};

std::vector<Line> SplitLines(const std::string& text) {
  std::vector<Line> lines;
  std::size_t start = 0, number = 1;
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) start = 3;  // UTF-8 byte order mark
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    lines.push_back({number++, Trim(text.substr(start, end - start))});
    start = end + 1;
  }
  return lines;
}

// "TARGET DATA" for "TARGET DATA::"; nullopt when the line is not a section line.
std::optional<std::string> SectionName(const std::string& line) {
  if (line.size() < 3 || line.compare(line.size() - 2, 2, "::") != 0) return std::nullopt;
  if (line.find(':') != line.size() - 2) return std::nullopt;
  for (std::size_t i = 0; i + 2 < line.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(line[i]);
    if (!std::isalnum(c) && c != ' ' && c != '-' && c != '_') return std::nullopt;
  }
  return Trim(line.substr(0, line.size() - 2));
}

// Key compared without case, spaces, '-' and '_': "Target-count" == "target count".
std::string KeyOf(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == ' ' || c == '-' || c == '_' || c == '\t') continue;
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

std::string Lower(const std::string& text) {
  std::string out;
  for (char c : text) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::vector<std::string> Words(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// All words numbers (and at least one)?
bool AllNumbers(const std::vector<std::string>& words) {
  if (words.empty()) return false;
  for (const auto& w : words) {
    if (!tools::ParseDouble(w)) return false;
  }
  return true;
}

// Valid UTF-8 (no overlong / surrogate checks needed for display); invalid bytes become '?'.
bool ToUtf8(std::string* value) {
  bool ok = true;
  std::string out;
  const std::string& s = *value;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80         ? 1
                          : (c >> 5) == 6  ? 2
                          : (c >> 4) == 14 ? 3
                          : (c >> 3) == 30 ? 4
                                           : 0;
    bool good = n > 0 && i + n <= s.size();
    for (std::size_t k = 1; good && k < n; ++k) {
      good = (static_cast<unsigned char>(s[i + k]) >> 6) == 2;
    }
    if (good) {
      out.append(s, i, n);
      i += n;
    } else {
      out += '?';
      ok = false;
      ++i;
    }
  }
  *value = out;
  return ok;
}

// A line as quoted in a message: at most 60 characters.
std::string Quoted(const std::string& text) {
  return "\"" + (text.size() > 60 ? text.substr(0, 57) + "..." : text) + "\"";
}

std::string Plural(std::size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// The file's length units and what one of each is in mm / µm (the one conversion of an .rtl).
struct LengthUnits {
  const char* target;
  const char* deviation;
  double mm_per_target;
  double um_per_deviation;
};

LengthUnits LengthUnitsOf(RtlUnits units) {
  // 1 in = 25.4 mm exactly, so 1 µin = 0.0254 µm.
  if (units == RtlUnits::kIn) {
    return {"in", "µin", metrology::kMmPerInch, metrology::kMicrometresPerMicroinch};
  }
  return {"mm", "µm", 1.0, 1.0};
}

class Reader {
 public:
  Reader(std::string source, const RtlOptions& options)
      : source_(std::move(source)), options_(options), units_(LengthUnitsOf(options.units)) {}

  Expected<RtlTest> Read(const std::string& text);

 private:
  Unexpected<Failure> At(std::size_t line, const std::string& message) const {
    return Fail(Error::kInputInvalid, source_ + ":" + std::to_string(line) + ": " + message);
  }
  void Warn(std::size_t line, const std::string& message) {
    test_.warnings.push_back(source_ + ":" + std::to_string(line) + ": " + message);
  }
  Outcome Section(const Line& line, const std::string& name);
  Outcome Entry(const Line& line);
  Outcome TargetEntry(const Line& line, const std::string& key, const std::string& value);
  Outcome TargetNumbers(const Line& line, const std::vector<std::string>& words);
  Outcome DeviationRow(const Line& line);
  Outcome EnvironmentEntry(const Line& line, const std::string& key, const std::string& value);
  Expected<int> Count(const Line& line, const std::string& name, const std::string& value) const;
  Outcome Finish(std::size_t last_line);
  void AddCondition(const std::string& key, std::string value, std::size_t line);
  void AddEnvironmentConditions();
  Outcome ConvertEnvironment();
  Outcome ConvertTemperatures();
  Outcome ConvertPressure();
  void ConvertExpansion();

  std::string source_;
  RtlOptions options_;
  LengthUnits units_;
  std::vector<std::string> units_read_;  // "temperatures °F", ...: for "units as read"
  bool fahrenheit_ = false;              // the temperatures are °F
  RtlTest test_;
  std::string section_;  // current section name, "" before the first
  std::map<std::string, std::size_t> section_lines_;
  std::optional<int> target_count_;
  std::size_t target_count_line_ = 0;
  bool in_targets_ = false;  // numbers on the following lines continue the Targets list
  std::size_t targets_line_ = 0;
  std::optional<int> run_count_;
  std::size_t run_count_line_ = 0;
  struct Row {
    int run;
    int target;
    double deviation;
    std::size_t line;
  };
  std::vector<Row> rows_;
  std::map<std::pair<int, int>, std::size_t> row_line_;  // (run, target) -> line
  struct Text {
    std::string key;
    std::string value;
    std::size_t line;
  };
  std::vector<Text> user_text_;
  std::vector<Text> other_environment_;
  std::size_t date_time_line_ = 0;
};

Outcome Reader::Section(const Line& line, const std::string& name) {
  in_targets_ = false;
  const std::string key = KeyOf(name);
  const auto [it, added] = section_lines_.emplace(key, line.number);
  if (!added) {
    return At(line.number, "a second " + name + ":: section (the first is on line " +
                               std::to_string(it->second) +
                               "): the file holds more than one test or axis; volcomp reads one "
                               "axis per .rtl file, so save each axis to its own file");
  }
  static const char* const kKnown[] = {"header",     "targetdata",  "usertext", "runs",
                                       "deviations", "environment", "equipment"};
  bool known = false;
  for (const char* k : kKnown) known = known || key == k;
  if (!known) Warn(line.number, "unknown section " + name + ":: skipped");
  section_ = key;
  if (key == "deviations") test_.deviations_line = line.number;
  return Outcome::Ok();
}

Expected<int> Reader::Count(const Line& line,
                            const std::string& name,
                            const std::string& value) const {
  const auto n = tools::ParseInteger(value);
  if (!n || *n < 1 || *n > 100000) {
    return At(line.number, name + " \"" + value + "\" is not a count from 1 to 100000");
  }
  return static_cast<int>(*n);
}

Outcome Reader::TargetNumbers(const Line& line, const std::vector<std::string>& words) {
  for (const std::string& w : words) {
    const auto v = tools::ParseDouble(w);
    if (!v) {
      return At(line.number, "Targets (line " + std::to_string(targets_line_) + "): \"" + w +
                                 "\" is not a number");
    }
    if (target_count_ && static_cast<int>(test_.targets_mm.size()) == *target_count_) {
      return At(line.number, "Targets lists more than the " + Plural(*target_count_, "target") +
                                 " of Target-count (line " + std::to_string(target_count_line_) +
                                 ")");
    }
    const double target_mm = *v * units_.mm_per_target;
    for (std::size_t j = 0; j < test_.targets_mm.size(); ++j) {
      if (test_.targets_mm[j] == target_mm) {
        return At(line.number, "target " + w + " " + units_.target + " is listed twice (targets " +
                                   std::to_string(j + 1) + " and " +
                                   std::to_string(test_.targets_mm.size() + 1) + ")");
      }
    }
    test_.targets_mm.push_back(target_mm);
  }
  return Outcome::Ok();
}

Outcome Reader::TargetEntry(const Line& line, const std::string& key, const std::string& value) {
  if (key == "targetcount") {
    VOLCOMP_TRY_ASSIGN(target_count_, Count(line, "Target-count", value));
    target_count_line_ = line.number;
    if (test_.targets_mm.size() > static_cast<std::size_t>(*target_count_)) {
      return At(line.number, "Target-count " + value + " but Targets (line " +
                                 std::to_string(targets_line_) + ") lists " +
                                 Plural(test_.targets_mm.size(), "target"));
    }
  } else if (key == "targets") {
    if (targets_line_ != 0) {
      return At(line.number, "a second Targets list (the first is on line " +
                                 std::to_string(targets_line_) + ")");
    }
    targets_line_ = line.number;
    in_targets_ = true;
    return TargetNumbers(line, Words(value));
  }
  return Outcome::Ok();  // Filetype, Flags: meaning unknown, not needed
}

Outcome Reader::DeviationRow(const Line& line) {
  const std::vector<std::string> w = Words(line.text);
  if (w.size() != 3 || !AllNumbers(w)) {
    return At(line.number, Quoted(line.text) +
                               " is not a deviation row (run, target and deviation: three "
                               "numbers)");
  }
  if (!run_count_ || !target_count_) {
    return At(line.number, std::string("deviation rows before the ") +
                               (target_count_ ? "Run-count" : "Target-count") +
                               " that says how many there are");
  }
  const auto run = tools::ParseInteger(w[0]);
  const auto target = tools::ParseInteger(w[1]);
  if (!run || *run < 1 || *run > *run_count_) {
    return At(line.number, "run \"" + w[0] + "\" is not a run from 1 to Run-count " +
                               std::to_string(*run_count_) + " (line " +
                               std::to_string(run_count_line_) + ")");
  }
  if (!target || *target < 1 || *target > *target_count_) {
    return At(line.number, "target \"" + w[1] +
                               "\" is not a target number from 1 to Target-count " +
                               std::to_string(*target_count_) + " (line " +
                               std::to_string(target_count_line_) + ")");
  }
  const double deviation = *tools::ParseDouble(w[2]) * units_.um_per_deviation;  // µm
  if (std::fabs(deviation) > metrology::kMaxReadingMagnitude) {
    return At(line.number, "a deviation of " + w[2] + " " + units_.deviation +
                               " cannot be a reading (the limit is ±1e9 µm); refused");
  }
  const std::pair<int, int> key{static_cast<int>(*run), static_cast<int>(*target)};
  const auto [it, added] = row_line_.emplace(key, line.number);
  if (!added) {
    return At(line.number, "run " + w[0] + " target " + w[1] + " is given twice (also on line " +
                               std::to_string(it->second) + ")");
  }
  rows_.push_back({key.first, key.second, deviation, line.number});
  return Outcome::Ok();
}

Outcome Reader::EnvironmentEntry(const Line& line,
                                 const std::string& key,
                                 const std::string& value) {
  std::optional<RtlReading>* slot = nullptr;
  RtlEnvironment& env = test_.environment;
  if (key == "airtemp") slot = &env.air_temperature_c;
  if (key == "airpress") slot = &env.air_pressure_kpa;
  if (key == "airhumid") slot = &env.humidity_pct;
  if (key == "mattemp1") slot = &env.material_temperature_c[0];
  if (key == "mattemp2") slot = &env.material_temperature_c[1];
  if (key == "mattemp3") slot = &env.material_temperature_c[2];
  if (key == "expcoeff") slot = &env.expansion_ppm_per_c;
  if (key == "envfactor") slot = &env.environment_factor;
  if (key == "datetime") {
    // "10:46 Dec 12 2016" "11:01 Dec 12 2016": the quoted stamps at the start and the end.
    std::vector<std::string> stamps;
    std::istringstream in(value);
    for (std::string piece; std::getline(in, piece, '"');) {
      if (!Trim(piece).empty()) stamps.push_back(Trim(piece));
    }
    env.date_time = stamps.size() == 2 ? stamps[0] + " to " + stamps[1] : value;
    date_time_line_ = line.number;
    return Outcome::Ok();
  }
  if (key == "finaldata") return Outcome::Ok();  // meaning unknown
  if (!slot) {
    other_environment_.push_back(
        {Trim(line.text.substr(0, line.text.find(':'))), value, line.number});
    return Outcome::Ok();
  }
  const std::vector<std::string> w = Words(value);
  const auto start = w.size() >= 2 ? tools::ParseDouble(w[0]) : std::nullopt;
  const auto end = w.size() >= 2 ? tools::ParseDouble(w[1]) : std::nullopt;
  if (!start || !end || w.size() > 3) {
    return At(line.number, Quoted(line.text) +
                               ": an environment line holds a start and an end value (and an "
                               "optional flag)");
  }
  if (key.rfind("mattemp", 0) == 0 && *start == -10.0 && *end == -10.0) return Outcome::Ok();
  *slot = RtlReading{*start, *end, line.number};
  return Outcome::Ok();
}

Outcome Reader::Entry(const Line& line) {
  if (section_ == "targetdata" && in_targets_) {
    // Numbers continue the list; a line without a key names its word that is not a number.
    if (line.text.find(':') == std::string::npos) return TargetNumbers(line, Words(line.text));
    in_targets_ = false;
  }
  if (section_ == "deviations" && AllNumbers(Words(line.text))) return DeviationRow(line);
  const std::size_t colon = line.text.find(':');
  if (colon == std::string::npos) {
    if (section_ == "deviations") return DeviationRow(line);  // names the bad row
    if (section_ == "header" || section_ == "targetdata" || section_ == "usertext" ||
        section_ == "runs" || section_ == "environment") {
      return At(line.number, Quoted(line.text) + " is not a \"Key: value\" line");
    }
    return Outcome::Ok();  // unknown or EQUIPMENT section
  }
  const std::string key = KeyOf(line.text.substr(0, colon));
  const std::string value = Trim(line.text.substr(colon + 1));
  if (section_ == "header") {
    if (key == "data" || key == "samplerate" || key == "actualsamplerate") {
      return At(line.number,
                "\"" + line.text.substr(0, colon) +
                    "\" in the HEADER: this is a CARTO dynamic capture (.rtx), a time series, "
                    "not a linear test (.rtl)");
    }
    return Outcome::Ok();
  }
  if (section_ == "targetdata") return TargetEntry(line, key, value);
  if (section_ == "usertext") {
    user_text_.push_back({Trim(line.text.substr(0, colon)), value, line.number});
    return Outcome::Ok();
  }
  if (section_ == "runs") {
    if (key == "runcount") {
      VOLCOMP_TRY_ASSIGN(run_count_, Count(line, "Run-count", value));
      run_count_line_ = line.number;
    }
    return Outcome::Ok();
  }
  if (section_ == "deviations") {
    if (key == "runtargetdata") return Outcome::Ok();
    return DeviationRow(line);
  }
  if (section_ == "environment") return EnvironmentEntry(line, key, value);
  return Outcome::Ok();
}

std::string Number(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string ReadingText(const RtlReading& r) {
  if (r.start == r.end) return Number(r.start);
  return Number(r.start) + " at start, " + Number(r.end) + " at end";
}

// "68.6 and 68.7 °F", or "6.5 ppm/°F" when start and end agree (no unit: "") for messages.
std::string ValuesText(const RtlReading& r, const std::string& unit) {
  const std::string values =
      r.start == r.end ? Number(r.start) : Number(r.start) + " and " + Number(r.end);
  return unit.empty() ? values : values + " " + unit;
}

// The temperatures in °C: each line's unit recognised by its range (environment_units.hpp).
Outcome Reader::ConvertTemperatures() {
  RtlEnvironment& env = test_.environment;
  const std::pair<std::optional<RtlReading>*, const char*> temperatures[] = {
      {&env.air_temperature_c, "Air temp"},
      {&env.material_temperature_c[0], "Mat temp 1"},
      {&env.material_temperature_c[1], "Mat temp 2"},
      {&env.material_temperature_c[2], "Mat temp 3"}};
  std::size_t celsius_line = 0, fahrenheit_line = 0;
  for (const auto& [slot, name] : temperatures) {
    if (!*slot) continue;
    RtlReading& r = **slot;
    const std::optional<TemperatureUnit> unit = RecogniseTemperature(r.start, r.end);
    if (!unit) {
      return At(r.line, std::string(name) + " " + ValuesText(r, "") +
                            " is not a shop temperature: °C up to 45, or °F above 45 up to " +
                            Number(kHighestShopFahrenheit) + " (45 °C), start and end alike");
    }
    if (*unit == TemperatureUnit::kCelsius) {
      if (celsius_line == 0) celsius_line = r.line;
      continue;
    }
    if (fahrenheit_line == 0) fahrenheit_line = r.line;
    const std::string as_written = ValuesText(r, "°F");
    r.start = CelsiusFromFahrenheit(r.start);
    r.end = CelsiusFromFahrenheit(r.end);
    Warn(r.line, std::string(name) + " is above 45, so read as °F: " + as_written + " = " +
                     ValuesText(r, "°C"));
  }
  fahrenheit_ = fahrenheit_line != 0;
  if (fahrenheit_) units_read_.push_back("temperatures °F");
  if (fahrenheit_ && celsius_line != 0) {
    Warn(celsius_line, "this temperature is 45 or below, so read as °C, but line " +
                           std::to_string(fahrenheit_line) +
                           "'s is °F: check both against the laser software");
  }
  if (fahrenheit_ && options_.units == RtlUnits::kMm) {
    Warn(fahrenheit_line,
         "the temperatures are °F but the file is read in mm and µm (--rtl-units mm): it was "
         "probably written in inch units; if its targets are inches, read it with --rtl-units in");
  } else if (!fahrenheit_ && celsius_line != 0 && options_.units == RtlUnits::kIn) {
    Warn(celsius_line,
         "the temperatures are °C but the file is read in inches and µin (--rtl-units in): it "
         "was probably written in metric units; if its targets are mm, read it with "
         "--rtl-units mm");
  }
  return Outcome::Ok();
}

// The air pressure in kPa: its unit recognised by its range (environment_units.hpp).
Outcome Reader::ConvertPressure() {
  std::optional<RtlReading>& pressure = test_.environment.air_pressure_kpa;
  if (!pressure) return Outcome::Ok();
  RtlReading& r = *pressure;
  const PressureUnit* unit = RecognisePressure(r.start, r.end);
  if (!unit) {
    return At(r.line, "Air press " + ValuesText(r, "") +
                          " is in none of the air pressure ranges (" + PressureRangesText() +
                          ", start and end alike)");
  }
  if (unit->kpa_per_unit == 1.0) return Outcome::Ok();
  const std::string as_written = ValuesText(r, unit->name);
  r.start *= unit->kpa_per_unit;
  r.end *= unit->kpa_per_unit;
  Warn(r.line, std::string("Air press read as ") + unit->name + " by its range (" +
                   PressureRangesText() + "): " + as_written + " = " + ValuesText(r, "kPa"));
  units_read_.push_back(std::string("pressure ") + unit->name);
  return Outcome::Ok();
}

// The expansion coefficient in ppm/°C.
void Reader::ConvertExpansion() {
  std::optional<RtlReading>& expansion = test_.environment.expansion_ppm_per_c;
  if (!expansion) return;
  const RtlExpansionPer per = options_.expansion_per;
  if (per == RtlExpansionPer::kCelsius || (per == RtlExpansionPer::kAuto && !fahrenheit_)) return;
  RtlReading& r = *expansion;
  const std::string as_written = ValuesText(r, "ppm/°F");
  r.start *= 1.8;  // per °F → per °C: a kelvin is 1.8 °F
  r.end *= 1.8;
  units_read_.push_back("expansion coefficient ppm/°F");
  if (per == RtlExpansionPer::kAuto) {
    Warn(r.line, "Exp coeff read as ppm/°F, since the temperatures are °F: " + as_written + " = " +
                     ValuesText(r, "ppm/°C") +
                     "; give --rtl-expansion-per C if the file states ppm/°C");
  }
}

Outcome Reader::ConvertEnvironment() {
  if (options_.units == RtlUnits::kIn) units_read_.push_back("targets in, deviations µin");
  VOLCOMP_TRY(ConvertTemperatures());
  VOLCOMP_TRY(ConvertPressure());
  ConvertExpansion();
  if (!units_read_.empty()) {
    std::string text;
    for (const std::string& u : units_read_) text += (text.empty() ? "" : ", ") + u;
    test_.conditions.entries.emplace_back("units as read",
                                          text + " (converted to mm, µm, °C, kPa and ppm/°C)");
  }
  return Outcome::Ok();
}

void Reader::AddCondition(const std::string& key, std::string value, std::size_t line) {
  if (value.empty()) return;
  if (!ToUtf8(&value)) {
    Warn(line, "the value of \"" + key +
                   "\" is not UTF-8 text (perhaps GBK); kept with '?' for the bytes that are not");
  }
  test_.conditions.entries.emplace_back(key, value);
}

void Reader::AddEnvironmentConditions() {
  const RtlEnvironment& env = test_.environment;
  const auto add = [this](const char* key, const std::optional<RtlReading>& r) {
    if (r) AddCondition(key, ReadingText(*r), r->line);
  };
  add("air temperature C", env.air_temperature_c);
  add("material temperature C", env.material_temperature_c[0]);
  add("material temperature 2 C", env.material_temperature_c[1]);
  add("material temperature 3 C", env.material_temperature_c[2]);
  add("air pressure kPa", env.air_pressure_kpa);
  add("humidity %RH", env.humidity_pct);
  add("expansion coefficient ppm/C", env.expansion_ppm_per_c);
  add("environment factor", env.environment_factor);
  if (!env.date_time.empty()) AddCondition("measured", env.date_time, date_time_line_);
  for (const Text& t : other_environment_) AddCondition(t.key, t.value, t.line);
}

// "runs 2, 4 and 6".
std::string RunsText(const std::vector<int>& runs) {
  std::string s = runs.size() == 1 ? "run " : "runs ";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (i > 0) s += i + 1 == runs.size() ? " and " : ", ";
    s += std::to_string(runs[i]);
  }
  return s;
}

Outcome Reader::Finish(std::size_t last_line) {
  const auto section_line = [this](const char* key) {
    const auto it = section_lines_.find(key);
    return it == section_lines_.end() ? std::size_t{0} : it->second;
  };
  const std::size_t targets_section = section_line("targetdata");
  if (targets_section == 0) {
    return At(last_line, "end of file without a TARGET DATA:: section (Target-count, Targets)");
  }
  if (!target_count_) return At(targets_section, "TARGET DATA:: without a Target-count");
  if (targets_line_ == 0) return At(targets_section, "TARGET DATA:: without a Targets list");
  if (test_.targets_mm.size() < static_cast<std::size_t>(*target_count_)) {
    return At(targets_line_, "Targets lists " + Plural(test_.targets_mm.size(), "target") +
                                 " but Target-count (line " + std::to_string(target_count_line_) +
                                 ") says " + std::to_string(*target_count_));
  }
  if (!run_count_) {
    const std::size_t runs = section_line("runs");
    return At(runs != 0 ? runs : last_line,
              runs != 0 ? "RUNS:: without a Run-count"
                        : "end of file without a RUNS:: section (Run-count)");
  }
  if (test_.deviations_line == 0) {
    return At(last_line, "end of file without a DEVIATIONS:: section");
  }
  const std::size_t expected = static_cast<std::size_t>(*run_count_) * *target_count_;
  if (rows_.size() < expected) {
    std::string missing;
    int runs_named = 0;
    for (int r = 1; r <= *run_count_ && runs_named < 3; ++r) {
      std::vector<int> targets;
      for (int t = 1; t <= *target_count_; ++t) {
        if (!row_line_.count({r, t})) targets.push_back(t);
      }
      if (targets.empty()) continue;
      std::string list;
      for (std::size_t k = 0; k < targets.size() && k < 6; ++k) {
        list += (k ? ", " : "") + std::to_string(targets[k]);
      }
      if (targets.size() > 6) list += ", ...";
      missing += (missing.empty() ? "" : "; ") + std::string("run ") + std::to_string(r) +
                 (targets.size() == 1 ? " target " : " targets ") + list;
      ++runs_named;
    }
    const std::size_t at = rows_.empty() ? test_.deviations_line : rows_.back().line;
    return At(at, "the deviation rows end here after " + std::to_string(rows_.size()) + " of the " +
                      std::to_string(expected) + " that Run-count " + std::to_string(*run_count_) +
                      " (line " + std::to_string(run_count_line_) + ") × Target-count " +
                      std::to_string(*target_count_) + " (line " +
                      std::to_string(target_count_line_) +
                      ") ask for (a truncated file?); missing: " + missing +
                      (runs_named == 3 ? "; ..." : ""));
  }

  // Directions, and the row order within each run as the cross-check.
  std::map<int, std::vector<int>> order;  // run -> target numbers in file order
  for (const Row& r : rows_) order[r.run].push_back(r.target);
  const auto direction_of = [this](int run) {
    if (options_.runs == RtlRuns::kForward) return Direction::kUp;
    if (options_.runs == RtlRuns::kReverse) return Direction::kDown;
    return run % 2 == 1 ? Direction::kUp : Direction::kDown;
  };
  std::vector<int> up_listed_down, down_listed_up;
  for (const auto& [run, targets] : order) {
    bool ascending = targets.size() > 1, descending = targets.size() > 1;
    for (std::size_t k = 1; k < targets.size(); ++k) {
      ascending = ascending && targets[k] > targets[k - 1];
      descending = descending && targets[k] < targets[k - 1];
    }
    if (direction_of(run) == Direction::kUp && descending) up_listed_down.push_back(run);
    if (direction_of(run) == Direction::kDown && ascending) down_listed_up.push_back(run);
  }
  if (!up_listed_down.empty()) {
    Warn(test_.deviations_line, RunsText(up_listed_down) +
                                    " (read as ↑) list their targets from the last down, as a "
                                    "reverse run is travelled; check the direction of each run");
  }
  if (!down_listed_up.empty()) {
    Warn(test_.deviations_line,
         RunsText(down_listed_up) +
             " (read as ↓ by run parity) list their targets in ascending order, so the row order "
             "does not confirm the direction; if the test was unidirectional, read it with every "
             "run forward (--rtl-runs forward)");
  }

  metrology::PositioningData& d = test_.readings;
  d.source = source_;
  d.kind = metrology::AxisKind::kLinear;
  d.column = "DEVIATIONS";
  d.column_scale = units_.um_per_deviation;
  d.read_in_inches = options_.units == RtlUnits::kIn;
  for (const Row& r : rows_) {
    metrology::PositioningReading reading;
    reading.target = test_.targets_mm[static_cast<std::size_t>(r.target - 1)];
    reading.direction = direction_of(r.run);
    reading.run = options_.runs == RtlRuns::kAlternate ? (r.run + 1) / 2 : r.run;
    reading.deviation = options_.negate ? -r.deviation : r.deviation;
    reading.line = r.line;
    d.readings.push_back(reading);
  }
  test_.run_count = *run_count_;

  for (const Text& t : user_text_) {
    const std::string key = KeyOf(t.key);
    const std::string name = key == "machine" ? "machine"
                             : key == "axis"  ? "axis"
                             : key == "date"  ? "date"
                             : key == "by"    ? "operator"
                                              : Lower(t.key);
    AddCondition(name, t.value, t.line);
  }
  test_.conditions.entries.emplace_back("instrument", "Renishaw laser (.rtl file)");
  if (section_line("environment") == 0) {
    Warn(last_line,
         "no ENVIRONMENT:: section: the test conditions give no air or material "
         "temperature");
  }
  VOLCOMP_TRY(ConvertEnvironment());
  AddEnvironmentConditions();
  return Outcome::Ok();
}

Expected<RtlTest> Reader::Read(const std::string& text) {
  const std::vector<Line> lines = SplitLines(text);
  std::size_t last_line = 1;
  for (const Line& line : lines) {
    if (line.text.empty()) continue;
    last_line = line.number;
    if (const auto name = SectionName(line.text)) {
      VOLCOMP_TRY(Section(line, *name));
      continue;
    }
    if (section_.empty()) {
      return At(line.number, Quoted(line.text) +
                                 " before the first section: a Renishaw .rtl file starts with "
                                 "HEADER:: (a section line NAME::)");
    }
    VOLCOMP_TRY(Entry(line));
  }
  VOLCOMP_TRY(Finish(last_line));
  return std::move(test_);
}

}  // namespace

const char* RtlUnitsName(RtlUnits units) { return units == RtlUnits::kIn ? "in" : "mm"; }

bool LooksLikeRtl(const std::string& text) {
  std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = Trim(text.substr(start, end - start));
    if (!line.empty()) return SectionName(line).has_value();
    start = end + 1;
  }
  return false;
}

Expected<RtlTest> ParseRtl(const std::string& text,
                           const std::string& source,
                           const RtlOptions& options) {
  Reader reader(source, options);
  return reader.Read(text);
}

}  // namespace volcomp::datasets
