// LinuxCNC joint compensation files (see linuxcnc_comp.hpp).
#include "volcomp/exporters/linuxcnc_comp.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "volcomp/builders/axis1d.hpp"

namespace volcomp::exporters {

Expected<LinuxcncComp> BuildLinuxcncComp(const model::PositioningData& data,
                                         LinuxcncCompType type,
                                         double spacing) {
  builders::Axis1dOptions o;
  o.reverse = builders::ReverseMode::kTables;
  o.spacing = spacing;
  VOLCOMP_TRY_ASSIGN(const builders::Axis1dTable t, builders::BuildAxis1d(data, o));
  if (t.forward.size() > kLinuxcncMaxCompEntries) {
    const double span = t.spacing * static_cast<double>(t.forward.size() - 1);
    char msg[256];
    std::snprintf(msg, sizeof msg,
                  "%zu compensation points, LinuxCNC loads at most %zu: use a spacing of at "
                  "least %.6g",
                  t.forward.size(), kLinuxcncMaxCompEntries,
                  span / static_cast<double>(kLinuxcncMaxCompEntries - 1));
    return Fail(Error::kInvalidArgument, msg);
  }
  // Corrections are in µm (arcsec); the file is in machine units, mm (deg).
  const double unit = data.rotary ? 1.0 / 3600.0 : 1.0 / 1000.0;
  LinuxcncComp c;
  c.type = type;
  c.max_residual = t.max_residual;
  for (std::size_t i = 0; i < t.forward.size(); ++i) {
    LinuxcncCompRow r;
    r.nominal = t.origin + t.spacing * static_cast<double>(i);
    const double fwd = t.forward[i] * unit;
    const double rev = (t.reverse.empty() ? t.forward[i] : t.reverse[i]) * unit;
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

}  // namespace volcomp::exporters
