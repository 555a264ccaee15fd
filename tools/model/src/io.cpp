// Loading axis tables, model configs and tracker lines (see io.hpp for the formats).
#include "volcomp/model/io.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "volcomp/model/s500.hpp"

namespace volcomp::model {
namespace {

using tools::CsvTable;
using tools::InputError;

constexpr double kUradPerArcsec = 4.84813681109536;

struct AngleColumn {
  std::string name;
  double to_urad;
};

AngleColumn FindAngle(const CsvTable& csv, const std::string& stem) {
  static const std::pair<const char*, double> kUnits[] = {
      {"_urad", 1.0}, {"_mrad", 1000.0}, {"_um_per_mm", 1000.0}, {"_arcsec", kUradPerArcsec}};
  AngleColumn found{"", 0};
  for (const auto& u : kUnits) {
    const std::string name = stem + u.first;
    if (csv.find(name)) {
      if (!found.name.empty()) {
        throw csv.error(csv.header_line(), "columns \"" + found.name + "\" and \"" + name +
                                               "\" give the same angle twice");
      }
      found = {name, u.second};
    }
  }
  if (found.name.empty()) {
    throw csv.error(csv.header_line(),
                    "missing column \"" + stem + "_urad\" (or _mrad, _um_per_mm, _arcsec)");
  }
  return found;
}

std::string Trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  return s.substr(b, e - b);
}

std::string Lower(std::string s) {
  for (char& c : s) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return s;
}

std::string JoinPath(const std::string& dir, const std::string& file) {
  if (file.empty() || file[0] == '/' || dir.empty()) return file;
  return dir + "/" + file;
}

std::string DirName(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash == 0 ? 1 : slash);
}

}  // namespace

AxisErrorTable AxisTableFromCsv(const CsvTable& csv) {
  for (const char* c : {"position_mm", "ex_um", "ey_um", "ez_um"}) csv.require(c);
  const AngleColumn angles[3] = {FindAngle(csv, "ea"), FindAngle(csv, "eb"), FindAngle(csv, "ec")};
  std::vector<double> pos;
  std::vector<AxisErrorSample> rows;
  for (const tools::CsvRow& r : csv.rows()) {
    const double p = r.number("position_mm");
    if (!pos.empty() && !(p > pos.back())) {
      throw csv.error(r.line(), "positions must increase from row to row");
    }
    pos.push_back(p);
    AxisErrorSample s;
    s.linear_um = {r.number("ex_um"), r.number("ey_um"), r.number("ez_um")};
    for (int a = 0; a < 3; ++a) {
      s.angular_urad[a] = r.number(angles[a].name) * angles[a].to_urad;
    }
    rows.push_back(s);
  }
  if (pos.size() < 2) throw csv.error(csv.header_line(), "an axis table needs at least 2 rows");
  return AxisErrorTable(std::move(pos), std::move(rows));
}

AxisErrorTable LoadAxisTableCsv(const std::string& path) {
  return AxisTableFromCsv(CsvTable::ParseFile(path));
}

