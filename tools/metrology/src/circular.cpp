// ISO 230-4 circular test evaluation.
#include "volcomp/metrology/circular.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <utility>

#include "volcomp/metrology/polar_fit.hpp"
#include "volcomp/report/format.hpp"

namespace volcomp::metrology {
namespace {

// A gap between neighbouring readings wider than this is reported: the least-squares centre leans
// towards the readings and H interpolates across the gap. 8 equally spaced readings pass.
constexpr double kWideGapDeg = 45.0 + 1e-6;
constexpr double kSameAngleDeg = 1e-9;

double Wrap360(double deg) {
  const double r = std::fmod(deg, 360.0);
  return r < 0 ? r + 360.0 : r;
}

using Profile = std::vector<std::pair<double, double>>;  // (angle in [0, 360), value), ascending

// The readings sorted by angle, readings at the same angle averaged.
Profile SortedProfile(const std::vector<double>& angle_deg, const std::vector<double>& value) {
  Profile s;
  for (std::size_t i = 0; i < angle_deg.size(); ++i)
    s.emplace_back(Wrap360(angle_deg[i]), value[i]);
  std::sort(s.begin(), s.end());
  Profile out;
  std::size_t i = 0;
  while (i < s.size()) {
    std::size_t j = i;
    double sum = 0;
    while (j < s.size() && s[j].first - s[i].first <= kSameAngleDeg) sum += s[j++].second;
    out.emplace_back(s[i].first, sum / static_cast<double>(j - i));
    i = j;
  }
  // 0° and 360° (taken as 0°) may both be present under slightly different round-off.
  if (out.size() > 1 && out.back().first > 360.0 - kSameAngleDeg) {
    out.front().second = (out.front().second + out.back().second) / 2.0;
    out.pop_back();
  }
  return out;
}

// The profile at `angle` by linear interpolation between its two neighbouring readings,
// periodic in angle (the profile holds at least 2 distinct angles).
double InterpolateAt(const Profile& p, double angle) {
  const double a = Wrap360(angle);
  std::size_t hi = 0;
  while (hi < p.size() && p[hi].first < a) ++hi;
  if (hi < p.size() && p[hi].first - a <= kSameAngleDeg) return p[hi].second;
  const auto& upper = hi == p.size() ? p.front() : p[hi];
  const auto& lower = hi == 0 ? p.back() : p[hi - 1];
  const double span = Wrap360(upper.first - lower.first);
  const double from_lower = Wrap360(a - lower.first);
  if (span <= 0.0) return lower.second;
  return lower.second + (upper.second - lower.second) * from_lower / span;
}

Outcome CheckPath(const CircularPath& p,
                  const std::string& name,
                  std::vector<std::string>* warnings) {
  const Profile s = SortedProfile(p.angle_deg, p.deviation_um);
  if (s.size() < 3) {
    return Fail(Error::kInputInvalid, "the " + name + " path has readings at " +
                                          std::to_string(s.size()) +
                                          " distinct angle(s); at least 3 are needed");
  }
  std::size_t widest = 0;
  double widest_gap = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double gap = Wrap360(s[(i + 1) % s.size()].first - s[i].first);
    if (gap > widest_gap) widest = i, widest_gap = gap;
  }
  if (widest_gap > kWideGapDeg) {
    warnings->push_back("the " + name + " path has no reading between " +
                        report::FormatNumber(s[widest].first) + "° and " +
                        report::FormatNumber(s[(widest + 1) % s.size()].first) + "° (" +
                        report::FormatNumber(widest_gap) +
                        "°): G, H and the centre are evaluated over less than the circle");
  }
  return Outcome::Ok();
}

// Trimmed and lower-case.
std::string Lower(const std::string& text) {
  const std::size_t b = text.find_first_not_of(" \t");
  const std::size_t e = text.find_last_not_of(" \t");
  std::string s = b == std::string::npos ? "" : text.substr(b, e - b + 1);
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

Expected<CircularResult> EvaluateCircular(const CircularData& data) {
  CircularResult r;
  r.points_cw = data.cw.angle_deg.size();
  r.points_ccw = data.ccw.angle_deg.size();
  r.has_cw = r.points_cw > 0;
  r.has_ccw = r.points_ccw > 0;
  const std::string prefix = data.source.empty() ? "" : data.source + ": ";
  if (!r.has_cw && !r.has_ccw) return Fail(Error::kInputInvalid, prefix + "no readings");
  for (const CircularPath* p : {&data.cw, &data.ccw}) {
    if (p->angle_deg.size() != p->deviation_um.size()) {
      return Fail(Error::kInvalidArgument, prefix + "as many angles as deviations are needed");
    }
  }
  std::vector<double> all_angle, all_dev;
  for (const CircularPath* p : {&data.cw, &data.ccw}) {
    all_angle.insert(all_angle.end(), p->angle_deg.begin(), p->angle_deg.end());
    all_dev.insert(all_dev.end(), p->deviation_um.begin(), p->deviation_um.end());
  }
  auto path_g = [&](const CircularPath& p, const char* name) -> Expected<double> {
    if (auto ok = CheckPath(p, name, &r.warnings); !ok.ok()) {
      return Fail(Error::kInputInvalid, prefix + ok.error().message);
    }
    VOLCOMP_TRY_ASSIGN(const CentreFit c, FitLeastSquaresCentre(p.angle_deg, p.deviation_um));
    return ValueAbout(p.angle_deg, p.deviation_um, c.a, c.b);
  };
  if (r.has_cw) {
    VOLCOMP_TRY_ASSIGN(r.G_cw_um, path_g(data.cw, "clockwise (cw)"));
  }
  if (r.has_ccw) {
    VOLCOMP_TRY_ASSIGN(r.G_ccw_um, path_g(data.ccw, "counter-clockwise (ccw)"));
  }
  VOLCOMP_TRY_ASSIGN(const CentreFit common, FitLeastSquaresCentre(all_angle, all_dev));
  r.centre_offset_x_um = common.a;
  r.centre_offset_y_um = common.b;
  r.mean_radius_dev_um = common.mean;
  r.F_max_um = *std::max_element(all_dev.begin(), all_dev.end());
  r.F_min_um = *std::min_element(all_dev.begin(), all_dev.end());
  if (r.has_cw && r.has_ccw) {
    r.G_b_um = ValueAbout(all_angle, all_dev, common.a, common.b);
    // Both paths about the common centre; the other path interpolated at every reading's angle.
    const Profile cw =
        SortedProfile(data.cw.angle_deg,
                      ResidualsAbout(data.cw.angle_deg, data.cw.deviation_um, common.a, common.b));
    const Profile ccw = SortedProfile(
        data.ccw.angle_deg,
        ResidualsAbout(data.ccw.angle_deg, data.ccw.deviation_um, common.a, common.b));
    r.H_um = -1.0;
    auto compare = [&r](const Profile& from, const Profile& other) {
      for (const auto& [angle, value] : from) {
        const double h = std::fabs(value - InterpolateAt(other, angle));
        if (h > r.H_um) r.H_um = h, r.H_angle_deg = angle;
      }
    };
    compare(cw, ccw);
    compare(ccw, cw);
  }
  return r;
}

Expected<CircularData> ReadCircularCsv(const tools::CsvTable& csv, double nominal_radius_mm) {
  CircularData data;
  data.source = csv.source();
  data.nominal_radius_mm = nominal_radius_mm;
  VOLCOMP_TRY(csv.Require("direction"));
  VOLCOMP_TRY(csv.Require("angle_deg"));
  const bool by_radius = nominal_radius_mm > 0;
  if (by_radius) {
    if (!csv.find("radius_mm")) {
      return Fail(csv.LineFailure(csv.header_line(),
                                  "missing column \"radius_mm\" (--radius reads measured radii)"));
    }
  } else if (!csv.find("deviation_um")) {
    return Fail(csv.LineFailure(
        csv.header_line(),
        csv.find("radius_mm")
            ? "column \"radius_mm\" holds measured radii: give the nominal radius with --radius"
            : "missing column \"deviation_um\" (or radius_mm with --radius)"));
  }
  if (csv.rows().empty()) {
    return Fail(csv.LineFailure(csv.header_line(), "no data rows after the header"));
  }
  for (const tools::CsvRow& row : csv.rows()) {
    tools::CsvFields f(row);
    const std::string dir_text = f.Text("direction");
    const std::string dir = Lower(dir_text);
    const double angle = f.Number("angle_deg");
    const double dev =
        by_radius ? (f.Number("radius_mm") - nominal_radius_mm) * 1000.0 : f.Number("deviation_um");
    VOLCOMP_TRY(f.status());
    CircularPath* path = nullptr;
    if (dir == "cw") path = &data.cw;
    if (dir == "ccw") path = &data.ccw;
    if (path == nullptr) {
      return Fail(csv.LineFailure(
          row.line(), "column \"direction\": \"" + dir_text + "\" is neither cw nor ccw"));
    }
    path->angle_deg.push_back(angle);
    path->deviation_um.push_back(dev);
  }
  return data;
}

}  // namespace volcomp::metrology
