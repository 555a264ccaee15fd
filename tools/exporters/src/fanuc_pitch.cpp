// FANUC pitch error compensation entry sheet (see fanuc_pitch.hpp).
#include "volcomp/exporters/fanuc_pitch.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace volcomp::exporters {
namespace {

constexpr const char* kHeader =
    "FANUC PITCH ERROR COMPENSATION - ENTRY SHEET (volcomp export fanuc)\n"
    "NOT A PUNCH FILE: the block syntax of pitch data in a FANUC parameter file is not\n"
    "confirmed by volcomp's sources. Enter the values on the control's parameter and pitch\n"
    "error compensation screens.\n"
    "Sign: the values are corrections, -(actual - nominal), as FANUC enters the compensation\n"
    "amount (0i-PB parameter manual: the compensation is the running sum of the increments).\n"
    "FANUC's own wording of the sign is not in volcomp's sources (secondary: cnc.wiki;\n"
    "Mitsubishi's analogue is interval - actual movement): after entry, check one point; if\n"
    "the error doubled, export with --negate.\n"
    "Increments: the value of point n is output while moving through the interval that ends\n"
    "at n (a staircase, not interpolated).\n";

// The point table of one direction: increments of the rounded running sum.
std::vector<FanucPoint> Points(const ErrorTable& t,
                               const std::vector<double>& error_um,
                               int first,
                               std::size_t r,
                               double count) {
  std::vector<FanucPoint> points;
  std::vector<long> total;
  for (const double e : error_um)
    total.push_back(std::lround(-ToMachineUnits(e, false, t.unit) / count));
  for (std::size_t i = (r == 0 ? 0 : 1); i < t.position.size(); ++i) {
    FanucPoint p;
    p.number = first + static_cast<int>(points.size());
    p.to = t.position[i];
    p.from = p.to - t.spacing;
    p.total = static_cast<int>(total[i]);
    p.increment = i == 0 ? 0 : static_cast<int>(total[i] - total[i - 1]);
    points.push_back(p);
  }
  return points;
}

// Decimals of a position on the sheet: 0.1 µm in mm, 0.00001 in (0.25 µm) in inches.
int Decimals(LengthUnit unit) { return unit == LengthUnit::kInch ? 5 : 4; }

// The point furthest outside −128..127 of either direction, refused with the magnification that
// fits it.
Expected<void> CheckIncrements(char axis, const FanucAxisSheet& s, const FanucOptions& o) {
  const FanucPoint* worst = nullptr;
  double worst_ratio = 1;  // |increment| / the limit on its side
  for (const auto* points : {&s.forward, &s.reverse}) {
    for (const FanucPoint& p : *points) {
      const double ratio = static_cast<double>(p.increment) /
                           (p.increment < 0 ? kFanucMinIncrement : kFanucMaxIncrement);
      if (ratio > worst_ratio) {
        worst = &p;
        worst_ratio = ratio;
      }
    }
  }
  if (worst == nullptr) return {};
  const int needed = static_cast<int>(std::ceil(o.magnification * worst_ratio));
  char msg[320];
  std::snprintf(msg, sizeof msg,
                "%c: point %d (%.*f to %.*f %s) needs an increment of %d counts, FANUC takes "
                "%d..%d per point: give --magnification %d or more, or a smaller --spacing",
                axis, worst->number, Decimals(o.unit), worst->from, Decimals(o.unit), worst->to,
                UnitName(o.unit, false), worst->increment, kFanucMinIncrement, kFanucMaxIncrement,
                needed);
  return Fail(Error::kInvalidArgument, msg);
}

std::string Line(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string Line(const char* format, ...) {
  char s[256];
  va_list args;
  va_start(args, format);
  std::vsnprintf(s, sizeof s, format, args);
  va_end(args);
  return s;
}

std::string PointRows(const std::vector<FanucPoint>& points, LengthUnit unit) {
  std::string s =
      Line("  POINT  INTERVAL (%s)                  INCREMENT  TOTAL\n", UnitName(unit, false));
  for (const FanucPoint& p : points) {
    const std::string interval = Line("%.*f .. %.*f", Decimals(unit), p.from, Decimals(unit), p.to);
    s += Line("  %-6d %-30s %+-10d %+d\n", p.number, interval.c_str(), p.increment, p.total);
  }
  return s;
}

}  // namespace

Expected<FanucSheet> BuildFanucSheet(const std::vector<FanucAxis>& axes,
                                     const FanucOptions& options) {
  const char* unit = UnitName(options.unit, false);
  const int dp = Decimals(options.unit);
  if (!(options.detection_unit > 0) || options.magnification < 1) {
    return Fail(Error::kInvalidArgument,
                Line("detection unit %.6g %s and magnification %d: the unit must be > 0 and the "
                     "magnification (3623) at least 1",
                     options.detection_unit, unit, options.magnification));
  }
  const double count = options.detection_unit * options.magnification;
  FanucSheet sheet;
  sheet.text = kHeader;
  sheet.text +=
      Line("Units: 1 count = detection unit %.6g %s x magnification (3623) %d = %.6g %s.\n",
           options.detection_unit, unit, options.magnification, count, unit);
  if (options.unit == LengthUnit::kInch) {
    sheet.text +=
        "An inch machine: positions, 3624 and the detection unit in inches (the increment\n"
        "system's inch unit, IS-B 0.0001 in).\n";
  }
  int next = 0;
  for (const FanucAxis& a : axes) {
    const ErrorTable& t = a.table;
    if (!t.rotary && t.unit != options.unit) {
      return Fail(Error::kInvalidArgument, Line("%c: a table in %s on a sheet in %s", a.axis,
                                                UnitName(t.unit, false), unit));
    }
    if (t.rotary) {
      return Fail(Error::kInvalidArgument,
                  Line("%c: a rotary axis: FANUC's 3625 and the zero sum per revolution are not "
                       "written yet; export linear axes only",
                       a.axis));
    }
    auto spacing = RequireEqualSpacing(t, "FANUC pitch error compensation (3624)");
    if (!spacing.ok()) {
      return Fail(Error::kInvalidArgument, std::string(1, a.axis) + ": " + spacing.error().message);
    }
    if (!t.zero_at) return Fail(Error::kInvalidArgument, Line("%c: no reference position", a.axis));
    std::size_t r = 0;
    while (r < t.position.size() &&
           std::fabs(t.position[r] - *t.zero_at) > 1e-6 * std::fmax(1.0, std::fabs(*t.zero_at))) {
      ++r;
    }
    if (r == t.position.size()) {
      std::size_t above = 1;
      while (above + 1 < t.position.size() && t.position[above] < *t.zero_at) ++above;
      return Fail(
          Error::kInvalidArgument,
          Line("%c: reference position %.*f %s is not a compensation point (the "
               "nearest are %.*f and %.*f %s, every %.*f %s from %.*f): give --reference "
               "%c= one of the points",
               a.axis, dp, *t.zero_at, unit, dp, t.position[above - 1], dp, t.position[above], unit,
               dp, *spacing, unit, dp, t.position.front(), a.axis));
    }
    FanucAxisSheet s;
    s.axis = a.axis;
    s.interval = *spacing;
    s.most_negative = next;
    s.forward = Points(t, t.forward_um, next, r, count);
    s.reference_point = next + static_cast<int>(r) - (r == 0 ? 0 : 1);
    s.most_positive = s.forward.back().number;
    next = s.most_positive + 1;
    if (!t.reverse_um.empty()) {
      s.bidirectional = true;
      s.negative_block = next;
      s.reverse = Points(t, t.reverse_um, next, r, count);
      s.reference_opposite =
          static_cast<int>(std::lround(-ToMachineUnits(t.reverse_um[r], false, t.unit) / count));
      next = s.reverse.back().number + 1;
    }
    VOLCOMP_TRY(CheckIncrements(a.axis, s, options));
    if (next - 1 > kFanucMaxPointNumber) {
      return Fail(Error::kInvalidArgument,
                  Line("%c: the points run to data number %d, past %d (the data numbers all axes "
                       "share, inferred): give a larger --spacing or fewer axes per sheet",
                       a.axis, next - 1, kFanucMaxPointNumber));
    }
    const char c = a.axis;
    sheet.text += Line("\nAXIS %c (from %s)\n", c, a.source.c_str());
    if (t.negated) sheet.text += "  NEGATED (--negate): the values are (actual - nominal)\n";
    sheet.text += Line("  3620 %c = %-8d reference point number (position %.*f %s)\n", c,
                       s.reference_point, dp, *t.zero_at, unit);
    sheet.text += Line("  3621 %c = %-8d most negative point number\n", c, s.most_negative);
    sheet.text += Line("  3622 %c = %-8d most positive point number\n", c, s.most_positive);
    sheet.text += Line("  3623 %c = %-8d magnification\n", c, options.magnification);
    sheet.text += Line("  3624 %c = %.*f %s (%ld detection units) point interval\n", c, dp,
                       *spacing, unit, std::lround(*spacing / options.detection_unit));
    if (s.bidirectional) {
      sheet.text += Line("  3605#0 = 1       bidirectional pitch error compensation (16i/18i)\n");
      sheet.text += Line("  3626 %c = %-8d most negative point number, negative-direction travel\n",
                         c, s.negative_block);
      sheet.text += Line(
          "  3627 %c = %-8d compensation at the reference position approached from\n"
          "                  the negative side (reference return moving positive)\n",
          c, s.reference_opposite);
    }
    sheet.text +=
        Line("  positive-direction travel%s:\n", s.bidirectional ? "" : " (both directions)");
    sheet.text += PointRows(s.forward, options.unit);
    if (s.bidirectional) {
      sheet.text +=
          "  negative-direction travel (same intervals; the direction in which FANUC\n"
          "  reads these increments is not confirmed):\n" +
          PointRows(s.reverse, options.unit);
    }
    sheet.axes.push_back(s);
  }
  sheet.last_point = next - 1;
  return sheet;
}

}  // namespace volcomp::exporters
