// Shared command-line plumbing of the table builders (see build_cli.hpp).
#include "volcomp/model/build_cli.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "volcomp/image/axis_units.hpp"
#include "volcomp/model/image_glue.hpp"
#include "volcomp/model/io.hpp"
#include "volcomp/model/s500.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::model::cli {
namespace {

using tools::InputError;
using tools::UsageError;

std::string Num(double v, int digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
  return buf;
}

std::string Fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

}  // namespace

Model ParseModelOptions(tools::Args& args) {
  const std::string spec = args.required("--model");
  Model m;
  if (spec == "s500") {
    m = S500Model();
  } else {
    m = LoadModelConfig(spec);
  }
  if (args.flag("--no-squareness")) m.squareness = Squareness{};
  if (auto f = args.value("--formulation")) {
    if (*f == "physical") {
      m.formulation = Formulation::kPhysical;
    } else if (*f == "dissertation") {
      m.formulation = Formulation::kDissertation;
    } else {
      throw UsageError("--formulation must be physical or dissertation");
    }
  }
  if (auto o = args.value("--order")) {
    if (*o == "first") {
      m.order = Order::kFirst;
    } else if (*o == "exact" || *o == "second") {
      m.order = Order::kSecond;
    } else {
      throw UsageError("--order must be first or exact (second)");
    }
  }
  if (auto c = args.value("--dissertation-case")) {
    if (*c == "plus") {
      m.dissertation_case = DissertationCase::kPlus;
    } else if (*c == "minus") {
      m.dissertation_case = DissertationCase::kMinus;
    } else {
      throw UsageError("--dissertation-case must be plus or minus");
    }
  }
  if (auto k = args.number("--angle-scale")) m.angle_scale = *k;
  if (auto t = args.value("--tool-offset-mm")) {
    std::stringstream ss(*t);
    std::string part;
    std::vector<double> v;
    while (std::getline(ss, part, ',')) {
      const auto d = tools::ParseDouble(part);
      if (!d) throw UsageError("--tool-offset-mm: \"" + part + "\" is not a number");
      v.push_back(*d);
    }
    if (v.size() != 3) throw UsageError("--tool-offset-mm needs X,Y,Z");
    m.tool_offset_mm = {v[0], v[1], v[2]};
  }
  try {
    ValidateModel(m);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return m;
}

std::array<double, 3> ParseXyzNumbers(const std::string& text,
                                      const std::string& option,
                                      bool all_required) {
  std::array<double, 3> out = {NAN, NAN, NAN};
  if (const auto single = tools::ParseDouble(text)) {
    out = {*single, *single, *single};
    return out;
  }
  for (const auto& [name, value] : image::ParseAxisAssignments(text, option)) {
    const int a = name == 'X' ? 0 : name == 'Y' ? 1 : name == 'Z' ? 2 : -1;
    if (a < 0) throw UsageError(option + ": only X, Y and Z apply here");
    const auto v = tools::ParseDouble(value);
    if (!v) throw UsageError(option + ": \"" + value + "\" is not a number");
    out[static_cast<std::size_t>(a)] = *v;
  }
  if (all_required) {
    for (int a = 0; a < 3; ++a) {
      if (std::isnan(out[static_cast<std::size_t>(a)])) {
        throw UsageError(option + ": give X, Y and Z (or one number for all)");
      }
    }
  }
  return out;
}

void ParseImageOptions(tools::Args& args, image::ImageRequest* request) {
  const std::string element = args.value("--element").value_or("int16");
  if (element == "int16") {
    request->element = table::ElementType::kInt16;
  } else if (element == "int32") {
    request->element = table::ElementType::kInt32;
  } else if (element == "float32") {
    request->element = table::ElementType::kFloat32;
  } else {
    throw UsageError("--element must be int16, int32 or float32");
  }
  if (auto f = args.integer("--frac-bits")) {
    if (*f < 0 || *f > 8) throw UsageError("--frac-bits must be 0..8");
    request->frac_bits = static_cast<uint8_t>(*f);
  }
  if (auto id = args.integer("--table-id")) {
    if (*id < 1 || *id > 0xFFFFFFFFll) {
      throw UsageError("--table-id must be 1..4294967295 (0 means no table active)");
    }
    request->table_id = static_cast<uint32_t>(*id);
  }
  for (const std::string& kv : args.values("--info")) {
    const std::size_t eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw UsageError("--info takes KEY=VALUE");
    request->info[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
}

GridCommand ParseGridCommand(tools::Args& args,
                             const std::array<double, 3>& data_min_mm,
                             const std::array<double, 3>& data_max_mm,
                             const std::array<double, 3>& natural_spacing_mm) {
  GridCommand c;
  c.output = args.required("-o", "--output");
  c.request.axes = image::MakeAxisDefs({'X', 'Y', 'Z'}, args.value("--resolution-nm").value_or(""),
                                       args.value("--steps-per-unit").value_or(""));
  c.grid.min_mm = data_min_mm;
  c.grid.max_mm = data_max_mm;
  c.grid.natural_spacing_mm = natural_spacing_mm;
  for (std::size_t a = 0; a < 3; ++a) c.grid.step_mm[a] = c.request.axes[a].units_per_step();
  if (auto r = args.value("--range")) {
    for (const auto& [name, value] : image::ParseAxisAssignments(*r, "--range")) {
      const int a = name == 'X' ? 0 : name == 'Y' ? 1 : name == 'Z' ? 2 : -1;
      const std::size_t colon = value.find(':');
      double lo = NAN, hi = NAN;
      if (colon != std::string::npos) {
        lo = tools::ParseDouble(value.substr(0, colon)).value_or(NAN);
        hi = tools::ParseDouble(value.substr(colon + 1)).value_or(NAN);
      }
      if (a < 0 || !(hi > lo)) {
        throw UsageError("--range: expected AXIS=MIN:MAX with MIN < MAX (mm), got \"" +
                         std::string(1, name) + "=" + value + "\"");
      }
      c.grid.min_mm[static_cast<std::size_t>(a)] = lo;
      c.grid.max_mm[static_cast<std::size_t>(a)] = hi;
    }
  }
  const auto spacing = args.value("--spacing-mm");
  const auto max_err = args.number("--max-interp-error-um");
  if (spacing && max_err) {
    throw UsageError("give either --spacing-mm or --max-interp-error-um, not both");
  }
  if (spacing) {
    c.grid.spacing_mm = ParseXyzNumbers(*spacing, "--spacing-mm", true);
    for (double h : c.grid.spacing_mm) {
      if (!(h > 0)) throw UsageError("--spacing-mm must be positive");
    }
  }
  if (max_err) {
    if (!(*max_err > 0)) throw UsageError("--max-interp-error-um must be positive");
    c.grid.max_interp_error_um = *max_err;
  }
  if (auto b = args.number("--max-correction-um")) {
    if (!(*b > 0)) throw UsageError("--max-correction-um must be positive");
    c.grid.max_correction_um = *b;
  }
  ParseImageOptions(args, &c.request);
  c.json = args.flag("--json");
  return c;
}

std::string DescribeModel(const Model& m) {
  std::string s = m.formulation == Formulation::kPhysical ? "physical" : "dissertation";
  if (m.formulation == Formulation::kPhysical) {
    s += m.order == Order::kFirst ? ", first order" : ", exact rotations";
    s += ", chain " + m.chain.ToString();
  } else {
    s += m.order == Order::kFirst
             ? ", first order (3.10)"
             : (m.dissertation_case == DissertationCase::kPlus ? ", second order δ+ (3.9)"
                                                               : ", second order δ− (3.9)");
  }
  if (m.angle_scale != 1.0) s += ", angle scale " + Num(m.angle_scale);
  return s;
}

namespace {

// The grid, or the builder's refusal as the command line's error: a lattice that cannot be laid
// out is a usage error, data the checks refuse an input error (naming the option that moves the
// bound when the correction bound refused).
GridBuildResult BuildGrid(const GridBuildOptions& options,
                          const InverseMap& inverse,
                          const ForwardMap* forward) {
  try {
    return BuildCorrectionGrid(options, inverse, forward);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  } catch (const GridBuildError& e) {
    const bool bound = e.kind() == GridRefusal::kCorrectionBound;
    throw InputError(std::string(e.what()) + (bound ? " (--max-correction-um)" : ""));
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

// What went into the image file, for the report.
struct WrittenImage {
  std::size_t bytes = 0;
  uint8_t frac_bits = 0;  // 0 for float32
  const char* element = "";
  std::array<double, 3> lsb_um = {0, 0, 0};  // 0 for float32
};

// Completes the image request from the grid (corrections, INFO entries, fraction bits) and writes
// the image file.
WrittenImage WriteGridImage(GridCommand& command,
                            const GridBuildResult& r,
                            const std::map<std::string, std::string>& info) {
  image::ImageRequest& req = command.request;
  req.grid = ToGridCorrections(r.grid, req.axes);
  for (const auto& [k, v] : info) req.info.emplace(k, v);
  const GridAxes& g = r.grid.axes;
  req.info.emplace("lattice_mm", Num(g[0].origin_mm) + ":" + Num(g[0].spacing_mm) + ":" +
                                     Num(g[0].end_mm()) + "," + Num(g[1].origin_mm) + ":" +
                                     Num(g[1].spacing_mm) + ":" + Num(g[1].end_mm()) + "," +
                                     Num(g[2].origin_mm) + ":" + Num(g[2].spacing_mm) + ":" +
                                     Num(g[2].end_mm()));
  req.info.emplace("predicted_interp_error_um", Num(r.interpolation.max_um, 4));
  if (!req.frac_bits && req.element != table::ElementType::kFloat32) {
    req.frac_bits = image::ChooseFracBits(req);
  }
  WrittenImage w;
  w.frac_bits = req.element == table::ElementType::kFloat32 ? 0 : *req.frac_bits;
  const std::vector<uint8_t> bytes = image::BuildImage(req);
  image::WriteFileBytes(command.output, bytes);
  w.bytes = bytes.size();
  w.element = req.element == table::ElementType::kInt16   ? "int16"
              : req.element == table::ElementType::kInt32 ? "int32"
                                                          : "float32";
  for (std::size_t a = 0; a < 3; ++a) {
    w.lsb_um[a] =
        req.element == table::ElementType::kFloat32 ? 0.0 : LsbUm(req.axes[a], w.frac_bits);
  }
  return w;
}

// Everything a report shows.
struct GridReport {
  const GridCommand& command;
  const GridBuildResult& r;
  bool checked_inverse;  // a forward map checked the inverse at the nodes
  const std::map<std::string, std::string>& info;
  const WrittenImage& img;
};

void ReportGridJson(const GridReport& report, std::ostream& out) {
  const auto& [command, r, checked_inverse, info, img] = report;
  const GridAxes& g = r.grid.axes;
  tools::JsonWriter w(out);
  w.begin_object();
  w.key("image").value(command.output);
  w.key("bytes").value(static_cast<uint64_t>(img.bytes));
  w.key("source").begin_object();
  for (const auto& [k, v] : info) w.key(k).value(v);
  w.end_object();
  w.key("lattice").begin_array();
  for (std::size_t a = 0; a < 3; ++a) {
    w.begin_object();
    w.key("axis").value(std::string(1, "XYZ"[a]));
    w.key("origin_mm").value(g[a].origin_mm);
    w.key("spacing_mm").value(g[a].spacing_mm);
    w.key("nodes").value(g[a].nodes);
    w.key("spacing_steps").value(command.request.grid->lattice[a].spacing_steps);
    w.end_object();
  }
  w.end_array();
  w.key("max_correction_um").value(r.stats.max_correction_um);
  w.key("max_correction_at_mm").begin_array();
  for (int a = 0; a < 3; ++a) w.value(r.stats.max_correction_at_mm[a]);
  w.end_array();
  if (checked_inverse) w.key("max_inverse_residual_um").value(r.stats.max_residual_um);
  w.key("interpolation").begin_object();
  w.key("max_um").value(r.interpolation.max_um);
  w.key("rms_um").value(r.interpolation.rms_um);
  w.key("samples").value(static_cast<uint64_t>(r.interpolation.samples));
  w.key("worst_at_mm").begin_array();
  for (int a = 0; a < 3; ++a) w.value(r.interpolation.worst_at_mm[a]);
  w.end_array();
  w.end_object();
  w.key("spacings_tried").begin_array();
  for (const auto& t : r.tried) {
    w.begin_object();
    w.key("spacing_mm").begin_array();
    for (double h : t.first) w.value(h);
    w.end_array();
    w.key("max_um").value(t.second);
    w.end_object();
  }
  w.end_array();
  w.key("element").value(img.element);
  w.key("frac_bits").value(static_cast<unsigned>(img.frac_bits));
  w.key("lsb_um").begin_array();
  for (double l : img.lsb_um) w.value(l);
  w.end_array();
  w.end_object();
  out << "\n";
}

void ReportGridText(const GridReport& report, std::ostream& out) {
  const auto& [command, r, checked_inverse, info, img] = report;
  const GridAxes& g = r.grid.axes;
  for (const auto& [k, v] : info) out << "  " << k << ": " << v << "\n";
  for (std::size_t a = 0; a < 3; ++a) {
    out << "  lattice "
        << "XYZ"[a] << ": " << Num(g[a].origin_mm) << " .. " << Num(g[a].end_mm())
        << " mm, spacing " << Num(g[a].spacing_mm) << " mm ("
        << command.request.grid->lattice[a].spacing_steps << " steps), " << g[a].nodes
        << " nodes\n";
  }
  out << "  largest correction: " << Fixed(r.stats.max_correction_um, 3) << " µm at ("
      << Num(r.stats.max_correction_at_mm.x) << ", " << Num(r.stats.max_correction_at_mm.y) << ", "
      << Num(r.stats.max_correction_at_mm.z) << ") mm (bound "
      << Num(command.grid.max_correction_um) << " µm)\n";
  if (checked_inverse) {
    out << "  inverse at the nodes: worst residual " << Num(r.stats.max_residual_um, 3)
        << " µm (limit " << Num(command.grid.max_residual_um) << " µm)\n";
  }
  if (r.tried.size() > 1) {
    out << "  spacings tried:";
    for (const auto& t : r.tried) {
      out << " " << Num(t.first[0]) << "/" << Num(t.first[1]) << "/" << Num(t.first[2]) << " mm → "
          << Num(t.second, 3) << " µm;";
    }
    out << "\n";
  }
  out << "  predicted interpolation error between nodes: max " << Fixed(r.interpolation.max_um, 4)
      << " µm, rms " << Fixed(r.interpolation.rms_um, 4) << " µm over " << r.interpolation.samples
      << " samples (worst at " << Num(r.interpolation.worst_at_mm.x) << ", "
      << Num(r.interpolation.worst_at_mm.y) << ", " << Num(r.interpolation.worst_at_mm.z)
      << " mm)\n";
  out << "  elements: " << img.element;
  if (command.request.element != table::ElementType::kFloat32) {
    out << ", " << static_cast<unsigned>(img.frac_bits) << " fraction bits, LSB "
        << Num(img.lsb_um[0], 3) << "/" << Num(img.lsb_um[1], 3) << "/" << Num(img.lsb_um[2], 3)
        << " µm";
  }
  out << "\n  wrote " << command.output << " (" << img.bytes << " bytes)\n";
}

}  // namespace

int RunGridBuild(GridCommand& command,
                 const InverseMap& inverse,
                 const ForwardMap* forward,
                 const std::map<std::string, std::string>& info,
                 std::ostream& out) {
  const GridBuildResult r = BuildGrid(command.grid, inverse, forward);
  const WrittenImage img = WriteGridImage(command, r, info);
  const GridReport report{command, r, forward != nullptr, info, img};
  if (command.json) {
    ReportGridJson(report, out);
  } else {
    ReportGridText(report, out);
  }
  return 0;
}

}  // namespace volcomp::model::cli
