// `volcomp inspect IMAGE [--json] [--report DIR]`: what an image holds, validated by the
// firmware's parser; with --report, a picture of its correction (DIR/index.html).
#include <algorithm>
#include <cstdio>
#include <limits>
#include <ostream>

#include "commands.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/image/table_map.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::cli {
namespace {

struct Range {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  void Add(double v) {
    min = std::min(min, v);
    max = std::max(max, v);
  }
};

bool IsRotary(const table::AxisInfo& a) { return a.kind == table::AxisKind::kRotary; }

// Display unit of a correction and its factor from steps: µm (arcsec on a rotary axis).
std::pair<const char*, double> CorrectionUnit(const table::AxisInfo& a) {
  if (IsRotary(a)) return {"arcsec", a.resolution_e9 * 1e-9 * 3600.0};
  return {"um", a.resolution_e9 * 1e-9 * 1000.0};
}

// The THERMAL section's model in its own units (docs/table-image-format.md, "THERMAL").
JsonValue ThermalData(const table::TableView& v) {
  const thermal::ThermalModel m = table::ReadThermal(v.thermal);
  JsonValue t = JsonValue::Object();
  t.Set("slew_um_s", double{m.slew_um_s});
  t.Set("hold_ms", uint64_t{m.hold_ms});
  JsonValue& channels = t["channels"] = JsonValue::Array();
  for (uint8_t j = 0; j < thermal::kMaxChannels; ++j) {
    if (((m.channel_mask >> j) & 1u) == 0) continue;
    JsonValue c = JsonValue::Object();
    c.Set("channel", unsigned{j});
    c.Set("reference_C", m.reference_cC[j] / 100.0);
    c.Set("calibrated_low_C", m.calibrated_low_cC[j] / 100.0);
    c.Set("calibrated_high_C", m.calibrated_high_cC[j] / 100.0);
    channels.Push(std::move(c));
  }
  JsonValue& axes = t["axes"] = JsonValue::Array();
  for (uint8_t a = 0; a < m.axis_count; ++a) {
    const thermal::AxisModel& x = m.axis[a];
    JsonValue r = JsonValue::Object();
    r.Set("axis", std::string(1, v.axes[a].name));
    r.Set("p0_mm", double{x.p0_mm});
    r.Set("reach_mm", double{x.reach_mm});
    JsonValue offset = JsonValue::Array(), slope = JsonValue::Array();
    for (uint8_t j = 0; j < thermal::kMaxChannels; ++j) {
      if (((m.channel_mask >> j) & 1u) == 0) continue;
      offset.Push(JsonValue(double{x.offset_um_per_K[j]}));
      slope.Push(JsonValue(double{x.slope_um_per_K_m[j]}));
    }
    r.Set("offset_um_per_K", std::move(offset));
    r.Set("slope_um_per_K_m", std::move(slope));
    axes.Push(std::move(r));
  }
  return t;
}

// Everything `inspect` reports, from the validated view.
JsonValue InspectData(const std::string& file, const table::TableView& v) {
  JsonValue d = JsonValue::Object();
  d.Set("file", file);
  d.Set("image_size", uint64_t{v.image_size});
  d.Set("crc32", tools::Hex32(v.crc32));
  d.Set("table_id", uint64_t{v.table_id});
  d.Set("format_version",
        std::to_string(table::kVersionMajor) + "." + std::to_string(v.version_minor));
  JsonValue& axes = d["axes"] = JsonValue::Array();
  for (uint8_t i = 0; i < v.axis_count; ++i) {
    const auto& a = v.axes[i];
    JsonValue x = JsonValue::Object();
    x.Set("name", std::string(1, a.name));
    x.Set("kind", IsRotary(a) ? "rotary" : "linear");
    x.Set("resolution_e9", uint64_t{a.resolution_e9});
    x.Set("units_per_step", a.resolution_e9 * 1e-9);
    axes.Push(std::move(x));
  }
  if (v.grid.present) {
    std::vector<Range> range(3);
    const uint64_t n = uint64_t{v.grid.dim[0].nodes} * v.grid.dim[1].nodes * v.grid.dim[2].nodes;
    for (uint64_t i = 0; i < n * 3; ++i) {
      range[i % 3].Add(table::ElementSteps(v.grid.data, v.grid.type, v.grid.frac_bits,
                                           static_cast<uint32_t>(i)));
    }
    JsonValue& g = d["grid3"] = JsonValue::Object();
    g.Set("element", table::ElementTypeName(v.grid.type));
    g.Set("frac_bits", unsigned{v.grid.frac_bits});
    JsonValue& dims = g["dimensions"] = JsonValue::Array();
    for (int k = 0; k < 3; ++k) {
      const auto& a = v.axes[v.grid.axis[k]];
      const auto& dim = v.grid.dim[k];
      const double per = a.resolution_e9 * 1e-9;
      const auto unit = CorrectionUnit(a);
      JsonValue x = JsonValue::Object();
      x.Set("axis", std::string(1, a.name));
      x.Set("nodes", uint64_t{dim.nodes});
      x.Set("origin_steps", int64_t{dim.origin_steps});
      x.Set("spacing_steps", uint64_t{dim.spacing_steps});
      x.Set("correction_min_steps", range[k].min);
      x.Set("correction_max_steps", range[k].max);
      x.Set("position_unit", IsRotary(a) ? "deg" : "mm");
      x.Set("from", dim.origin_steps * per);
      x.Set("to", (dim.origin_steps + double(dim.nodes - 1) * dim.spacing_steps) * per);
      x.Set("spacing", dim.spacing_steps * per);
      x.Set("correction_unit", unit.first);
      x.Set("correction_min", range[k].min * unit.second);
      x.Set("correction_max", range[k].max * unit.second);
      dims.Push(std::move(x));
    }
  }
  JsonValue& tables = d["axis1d"] = JsonValue::Array();
  for (uint8_t i = 0; i < v.axis1d_count; ++i) {
    const auto& t = v.axis1d[i];
    JsonValue x = JsonValue::Object();
    x.Set("axis", std::string(1, v.axes[t.axis].name));
    x.Set("element", table::ElementTypeName(t.type));
    x.Set("frac_bits", unsigned{t.frac_bits});
    x.Set("nodes", uint64_t{t.dim.nodes});
    x.Set("origin_steps", int64_t{t.dim.origin_steps});
    x.Set("spacing_steps", uint64_t{t.dim.spacing_steps});
    x.Set("has_reverse", t.reverse != nullptr);
    x.Set("wrap_period_steps", uint64_t{t.period_steps});
    x.Set("backlash_steps", t.backlash_q8 / 256.0);
    tables.Push(std::move(x));
  }
  if (v.thermal != nullptr) d["thermal"] = ThermalData(v);
  d.Set("info", v.info ? std::string(v.info, v.info_size) : std::string());
  return d;
}

void InspectText(const JsonValue& d, std::ostream& out) {
  out << d.get("file")->string << ": valid volcomp table image, format "
      << d.get("format_version")->string << ", " << d.get("image_size")->integer
      << " bytes, CRC-32 " << d.get("crc32")->string << ", table id " << d.get("table_id")->integer
      << "\n";
  out << "axes:";
  for (const JsonValue& a : d.get("axes")->array) {
    const bool rotary = a.get("kind")->string == "rotary";
    out << " " << a.get("name")->string << " (" << (rotary ? "rotary, " : "")
        << a.get("units_per_step")->number << (rotary ? " deg" : " mm") << "/step)";
  }
  out << "\n";
  if (const JsonValue* g = d.get("grid3")) {
    const auto& dims = g->get("dimensions")->array;
    out << "GRID3: " << g->get("element")->string << " Q." << g->get("frac_bits")->integer << ", "
        << dims[0].get("nodes")->integer << " x " << dims[1].get("nodes")->integer << " x "
        << dims[2].get("nodes")->integer << " nodes\n";
    for (const JsonValue& x : dims) {
      char line[256];
      std::snprintf(
          line, sizeof line,
          "  %s: from %.6g to %.6g %s every %.6g (%d steps), correction %.4g .. %.4g %s\n",
          x.get("axis")->string.c_str(), x.get("from")->number, x.get("to")->number,
          x.get("position_unit")->string.c_str(), x.get("spacing")->number,
          static_cast<int>(x.get("spacing_steps")->integer), x.get("correction_min")->number,
          x.get("correction_max")->number, x.get("correction_unit")->string.c_str());
      out << line;
    }
  }
  for (const JsonValue& t : d.get("axis1d")->array) {
    const int64_t period = t.get("wrap_period_steps")->integer;
    out << "AXIS1D " << t.get("axis")->string << ": " << t.get("element")->string << " Q."
        << t.get("frac_bits")->integer << ", " << t.get("nodes")->integer << " nodes from step "
        << t.get("origin_steps")->integer << " every " << t.get("spacing_steps")->integer
        << " steps" << (t.get("has_reverse")->boolean ? ", forward+reverse" : ", one direction")
        << ", backlash " << t.get("backlash_steps")->number << " steps"
        << (period != 0 ? ", wraps every " + std::to_string(period) + " steps" : std::string())
        << "\n";
  }
  if (const JsonValue* t = d.get("thermal")) {
    out << "THERMAL: slew " << t->get("slew_um_s")->number << " um/s, hold "
        << static_cast<double>(t->get("hold_ms")->integer) / 1000.0 << " s after a channel fault\n";
    for (const JsonValue& c : t->get("channels")->array) {
      out << "  channel " << c.get("channel")->integer << ": reference "
          << c.get("reference_C")->number << " C, calibrated " << c.get("calibrated_low_C")->number
          << " .. " << c.get("calibrated_high_C")->number << " C\n";
    }
    for (const JsonValue& a : t->get("axes")->array) {
      out << "  " << a.get("axis")->string << ": p0 " << a.get("p0_mm")->number << " mm, reach "
          << a.get("reach_mm")->number << " mm; per channel offset um/K";
      for (const JsonValue& k : a.get("offset_um_per_K")->array) out << " " << k.number;
      out << ", slope um/(K m)";
      for (const JsonValue& k : a.get("slope_um_per_K_m")->array) out << " " << k.number;
      out << "\n";
    }
  }
  const std::string& info = d.get("info")->string;
  if (!info.empty()) {
    out << "info:\n";
    std::size_t start = 0;
    while (start < info.size()) {
      const std::size_t end = std::min(info.find('\n', start), info.size());
      out << "  " << info.substr(start, end - start) << "\n";
      start = end + 1;
    }
  }
}

// The text view with the map's summary after it.
void InspectReportText(const JsonValue& d, std::ostream& out) {
  InspectText(d, out);
  const JsonValue& map = *d.get("map");
  out << "map: " << map.get("report")->string << "\n";
  // A position on an axis with its unit: "X = 400 mm".
  const auto position = [&map](const std::string& axis, double value) {
    std::string unit;
    for (const JsonValue& a : map.get("axes")->array) {
      if (a.get("name")->string == axis) unit = " " + a.get("position_unit")->string;
    }
    return axis + " = " + report::FormatNumber(value, 6) + unit;
  };
  if (const JsonValue* g = map.get("grid3")) {
    for (const JsonValue& c : g->get("components")->array) {
      std::string at;
      for (const auto& [axis, pos] : c.get("max_abs_at")->object) {
        at += (at.empty() ? "" : ", ") + position(axis, pos.number);
      }
      out << "  largest |" << c.get("component")->string << "| "
          << report::FormatNumber(c.get("max_abs")->number, 4) << " " << c.get("unit")->string
          << " at " << at << "\n";
    }
    for (const JsonValue& p : g->get("planes")->array) {
      out << "  plane " << p.get("plane")->string << ": slices at";
      const char* sep = " ";
      for (const JsonValue& s : p.get("slices")->array) {
        out << sep << position(s.get("axis")->string, s.get("position")->number) << " ("
            << s.get("which")->string << ")";
        sep = ", ";
      }
      const double m = p.get("magnification")->number;
      out << ", vectors "
          << (m > 0 ? "x" + report::FormatNumber(m, 6)
                    : report::FormatNumber(p.get("arrow_px_per_unit")->number, 6) + " px per unit")
          << "\n";
    }
  }
  for (const JsonValue& t : map.get("axis1d")->array) {
    out << "  AXIS1D " << t.get("axis")->string << ": forward "
        << report::FormatNumber(t.get("forward_min")->number, 4) << " .. "
        << report::FormatNumber(t.get("forward_max")->number, 4) << ", reverse - forward "
        << report::FormatNumber(t.get("backlash_min")->number, 4) << " .. "
        << report::FormatNumber(t.get("backlash_max")->number, 4) << " " << t.get("unit")->string
        << "\n";
  }
}

Expected<Output> RunInspect(Args& args, Context&) {
  args.Flag("--json");  // the command layer prints the data as JSON
  const auto report_dir = args.Value("--report");
  const auto files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (files.size() != 1) return UsageFailure("expected one IMAGE file");
  VOLCOMP_TRY_ASSIGN(const image::LoadedImage img, image::ReadImageFile(files[0]));
  JsonValue data = InspectData(files[0], img.view());
  if (!report_dir) return Output{std::move(data), InspectText};
  VOLCOMP_TRY_ASSIGN(const image::TableMap map, image::MapTable(img, files[0]));
  VOLCOMP_TRY_ASSIGN(const std::string path, image::WriteTableMapReport(map, *report_dir));
  JsonValue& m = data["map"] = image::TableMapJson(map);
  m.Set("report", path);
  return Output{std::move(data), InspectReportText};
}

}  // namespace

const Command& InspectCommand() {
  static const Command kCommand{
      "inspect",
      "summarise a table image",
      "IMAGE",
      {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"},
       {"--report", nullptr, "DIR", nullptr, nullptr,
        "also write DIR/index.html: the correction on slices through the lattice (magnified "
        "vectors, colour maps per component) and the AXIS1D curves"}},
      RunInspect};
  return kCommand;
}

}  // namespace volcomp::cli