Model ModelFromConfigText(const std::string& text,
                          const std::string& source,
                          const std::string& base_dir) {
  struct Entry {
    std::string value;
    std::size_t line;
  };
  std::map<std::string, Entry> entries;
  std::istringstream in(text);
  std::string raw;
  std::size_t line_no = 0;
  const auto fail = [&source](std::size_t line, const std::string& msg) {
    return InputError(source + ":" + std::to_string(line) + ": " + msg);
  };
  while (std::getline(in, raw)) {
    ++line_no;
    const std::string line = Trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos)
      throw fail(line_no, "expected `key = value`, got \"" + line + "\"");
    const std::string key = Lower(Trim(line.substr(0, eq)));
    const std::string value = Trim(line.substr(eq + 1));
    if (entries.count(key)) {
      throw fail(line_no, "key \"" + key + "\" repeats line " + std::to_string(entries[key].line));
    }
    entries[key] = {value, line_no};
  }

  Model m;
  bool have_axis[3] = {false, false, false};
  std::string workpiece_axes, tool_axes = "XYZ";
  bool chain_given = false;
  std::string order_text;
  std::size_t order_line = 0;
  if (entries.count("builtin")) {
    const Entry& e = entries["builtin"];
    if (Lower(e.value) != "s500") throw fail(e.line, "unknown builtin \"" + e.value + "\"");
    m = S500Model();
    have_axis[0] = have_axis[1] = have_axis[2] = true;
    entries.erase("builtin");
  }
  const auto number = [&fail](const Entry& e, const std::string& key) {
    const auto v = tools::ParseDouble(e.value);
    if (!v) throw fail(e.line, key + ": \"" + e.value + "\" is not a number");
    return *v;
  };
  for (const auto& [key, e] : entries) {
    if (key == "name") {
      m.name = e.value;
    } else if (key == "axis_x" || key == "axis_y" || key == "axis_z") {
      const int a = key[5] - 'x';
      m.axes[static_cast<std::size_t>(a)] = LoadAxisTableCsv(JoinPath(base_dir, e.value));
      have_axis[a] = true;
    } else if (key == "squareness_c0y_urad") {
      m.squareness.c0y_urad = number(e, key);
    } else if (key == "squareness_b0z_urad") {
      m.squareness.b0z_urad = number(e, key);
    } else if (key == "squareness_a0z_urad") {
      m.squareness.a0z_urad = number(e, key);
    } else if (key == "tool_offset_mm") {
      std::stringstream ss(e.value);
      std::string part;
      std::vector<double> v;
      while (std::getline(ss, part, ',')) {
        const auto d = tools::ParseDouble(part);
        if (!d) throw fail(e.line, "tool_offset_mm: \"" + part + "\" is not a number");
        v.push_back(*d);
      }
      if (v.size() != 3) throw fail(e.line, "tool_offset_mm needs three numbers: X, Y, Z");
      m.tool_offset_mm = {v[0], v[1], v[2]};
    } else if (key == "workpiece_axes") {
      workpiece_axes = e.value;
      chain_given = true;
    } else if (key == "tool_axes") {
      tool_axes = e.value;
      chain_given = true;
    } else if (key == "workpiece_errors") {
      const std::string v = Lower(e.value);
      if (v != "relative" && v != "carriage") {
        throw fail(e.line, "workpiece_errors must be relative or carriage");
      }
      m.chain.workpiece_errors = v == "carriage" ? ErrorSide::kCarriage : ErrorSide::kRelative;
    } else if (key == "formulation") {
      const std::string v = Lower(e.value);
      if (v != "physical" && v != "dissertation") {
        throw fail(e.line, "formulation must be physical or dissertation");
      }
      m.formulation = v == "physical" ? Formulation::kPhysical : Formulation::kDissertation;
    } else if (key == "order") {
      order_text = Lower(e.value);
      order_line = e.line;
    } else if (key == "dissertation_case") {
      const std::string v = Lower(e.value);
      if (v != "plus" && v != "minus")
        throw fail(e.line, "dissertation_case must be plus or minus");
      m.dissertation_case = v == "plus" ? DissertationCase::kPlus : DissertationCase::kMinus;
    } else if (key == "angle_scale") {
      m.angle_scale = number(e, key);
    } else {
      throw fail(e.line, "unknown key \"" + key + "\"");
    }
  }
  if (!order_text.empty()) {
    if (order_text == "first") {
      m.order = Order::kFirst;
    } else if (order_text == "exact" || order_text == "second") {
      m.order = Order::kSecond;
    } else {
      throw fail(order_line, "order must be first or exact (second)");
    }
  }
  if (chain_given) {
    try {
      const ErrorSide side = m.chain.workpiece_errors;
      m.chain = KinematicChain::Parse(workpiece_axes, tool_axes);
      m.chain.workpiece_errors = side;
    } catch (const std::invalid_argument& ex) {
      const std::size_t line =
          entries.count("tool_axes") ? entries["tool_axes"].line : entries["workpiece_axes"].line;
      throw fail(line, ex.what());
    }
  }
  for (int a = 0; a < 3; ++a) {
    if (!have_axis[a]) {
      throw InputError(source + ": no table for axis " + "XYZ"[a] + " (key axis_" + "xyz"[a] +
                       " or builtin = s500)");
    }
  }
  try {
    ValidateModel(m);
  } catch (const std::invalid_argument& ex) {
    throw InputError(source + ": " + ex.what());
  }
  if (m.name.empty()) m.name = source;
  return m;
}

