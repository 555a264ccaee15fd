// SINUMERIK LEC / CEC compensation programs (see siemens_comp.hpp).
#include "volcomp/exporters/siemens_comp.hpp"

#include <cmath>
#include <cstdio>

namespace volcomp::exporters {
namespace {

// A position or value in the table's unit: 4 decimals in mm or deg (0.1 µm), 6 in inches
// (0.000001 in = 0.0254 µm), without a "-0.0000".
std::string InUnit(double v, const ErrorTable& t) {
  const bool inch = t.unit == LengthUnit::kInch && !t.rotary;
  const double scale = inch ? 1e6 : 1e4;
  double r = std::round(v * scale) / scale;
  if (r == 0) r = 0;
  char s[48];
  std::snprintf(s, sizeof s, inch ? "%.6f" : "%.4f", r);
  return s;
}

struct Column {  // one table's values in the control's unit
  int direction = 0;
  std::vector<double> value;
};

// The tables of one axis: LEC one (the mean of both directions when there are two), CEC one
// per direction measured.
std::vector<Column> Columns(const ErrorTable& t, SiemensMode mode) {
  std::vector<Column> c;
  const bool two = !t.reverse_um.empty();
  if (mode == SiemensMode::kCec && two) {
    c.push_back({1, {}});
    c.push_back({-1, {}});
  } else {
    c.push_back({0, {}});
  }
  for (std::size_t i = 0; i < t.position.size(); ++i) {
    const double f = ToMachineUnits(t.forward_um[i], t.rotary, t.unit);
    if (!two) {
      c[0].value.push_back(f);
      continue;
    }
    const double r = ToMachineUnits(t.reverse_um[i], t.rotary, t.unit);
    if (c.size() == 2) {
      c[0].value.push_back(f);
      c[1].value.push_back(r);
    } else {
      c[0].value.push_back((f + r) / 2);
    }
  }
  return c;
}

std::string SignLines(const SiemensAxis& a) {
  std::string s;
  const ErrorTable& t = a.table;
  if (t.zero_at) {
    s += "; " + a.machine_axis + ": zeroed at " + InUnit(*t.zero_at, t) +
         " (the reference point: K3 asks for 0 there)\n";
  } else {
    s += "; " + a.machine_axis +
         ": not zeroed at the reference point (K3 asks for 0 there: --reference)\n";
  }
  if (t.negated) {
    s += "; " + a.machine_axis + ": NEGATED (--negate): the values are -(actual - nominal)\n";
  }
  return s;
}

std::string SignAndUnit(LengthUnit unit) {
  const bool inch = unit == LengthUnit::kInch;
  std::string s = std::string("; values: the measured error, actual - nominal, in ") +
                  (inch ? "inches" : "mm") +
                  " (deg on a rotary axis), which the\n"
                  ";   control subtracts: \"a positive compensation value causes the machine axis "
                  "to move in\n"
                  ";   the negative direction\" (SINUMERIK K3 function manual, "
                  "6FC5397-1BP40-3BA1)\n";
  if (inch) {
    s += "; an inch machine: the basic system is inch (MD10240 $MN_SCALING_SYSTEM_IS_METRIC = 0);\n"
         ";   the tables are in the basic system's unit [inferred: K3's examples are in mm], so\n"
         ";   check one value on the control\n";
  }
  return s;
}

}  // namespace

Expected<SiemensProgram> BuildSiemensProgram(const std::vector<SiemensAxis>& axes,
                                             const SiemensOptions& options) {
  if (options.encoder != 0 && options.encoder != 1) {
    return Fail(Error::kInvalidArgument, "encoder " + std::to_string(options.encoder) +
                                             ": 0 (first measuring system) or 1 (second)");
  }
  const bool lec = options.mode == SiemensMode::kLec;
  const std::string what = lec ? "SINUMERIK LEC ($AA_ENC_COMP)" : "SINUMERIK CEC ($AN_CEC)";
  const std::string limit_md = lec ? "MD38000 MM_ENC_COMP_MAX_POINTS" : "MD18342 MM_CEC_MAX_POINTS";
  SiemensProgram p;
  std::string head, body, md;
  head = lec ? "%_N_AX_EEC_INI\n; volcomp export siemens: LEC tables ($AA_ENC_COMP), SINUMERIK "
               "840D sl / 828D / 808D\n"
             : "%_N_NC_CEC_INI\n; volcomp export siemens: CEC tables ($AN_CEC), direction-"
               "dependent pitch error, SINUMERIK 840D sl / 828D\n; the program name is the "
               "customary one for CEC tables, not confirmed by volcomp's sources\n";
  head += SignAndUnit(options.unit);
  const std::string enc = std::to_string(options.encoder);
  int next_table = 0;
  for (const SiemensAxis& a : axes) {
    const std::string& ax = a.machine_axis;
    const std::string& out = a.output_axis.empty() ? ax : a.output_axis;
    if (!a.table.rotary && a.table.unit != options.unit) {
      return Fail(Error::kInvalidArgument, ax + ": a table in " + UnitName(a.table.unit, false) +
                                               " in a program in " + UnitName(options.unit, false));
    }
    if (lec && out != ax) {
      return Fail(Error::kInvalidArgument,
                  ax + " -> " + out + ": a cross-axis table is a CEC table (--mode cec)");
    }
    auto spacing = RequireEqualSpacing(a.table, what);
    if (!spacing.ok()) return Fail(Error::kInvalidArgument, ax + ": " + spacing.error().message);
    const Expected<void> count =
        RequirePointLimit(a.table, options.max_points,
                          what + " with " + limit_md + " = " + std::to_string(options.max_points));
    if (!count.ok()) return Fail(Error::kInvalidArgument, ax + ": " + count.error().message);
    const ErrorTable& t = a.table;
    const std::size_t n = t.position.size();
    const std::vector<Column> columns = Columns(t, options.mode);
    const std::string range = std::to_string(n) + " points, " + InUnit(t.position.front(), t) +
                              " to " + InUnit(t.position.back(), t) + " step " +
                              InUnit(*spacing, t) + " " + UnitName(t.unit, t.rotary);
    if (lec && !t.reverse_um.empty()) {
      double reversal = 0;
      for (std::size_t i = 0; i < n; ++i) reversal += t.forward_um[i] - t.reverse_um[i];
      char msg[200];
      std::snprintf(msg, sizeof msg,
                    "%s: LEC holds one direction: the table is the mean of both, the mean "
                    "reversal (%.2f %s) is not in it (--mode cec writes a table per direction)",
                    ax.c_str(), reversal / static_cast<double>(n), t.rotary ? "arcsec" : "um");
      p.notes.push_back(msg);
      head += "; " + std::string(msg) + "\n";
    }
    head += "; " + (out == ax ? ax : ax + " -> " + out) + ": from " + a.source + ", " + range +
            "\n" + (a.what.empty() ? "" : "; " + a.what + "\n") + SignLines(a);
    for (const Column& c : columns) {
      SiemensTableInfo info;
      info.machine_axis = ax;
      info.output_axis = out;
      info.rotary = t.rotary;
      info.cec_table = lec ? -1 : next_table;
      info.direction = c.direction;
      info.points = n;
      info.min = t.position.front();
      info.max = t.position.back();
      info.step = *spacing;
      for (const double v : c.value) {
        info.largest_value = std::fmax(info.largest_value, std::fabs(v));
      }
      if (lec) {
        md += ";   MD38000 $MA_MM_ENC_COMP_MAX_POINTS[" + enc + "," + ax +
              "] >= " + std::to_string(n) + "\n;   MD32700 $MA_ENC_COMP_ENABLE[" + enc + "," + ax +
              "] = 0 while loading, 1 afterwards\n";
        for (std::size_t i = 0; i < n; ++i) {
          body += "$AA_ENC_COMP[" + enc + "," + std::to_string(i) + "," + ax +
                  "]=" + InUnit(c.value[i], t) + "\n";
        }
        const std::string idx = "[" + enc + "," + ax + "]=";
        body += "$AA_ENC_COMP_STEP" + idx + InUnit(*spacing, t) + "\n$AA_ENC_COMP_MIN" + idx +
                InUnit(t.position.front(), t) + "\n$AA_ENC_COMP_MAX" + idx +
                InUnit(t.position.back(), t) + "\n$AA_ENC_COMP_IS_MODULO" + idx + "0\n";
      } else {
        const std::string k = std::to_string(next_table);
        md += ";   MD18342 $MN_MM_CEC_MAX_POINTS[" + k + "] >= " + std::to_string(n) + " (table " +
              k + ": " + (out == ax ? ax : ax + " -> " + out) +
              (c.direction > 0   ? ", positive traverse"
               : c.direction < 0 ? ", negative traverse"
                                 : ", both directions") +
              ")\n";
        body += "$AN_CEC_INPUT_AXIS[" + k + "]=(" + ax + ")\n$AN_CEC_OUTPUT_AXIS[" + k + "]=(" +
                out + ")\n$AN_CEC_STEP[" + k + "]=" + InUnit(*spacing, t) + "\n$AN_CEC_MIN[" + k +
                "]=" + InUnit(t.position.front(), t) + "\n$AN_CEC_MAX[" + k +
                "]=" + InUnit(t.position.back(), t) + "\n$AN_CEC_DIRECTION[" + k +
                "]=" + std::to_string(c.direction) + "\n$AN_CEC_IS_MODULO[" + k + "]=0\n";
        for (std::size_t i = 0; i < n; ++i) {
          body += "$AN_CEC[" + k + "," + std::to_string(i) + "]=" + InUnit(c.value[i], t) + "\n";
        }
        ++next_table;
      }
      p.tables.push_back(info);
    }
  }
  head += "; machine data to set (K3) before loading this program:\n" + md;
  if (lec) {
    head += "; the compensation acts after the axis is referenced\nCHANDATA(1)\n";
  } else {
    head +=
        "; then enable the tables as K3 describes (their enable data are not in volcomp's "
        "sources)\n";
  }
  p.text = head + body + "M17\n";
  return p;
}

}  // namespace volcomp::exporters
