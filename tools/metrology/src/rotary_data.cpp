// Reader for angle-sampled error-motion data.
#include "volcomp/metrology/rotary_data.hpp"

#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "volcomp/report/format.hpp"

namespace volcomp::metrology {
namespace {

std::string Num(double v) { return report::FormatNumber(v); }

}  // namespace

const std::vector<std::string>& RotaryChannelNames() {
  static const std::vector<std::string> kNames = {"x_um",  "y_um", "x2_um",
                                                  "y2_um", "z_um", "face_um"};
  return kNames;
}

const char* RotationSenseName(RotationSense sense) {
  switch (sense) {
    case RotationSense::kCw:
      return "CW";
    case RotationSense::kCcw:
      return "CCW";
    case RotationSense::kUnstated:
      break;
  }
  return "unstated";
}

RotaryRecord RevolutionsTurning(const RotaryRecord& record, RotationSense sense) {
  RotaryRecord r = record;
  r.revs.clear();
  r.rev_sense.clear();
  for (auto& [name, revs] : r.channels) revs.clear();
  for (std::size_t k = 0; k < record.revs.size(); ++k) {
    if (record.rev_sense[k] != sense) continue;
    r.revs.push_back(record.revs[k]);
    r.rev_sense.push_back(sense);
    for (auto& [name, revs] : r.channels) revs.push_back(record.channels.at(name)[k]);
  }
  return r;
}

Expected<RotaryRecord> ReadRotaryCsv(const tools::CsvTable& t) {
  RotaryRecord rec;
  rec.source = t.source();
  VOLCOMP_TRY_ASSIGN(const std::size_t rev_col, t.Require("rev"));
  VOLCOMP_TRY_ASSIGN(const std::size_t ang_col, t.Require("angle_deg"));
  const std::optional<std::size_t> dir_col = t.find("direction");
  std::vector<std::pair<std::string, std::size_t>> chans;
  for (const auto& name : RotaryChannelNames()) {
    if (const auto c = t.find(name)) chans.push_back({name, *c});
  }
  if (chans.empty()) {
    return Fail(t.LineFailure(t.header_line(),
                              "no displacement column: give at least one of x_um, y_um, x2_um, "
                              "y2_um, z_um, face_um"));
  }
  if (t.rows().empty()) {
    return Fail(t.LineFailure(t.header_line(), "no data rows after the header"));
  }

  std::set<long long> finished;
  std::vector<double> current_angles;
  long long current_rev = 0;
  bool in_rev = false;
  std::size_t rev_first_line = 0;
  auto close_rev = [&](std::size_t line) -> Outcome {
    if (!in_rev) return Outcome::Ok();
    if (rec.revs.size() == 1) {
      rec.angle_deg = current_angles;
      if (rec.angle_deg.size() < 4) {
        return Fail(t.LineFailure(rev_first_line,
                                  "revolution " + std::to_string(current_rev) + " has " +
                                      std::to_string(rec.angle_deg.size()) +
                                      " angles; at least 4 are needed (8 or more advised)"));
      }
    } else if (current_angles.size() != rec.angle_deg.size()) {
      return Fail(t.LineFailure(line, "revolution " + std::to_string(current_rev) + " has " +
                                          std::to_string(current_angles.size()) +
                                          " angles, the first one " +
                                          std::to_string(rec.angle_deg.size()) +
                                          "; every revolution must be sampled at the same angles"));
    }
    finished.insert(current_rev);
    return Outcome::Ok();
  };
  for (const auto& row : t.rows()) {
    // Every row has as many fields as the header (the reader checks).
    const std::string& rev_text = row.fields()[rev_col];
    const auto rev_v = tools::ParseInteger(rev_text);
    if (!rev_v) {
      return Fail(
          t.LineFailure(row.line(), "column \"rev\": \"" + rev_text + "\" is not an integer"));
    }
    VOLCOMP_TRY_ASSIGN(const double angle, row.Number(ang_col));
    if (!(angle >= 0.0 && angle < 360.0)) {
      return Fail(t.LineFailure(row.line(),
                                "column \"angle_deg\": " + Num(angle) + " is outside [0, 360)"));
    }
    RotationSense sense = RotationSense::kUnstated;
    if (dir_col) {
      const std::string& d = row.fields()[*dir_col];
      if (d == "CW" || d == "cw" || d == "+") {
        sense = RotationSense::kCw;
      } else if (d == "CCW" || d == "ccw" || d == "-" || d == "−") {
        sense = RotationSense::kCcw;
      } else {
        return Fail(t.LineFailure(
            row.line(), "column \"direction\": \"" + d + "\" is not CW or CCW (or + / −)"));
      }
    }
    if (!in_rev || *rev_v != current_rev) {
      VOLCOMP_TRY(close_rev(row.line()));
      if (finished.count(*rev_v)) {
        return Fail(t.LineFailure(row.line(), "revolution " + std::to_string(*rev_v) +
                                                  " appears again after other revolutions; the "
                                                  "rows of a revolution must be contiguous"));
      }
      current_rev = *rev_v;
      in_rev = true;
      rev_first_line = row.line();
      current_angles.clear();
      rec.revs.push_back(current_rev);
      rec.rev_sense.push_back(sense);
      for (const auto& c : chans) rec.channels[c.first].emplace_back();
    }
    if (sense != rec.rev_sense.back()) {
      return Fail(t.LineFailure(row.line(), std::string("column \"direction\": ") +
                                                RotationSenseName(sense) + " within revolution " +
                                                std::to_string(current_rev) + ", which began " +
                                                RotationSenseName(rec.rev_sense.back())));
    }
    if (!current_angles.empty() && angle <= current_angles.back()) {
      return Fail(t.LineFailure(row.line(), "column \"angle_deg\": " + Num(angle) +
                                                " does not increase within revolution " +
                                                std::to_string(current_rev)));
    }
    if (rec.revs.size() > 1) {
      const std::size_t j = current_angles.size();
      if (j >= rec.angle_deg.size() || std::fabs(rec.angle_deg[j] - angle) > 1e-6) {
        return Fail(t.LineFailure(
            row.line(), "angle " + Num(angle) + "° of revolution " + std::to_string(current_rev) +
                            (j < rec.angle_deg.size()
                                 ? " differs from " + Num(rec.angle_deg[j]) + "° of the first"
                                 : " is beyond the angles of the first") +
                            " revolution; every revolution must be sampled at the same angles"));
      }
    }
    current_angles.push_back(angle);
    for (const auto& c : chans) {
      VOLCOMP_TRY_ASSIGN(const double value, row.Number(c.second));
      rec.channels[c.first].back().push_back(value);
    }
  }
  VOLCOMP_TRY(close_rev(t.rows().back().line()));
  const double step = 360.0 / static_cast<double>(rec.angle_deg.size());
  for (std::size_t j = 0; j < rec.angle_deg.size(); ++j) {
    if (std::fabs(rec.angle_deg[j] - rec.angle_deg[0] - step * static_cast<double>(j)) >
        1e-3 * step) {
      rec.equally_spaced = false;
    }
  }
  return rec;
}

}  // namespace volcomp::metrology
