// Building, writing and reporting a GRID3 image (see grid_build.hpp).
#include "grid_build.hpp"

#include <array>
#include <cstdio>
#include <ostream>
#include <utility>

#include "volcomp/builders/grid_image.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

using report::FormatFixed;
using report::FormatNumber;

JsonValue Xyz(double x, double y, double z) { return JsonValue::Array().Push(x).Push(y).Push(z); }
JsonValue Xyz(const model::Vec3& v) { return Xyz(v.x, v.y, v.z); }
JsonValue Xyz(const std::array<double, 3>& v) { return Xyz(v[0], v[1], v[2]); }

// A refusal of the builder as the command's failure: a lattice that cannot be laid out is a usage
// failure, data the checks refuse an input failure (naming the option that moves the bound when
// the correction bound refused).
Unexpected<Failure> BuildFailure(const Failure& f) {
  switch (f.code) {
    case Error::kInvalidArgument:
      return UsageFailure(f.message);
    case Error::kOutOfRange:
      return Fail(Error::kInputInvalid, f.message + " (--max-correction-um)");
    default:
      return Fail(f);
  }
}

JsonValue ReportData(const GridCommand& command,
                     const builders::GridImage& img,
                     const builders::GridSource& source) {
  const builders::GridBuildResult& r = img.grid.build;
  const model::GridAxes& g = r.grid.axes;
  JsonValue d = JsonValue::Object();
  d.Set("image", command.output);
  d.Set("bytes", uint64_t{img.bytes.size()});
  JsonValue& info = d["source"] = JsonValue::Object();
  for (const auto& [k, v] : source.info) info.Set(k, v);
  JsonValue& lattice = d["lattice"] = JsonValue::Array();
  for (std::size_t a = 0; a < 3; ++a) {
    JsonValue x = JsonValue::Object();
    x.Set("axis", std::string(1, "XYZ"[a]));
    x.Set("origin_mm", g[a].origin_mm);
    x.Set("spacing_mm", g[a].spacing_mm);
    x.Set("nodes", g[a].nodes);
    x.Set("spacing_steps", img.grid.section.lattice[a].spacing_steps);
    x.Set("end_mm", g[a].end_mm());
    lattice.Push(std::move(x));
  }
  d.Set("max_correction_um", r.stats.max_correction_um);
  d.Set("max_correction_at_mm", Xyz(r.stats.max_correction_at_mm));
  const bool checked_inverse = source.forward_or_null() != nullptr;
  if (checked_inverse) d.Set("max_inverse_residual_um", r.stats.max_residual_um);
  JsonValue& interpolation = d["interpolation"] = JsonValue::Object();
  interpolation.Set("max_um", r.interpolation.max_um);
  interpolation.Set("rms_um", r.interpolation.rms_um);
  interpolation.Set("samples", uint64_t{r.interpolation.samples});
  interpolation.Set("worst_at_mm", Xyz(r.interpolation.worst_at_mm));
  JsonValue& tried = d["spacings_tried"] = JsonValue::Array();
  for (const auto& t : r.tried) {
    JsonValue x = JsonValue::Object();
    x.Set("spacing_mm", Xyz(t.first));
    x.Set("max_um", t.second);
    tried.Push(std::move(x));
  }
  d.Set("element", table::ElementTypeName(img.request.element));
  d.Set("frac_bits", unsigned{img.frac_bits});
  d.Set("lsb_um", Xyz(img.lsb_um));
  d.Set("max_correction_bound_um", command.grid.max_correction_um);
  if (checked_inverse) d.Set("max_inverse_residual_limit_um", command.grid.max_residual_um);
  return d;
}

std::string XyzText(const JsonValue& v, const char* separator) {
  return FormatNumber(v.array[0].number, 6) + separator + FormatNumber(v.array[1].number, 6) +
         separator + FormatNumber(v.array[2].number, 6);
}

void ReportText(const JsonValue& d, std::ostream& out) {
  const JsonValue& source = *d.get("source");
  out << source.get("builder")->string << "\n";
  for (const auto& [k, v] : source.object) out << "  " << k << ": " << v.string << "\n";
  for (const JsonValue& a : d.get("lattice")->array) {
    out << "  lattice " << a.get("axis")->string << ": "
        << FormatNumber(a.get("origin_mm")->number, 6) << " .. "
        << FormatNumber(a.get("end_mm")->number, 6) << " mm, spacing "
        << FormatNumber(a.get("spacing_mm")->number, 6) << " mm ("
        << a.get("spacing_steps")->integer << " steps), " << a.get("nodes")->integer << " nodes\n";
  }
  out << "  largest correction: " << FormatFixed(d.get("max_correction_um")->number, 3)
      << " µm at (" << XyzText(*d.get("max_correction_at_mm"), ", ") << ") mm (bound "
      << FormatNumber(d.get("max_correction_bound_um")->number, 6) << " µm)\n";
  if (const JsonValue* residual = d.get("max_inverse_residual_um")) {
    out << "  inverse at the nodes: worst residual " << FormatNumber(residual->number, 3)
        << " µm (limit " << FormatNumber(d.get("max_inverse_residual_limit_um")->number, 6)
        << " µm)\n";
  }
  const auto& tried = d.get("spacings_tried")->array;
  if (tried.size() > 1) {
    out << "  spacings tried:";
    for (const JsonValue& t : tried) {
      out << " " << XyzText(*t.get("spacing_mm"), "/") << " mm → "
          << FormatNumber(t.get("max_um")->number, 3) << " µm;";
    }
    out << "\n";
  }
  const JsonValue& interpolation = *d.get("interpolation");
  out << "  predicted interpolation error between nodes: max "
      << FormatFixed(interpolation.get("max_um")->number, 4) << " µm, rms "
      << FormatFixed(interpolation.get("rms_um")->number, 4) << " µm over "
      << interpolation.get("samples")->integer << " samples (worst at "
      << XyzText(*interpolation.get("worst_at_mm"), ", ") << " mm)\n";
  const std::string& element = d.get("element")->string;
  out << "  elements: " << element;
  if (element != "float32") {
    const auto& lsb = d.get("lsb_um")->array;
    out << ", " << d.get("frac_bits")->integer << " fraction bits, LSB "
        << FormatNumber(lsb[0].number, 3) << "/" << FormatNumber(lsb[1].number, 3) << "/"
        << FormatNumber(lsb[2].number, 3) << " µm";
  }
  out << "\n  wrote " << d.get("image")->string << " (" << d.get("bytes")->integer << " bytes)\n";
}

}  // namespace

Expected<Output> RunGridBuild(const GridCommand& command,
                              builders::GridSource source,
                              const char* builder) {
  source.info.emplace("builder", builder);
  const Expected<builders::GridImage> img =
      builders::BuildGridImage(command.grid, command.request, source);
  if (!img.ok()) return BuildFailure(img.error());
  Output output;
  JsonValue board;
  if (command.board) {
    VOLCOMP_TRY(CheckImageAgainstBoardFile(*command.board, img->bytes, &output.warnings, &board));
  }
  VOLCOMP_TRY(tools::WriteFileBytes(command.output, img->bytes));
  output.data = ReportData(command, *img, source);
  if (command.board) output.data.Set("board_check", std::move(board));
  output.text = ReportText;
  return output;
}

}  // namespace volcomp::cli
