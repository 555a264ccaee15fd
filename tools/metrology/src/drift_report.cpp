// Text, JSON, SVG and HTML output of a thermal drift test.
#include "volcomp/metrology/drift_report.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "json_fields.hpp"
#include "volcomp/metrology/report_files.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/xy_chart.hpp"

namespace volcomp::metrology {
namespace {

using report::FormatFixed;
using report::FormatNumber;
using report::FormatSigned;
using tools::JsonValue;

const char* const kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                               "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

JsonValue ComponentsJson(const std::optional<DriftComponents>& c) {
  if (!c) return JsonValue();
  JsonValue j = JsonValue::Object();
  j.Set("time_s", c->time_s);
  j.Set("offset_um", c->offset_um);
  j.Set("slope_um_per_m", c->slope_um_per_m);
  return j;
}

JsonValue Numbers(const std::vector<double>& v) {
  JsonValue a = JsonValue::Array();
  for (double x : v) a.Push(x);
  return a;
}

std::string Hours(double seconds) { return FormatFixed(seconds / 3600.0, 2) + " h"; }

void WriteComponentsText(std::ostream& out, const JsonValue& axis) {
  const JsonValue& end = json::At(axis, "final");
  if (end.is_null()) {
    out << "  offset and slope: none (the points' readings do not overlap in time)\n";
    return;
  }
  const JsonValue& mo = json::At(axis, "max_offset");
  const JsonValue& ms = json::At(axis, "max_slope");
  out << "  offset at " << FormatNumber(json::Number(axis, "mean_position_mm"))
      << " mm: " << FormatSigned(json::Number(end, "offset_um"), 2) << " µm at "
      << Hours(json::Number(end, "time_s")) << ", largest "
      << FormatSigned(json::Number(mo, "offset_um"), 2) << " µm at "
      << Hours(json::Number(mo, "time_s")) << "\n";
  out << "  slope: " << FormatSigned(json::Number(end, "slope_um_per_m"), 2) << " µm/m at "
      << Hours(json::Number(end, "time_s")) << ", largest "
      << FormatSigned(json::Number(ms, "slope_um_per_m"), 2) << " µm/m at "
      << Hours(json::Number(ms, "time_s")) << "\n";
}

report::XyChart DriftChart(const DriftEvaluation& ev) {
  report::XyChart c;
  c.title = "Drift of each point (reading − its first reading)";
  c.x_label = "time, h";
  c.y_label = "drift, µm";
  std::size_t k = 0;
  for (const DriftAxisResult& a : ev.axes) {
    for (const DriftPointResult& p : a.points) {
      report::XySeries s;
      s.label = std::string(1, a.name) + " " + FormatNumber(p.position_mm) + " mm";
      for (std::size_t i = 0; i < p.time_s.size(); ++i) {
        s.x.push_back(p.time_s[i] / 3600.0);
        s.y.push_back(p.drift_um[i]);
      }
      s.color = kColors[k % 8];
      s.marker = k % 2 ? report::Marker::kSquare : report::Marker::kCircle;
      c.series.push_back(s);
      ++k;
    }
  }
  return c;
}

// The channels' log in time order, per channel (x in h).
report::XyChart TemperatureChartOf(const DriftEvaluation& ev) {
  std::vector<std::vector<double>> xs(ev.channels.size()), ys(ev.channels.size());
  std::vector<std::size_t> order(ev.log_time_s.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return ev.log_time_s[a] < ev.log_time_s[b];
  });
  for (std::size_t i : order) {
    for (std::size_t j = 0; j < ev.channels.size(); ++j) {
      xs[j].push_back(ev.log_time_s[i] / 3600.0);
      ys[j].push_back(ev.log_temperature_C[i][j]);
    }
  }
  report::XyChart c;
  c.title = "Temperature channels";
  c.x_label = "time, h";
  c.y_label = "temperature, °C";
  c.include_zero = false;
  for (std::size_t j = 0; j < ev.channels.size(); ++j) {
    report::XySeries s;
    s.label = std::to_string(j) + " " + ev.channels[j].name;
    s.x = xs[j];
    s.y = ys[j];
    s.color = kColors[j % 8];
    s.marker = report::Marker::kNone;
    c.series.push_back(s);
  }
  return c;
}

}  // namespace

