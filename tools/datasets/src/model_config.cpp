// Model config files (see model_config.hpp for the format).
#include "volcomp/datasets/model_config.hpp"

#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "trim.hpp"
#include "volcomp/datasets/axis_table_csv.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::datasets {
namespace {

using model::Model;

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

struct Entry {
  std::string value;
  std::size_t line;
};
using Entries = std::map<std::string, Entry>;

// The config's entries by lower-case key; a line without '=' or a repeated key is a failure.
Expected<Entries> ReadEntries(const std::string& text, const std::string& source) {
  Entries entries;
  std::istringstream in(text);
  std::string raw;
  std::size_t line_no = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    const std::string line = Trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const std::size_t eq = line.find('=');
    const std::string where = source + ":" + std::to_string(line_no) + ": ";
    if (eq == std::string::npos) {
      return Fail(Error::kInputInvalid, where + "expected `key = value`, got \"" + line + "\"");
    }
    const std::string key = Lower(Trim(line.substr(0, eq)));
    if (const auto seen = entries.find(key); seen != entries.end()) {
      return Fail(Error::kInputInvalid,
                  where + "key \"" + key + "\" repeats line " + std::to_string(seen->second.line));
    }
    entries[key] = {Trim(line.substr(eq + 1)), line_no};
  }
  return entries;
}

}  // namespace

Expected<Model> ModelFromConfigText(const std::string& text,
                                    const std::string& source,
                                    const std::string& base_dir) {
  const auto fail = [&source](std::size_t line, const std::string& msg) {
    return Fail(Error::kInputInvalid, source + ":" + std::to_string(line) + ": " + msg);
  };
  VOLCOMP_TRY_ASSIGN(Entries entries, ReadEntries(text, source));
  const auto number = [&fail](const Entry& e, const std::string& key) -> Expected<double> {
    const auto v = tools::ParseDouble(e.value);
    if (!v) return fail(e.line, key + ": \"" + e.value + "\" is not a number");
    return *v;
  };

  Model m;
  bool have_axis[3] = {false, false, false};
  std::string workpiece_axes, tool_axes = "XYZ";
  bool chain_given = false;
  std::string order_text;
  std::size_t order_line = 0;
  if (entries.count("builtin")) {
    const Entry& e = entries["builtin"];
    if (Lower(e.value) != "s500") return fail(e.line, "unknown builtin \"" + e.value + "\"");
    m = S500Model();
    have_axis[0] = have_axis[1] = have_axis[2] = true;
    entries.erase("builtin");
  }
  for (const auto& [key, e] : entries) {
    if (key == "name") {
      m.name = e.value;
    } else if (key == "axis_x" || key == "axis_y" || key == "axis_z") {
      const int a = key[5] - 'x';
      VOLCOMP_TRY_ASSIGN(m.axes[static_cast<std::size_t>(a)],
                         LoadAxisTableCsv(JoinPath(base_dir, e.value)));
      have_axis[a] = true;
    } else if (key == "squareness_c0y_urad") {
      VOLCOMP_TRY_ASSIGN(m.squareness.c0y_urad, number(e, key));
    } else if (key == "squareness_b0z_urad") {
      VOLCOMP_TRY_ASSIGN(m.squareness.b0z_urad, number(e, key));
    } else if (key == "squareness_a0z_urad") {
      VOLCOMP_TRY_ASSIGN(m.squareness.a0z_urad, number(e, key));
    } else if (key == "tool_offset_mm") {
      std::stringstream ss(e.value);
      std::string part;
      std::vector<double> v;
      while (std::getline(ss, part, ',')) {
        const auto d = tools::ParseDouble(part);
        if (!d) return fail(e.line, "tool_offset_mm: \"" + part + "\" is not a number");
        v.push_back(*d);
      }
      if (v.size() != 3) return fail(e.line, "tool_offset_mm needs three numbers: X, Y, Z");
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
        return fail(e.line, "workpiece_errors must be relative or carriage");
      }
      m.chain.workpiece_errors =
          v == "carriage" ? model::ErrorSide::kCarriage : model::ErrorSide::kRelative;
    } else if (key == "formulation") {
      const std::string v = Lower(e.value);
      if (v != "physical" && v != "dissertation") {
        return fail(e.line, "formulation must be physical or dissertation");
      }
      m.formulation =
          v == "physical" ? model::Formulation::kPhysical : model::Formulation::kDissertation;
    } else if (key == "order") {
      order_text = Lower(e.value);
      order_line = e.line;
    } else if (key == "dissertation_case") {
      const std::string v = Lower(e.value);
      if (v != "plus" && v != "minus") {
        return fail(e.line, "dissertation_case must be plus or minus");
      }
      m.dissertation_case =
          v == "plus" ? model::DissertationCase::kPlus : model::DissertationCase::kMinus;
    } else if (key == "angle_scale") {
      VOLCOMP_TRY_ASSIGN(m.angle_scale, number(e, key));
    } else {
      return fail(e.line, "unknown key \"" + key + "\"");
    }
  }
  if (!order_text.empty()) {
    if (order_text == "first") {
      m.order = model::Order::kFirst;
    } else if (order_text == "exact" || order_text == "second") {
      m.order = model::Order::kSecond;
    } else {
      return fail(order_line, "order must be first or exact (second)");
    }
  }
  if (chain_given) {
    const auto chain = model::KinematicChain::Parse(workpiece_axes, tool_axes);
    if (!chain.ok()) {
      const std::size_t line =
          entries.count("tool_axes") ? entries["tool_axes"].line : entries["workpiece_axes"].line;
      return fail(line, chain.error().message);
    }
    const model::ErrorSide side = m.chain.workpiece_errors;
    m.chain = *chain;
    m.chain.workpiece_errors = side;
  }
  for (int a = 0; a < 3; ++a) {
    if (!have_axis[a]) {
      return Fail(Error::kInputInvalid, source + ": no table for axis " + "XYZ"[a] + " (key axis_" +
                                            "xyz"[a] + " or builtin = s500)");
    }
  }
  if (const Outcome valid = model::ValidateModel(m); !valid.ok()) {
    return Fail(Error::kInputInvalid, source + ": " + valid.error().message);
  }
  if (m.name.empty()) m.name = source;
  return m;
}

Expected<Model> LoadModelConfig(const std::string& path) {
  const auto bytes = tools::ReadFileBytes(path);
  if (!bytes.ok()) return Fail(Error::kIoError, path + ": cannot open the model config");
  return ModelFromConfigText(std::string(bytes->begin(), bytes->end()), path, DirName(path));
}

}  // namespace volcomp::datasets
