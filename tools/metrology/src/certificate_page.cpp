// The certificate as one self-contained HTML page, laid out for one A4 sheet (print stylesheet)
// and readable on screen. No charts: the figures and the fields only.
#include <algorithm>
#include <string>

#include "volcomp/metrology/certificate.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::metrology {
namespace {

using report::EscapeXml;

const char* const kStyle =
    "@page{size:A4;margin:10mm 12mm 10mm 12mm}\n"
    "body{font-family:sans-serif;font-size:9pt;line-height:1.2;color:#111;margin:1.5em auto;"
    "max-width:186mm}\n"
    "h1{font-size:15pt;margin:0 0 1mm 0}h2{font-size:10pt;margin:2.5mm 0 0.8mm 0}\n"
    ".sub{color:#444;margin:0 0 2mm 0}\n"
    "table{border-collapse:collapse;width:100%;font-size:7.5pt;margin:0}\n"
    "th,td{border:1px solid #999;padding:0.1mm 1.2mm;text-align:left;vertical-align:top}\n"
    "th{background:#eee}td.n,td.k{white-space:nowrap}td.n{text-align:right}\n"
    "tr.group td{background:#f5f5f5;font-weight:bold}\n"
    ".fields{display:flex;gap:4mm}.fields>div{flex:1}\n"
    ".fields td:first-child{width:32%;color:#444}\n"
    "td.fill{border-bottom:1px solid #111;min-width:30mm}\n"
    ".pass{color:#17632a;font-weight:bold}.fail{color:#b00020;font-weight:bold}\n"
    ".verdict{font-size:10pt;margin:1.5mm 0 1mm 0}\n"
    ".note{font-size:7.5pt;color:#333;margin:1mm 0}\n"
    ".sign{display:flex;gap:8mm;margin-top:1mm}.sign>div{flex:1}\n"
    ".sign td{border:none;border-bottom:1px solid #111;height:6mm;vertical-align:bottom}\n"
    ".sign td:first-child{border:none;width:22%;color:#444}\n"

    "@media print{body{margin:0;max-width:none}tr,.sign{break-inside:avoid}}\n";

std::string Cell(const std::string& text, const char* cls = nullptr) {
  return std::string("<td") + (cls != nullptr ? std::string(" class=\"") + cls + "\"" : "") + ">" +
         EscapeXml(text) + "</td>";
}

// A field: its value, or an empty line to fill in by hand.
std::string FieldRow(const std::string& label, const std::string& value) {
  return "<tr><td>" + EscapeXml(label) + "</td>" +
         (value.empty() ? "<td class=\"fill\"></td>" : Cell(value)) + "</tr>\n";
}

std::string Verdict(const std::optional<bool>& pass) {
  if (!pass) return "<td class=\"n\">—</td>";
  return *pass ? "<td class=\"n pass\">pass</td>" : "<td class=\"n fail\">fail</td>";
}

std::string Fixed(double v) { return report::FormatFixed(v, 2); }

std::string Condition(const std::vector<std::pair<std::string, std::string>>& list,
                      const std::string& key) {
  for (const auto& [k, v] : list) {
    if (k == key) return v;
  }
  return std::string();
}

// The conditions the table has no column for, as "key: value; ..." (the geometry lines the
// diagonal templates carry, the program name and the uncertainty budget's inputs, which the
// uncertainty column stands for, stay in the JSON).
std::string OtherConditions(const std::vector<std::pair<std::string, std::string>>& list) {
  static const char* const kShown[] = {"axis",
                                       "date",
                                       "instrument",
                                       "air temperature C",
                                       "material temperature C",
                                       "program",
                                       "instrument_u_um",
                                       "instrument_ppm",
                                       "instrument_range_um",
                                       "instrument_u_arcsec",
                                       "instrument_accuracy_arcsec",
                                       "setup_u_um",
                                       "calibrator_u_um",
                                       "drift_range_um",
                                       "drift_range_arcsec",
                                       "expansion_um_per_m_K",
                                       "nominal_radius_mm"};
  std::string out;
  for (const auto& [k, v] : list) {
    if (std::find(std::begin(kShown), std::end(kShown), k) != std::end(kShown)) continue;
    if (k.rfind("diagonal ", 0) == 0) continue;
    out += (out.empty() ? "" : "; ") + k + ": " + v;
  }
  return out;
}

// One value before and after: once when both agree, else "before / after".
std::string BeforeAfter(const std::string& before, const std::string& after) {
  if (before == after) return after;
  return (before.empty() ? std::string("—") : before) + " / " +
         (after.empty() ? std::string("—") : after);
}

std::string Temperature(const std::vector<std::pair<std::string, std::string>>& list) {
  const std::string air = Condition(list, "air temperature C");
  const std::string material = Condition(list, "material temperature C");
  std::string t;
  if (!air.empty()) t += "air " + air;
  if (!material.empty()) t += (t.empty() ? "" : ", ") + std::string("part ") + material;
  return t;
}

// The cells of a test's conditions row after its label: date, instrument, temperature, other.
std::vector<std::string> ConditionCells(const CertificateTest& t) {
  const auto& b = t.conditions_before;
  const auto& a = t.conditions_after;
  return {BeforeAfter(Condition(b, "date"), Condition(a, "date")),
          BeforeAfter(Condition(b, "instrument"), Condition(a, "instrument")),
          BeforeAfter(Temperature(b), Temperature(a)),
          BeforeAfter(OtherConditions(b), OtherConditions(a))};
}

// One row per set of equal conditions: "X axis, Y axis, Z axis" measured alike share a row.
std::string ConditionRows(const std::vector<CertificateTest>& tests) {
  std::vector<std::pair<std::string, std::vector<std::string>>> rows;
  for (const CertificateTest& t : tests) {
    const auto cells = ConditionCells(t);
    auto same =
        std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r.second == cells; });
    if (same != rows.end()) {
      same->first += ", " + t.label;
    } else {
      rows.emplace_back(t.label, cells);
    }
  }
  std::string h;
  for (const auto& [label, cells] : rows) {
    h += "<tr>" + Cell(label);
    for (std::size_t k = 0; k < cells.size(); ++k) h += Cell(cells[k], k == 0 ? "k" : nullptr);
    h += "</tr>\n";
  }
  return h;
}

}  // namespace

