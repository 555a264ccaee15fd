// LinuxCNC joint compensation files (see linuxcnc_comp.hpp).
#include "volcomp/exporters/linuxcnc_comp.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/builders/axis1d.hpp"
#include "volcomp/hosted/linuxcnc_units.hpp"

namespace volcomp::exporters {

Expected<LinuxcncComp> BuildLinuxcncComp(const model::PositioningData& data,
                                         LinuxcncCompType type,
                                         double spacing,
                                         LengthUnit unit) {
  // The test and the builder are in mm (deg); the file in the machine's unit.
  const double mm_per_unit = data.rotary ? 1.0 : MmPerUnit(unit);
  builders::Axis1dOptions o;
  o.reverse = builders::ReverseMode::kTables;
  o.spacing = spacing * mm_per_unit;
  VOLCOMP_TRY_ASSIGN(const builders::Axis1dTable t, builders::BuildAxis1d(data, o));
  if (t.forward.size() > kLinuxcncMaxCompEntries) {
    const double span = t.spacing * static_cast<double>(t.forward.size() - 1);
    char msg[256];
    std::snprintf(msg, sizeof msg,
                  "%zu compensation points, LinuxCNC loads at most %zu: use a spacing of at "
                  "least %.6g %s",
                  t.forward.size(), kLinuxcncMaxCompEntries,
                  span / static_cast<double>(kLinuxcncMaxCompEntries - 1) / mm_per_unit,
                  UnitName(unit, data.rotary));
    return Fail(Error::kInvalidArgument, msg);
  }
  std::vector<double> nominal, forward = t.forward, reverse = t.reverse;
  for (std::size_t i = 0; i < t.forward.size(); ++i) {
    nominal.push_back(t.origin + t.spacing * static_cast<double>(i));
  }
  // The lattice's last node lies up to a spacing past the last tested position, where nothing
  // was measured: the file ends at that position instead, with the correction there (the last
  // node of a one-cell lattice from the first to the last position).
  const double hi = data.position.back();
  if (nominal.size() >= 2 && nominal.back() > hi + 1e-9 * std::fmax(1.0, std::fabs(hi))) {
    builders::Axis1dOptions end = o;
    end.spacing = hi - t.origin;
    VOLCOMP_TRY_ASSIGN(const builders::Axis1dTable e, builders::BuildAxis1d(data, end));
    nominal.back() = hi;
    forward.back() = e.forward.back();
    if (!reverse.empty()) reverse.back() = e.reverse.back();
  }
  // Corrections are in µm (arcsec); the file is in machine units, mm or in (deg).
  LinuxcncComp c;
  c.type = type;
  c.unit = unit;
  c.max_residual = t.max_residual;
  for (std::size_t i = 0; i < nominal.size(); ++i) {
    LinuxcncCompRow r;
    r.nominal = data.rotary ? nominal[i] : FromMm(nominal[i], unit);
    const double fwd = ToMachineUnits(forward[i], data.rotary, unit);
    const double rev = ToMachineUnits(reverse.empty() ? forward[i] : reverse[i], data.rotary, unit);
    if (type == LinuxcncCompType::kTrims) {
      r.forward = fwd;
      r.reverse = rev;
    } else {
      r.forward = r.nominal - fwd;
      r.reverse = r.nominal - rev;
    }
    c.rows.push_back(r);
  }
  return c;
}

std::string FormatLinuxcncComp(const LinuxcncComp& comp) {
  std::string s;
  char line[128];
  for (const LinuxcncCompRow& r : comp.rows) {
    std::snprintf(line, sizeof line, "%.6f %.6f %.6f\n", r.nominal, r.forward, r.reverse);
    s += line;
  }
  return s;
}

std::string LinuxcncJointIni(int joint, const std::string& comp_file, LinuxcncCompType type) {
  return "[JOINT_" + std::to_string(joint) + "]\nCOMP_FILE = " + comp_file +
         "\nCOMP_FILE_TYPE = " + std::to_string(static_cast<int>(type)) + "\n";
}

namespace {

std::string Trim(const std::string& s) {
  const std::size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// The key of an INI line ("COMP_FILE = x" -> "COMP_FILE"), "" for a comment, blank or header.
std::string KeyOf(const std::string& line) {
  const std::string t = Trim(line);
  if (t.empty() || t[0] == '#' || t[0] == ';' || t[0] == '[') return "";
  const std::size_t eq = t.find('=');
  return eq == std::string::npos ? "" : Trim(t.substr(0, eq));
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {
      lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

}  // namespace

Expected<std::optional<LengthUnit>> LinuxcncLinearUnits(const std::string& ini,
                                                        const std::string& source) {
  const std::vector<std::string> lines = Lines(ini);
  bool in_traj = false, seen_traj = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string t = Trim(lines[i]);
    if (!t.empty() && t[0] == '[') {
      if (in_traj) break;  // LinuxCNC reads the first [TRAJ] section only
      in_traj = !seen_traj && t == "[TRAJ]";
      seen_traj = seen_traj || in_traj;
      continue;
    }
    if (!in_traj || KeyOf(lines[i]) != "LINEAR_UNITS") continue;
    std::string v = Trim(t.substr(t.find('=') + 1));
    v = v.substr(0, v.find_first_of(" \t#;"));
    if (const std::optional<double> mm = hosted::LinuxcncMmPerLinearUnit(v)) {
      return std::optional<LengthUnit>(*mm == 1.0 ? LengthUnit::kMm : LengthUnit::kInch);
    }
    return Fail(Error::kInvalidArgument,
                source + ":" + std::to_string(i + 1) + ": [TRAJ] LINEAR_UNITS = " + v +
                    ": volcomp writes mm or inch tables (mm, metric, 1.0; inch, in, imperial, "
                    "0.03937)");
  }
  return std::optional<LengthUnit>();
}

LinuxcncIniMerge MergeLinuxcncJointIni(const std::string& ini,
                                       const std::vector<LinuxcncJointComp>& joints,
                                       const std::string& source) {
  LinuxcncIniMerge m;
  const std::vector<std::string> original = Lines(ini);
  std::vector<std::string> lines = original;
  for (const LinuxcncJointComp& j : joints) {
    const std::string header = "[JOINT_" + std::to_string(j.joint) + "]";
    const std::string values[2] = {j.comp_file, std::to_string(static_cast<int>(j.type))};
    const char* const keys[2] = {"COMP_FILE", "COMP_FILE_TYPE"};
    std::vector<std::size_t> headers;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (Trim(lines[i]) == header) headers.push_back(i);
    }
    if (headers.empty()) {
      if (!lines.empty() && !Trim(lines.back()).empty()) lines.emplace_back();
      lines.push_back(header);
      for (int k = 0; k < 2; ++k) lines.push_back(std::string(keys[k]) + " = " + values[k]);
      continue;
    }
    if (headers.size() > 1) {
      std::string at;  // line numbers in the file as it was
      for (std::size_t i = 0, seen = 0; i < original.size(); ++i) {
        if (Trim(original[i]) != header || seen++ == 0) continue;
        at += (at.empty() ? "" : ", ") + std::to_string(i + 1);
      }
      m.warnings.push_back(source + ": " + header + " appears " + std::to_string(headers.size()) +
                           " times (again at line" + std::string(headers.size() > 2 ? "s " : " ") +
                           at +
                           "): LinuxCNC reads the first only; the lines went into the first, "
                           "merge or delete the others");
    }
    // The first section: from its header to the next header.
    const std::size_t begin = headers[0] + 1;
    std::size_t end = begin;
    while (end < lines.size() && Trim(lines[end]).rfind('[', 0) != 0) ++end;
    std::size_t last_key = headers[0];
    bool done[2] = {false, false};
    std::size_t i = begin;
    while (i < end) {
      const std::string key = KeyOf(lines[i]);
      const int k = key == keys[0] ? 0 : (key == keys[1] ? 1 : -1);
      const std::string old = k >= 0 ? Trim(lines[i].substr(lines[i].find('=') + 1)) : "";
      if (k >= 0 && done[k]) {  // LinuxCNC would read the first: one is enough
        m.warnings.push_back(source + ": " + header + " had a second " + keys[k] + " (" + old +
                             "): removed");
        lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
        --end;
        continue;
      }
      if (!key.empty()) last_key = i;
      if (k >= 0) {
        if (old != values[k]) {
          m.warnings.push_back(source + ": " + header + " " + keys[k] + " was " + old + ", now " +
                               values[k]);
        }
        lines[i] = std::string(keys[k]) + " = " + values[k];
        done[k] = true;
      }
      ++i;
    }
    std::vector<std::string> add;
    for (int k = 0; k < 2; ++k) {
      if (!done[k]) add.push_back(std::string(keys[k]) + " = " + values[k]);
    }
    lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(last_key + 1), add.begin(), add.end());
  }
  for (const std::string& l : lines) m.text += l + "\n";
  return m;
}

}  // namespace volcomp::exporters