Model LoadModelConfig(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw InputError(path + ": cannot open the model config");
  std::stringstream ss;
  ss << f.rdbuf();
  return ModelFromConfigText(ss.str(), path, DirName(path));
}

TrackerData TrackerDataFromCsv(const CsvTable& csv) {
  static const char* kCmd[3] = {"x_cmd_mm", "y_cmd_mm", "z_cmd_mm"};
  static const char* kPos[3] = {"x_mm", "y_mm", "z_mm"};
  csv.require("axis");
  for (int a = 0; a < 3; ++a) {
    csv.require(kCmd[a]);
    csv.require(kPos[a]);
  }
  const int cos_columns =
      (csv.find("cos_x") ? 1 : 0) + (csv.find("cos_y") ? 1 : 0) + (csv.find("cos_z") ? 1 : 0);
  if (cos_columns != 0 && cos_columns != 3) {
    throw csv.error(csv.header_line(), "give all of cos_x, cos_y, cos_z or none");
  }
  TrackerData d;
  d.name = csv.source();
  d.has_printed_cosines = cos_columns == 3;
  for (const tools::CsvRow& r : csv.rows()) {
    const std::string axis = Trim(r.text("axis"));
    const int a = axis == "X" || axis == "x"   ? 0
                  : axis == "Y" || axis == "y" ? 1
                  : axis == "Z" || axis == "z" ? 2
                                               : -1;
    if (a < 0) throw csv.error(r.line(), "axis must be X, Y or Z, got \"" + axis + "\"");
    TrackerNode n;
    for (int b = 0; b < 3; ++b) {
      const double c = r.number(kCmd[b]);
      if (b == a) {
        n.q_mm = c;
      } else if (c != 0.0) {
        throw csv.error(r.line(), std::string("the ") + "XYZ"[a] + " line must keep " + kCmd[b] +
                                      " at 0 (the lines run through a common origin)");
      }
      n.p_mm[b] = r.number(kPos[b]);
    }
    if (d.has_printed_cosines) {
      n.printed_cos = {r.number("cos_x"), r.number("cos_y"), r.number("cos_z")};
    }
    auto& line = d.lines[static_cast<std::size_t>(a)];
    if (line.empty() && n.q_mm != 0.0) {
      throw csv.error(r.line(), std::string("the ") + "XYZ"[a] +
                                    " line must start at its origin node (commanded 0)");
    }
    if (!line.empty()) {
      const double h = line.size() >= 2 ? line[1].q_mm - line[0].q_mm : n.q_mm - line[0].q_mm;
      if (!(n.q_mm > line.back().q_mm)) {
        throw csv.error(r.line(), std::string("the ") + "XYZ"[a] + " line must increase");
      }
      if (std::fabs(n.q_mm - line.back().q_mm - h) > 1e-9) {
        throw csv.error(r.line(), std::string("the ") + "XYZ"[a] +
                                      " line must be equally spaced (step " + std::to_string(h) +
                                      " mm)");
      }
    }
    line.push_back(n);
  }
  try {
    ValidateTrackerData(d);
  } catch (const std::invalid_argument& ex) {
    throw InputError(csv.source() + ": " + ex.what());
  }
  return d;
}

TrackerData LoadTrackerCsv(const std::string& path) {
  return TrackerDataFromCsv(CsvTable::ParseFile(path));
}

}  // namespace volcomp::model
