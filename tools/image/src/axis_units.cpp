// Axis option parsing and unit conversion.
#include "volcomp/image/axis_units.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "volcomp/tools/csv.hpp"

namespace volcomp::image {
namespace {

Unexpected<Failure> UsageFailure(const std::string& message) {
  return Fail(Error::kUsage, message);
}

Expected<char> CheckName(char c, const std::string& option) {
  const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const char* p = table::kAxisNames; *p != '\0'; ++p) {
    if (*p == u) return u;
  }
  return UsageFailure(option + ": \"" + std::string(1, c) + "\" is not an axis name (XYZABCUVW)");
}

}  // namespace

bool IsRotaryName(char name) { return name == 'A' || name == 'B' || name == 'C'; }

std::string ResolutionText(uint32_t resolution_e9, bool rotary) {
  // steps per unit = 1e9 / resolution_e9; nm (µ°) per step = pm (ndeg) per step / 1000.
  const char* per_step = rotary ? "µ°/step" : "nm/step";
  char text[96];
  if (resolution_e9 == 0) {
    std::snprintf(text, sizeof text, "0 %s", per_step);
  } else {
    std::snprintf(text, sizeof text, "%.9g steps/%s (%.9g %s)", 1e9 / resolution_e9,
                  rotary ? "deg" : "mm", resolution_e9 / 1000.0, per_step);
  }
  return text;
}

std::string ColumnName(char axis) {
  return std::string(1, static_cast<char>(std::tolower(static_cast<unsigned char>(axis))));
}

Expected<std::map<char, std::string>> ParseAxisAssignments(const std::string& text,
                                                           const std::string& option) {
  std::map<char, std::string> out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    const size_t eq = item.find('=');
    if (eq != 1 || item.size() < 3) {
      return UsageFailure(option + ": expected AXIS=VALUE items like X=1000, got \"" + item + "\"");
    }
    VOLCOMP_TRY_ASSIGN(const char name, CheckName(item[0], option));
    if (out.count(name)) return UsageFailure(option + ": axis " + std::string(1, name) + " twice");
    out[name] = item.substr(2);
    start = end + 1;
  }
  return out;
}

Expected<std::vector<char>> ParseAxisList(const std::string& text, const std::string& option) {
  std::vector<char> out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    if (item.size() != 1) return UsageFailure(option + ": expected a list like X,Y,Z");
    VOLCOMP_TRY_ASSIGN(const char name, CheckName(item[0], option));
    if (std::find(out.begin(), out.end(), name) != out.end()) {
      return UsageFailure(option + ": axis " + std::string(1, name) + " twice");
    }
    out.push_back(name);
    start = end + 1;
  }
  return out;
}

Expected<std::vector<AxisDef>> MakeAxisDefs(const std::vector<char>& names,
                                            const std::string& resolution_nm,
                                            const std::string& steps_per_unit) {
  if (!resolution_nm.empty() && !steps_per_unit.empty()) {
    return UsageFailure(
        "give either --resolution-nm or --steps-per-unit, not both (they state the same step "
        "size twice and could disagree)");
  }
  std::map<char, std::string> res, spu;
  if (!resolution_nm.empty()) {
    VOLCOMP_TRY_ASSIGN(res, ParseAxisAssignments(resolution_nm, "--resolution-nm"));
  }
  if (!steps_per_unit.empty()) {
    VOLCOMP_TRY_ASSIGN(spu, ParseAxisAssignments(steps_per_unit, "--steps-per-unit"));
  }
  std::vector<AxisDef> defs;
  for (char name : names) {
    AxisDef d;
    d.name = name;
    d.kind = IsRotaryName(name) ? table::AxisKind::kRotary : table::AxisKind::kLinear;
    double e9 = 0;
    const std::string what = std::string("axis ") + name;
    if (const auto r = res.find(name); r != res.end()) {
      const auto v = tools::ParseDouble(r->second);
      if (!v || *v <= 0)
        return UsageFailure("--resolution-nm: " + what + " needs a positive number");
      // Linear: nm/step -> pm/step. Rotary: micro-degrees/step -> nano-degrees/step.
      e9 = *v * 1000.0;
    } else if (const auto s = spu.find(name); s != spu.end()) {
      const auto v = tools::ParseDouble(s->second);
      if (!v || *v <= 0) {
        return UsageFailure("--steps-per-unit: " + what + " needs a positive number");
      }
      e9 = 1e9 / *v;
    } else {
      return UsageFailure(what + " needs --resolution-nm or --steps-per-unit");
    }
    const double rounded = std::round(e9);
    if (std::fabs(e9 - rounded) > 1e-6 * std::max(1.0, e9) || rounded < 1 ||
        rounded > 4294967295.0) {
      return UsageFailure(what +
                          ": the step size must be a whole number of 1e-9 units (pm or "
                          "nano-degrees) between 1 and 2^32-1");
    }
    d.resolution_e9 = static_cast<uint32_t>(rounded);
    defs.push_back(d);
  }
  return defs;
}

}  // namespace volcomp::image
