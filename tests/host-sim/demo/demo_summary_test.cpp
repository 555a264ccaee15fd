// The demo's summary and DIR/summary.json (demo_summary.cpp, demo_report.cpp) and the worn
// machine's header (demo_sources.cpp): reduced runs (few targets, 2 approaches, a coarse lattice;
// a few seconds each), the printed text read back line by line here and compared with the JSON
// file read back with ParseJson. One test case per demo run (ctest runs each in its own process).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "volcomp/sim/demo.hpp"
#include "volcomp/tools/file_io.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::sim {
namespace {

using tools::JsonValue;

DemoOptions Reduced(bool worn) {
  DemoOptions o;
  if (worn) UseWornMachine(&o);
  o.random_points = 10;
  o.gost_targets = 4;
  o.gost_runs = 2;
  o.diagonal_targets = 4;
  o.diagonal_runs = 2;
  o.parametric_step_mm = 40;
  o.benchmark_moves = 0;
  o.axis_run_pitch_mm = 80;
  o.lattice_spacing_mm = 100;
  o.drift_readings = 2;
  o.circle_radius_mm = 20;  // shorter circular tests (the worn run), the same figures
  o.circle_feed_mm_min = 3000;
  return o;
}

std::string TempDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("volcomp_sim_summary_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

// Writes the report of `r` into `dir`, prints its summary into *text and reads summary.json back.
void ReportAndRead(const DemoResult& r,
                   const std::string& dir,
                   std::ostringstream* text,
                   std::optional<JsonValue>* json) {
  ASSERT_TRUE(WriteDemoReport(r, dir).ok());
  {
    SCOPED_TRACE("the final table's map on the page, its figures in table_map.json");
    const Expected<std::string> page = tools::ReadTextFile(dir + "/index.html");
    ASSERT_TRUE(page.ok()) << page.error().message;
    EXPECT_NE(page->find("<h3>Correction map: table.vct</h3>"), std::string::npos);
    EXPECT_NE(page->find("<h4>GRID3, plane XY</h4>"), std::string::npos);
    const Expected<std::string> map = tools::ReadTextFile(dir + "/table_map.json");
    ASSERT_TRUE(map.ok()) << map.error().message;
    const Expected<JsonValue> parsed = tools::ParseJson(*map, "table_map.json");
    ASSERT_TRUE(parsed.ok()) << parsed.error().message;
    const size_t tables = r.table.axis_tables.size();
    EXPECT_EQ(parsed->get("axis1d")->array.size(), tables);
    for (const JsonValue& t : parsed->get("axis1d")->array) {
      EXPECT_NE(page->find("<h4>AXIS1D " + t.get("axis")->string + "</h4>"), std::string::npos);
    }
  }
  PrintSummary(r, *text);
  const Expected<std::string> file = tools::ReadTextFile(dir + "/summary.json");
  ASSERT_TRUE(file.ok()) << file.error().message;
  Expected<JsonValue> parsed = tools::ParseJson(*file, "summary.json");
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  *json = std::move(*parsed);
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string Fixed(double v, int decimals) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

const JsonValue& Member(const JsonValue& v, const std::string& key) {
  static const JsonValue kNull;
  const JsonValue* m = v.get(key);
  return m != nullptr ? *m : kNull;
}

void Flatten(const JsonValue& v, std::vector<double>* numbers, std::vector<std::string>* strings) {
  if (v.is_number()) numbers->push_back(v.number);
  if (v.is_string()) strings->push_back(v.string);
  for (const JsonValue& e : v.array) Flatten(e, numbers, strings);
  for (const auto& [key, e] : v.object) Flatten(e, numbers, strings);
}

// Every number the summary text prints (outside the names and labels the JSON holds as strings,
// and a few words of the layout) is a number of the JSON, printed at the text's precision.
void CheckEveryPrintedNumberIsInTheJson(const std::string& text, const JsonValue& json) {
  std::vector<double> numbers;
  std::vector<std::string> strings;
  Flatten(json, &numbers, &strings);
  strings.erase(std::remove_if(strings.begin(), strings.end(),
                               [](const std::string& s) { return s.size() < 4; }),
                strings.end());
  std::sort(strings.begin(), strings.end(),
            [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
  // The layout's own words (standards, formula terms), not figures.
  const std::vector<std::string> words = {"ISO 230-6", "GOST 27843", "3 sigma", "(3-D)", "1 step",
                                          "p99.9",     "p50",        "p90",     "p99"};
  const std::regex number(R"(-?\d+(\.\d+)?)");
  int checked = 0;
  for (std::string line : Lines(text)) {
    if (line.rfind("all checks passed", 0) == 0) continue;  // the checks' fixed wording
    for (const std::string& s : strings) {
      for (size_t at; (at = line.find(s)) != std::string::npos;) line.replace(at, s.size(), " ");
    }
    for (const std::string& w : words) {
      for (size_t at; (at = line.find(w)) != std::string::npos;) line.replace(at, w.size(), " ");
    }
    for (std::sregex_iterator it(line.begin(), line.end(), number), end; it != end; ++it) {
      const std::string token = it->str();
      const size_t dot = token.find('.');
      const int decimals = dot == std::string::npos ? 0 : static_cast<int>(token.size() - dot - 1);
      const bool found = std::any_of(numbers.begin(), numbers.end(), [&](double n) {
        return Fixed(n, decimals) == token || (decimals == 0 && Fixed(n, 0) == token);
      });
      EXPECT_TRUE(found) << token << " in \"" << line << "\" is not in summary.json";
      ++checked;
    }
  }
  EXPECT_GT(checked, 60);
}

// The figure table: the header names the JSON's phases, each row its name, values and reduction.
void CheckFigureRows(const std::string& text, const JsonValue& json) {
  const std::vector<std::string> lines = Lines(text);
  const auto header = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.find("reduction") != std::string::npos;
  });
  ASSERT_NE(header, lines.end());
  std::istringstream h(*header);
  std::vector<std::string> labels;
  for (std::string w; h >> w;) labels.push_back(w);
  std::string phases;
  for (const JsonValue& p : Member(json, "phases").array) phases += p.string + " ";
  std::string printed;
  for (size_t i = 0; i + 1 < labels.size(); ++i) printed += labels[i] + " ";
  EXPECT_EQ(printed, phases);

  const std::vector<JsonValue>& rows = Member(json, "figures").array;
  // 14 rows, and on the worn machine G(b) and H of the three circular tests.
  ASSERT_EQ(rows.size(), Member(Member(json, "run"), "profile").string == "worn" ? 20u : 14u);
  for (size_t i = 0; i < rows.size(); ++i) {
    const JsonValue& row = rows[i];
    const std::string& line = *(header + 1 + static_cast<long>(i));
    const std::string& name = Member(row, "name").string;
    ASSERT_EQ(line.rfind(name, 0), 0u) << line;
    std::istringstream rest(line.substr(name.size()));
    for (const JsonValue& v : Member(row, "values").array) {
      std::string value, unit;
      rest >> value >> unit;
      EXPECT_EQ(value, Fixed(v.number, 3)) << name;
      EXPECT_EQ(unit, Member(row, "unit").string) << name;
    }
    std::string last;
    rest >> last;
    const JsonValue& reduction = Member(row, "reduction_pct");
    if (reduction.is_number()) {
      EXPECT_EQ(last, Fixed(reduction.number, 2)) << name;
      const std::vector<JsonValue>& v = Member(row, "values").array;
      EXPECT_NEAR(reduction.number, 100 * (1 - v.back().number / v.front().number), 1e-9) << name;
    } else {
      EXPECT_EQ(last, "(" + Member(row, "note").string + ")") << name;
    }
  }
}

void CheckStepsAndRun(const DemoResult& r, const JsonValue& json) {
  const JsonValue& run = Member(json, "run");
  EXPECT_EQ(Member(run, "machine").string, r.machine_name);
  EXPECT_EQ(Member(run, "seed").integer, static_cast<int64_t>(r.options.seed));
  EXPECT_EQ(Member(run, "points").integer, r.options.random_points);
  const std::vector<JsonValue>& tables = Member(run, "tables").array;
  ASSERT_EQ(tables.size(), r.earlier_tables.size() + 1);
  char crc[16];
  std::snprintf(crc, sizeof crc, "0x%08X", r.table.crc32);
  EXPECT_EQ(Member(tables.back(), "crc32").string, crc);
  EXPECT_EQ(Member(tables.back(), "active_crc32").string, crc);
  const JsonValue& steps = Member(json, "steps");
  EXPECT_EQ(Member(steps, "input_steps").integer, static_cast<int64_t>(r.audit.input_steps));
  EXPECT_EQ(Member(steps, "lost_steps").integer, static_cast<int64_t>(r.audit.lost_steps));
  EXPECT_EQ(Member(Member(json, "latency"), "max_ticks").number, r.latency.max_ticks);
  EXPECT_EQ(Member(json, "passed").boolean, r.failures.empty());
}

// A worn run with lost motion and sag other than the defaults: the header prints the machine's.
TEST(SimDemoSummary, WornRunWritesEveryPrintedFigureAndNamesEverySource) {
  DemoOptions o = Reduced(true);
  o.wear.lost_motion_um = {12, 17, 6};
  o.wear.sag_um = 10;
  const std::string dir = TempDir("worn");
  std::ostringstream log;
  const Expected<DemoResult> run = RunDemo(o, log);
  ASSERT_TRUE(run.ok()) << run.error().message;
  const DemoResult& r = run.value();
  std::ostringstream text;
  std::optional<JsonValue> json;
  ASSERT_NO_FATAL_FAILURE(ReportAndRead(r, dir, &text, &json));
  {
    SCOPED_TRACE("every printed number");
    CheckEveryPrintedNumberIsInTheJson(text.str(), *json);
  }
  {
    SCOPED_TRACE("the figure rows");
    CheckFigureRows(text.str(), *json);
  }
  {
    SCOPED_TRACE("the goals");
    const std::vector<JsonValue>& goals = Member(*json, "goals").array;
    ASSERT_EQ(goals.size(), r.goals.size());
    // 6 of the worn profile, G(b) and H of 3 circular tests, 8 of the thermal step.
    ASSERT_EQ(goals.size(), 20u);
    const std::vector<std::string> lines = Lines(text.str());
    for (const JsonValue& g : goals) {
      const double value = Member(g, "value").number, limit = Member(g, "limit").number;
      const bool at_least = Member(g, "at_least").boolean;
      EXPECT_EQ(Member(g, "holds").boolean, at_least ? value >= limit : value <= limit);
      const std::string& unit = Member(g, "unit").string;
      EXPECT_TRUE(at_least ? unit == "%" : (unit == "um" || unit == "um/s" || unit == "s")) << unit;
      const std::string& name = Member(g, "name").string;
      const auto line = std::find_if(lines.begin(), lines.end(),
                                     [&](const std::string& l) { return l.rfind(name, 0) == 0; });
      ASSERT_NE(line, lines.end()) << name;
      std::istringstream rest(line->substr(name.size()));
      std::string v, u1, op, l, u2, verdict;
      rest >> v >> u1 >> op >> l >> u2 >> verdict;
      EXPECT_EQ(v, Fixed(value, 2));
      EXPECT_EQ(l, Fixed(limit, 2));
      EXPECT_EQ(u1, Member(g, "unit").string);
      EXPECT_EQ(op, at_least ? ">=" : "<=");
      const bool asserted = Member(g, "asserted").boolean;
      EXPECT_EQ(verdict, Member(g, "holds").boolean ? "holds" : asserted ? "FAILS" : "misses");
      EXPECT_TRUE(asserted) << name;
    }
    // The circular tests' figures: their goals are the rows' reductions, and the
    // "circular" section holds each plane's every figure per phase.
    const JsonValue& circular = Member(*json, "circular");
    ASSERT_EQ(Member(circular, "planes").array.size(), 3u);
    for (size_t k = 0; k < 3; ++k) {
      const JsonValue& plane = Member(circular, "planes").array[k];
      const std::vector<JsonValue>& by_phase = Member(plane, "phases").array;
      ASSERT_EQ(by_phase.size(), 4u);
      const std::string key = Member(plane, "plane").string;
      const JsonValue& gb = goals[6 + 2 * k];
      EXPECT_EQ(Member(gb, "name").string.rfind("ISO 230-4 " + key + " G(b)", 0), 0u);
      const double before = Member(by_phase.front(), "G_b_um").number;
      const double after = Member(by_phase.back(), "G_b_um").number;
      EXPECT_NEAR(Member(gb, "value").number, 100 * (1 - after / before), 1e-9);
      EXPECT_EQ(Member(by_phase.front(), "G_b_um").number, r.before.circular[k].result.G_b_um);
      EXPECT_EQ(Member(by_phase.back(), "H_um").number, r.after.circular[k].result.H_um);
    }
    const JsonValue& b = Member(*json, "error_budget");
    const double s0 = b.get("sigma_um")->array[0].number, s1 = b.get("sigma_um")->array[1].number,
                 s2 = b.get("sigma_um")->array[2].number;
    EXPECT_NEAR(Member(b, "three_sigma_um").number, 3 * std::sqrt(s0 * s0 + s1 * s1 + s2 * s2),
                1e-9);
    EXPECT_NEAR(Member(b, "goal_limit_um").number,
                Member(b, "limit_um").number + Member(b, "short_period_norm_um").number, 1e-9);
    EXPECT_EQ(Member(b, "max_residual_within_limit").boolean,
              Member(b, "max_residual_um").number <= Member(b, "limit_um").number);
    EXPECT_EQ(Member(goals[5], "value").number, Member(b, "max_residual_um").number);
    EXPECT_EQ(Member(goals[5], "limit").number, Member(b, "goal_limit_um").number);
  }
  {
    SCOPED_TRACE("run, steps");
    CheckStepsAndRun(r, *json);
    EXPECT_EQ(Member(Member(*json, "run"), "profile").string, "worn");
  }
  {
    SCOPED_TRACE("the header names every error source with its size");
    const std::string header = log.str().substr(0, log.str().find("\n[1/"));
    for (const char* source :
         {"    geometry: 21 parameters", "    lost motion: ", "    scatter at rest: ",
          "    screw, short period ", "    thermal: ", "    sag: ", "    instruments: "}) {
      EXPECT_NE(header.find(source), std::string::npos) << source << "\n" << header;
    }
    const JsonValue& scatter = Member(Member(Member(*json, "run"), "error_sources"), "scatter");
    EXPECT_EQ(Member(scatter, "standstill_ms").number, o.wear.scatter_standstill_ms);
    EXPECT_NE(header.find("(at rest: no step for " +
                          Fixed(Member(scatter, "standstill_ms").number, 0) + " ms)"),
              std::string::npos)
        << header;
    std::smatch m;
    ASSERT_TRUE(
        std::regex_search(header, m, std::regex(R"(lost motion: X (\S+), Y (\S+), Z (\S+) um)")))
        << header;
    for (size_t a = 0; a < 3; ++a) {
      EXPECT_EQ(std::stod(m[a + 1].str()), o.wear.lost_motion_um[a]) << a;
    }
    ASSERT_TRUE(std::regex_search(header, m, std::regex(R"(sag: (\S+) um)"))) << header;
    EXPECT_EQ(std::stod(m[1].str()), o.wear.sag_um);
    ASSERT_TRUE(std::regex_search(
        header, m,
        std::regex(R"(screw, short period (\S+) mm: amplitude X (\S+), Y (\S+), Z (\S+) um)")));
    EXPECT_EQ(std::stod(m[1].str()), o.wear.screw_period_mm);
    for (size_t a = 0; a < 3; ++a) {
      EXPECT_EQ(std::stod(m[a + 2].str()), o.wear.screw_amplitude_um[a]) << a;
    }
    const JsonValue& sources = Member(Member(*json, "run"), "error_sources");
    const JsonValue& lost = Member(sources, "lost_motion");
    EXPECT_TRUE(Member(lost, "on").boolean);
    ASSERT_EQ(Member(lost, "um").array.size(), 3u);
    for (size_t a = 0; a < 3; ++a) {
      EXPECT_EQ(Member(lost, "um").array[a].number, o.wear.lost_motion_um[a]) << a;
    }
    EXPECT_EQ(Member(Member(sources, "sag"), "um").number, o.wear.sag_um);
  }
  std::filesystem::remove_all(dir);
}

// The ideal machine: no goals or budget in the summary, the same correspondence.
TEST(SimDemoSummary, IdealRunWritesEveryPrintedFigure) {
  const DemoOptions o = Reduced(false);
  const std::string dir = TempDir("ideal");
  std::ostringstream log;
  const Expected<DemoResult> run = RunDemo(o, log);
  ASSERT_TRUE(run.ok()) << run.error().message;
  const DemoResult& r = run.value();
  std::ostringstream text;
  std::optional<JsonValue> json;
  ASSERT_NO_FATAL_FAILURE(ReportAndRead(r, dir, &text, &json));
  CheckEveryPrintedNumberIsInTheJson(text.str(), *json);
  CheckFigureRows(text.str(), *json);
  CheckStepsAndRun(r, *json);
  EXPECT_EQ(json->get("goals"), nullptr);
  EXPECT_EQ(Member(Member(*json, "run"), "profile").string, "ideal");
  EXPECT_EQ(log.str().find("lost motion"), std::string::npos);  // the ideal header is unchanged
  // The rigid-body machine: every worn source off, the geometry there.
  const JsonValue& sources = Member(Member(*json, "run"), "error_sources");
  for (const char* source : {"lost_motion", "scatter", "screw", "thermal", "sag"}) {
    EXPECT_FALSE(Member(Member(sources, source), "on").boolean) << source;
  }
  EXPECT_EQ(Member(Member(sources, "geometry"), "axes").array.size(), 3u);
  EXPECT_EQ(Member(Member(Member(*json, "run"), "tables").array.at(0), "label").string, "21-param");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace volcomp::sim
