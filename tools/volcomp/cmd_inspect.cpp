// `volcomp inspect IMAGE [--json]`: what an image holds, validated by the firmware's parser.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <limits>

#include "commands.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/hex.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {
namespace {

const char* TypeName(table::ElementType t) {
  switch (t) {
    case table::ElementType::kInt16:
      return "int16";
    case table::ElementType::kInt32:
      return "int32";
    case table::ElementType::kFloat32:
      return "float32";
  }
  return "?";
}

struct Range {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  void Add(double v) {
    min = std::min(min, v);
    max = std::max(max, v);
  }
};

// Unit name and factor from steps for an axis.
std::pair<const char*, double> DisplayUnit(const table::AxisInfo& a) {
  if (a.kind == table::AxisKind::kRotary) return {"arcsec", a.resolution_e9 * 1e-9 * 3600.0};
  return {"um", a.resolution_e9 * 1e-9 * 1000.0};
}

}  // namespace

int RunInspect(Args& args) {
  const bool json = args.flag("--json");
  const auto pos = args.positionals();
  args.finish();
  if (pos.size() != 1) throw UsageError("expected one IMAGE file");
  const image::LoadedImage img = image::LoadImageFile(pos[0]);
  const table::TableView& v = img.view();

  std::vector<Range> grid_range(3);
  if (v.grid.present) {
    const uint64_t n = uint64_t{v.grid.dim[0].nodes} * v.grid.dim[1].nodes * v.grid.dim[2].nodes;
    for (uint64_t i = 0; i < n * 3; ++i) {
      grid_range[i % 3].Add(table::ElementSteps(v.grid.data, v.grid.type, v.grid.frac_bits,
                                                static_cast<uint32_t>(i)));
    }
  }

  if (json) {
    JsonWriter w(std::cout);
    w.begin_object();
    w.key("file").value(pos[0]);
    w.key("image_size").value(uint64_t{v.image_size});
    w.key("crc32").value(Hex32(v.crc32));
    w.key("table_id").value(uint64_t{v.table_id});
    w.key("format_version")
        .value(std::to_string(table::kVersionMajor) + "." + std::to_string(v.version_minor));
    w.key("axes").begin_array();
    for (uint8_t i = 0; i < v.axis_count; ++i) {
      const auto& a = v.axes[i];
      w.begin_object();
      w.key("name").value(std::string(1, a.name));
      w.key("kind").value(a.kind == table::AxisKind::kRotary ? "rotary" : "linear");
      w.key("resolution_e9").value(uint64_t{a.resolution_e9});
      w.key("units_per_step").value(a.resolution_e9 * 1e-9);
      w.end_object();
    }
    w.end_array();
    if (v.grid.present) {
      w.key("grid3").begin_object();
      w.key("element").value(TypeName(v.grid.type));
      w.key("frac_bits").value(unsigned{v.grid.frac_bits});
      w.key("dimensions").begin_array();
      for (int d = 0; d < 3; ++d) {
        const auto& a = v.axes[v.grid.axis[d]];
        w.begin_object();
        w.key("axis").value(std::string(1, a.name));
        w.key("nodes").value(uint64_t{v.grid.dim[d].nodes});
        w.key("origin_steps").value(int64_t{v.grid.dim[d].origin_steps});
        w.key("spacing_steps").value(uint64_t{v.grid.dim[d].spacing_steps});
        w.key("correction_min_steps").value(grid_range[d].min);
        w.key("correction_max_steps").value(grid_range[d].max);
        w.end_object();
      }
      w.end_array();
      w.end_object();
    }
    w.key("axis1d").begin_array();
    for (uint8_t i = 0; i < v.axis1d_count; ++i) {
      const auto& t = v.axis1d[i];
      w.begin_object();
      w.key("axis").value(std::string(1, v.axes[t.axis].name));
      w.key("element").value(TypeName(t.type));
      w.key("frac_bits").value(unsigned{t.frac_bits});
      w.key("nodes").value(uint64_t{t.dim.nodes});
      w.key("origin_steps").value(int64_t{t.dim.origin_steps});
      w.key("spacing_steps").value(uint64_t{t.dim.spacing_steps});
      w.key("has_reverse").value(t.reverse != nullptr);
      w.key("wrap_period_steps").value(uint64_t{t.period_steps});
      w.key("backlash_steps").value(t.backlash_q8 / 256.0);
      w.end_object();
    }
    w.end_array();
    w.key("info").value(v.info ? std::string(v.info, v.info_size) : std::string());
    w.end_object();
    return 0;
  }

  std::cout << pos[0] << ": valid volcomp table image, format " << int(table::kVersionMajor) << "."
            << int(v.version_minor) << ", " << v.image_size << " bytes, CRC-32 " << Hex32(v.crc32)
            << ", table id " << v.table_id << "\n";
  std::cout << "axes:";
  for (uint8_t i = 0; i < v.axis_count; ++i) {
    const auto& a = v.axes[i];
    std::cout << " " << a.name << " (" << (a.kind == table::AxisKind::kRotary ? "rotary, " : "")
              << a.resolution_e9 * 1e-9 << (a.kind == table::AxisKind::kRotary ? " deg" : " mm")
              << "/step)";
  }
  std::cout << "\n";
  if (v.grid.present) {
    std::cout << "GRID3: " << TypeName(v.grid.type) << " Q." << int(v.grid.frac_bits) << ", "
              << v.grid.dim[0].nodes << " x " << v.grid.dim[1].nodes << " x " << v.grid.dim[2].nodes
              << " nodes\n";
    for (int d = 0; d < 3; ++d) {
      const auto& a = v.axes[v.grid.axis[d]];
      const auto unit = DisplayUnit(a);
      const double per = a.resolution_e9 * 1e-9;
      std::printf("  %c: from %.6g to %.6g %s every %.6g (%d steps), correction %.4g .. %.4g %s\n",
                  a.name, v.grid.dim[d].origin_steps * per,
                  (v.grid.dim[d].origin_steps +
                   double(v.grid.dim[d].nodes - 1) * v.grid.dim[d].spacing_steps) *
                      per,
                  a.kind == table::AxisKind::kRotary ? "deg" : "mm",
                  v.grid.dim[d].spacing_steps * per, int(v.grid.dim[d].spacing_steps),
                  grid_range[d].min * unit.second, grid_range[d].max * unit.second, unit.first);
    }
    std::fflush(stdout);
  }
  for (uint8_t i = 0; i < v.axis1d_count; ++i) {
    const auto& t = v.axis1d[i];
    std::cout << "AXIS1D " << v.axes[t.axis].name << ": " << TypeName(t.type) << " Q."
              << int(t.frac_bits) << ", " << t.dim.nodes << " nodes from step "
              << t.dim.origin_steps << " every " << t.dim.spacing_steps << " steps"
              << (t.reverse ? ", forward+reverse" : ", one direction") << ", backlash "
              << t.backlash_q8 / 256.0 << " steps"
              << (t.period_steps ? ", wraps every " + std::to_string(t.period_steps) + " steps"
                                 : std::string())
              << "\n";
  }
  if (v.info != nullptr && v.info_size > 0) {
    std::cout << "info:\n";
    std::string text(v.info, v.info_size);
    size_t start = 0;
    while (start < text.size()) {
      const size_t end = std::min(text.find('\n', start), text.size());
      std::cout << "  " << text.substr(start, end - start) << "\n";
      start = end + 1;
    }
  }
  return 0;
}

}  // namespace volcomp::tools
