// ISO 230-1 component-error sets and the 21-parameter model (see iso230_set.hpp).
#include "volcomp/datasets/iso230_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

namespace volcomp::datasets {
namespace {

constexpr double kUmPerMm = 1000.0;
constexpr double kUradPerRad = 1e6;
constexpr const char* kAxes = "XYZABC";
constexpr const char* kLinearAxes = "XYZ";

bool IsAxis(char c) { return c != '\0' && std::string(kAxes).find(c) != std::string::npos; }
bool IsLinearAxis(char c) {
  return c != '\0' && std::string(kLinearAxes).find(c) != std::string::npos;
}

std::string At(const Iso230Set& set, std::size_t line) {
  return line == 0 ? set.source + ": " : set.source + ":" + std::to_string(line) + ": ";
}

std::string Number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

// The value of `p` at `x`: linear between rows, end rows held (AxisErrorTable's rule).
double ValueAt(const Iso230Parameter& p, double x) {
  if (!p.tabulated) return p.values.front();
  const auto& a = p.arguments;
  if (x <= a.front()) return p.values.front();
  if (x >= a.back()) return p.values.back();
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(a.begin(), a.end(), x) - a.begin()) - 1;
  const double t = (x - a[i]) / (a[i + 1] - a[i]);
  return p.values[i] + t * (p.values[i + 1] - p.values[i]);
}

std::string ComponentName(int err, int axis) {
  return std::string("E") + kAxes[err] + kLinearAxes[axis];
}

}  // namespace

Iso230Kind ClassifyIso230Name(const std::string& n) {
  if (n.size() != 3) return Iso230Kind::kUnknown;
  if (n[0] == 'E' && IsAxis(n[1]) && IsAxis(n[2])) {
    return IsLinearAxis(n[2]) ? Iso230Kind::kModelComponent : Iso230Kind::kOther;
  }
  if (IsAxis(n[0]) && n[1] == '0' && IsAxis(n[2])) {
    return n == "C0Y" || n == "B0Z" || n == "A0Z" ? Iso230Kind::kModelPosition : Iso230Kind::kOther;
  }
  // ISG: P0X..P0Z (TCP zero), N0X..N0Z (tool orientation), PXA..PZC (rotary centres),
  // VXX..VZC (axis orientation of cardanic machines).
  if ((n[0] == 'P' || n[0] == 'N') && n[1] == '0' && IsLinearAxis(n[2])) return Iso230Kind::kOther;
  if (n[0] == 'P' && IsLinearAxis(n[1]) && (n[2] == 'A' || n[2] == 'B' || n[2] == 'C')) {
    return Iso230Kind::kOther;
  }
  if (n[0] == 'V' && IsLinearAxis(n[1]) && IsAxis(n[2])) return Iso230Kind::kOther;
  return Iso230Kind::kUnknown;
}

bool IsIso230Angle(const std::string& n) {
  if (n.size() != 3) return false;
  const char err = n[0] == 'E' ? n[1] : n[1] == '0' ? n[0] : '\0';
  return err == 'A' || err == 'B' || err == 'C';
}

