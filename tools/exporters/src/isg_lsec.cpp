// ISG leadscrew error compensation lists (see isg_lsec.hpp).
#include "volcomp/exporters/isg_lsec.hpp"

#include <cmath>
#include <cstdio>

namespace volcomp::exporters {
namespace {

constexpr double kUnitsPerMm = 1e4;           // 0.1 µm
constexpr double kUnitsPerUm = 10.0;          // 0.1 µm
constexpr double kUnitsPerDeg = 1e4;          // 0.0001°
constexpr double kUnitsPerArcsec = 1 / 0.36;  // 0.0001° = 0.36″

int64_t Round(double v) { return static_cast<int64_t>(std::llround(v)); }

std::string Line(const std::string& key, long long value) {
  char text[96];
  std::snprintf(text, sizeof text, "%-36s%lld\n", key.c_str(), value);
  return text;
}

}  // namespace

Expected<IsgLsec> BuildIsgLsec(const model::PositioningData& data, const IsgLsecOptions& options) {
  const std::size_t n = data.position.size();
  if (n < 2) {
    return Fail(
        Error::kInvalidArgument,
        "a compensation list needs at least 2 positions, the test has " + std::to_string(n));
  }
  if (n >= options.max_points) {
    return Fail(Error::kInvalidArgument,
                std::to_string(n) +
                    " positions: kw.ssfk.kw_nr_max must be smaller than "
                    "kw.ssfk.max_points (P-COMP-00059), " +
                    std::to_string(options.max_points) +
                    " here: test fewer positions, or give --max-points the controller's value");
  }
  IsgLsec list;
  list.rotary = data.rotary;
  list.bilateral = !data.dev_reverse.empty();
  const double position_scale = data.rotary ? kUnitsPerDeg : kUnitsPerMm;
  const double value_scale =
      (data.rotary ? kUnitsPerArcsec : kUnitsPerUm) * (options.negate ? -1 : 1);
  for (std::size_t i = 0; i < n; ++i) {
    IsgLsecRow row;
    row.setpoint = Round(data.position[i] * position_scale);
    row.pos = Round(data.dev_forward[i] * value_scale);
    row.neg = list.bilateral ? Round(data.dev_reverse[i] * value_scale) : row.pos;
    list.rows.push_back(row);
  }
  return list;
}

std::string FormatIsgLsec(const IsgLsec& list,
                          const IsgLsecOptions& options,
                          const std::vector<std::string>& header) {
  std::string out;
  for (const std::string& h : header) out += h.empty() ? "#\n" : "# " + h + "\n";
  out += Line("kopf.achs_nr", options.axis_number);
  char name[96];
  std::snprintf(name, sizeof name, "%-36s%s\n", "kopf.log_achs_name", options.axis_name.c_str());
  out += name;
  out += Line("kw.ssfk.unit", 1);
  out += Line("kw.ssfk.interval", 0);
  out += Line("kw.ssfk.kw_startpos", list.rows.front().setpoint);
  out += Line("kw.ssfk.kw_nr_max", static_cast<long long>(list.rows.size()));
  out += Line("kw.ssfk.bilateral", list.bilateral ? 1 : 0);
  const auto table = [&list](const char* field, int64_t IsgLsecRow::*member) {
    std::string lines;
    for (std::size_t i = 0; i < list.rows.size(); ++i) {
      lines += Line("kw.ssfk.table[" + std::to_string(i) + "]." + field, list.rows[i].*member);
    }
    return lines;
  };
  out += table("setpoint", &IsgLsecRow::setpoint);
  out += table("pos", &IsgLsecRow::pos);
  out += table("neg", &IsgLsecRow::neg);
  return out;
}

}  // namespace volcomp::exporters