std::string CertificateHtml(const Certificate& c) {
  const CertificateInfo& i = c.info;
  std::string title = "Certificate of volumetric compensation";
  std::string h;
  h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
       EscapeXml(title) + "</title>\n<style>\n" + kStyle + "</style>\n</head>\n<body>\n";
  h += "<h1>" + EscapeXml(title) + "</h1>\n";
  const std::string number = i.Field("test", "certificate");
  h += "<p class=\"sub\">Accuracy before and after compensation · certificate no. " +
       (number.empty() ? std::string("__________") : EscapeXml(number)) + " · " +
       EscapeXml(c.date) + " · volcomp " + EscapeXml(c.tool_version) + "</p>\n";

  h += "<div class=\"fields\"><div><h2>Customer</h2><table>\n";
  h += FieldRow("name", i.Field("customer", "name"));
  h += FieldRow("address", i.Field("customer", "address"));
  h += FieldRow("order no.", i.Field("customer", "order"));
  h += "</table></div><div><h2>Machine</h2><table>\n";
  h += FieldRow("maker", i.Field("machine", "maker"));
  h += FieldRow("model", i.Field("machine", "model"));
  h += FieldRow("serial no.", i.Field("machine", "serial"));
  h += FieldRow("location", i.Field("machine", "location"));
  h += "</table></div></div>\n";

  h += "<h2>Compensation table</h2><table>\n";
  const bool has_table = c.table.table_id.has_value();
  h += "<tr><td>table id</td>" +
       (has_table ? Cell(std::to_string(*c.table.table_id))
                  : std::string("<td class=\"fill\"></td>")) +
       "<td>CRC-32</td>" +
       (c.table.crc32 ? Cell(tools::Hex32(*c.table.crc32))
                      : std::string("<td class=\"fill\"></td>")) +
       "<td>read from</td>" +
       (c.table.source.empty()
            ? std::string("<td class=\"fill\"></td>")
            : Cell(c.table.origin == "status"
                       ? "the board's status, " + c.table.source +
                             (c.table.same_as_image.empty()
                                  ? std::string()
                                  : " (the same as the image " + c.table.same_as_image + ")")
                       : "the image " + c.table.source)) +
       "</tr>\n</table>\n";

  h += "<h2>Instrument and test conditions</h2><table>\n<tr><th>tests</th><th>date</th>"
       "<th>instrument</th><th>temperature, °C</th><th>other conditions</th></tr>\n";
  h += ConditionRows(c.tests);
  h += "</table>\n";

  h += "<h2>Results</h2><table>\n<tr><th>figure</th><th>meaning</th><th>unit</th>"
       "<th>before</th><th>after</th><th>tolerance</th><th>result before</th>"
       "<th>result after</th><th>uncertainty</th></tr>\n";
  for (const CertificateTest& t : c.tests) {
    bool any = false;
    for (const CertificateFigure& f : c.figures) any = any || f.test == t.name;
    if (!any) continue;
    h += "<tr class=\"group\"><td colspan=\"9\">" + EscapeXml(t.title) + "</td></tr>\n";
    for (const CertificateFigure& f : c.figures) {
      if (f.test != t.name) continue;
      // The standard's short name (without its year) before the symbol: "ISO 230-2 A".
      std::string standard = f.standard.substr(0, f.standard.find(':'));
      standard = standard.substr(0, standard.find("-88"));
      h += "<tr>" + Cell(standard + " " + f.symbol, "k") + Cell(f.meaning) + Cell(f.unit) +
           Cell(Fixed(f.before), "n") + Cell(Fixed(f.after), "n") +
           (f.tolerance ? Cell(report::FormatNumber(*f.tolerance, 6), "n")
                        : std::string("<td class=\"n\">—</td>")) +
           Verdict(f.before_pass) + Verdict(f.after_pass) +
           Cell(f.u_after ? "± " + Fixed(*f.u_after)
                          : (f.u_before ? "± " + Fixed(*f.u_before) + " (before)" : "not stated"),
                "k") +
           "</tr>\n";
    }
  }
  h += "</table>\n";
  const int toleranced = c.Toleranced();
  const int failed = c.FailedAfter();
  h += "<p class=\"verdict\">Result after compensation: ";
  if (toleranced == 0) {
    h += "— (no tolerances given)";
  } else if (failed == 0) {
    h += "<span class=\"pass\">pass</span>: all " + std::to_string(toleranced) +
         " figures with a tolerance are within it";
  } else {
    h += "<span class=\"fail\">fail</span>: " + std::to_string(failed) + " of " +
         std::to_string(toleranced) + " figures with a tolerance exceed it";
  }
  h += ".</p>\n";
  h += "<p class=\"note\">Figures to 0.01 µm (″: arc-seconds, rotary axis); pass: figure ≤ "
       "tolerance; —: no tolerance agreed. Uncertainty: U at k = 2 of the figure after "
       "compensation where the evaluation states its instrument (docs/metrology.md); the verdict "
       "compares the figure itself with the tolerance (no guard band). ISO 230-2 with 2s, "
       "GOST 27843-88 with 3S. Conditions that differ "
       "read before / after. Annex: the evaluation reports and the before/after page.</p>\n";
  const std::string remarks = i.Field("test", "remarks");
  if (!remarks.empty()) h += "<p class=\"note\">Remarks: " + EscapeXml(remarks) + "</p>\n";

  // Signature fields: the names when the info file gives them, lines to fill in otherwise.
  auto signature = [&](const std::string& heading, const std::string& name,
                       const std::string& place) {
    std::string s = "<div><h2>" + EscapeXml(heading) + "</h2><table>\n";
    s += "<tr><td>name</td>" + (name.empty() ? std::string("<td></td>") : Cell(name)) + "</tr>\n";
    s += "<tr><td>place, date</td>" +
         (place.empty() ? std::string("<td></td>") : Cell(place + ", ")) + "</tr>\n";
    s += "<tr><td>signature</td><td></td></tr>\n</table></div>";
    return s;
  };
  h += "<div class=\"sign\">" +
       signature("Tested by", i.Field("test", "tested_by"), i.Field("test", "place")) +
       signature("Accepted by (customer)", i.Field("test", "accepted_by"), std::string()) +
       "</div>\n</body>\n</html>\n";
  return h;
}

}  // namespace volcomp::metrology