Outcome CheckIso230Set(const Iso230Set& set) {
  std::map<std::string, std::size_t> seen;
  for (const Iso230Parameter& p : set.parameters) {
    const std::string at = At(set, p.line);
    const Iso230Kind kind = ClassifyIso230Name(p.name);
    if (kind == Iso230Kind::kUnknown) {
      return Fail(Error::kInputInvalid,
                  at + "unknown parameter \"" + p.name +
                      "\" (ISO 230-1 names: E<err><axis> such as EXX, ECY; <err>0<axis> such as "
                      "C0Y; err and axis one of X Y Z A B C)");
    }
    if (const auto [it, added] = seen.emplace(p.name, p.line); !added) {
      return Fail(Error::kInputInvalid, at + "parameter " + p.name + " repeats (first on line " +
                                            std::to_string(it->second) + ")");
    }
    const bool component = p.name[0] == 'E';  // a known name: E<err><axis>
    const bool position = IsAxis(p.name[0]) && p.name[1] == '0';
    if (component && p.tabulated && p.argument != std::string(1, p.name[2])) {
      return Fail(Error::kInputInvalid,
                  at + p.name + " is a function of " + p.name[2] + ", but its argument is " +
                      (p.argument.empty() ? std::string("missing") : p.argument));
    }
    if (position && p.tabulated) {
      return Fail(Error::kInputInvalid,
                  at + p.name + " is a position error: one value, not a table");
    }
    if (p.values.empty() || (p.tabulated && p.arguments.size() != p.values.size())) {
      return Fail(Error::kInputInvalid, at + p.name + " has no values");
    }
    for (std::size_t i = 1; p.tabulated && i < p.arguments.size(); ++i) {
      if (!(p.arguments[i] > p.arguments[i - 1])) {
        return Fail(Error::kInputInvalid, at + p.name + ": the arguments must increase, " +
                                              Number(p.arguments[i]) + " follows " +
                                              Number(p.arguments[i - 1]));
      }
    }
    // Outside the model (ISG's positions and vectors, rotary axes): refused when not zero by
    // ModelFromIso230Set; no unit check here, their sizes are not those of the model's errors.
    if (kind == Iso230Kind::kOther) continue;
    const bool angle = IsIso230Angle(p.name);
    const double limit = angle ? kIso230MaxAngle_rad : kIso230MaxLinear_mm;
    for (double v : p.values) {
      if (!std::isfinite(v) || std::fabs(v) > limit) {
        return Fail(Error::kInputInvalid,
                    at + p.name + " = " + Number(v) + (angle ? " rad" : " mm") +
                        " is beyond the plausible " + Number(limit) + (angle ? " rad" : " mm") +
                        ": the file must hold " + (angle ? "rad" : "mm") +
                        (angle ? " (a file in µrad, mrad or arcsec is not read; convert it)"
                               : " (a file in µm is not read; divide by 1000)"));
      }
    }
  }
  return Outcome::Ok();
}

Expected<ModelFromIso230> ModelFromIso230Set(const Iso230Set& set) {
  VOLCOMP_TRY(CheckIso230Set(set));
  ModelFromIso230 out;
  std::map<std::string, const Iso230Parameter*> by_name;
  for (const Iso230Parameter& p : set.parameters) {
    const Iso230Kind kind = ClassifyIso230Name(p.name);
    if (kind == Iso230Kind::kOther) {
      const bool all_zero =
          std::all_of(p.values.begin(), p.values.end(), [](double v) { return v == 0.0; });
      if (!all_zero) {
        return Fail(Error::kInputInvalid,
                    At(set, p.line) + p.name +
                        " is not zero, and the 21-parameter model (X, Y, Z component errors, "
                        "C0Y, B0Z, A0Z) has no place for it: refused rather than dropped");
      }
      out.warnings.push_back(At(set, p.line) + p.name +
                             " is zero throughout and not part of the 21-parameter model: ignored");
      continue;
    }
    by_name[p.name] = &p;
  }
  std::vector<std::string> missing;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> position;
    for (int err = 0; err < 6; ++err) {
      const auto it = by_name.find(ComponentName(err, axis));
      if (it == by_name.end() || !it->second->tabulated) continue;
      position.insert(position.end(), it->second->arguments.begin(), it->second->arguments.end());
    }
    std::sort(position.begin(), position.end());
    position.erase(std::unique(position.begin(), position.end()), position.end());
    if (position.size() < 2) {
      return Fail(Error::kInputInvalid,
                  set.source + ": no table of a component error of " + kLinearAxes[axis] + " (EX" +
                      kLinearAxes[axis] + ", EY" + kLinearAxes[axis] + ", EZ" + kLinearAxes[axis] +
                      ", ... with at least 2 rows): the model needs the axis's range");
    }
    std::vector<model::AxisErrorSample> rows(position.size());
    for (int err = 0; err < 6; ++err) {
      const std::string name = ComponentName(err, axis);
      const auto it = by_name.find(name);
      if (it == by_name.end()) {
        missing.push_back(name);
        continue;
      }
      for (std::size_t i = 0; i < position.size(); ++i) {
        const double v = ValueAt(*it->second, position[i]);
        if (err < 3) {
          rows[i].linear_um[err] = v * kUmPerMm;
        } else {
          rows[i].angular_urad[err - 3] = v * kUradPerRad;
        }
      }
    }
    auto table = model::AxisErrorTable::Create(std::move(position), std::move(rows));
    if (!table.ok()) return Fail(Error::kInputInvalid, set.source + ": " + table.error().message);
    out.model.axes[static_cast<std::size_t>(axis)] = std::move(*table);
  }
  const std::pair<const char*, double*> squareness[] = {{"C0Y", &out.model.squareness.c0y_urad},
                                                        {"B0Z", &out.model.squareness.b0z_urad},
                                                        {"A0Z", &out.model.squareness.a0z_urad}};
  for (const auto& [name, value] : squareness) {
    const auto it = by_name.find(name);
    if (it == by_name.end()) {
      missing.push_back(name);
    } else {
      *value = it->second->values.front() * kUradPerRad;
    }
  }
  if (!missing.empty()) {
    std::string list;
    for (const std::string& n : missing) list += (list.empty() ? "" : ", ") + n;
    out.warnings.push_back(set.source + ": not in the file, taken as 0: " + list);
  }
  out.model.name = set.source;
  if (const Outcome valid = model::ValidateModel(out.model); !valid.ok()) {
    return Fail(Error::kInputInvalid, set.source + ": " + valid.error().message);
  }
  return out;
}