JsonValue DriftJson(const DriftEvaluation& ev) {
  JsonValue j = JsonValue::Object();
  j.Set("command", "evaluate thermal");
  j.Set("standard", "ISO 230-3:2020 drift test");
  j.Set("source", ev.source);
  j.Set("conditions", ConditionsJson(ev.conditions));
  j.Set("start_s", ev.start_s);
  j.Set("end_s", ev.end_s);
  j.Set("duration_h", (ev.end_s - ev.start_s) / 3600.0);
  j.Set("readings", uint64_t{ev.readings});
  j.Set("rate_window_s", kDriftRateWindow_s);
  JsonValue axes = JsonValue::Array();
  for (const DriftAxisResult& a : ev.axes) {
    JsonValue o = JsonValue::Object();
    o.Set("axis", std::string(1, a.name));
    o.Set("mean_position_mm", a.mean_position_mm);
    JsonValue points = JsonValue::Array();
    for (const DriftPointResult& p : a.points) {
      JsonValue q = JsonValue::Object();
      q.Set("position_mm", p.position_mm);
      q.Set("readings", uint64_t{p.time_s.size()});
      q.Set("max_drift_um", p.max_drift_um);
      q.Set("max_drift_time_s", p.max_drift_time_s);
      q.Set("range_um", p.range_um);
      q.Set("final_drift_um", p.final_drift_um);
      q.Set("rate_um_per_h", p.rate_um_per_h);
      q.Set("rate_from_s", p.rate_from_s);
      q.Set("rate_readings", uint64_t{p.rate_readings});
      q.Set("time_s", Numbers(p.time_s));
      q.Set("drift_um", Numbers(p.drift_um));
      points.Push(std::move(q));
    }
    o.Set("points", std::move(points));
    o.Set("final", ComponentsJson(a.final_components));
    o.Set("max_offset", ComponentsJson(a.max_offset));
    o.Set("max_slope", ComponentsJson(a.max_slope));
    axes.Push(std::move(o));
  }
  j.Set("axes", std::move(axes));
  JsonValue channels = JsonValue::Array();
  for (const ChannelRise& c : ev.channels) {
    JsonValue o = JsonValue::Object();
    o.Set("channel", uint64_t{c.number});
    o.Set("name", c.name);
    o.Set("first_C", c.first_C);
    o.Set("last_C", c.last_C);
    o.Set("min_C", c.min_C);
    o.Set("max_C", c.max_C);
    o.Set("rise_K", c.rise_K);
    channels.Push(std::move(o));
  }
  j.Set("channels", std::move(channels));
  JsonValue warnings = JsonValue::Array();
  for (const auto& w : ev.warnings) warnings.Push(w);
  j.Set("warnings", std::move(warnings));
  return j;
}

void WriteDriftText(std::ostream& out, const JsonValue& ev) {
  out << "ISO 230-3 thermal drift test: " << json::Text(ev, "source") << "\n";
  const JsonValue& conditions = json::At(ev, "conditions");
  if (!conditions.object.empty()) out << "conditions: " << ConditionsText(conditions) << "\n";
  out << json::Integer(ev, "readings") << " readings over "
      << FormatFixed(json::Number(ev, "duration_h"), 2) << " h; drift = reading − the point's "
      << "first reading, rate = least-squares slope over the last "
      << FormatNumber(json::Number(ev, "rate_window_s") / 3600.0) << " h\n";
  for (const JsonValue& a : json::At(ev, "axes").array) {
    out << "axis " << json::Text(a, "axis") << "\n";
    out << "  point mm      max drift µm  at h    range µm  final µm  rate µm/h\n";
    for (const JsonValue& p : json::At(a, "points").array) {
      char line[200];
      std::snprintf(line, sizeof line, "  %-12s %12s %6s %10s %9s %10s\n",
                    FormatNumber(json::Number(p, "position_mm")).c_str(),
                    FormatSigned(json::Number(p, "max_drift_um"), 2).c_str(),
                    FormatFixed(json::Number(p, "max_drift_time_s") / 3600.0, 2).c_str(),
                    FormatFixed(json::Number(p, "range_um"), 2).c_str(),
                    FormatSigned(json::Number(p, "final_drift_um"), 2).c_str(),
                    FormatSigned(json::Number(p, "rate_um_per_h"), 2).c_str());
      out << line;
    }
    WriteComponentsText(out, a);
  }
  const JsonValue& channels = json::At(ev, "channels");
  if (!channels.array.empty()) out << "temperatures (°C)\n";
  for (const JsonValue& c : channels.array) {
    char line[200];
    std::snprintf(line, sizeof line, "  %lld %-12s %7s → %7s  (min %s, max %s)  rise %s K\n",
                  static_cast<long long>(json::Integer(c, "channel")),
                  json::Text(c, "name").c_str(), FormatFixed(json::Number(c, "first_C"), 2).c_str(),
                  FormatFixed(json::Number(c, "last_C"), 2).c_str(),
                  FormatFixed(json::Number(c, "min_C"), 2).c_str(),
                  FormatFixed(json::Number(c, "max_C"), 2).c_str(),
                  FormatSigned(json::Number(c, "rise_K"), 2).c_str());
    out << line;
  }
}

