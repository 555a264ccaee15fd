// The hobby writers' shared conversions (see hobby_common.hpp).
#include "volcomp/exporters/hobby_common.hpp"

#include <cmath>
#include <cstdio>

namespace volcomp::exporters {
namespace {

constexpr double kUradPerRad = 1e6;

double Rad(const std::optional<PlaneSquareness>& p) { return p ? p->urad / kUradPerRad : 0.0; }

std::optional<double> Signed(bool given, double value, bool negate) {
  if (!given) return std::nullopt;
  return negate ? -value : value;
}

}  // namespace

SkewValues KlipperMarlinFactors(const HobbySquareness& s, bool negate) {
  const double c0y = Rad(s.xy), b0z = Rad(s.xz), a0z = Rad(s.yz);
  SkewValues v;
  v.xy = Signed(s.xy.has_value(), -std::tan(c0y), negate);
  v.xz = Signed(s.xz.has_value(), std::tan(b0z), negate);
  v.yz = Signed(s.yz.has_value(), -std::tan(a0z) / std::cos(b0z), negate);
  return v;
}

SkewValues ReprapTangents(const HobbySquareness& s, bool negate) {
  return KlipperMarlinFactors(s, !negate);  // tangent = −factor
}

Expected<AxisBacklash> BacklashFromTest(char axis,
                                        const std::string& source,
                                        const model::PositioningData& data,
                                        bool negate_test) {
  if (data.dev_reverse.empty() || data.dev_reverse.size() != data.dev_forward.size()) {
    return Fail(Error::kInvalidArgument,
                source + ": a test in one direction has no reversal: the backlash of " +
                    std::string(1, axis) + " needs a test in both directions");
  }
  const double sign = negate_test ? -1.0 : 1.0;
  AxisBacklash b;
  b.axis = axis;
  b.source = source;
  b.rotary = data.rotary;
  b.test_negated = negate_test;
  b.targets = static_cast<int>(data.dev_forward.size());
  std::vector<double> lost;  // x̄↓_j − x̄↑_j per target
  double sum = 0;
  for (std::size_t j = 0; j < data.dev_forward.size(); ++j) {
    lost.push_back(sign * (data.dev_reverse[j] - data.dev_forward[j]));
    sum += lost.back();
    b.reversal_max_um = std::fmax(b.reversal_max_um, std::fabs(lost.back()));
  }
  b.lost_motion_um = sum / static_cast<double>(lost.size());
  b.reversal_mean_um = -b.lost_motion_um;
  for (const double l : lost) b.spread_um = std::fmax(b.spread_um, std::fabs(l - b.lost_motion_um));
  return b;
}

Expected<void> RequireLostMotion(const AxisBacklash& b, const std::string& controller) {
  if (b.lost_motion_um >= 0) return {};
  const char* unit = b.rotary ? "arcsec" : "um";
  return Fail(Error::kInvalidArgument,
              b.source + ": " + std::string(1, b.axis) + " backlash " +
                  FixedDecimals(b.lost_motion_um, 3) + " " + unit +
                  " (mean reversal B = " + (b.reversal_mean_um >= 0 ? "+" : "") +
                  FixedDecimals(b.reversal_mean_um, 3) + " " + unit +
                  ": the reverse deviations lie below the forward ones): " + controller +
                  " takes a backlash >= 0 (the distance added when the axis reverses). If the "
                  "instrument counted the other way, negate the test (--negate-tests)");
}

Expected<void> RequireBacklashAxis(const AxisBacklash& b,
                                   const std::string& axes,
                                   bool rotary_ok,
                                   const std::string& controller) {
  if (axes.find(b.axis) == std::string::npos) {
    return Fail(Error::kInvalidArgument, b.source + ": axis " + std::string(1, b.axis) + ": " +
                                             controller + " takes the backlash of " + axes);
  }
  if (b.rotary && !rotary_ok) {
    return Fail(Error::kInvalidArgument,
                b.source + ": " + std::string(1, b.axis) + " is a rotary axis: the unit of " +
                    controller + "'s backlash on a rotary axis is not in volcomp's sources");
  }
  return {};
}

Expected<std::string> BacklashWords(const std::vector<AxisBacklash>& backlash,
                                    const std::string& axes,
                                    const std::string& controller) {
  std::string words;
  for (const AxisBacklash& b : backlash) {
    VOLCOMP_TRY(RequireBacklashAxis(b, axes, false, controller));
    VOLCOMP_TRY(RequireLostMotion(b, controller));
    words += std::string(" ") + b.axis + FixedDecimals(BacklashInFileUnits(b), 4);
  }
  return words;
}

std::string SkewWords(const SkewValues& v, const char* letters, double scale, int decimals) {
  std::string words;
  const std::optional<double>* values[] = {&v.xy, &v.xz, &v.yz};
  for (int i = 0; i < 3; ++i) {
    if (*values[i])
      words += std::string(" ") + letters[i] + FixedDecimals(**values[i] * scale, decimals);
  }
  return words;
}

std::string PlanesNotGiven(const std::string& comment, const SkewValues& v) {
  std::string missing;
  if (!v.xy) missing += "XY";
  if (!v.xz) missing += std::string(missing.empty() ? "" : ", ") + "XZ";
  if (!v.yz) missing += std::string(missing.empty() ? "" : ", ") + "YZ";
  if (missing.empty()) return "";
  return comment + missing +
         ": no squareness given, not written (the controller keeps its value)\n";
}

double BacklashInFileUnits(const AxisBacklash& b) {
  return b.rotary ? b.lost_motion_um / 3600.0 : b.lost_motion_um / 1000.0;
}

std::string FixedDecimals(double value, int decimals) {
  // As long as the number needs (a large value is never cut short).
  std::string text(static_cast<std::size_t>(std::snprintf(nullptr, 0, "%.*f", decimals, value)),
                   '\0');
  std::snprintf(text.data(), text.size() + 1, "%.*f", decimals, value);
  if (!text.empty() && text[0] == '-' && text.find_first_not_of("-0.") == std::string::npos)
    text.erase(0, 1);
  return text;
}

std::string HobbyInputLines(const std::string& comment,
                            const std::string& command,
                            const HobbySquareness& squareness,
                            const std::vector<AxisBacklash>& backlash) {
  std::string text = comment + "written by volcomp " + command + "\n";
  const struct {
    const char* plane;
    const char* name;
    const std::optional<PlaneSquareness>* p;
  } planes[] = {
      {"XY", "C0Y", &squareness.xy}, {"XZ", "B0Z", &squareness.xz}, {"YZ", "A0Z", &squareness.yz}};
  for (const auto& p : planes) {
    if (!*p.p) continue;
    text += comment + "squareness " + p.plane + ": " + p.name + " = " +
            FixedDecimals((*p.p)->urad, 1) + " urad (" + (*p.p)->source + ")\n";
  }
  for (const AxisBacklash& b : backlash) {
    const char* unit = b.rotary ? "arcsec" : "um";
    text += comment + "backlash " + std::string(1, b.axis) + ": " +
            FixedDecimals(b.lost_motion_um, 2) + " " + unit + " = -(mean reversal B) over " +
            std::to_string(b.targets) + " targets, a constant leaves up to " +
            FixedDecimals(b.spread_um, 2) + " " + unit + (b.test_negated ? ", test negated" : "") +
            " (" + b.source + ")\n";
  }
  return text;
}

}  // namespace volcomp::exporters
