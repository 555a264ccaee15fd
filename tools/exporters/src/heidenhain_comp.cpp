// HEIDENHAIN .COM / .CMA tables (see heidenhain_comp.hpp).
#include "volcomp/exporters/heidenhain_comp.hpp"

#include <cmath>
#include <cstdio>

namespace volcomp::exporters {
namespace {

// "%+.<d>f" without a "-0.0…", left-justified in `width` (0: no padding).
std::string Signed(double v, int decimals, int width) {
  const double scale = std::pow(10.0, decimals);
  double r = std::round(v * scale) / scale;
  if (r == 0) r = 0;
  char n[48];
  std::snprintf(n, sizeof n, "%+.*f", decimals, r);
  std::string out = n;
  if (static_cast<int>(out.size()) < width) out += std::string(width - out.size(), ' ');
  return out;
}

std::string Pad(const std::string& s, std::size_t width) {
  return s.size() < width ? s + std::string(width - s.size(), ' ') : s + " ";
}

// The legacy spacing rule: spacing = 2^n × 0.1 µm.
bool PowerOfTwoSpacing(double spacing_mm) {
  const double units = spacing_mm / 1e-4;
  const double n = std::round(std::log2(units));
  return units >= 1 && std::fabs(std::ldexp(1.0, static_cast<int>(n)) - units) < 1e-6 * units;
}

}  // namespace

Expected<HeidenhainTable> BuildHeidenhainCom(const HeidenhainAxis& axis,
                                             HeidenhainControl control) {
  const std::string ax(1, axis.axis);
  const ErrorTable& t = axis.table;
  if (t.rotary) {
    return Fail(Error::kInvalidArgument,
                ax + ": a rotary axis: the .COM table's unit for rotary axes is not in volcomp's "
                     "sources; export linear axes only");
  }
  if (control == HeidenhainControl::kTnc4xx) {
    const std::string tnc = "the TNC 4xx (.COM)";
    auto spacing = RequireEqualSpacing(t, tnc);
    if (!spacing.ok()) return Fail(Error::kInvalidArgument, ax + ": " + spacing.error().message);
    if (!PowerOfTwoSpacing(*spacing)) {
      const double units = *spacing / 1e-4;
      const int lo = static_cast<int>(std::floor(std::log2(std::fmax(units, 1.0))));
      char msg[320];
      std::snprintf(msg, sizeof msg,
                    "%s: spacing %.6g mm is not a power of two times 0.1 um, which the TNC 4xx "
                    "needs: give --spacing %s=%.4f or %s=%.4f",
                    ax.c_str(), *spacing, ax.c_str(), std::ldexp(1.0, lo) * 1e-4, ax.c_str(),
                    std::ldexp(1.0, lo + 1) * 1e-4);
      return Fail(Error::kInvalidArgument, msg);
    }
    const Expected<void> count = RequirePointLimit(t, kHeidenhainLegacyMaxPoints, tnc);
    if (!count.ok()) return Fail(Error::kInvalidArgument, ax + ": " + count.error().message);
  }
  HeidenhainTable h;
  h.file_name = "AXIS_" + ax + ".COM";
  h.text = "BEGIN " + h.file_name + " MM\n" + Pad("NR", 5) + Pad("AXISPOS", 14) +
           Pad("BACKLASH", 14) + ax + "\n";
  for (std::size_t i = 0; i < t.position.size(); ++i) {
    const double value = ToMachineUnits(t.forward_um[i], false);
    const double backlash =
        t.reverse_um.empty() ? 0.0 : ToMachineUnits(t.reverse_um[i] - t.forward_um[i], false);
    h.largest_mm = std::fmax(h.largest_mm, std::fabs(value));
    h.largest_backlash_mm = std::fmax(h.largest_backlash_mm, std::fabs(backlash));
    h.text += Pad(std::to_string(i), 5) + Signed(t.position[i], 6, 14) + Signed(backlash, 4, 14) +
              Signed(value, 4, 0) + "\n";
  }
  h.text += "[END]\n";
  return h;
}

std::string HeidenhainCma(const std::string& cma_name,
                          const std::vector<char>& axes,
                          const std::vector<std::string>& com_files) {
  std::string head = Pad("NR", 5), row = Pad("0", 5);
  for (std::size_t i = 0; i < axes.size(); ++i) {
    head += Pad(std::string(1, axes[i]), 16);
    row += Pad(com_files[i], 16);
  }
  return "BEGIN " + cma_name + "\n" + head + "ACTIVE\n" + row + "*\n[END]\n";
}

std::string HeidenhainNotes(const std::vector<HeidenhainAxis>& axes,
                            const std::vector<HeidenhainTable>& tables,
                            const std::string& cma_name) {
  std::string s =
      "volcomp export heidenhain: nonlinear axis-error compensation tables (TNC .COM + .CMA)\n"
      "\n"
      "Values: the measured error, actual - nominal, in mm, as HEIDENHAIN's example plots it\n"
      "(\"Error in Z\", MANUALplus 620 manual pp. 716/718) and as the public writer\n"
      "Paolico/AxisCorection writes it (mean deviation / 1000, no change of sign). Not yet\n"
      "confirmed on a machine: check one point, and export with --negate if the error doubles.\n"
      "BACKLASH: the extra error moving negative (reverse - forward) at that position; the\n"
      "meaning of the column is our reading of the manual, unconfirmed.\n"
      "\n";
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const ErrorTable& t = axes[i].table;
    char line[256];
    std::snprintf(line, sizeof line, "%s: from %s, %zu points, %.6f to %.6f mm, %s\n",
                  tables[i].file_name.c_str(), axes[i].source.c_str(), t.position.size(),
                  t.position.front(), t.position.back(),
                  t.reverse_um.empty() ? "one direction (BACKLASH 0)" : "both directions");
    s += line;
    if (t.zero_at) {
      std::snprintf(line, sizeof line, "  zeroed at %.6f mm\n", *t.zero_at);
      s += line;
    }
    if (t.negated) s += "  NEGATED (--negate): the values are -(actual - nominal)\n";
  }
  s += cma_name + ": names the .COM files (column = the axis they depend on), line 0 active\n";
  return s;
}

}  // namespace volcomp::exporters