std::string DriftSvg(const DriftEvaluation& ev) {
  const double w = 760, h = 360;
  std::string drift = DriftChart(ev).Render(w, h);
  std::string temps = TemperatureChartOf(ev).Render(w, h);
  drift.insert(4, " x=\"0\" y=\"0\"");
  temps.insert(4, " x=\"0\" y=\"" + FormatNumber(h) + "\"");
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + FormatNumber(w) + "\" height=\"" +
         FormatNumber(2 * h) + "\">\n" + drift + temps + "</svg>\n";
}

report::HtmlPage DriftPage(const DriftEvaluation& ev) {
  report::HtmlPage page("ISO 230-3 thermal drift test");
  page.Paragraph("Source: " + ev.source + ". " + std::to_string(ev.readings) + " readings over " +
                 Hours(ev.end_s - ev.start_s) +
                 ". Drift = reading − the point's first reading (µm); rate = least-squares slope "
                 "of the drift over the point's last hour of readings.");
  AddConditionsSection(&page, ev.conditions);
  page.Heading(2, "Points");
  std::vector<std::vector<std::string>> rows;
  for (const DriftAxisResult& a : ev.axes) {
    for (const DriftPointResult& p : a.points) {
      rows.push_back({std::string(1, a.name), FormatNumber(p.position_mm),
                      FormatSigned(p.max_drift_um, 2), Hours(p.max_drift_time_s),
                      FormatFixed(p.range_um, 2), FormatSigned(p.final_drift_um, 2),
                      FormatSigned(p.rate_um_per_h, 2)});
    }
  }
  page.Table({"axis", "position mm", "max drift µm", "at", "range µm", "final µm", "rate µm/h"},
             rows);
  page.Heading(2, "Offset and slope per axis");
  rows.clear();
  for (const DriftAxisResult& a : ev.axes) {
    if (!a.final_components) continue;
    rows.push_back(
        {std::string(1, a.name), FormatNumber(a.mean_position_mm),
         FormatSigned(a.final_components->offset_um, 2),
         FormatSigned(a.final_components->slope_um_per_m, 2),
         FormatSigned(a.max_offset->offset_um, 2) + " at " + Hours(a.max_offset->time_s),
         FormatSigned(a.max_slope->slope_um_per_m, 2) + " at " + Hours(a.max_slope->time_s)});
  }
  page.Table({"axis", "mean position mm", "final offset µm", "final slope µm/m",
              "largest offset µm", "largest slope µm/m"},
             rows);
  if (!ev.channels.empty()) {
    page.Heading(2, "Temperatures");
    rows.clear();
    for (const ChannelRise& c : ev.channels) {
      rows.push_back({std::to_string(c.number), c.name, FormatFixed(c.first_C, 2),
                      FormatFixed(c.last_C, 2), FormatFixed(c.min_C, 2), FormatFixed(c.max_C, 2),
                      FormatSigned(c.rise_K, 2)});
    }
    page.Table({"channel", "name", "first °C", "last °C", "min °C", "max °C", "rise K"}, rows);
  }
  page.Figure(DriftChart(ev).Render(760, 360), "Drift of every point against time.");
  if (!ev.channels.empty()) {
    page.Figure(TemperatureChartOf(ev).Render(760, 360), "Temperature channels against time.");
  }
  if (!ev.warnings.empty()) {
    page.Heading(3, "Warnings");
    page.List(ev.warnings);
  }
  return page;
}

std::string DriftReportName(const DriftEvaluation& ev) {
  return "thermal_" + SourceStem(ev.source);
}

}  // namespace volcomp::metrology