Iso230FromModel Iso230SetFromModel(const model::Model& m) {
  Iso230FromModel out;
  out.set.source = m.name;
  for (int axis = 0; axis < 3; ++axis) {
    const model::AxisErrorTable& t = m.axes[static_cast<std::size_t>(axis)];
    const bool negate = m.chain.workpiece_errors == model::ErrorSide::kCarriage &&
                        m.chain.carries_workpiece[static_cast<std::size_t>(axis)];
    const double sign = negate ? -1.0 : 1.0;
    if (negate) {
      out.notes.push_back(std::string("the errors of ") + kLinearAxes[axis] +
                          " are the carriage's own (workpiece_errors = carriage): written negated, "
                          "as errors of the tool relative to the workpiece");
    }
    for (int err = 0; err < 6; ++err) {
      Iso230Parameter p;
      p.name = ComponentName(err, axis);
      p.tabulated = true;
      p.argument = std::string(1, kLinearAxes[axis]);
      for (std::size_t i = 0; i < t.size(); ++i) {
        p.arguments.push_back(t.position_mm(i));
        const model::AxisErrorSample& s = t.row(i);
        p.values.push_back(err < 3 ? sign * s.linear_um[err] / kUmPerMm
                                   : sign * m.angle_scale * s.angular_urad[err - 3] / kUradPerRad);
      }
      out.set.parameters.push_back(std::move(p));
    }
  }
  const std::pair<const char*, double> squareness[] = {{"C0Y", m.squareness.c0y_urad},
                                                       {"B0Z", m.squareness.b0z_urad},
                                                       {"A0Z", m.squareness.a0z_urad}};
  for (const auto& [name, value] : squareness) {
    Iso230Parameter p;
    p.name = name;
    p.values = {value / kUradPerRad};
    out.set.parameters.push_back(std::move(p));
  }
  if (m.angle_scale != 1.0) {
    out.notes.push_back("angle_scale " + Number(m.angle_scale) +
                        " applied: the angles written are the table's times " +
                        Number(m.angle_scale));
  }
  const std::string chain = m.chain.ToString();
  if (chain != model::KinematicChain{}.ToString()) {
    out.notes.push_back("the kinematic chain " + chain +
                        " is not written (the formats have no place for it): configure it on "
                        "the controller; read back, the file gives the chain |XYZ");
  }
  if (m.tool_offset_mm.x != 0 || m.tool_offset_mm.y != 0 || m.tool_offset_mm.z != 0) {
    out.notes.push_back("the tool offset (" + Number(m.tool_offset_mm.x) + ", " +
                        Number(m.tool_offset_mm.y) + ", " + Number(m.tool_offset_mm.z) +
                        ") mm is not written: the controller takes it from its tool data");
  }
  if (m.formulation == model::Formulation::kDissertation) {
    out.notes.push_back(
        "the model uses the dissertation's formulation: its tables are written, but a reader "
        "(and the controller) applies the ISO 230-1 rigid-body formulation");
  } else if (m.order == model::Order::kFirst) {
    out.notes.push_back("the model's first-order setting is not written (read back: exact)");
  }
  return out;
}

}  // namespace volcomp::datasets
