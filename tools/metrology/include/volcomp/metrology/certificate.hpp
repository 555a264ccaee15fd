// The certificate of a compensation (`volcomp report certificate BEFORE AFTER -o DIR`): one
// printable A4 page per machine that the customer signs. It states, from the compared results
// (compare.hpp), each standard's headline figures before and after with the tolerance the
// integrator gave (certificate_info.hpp) and pass/fail, the instrument and test conditions the
// readings files carried, the compensation table (id and CRC-32), the tool version and the date,
// and the fields and signature lines of both parties. docs/pc-tool.md "report certificate".
//
// The figures, per result kind:
//   positioning  ISO 230-2:2014 A, E, B, M, R (§2.2–2.3 bidirectional figures) and GOST 27843-88
//                A, R_max, B_max, of each standard the results hold; scope = the axis
//   diagonal     ISO 230-6 E_d, B_d of the body diagonals (scope "body") and of each face
//                (scope = its plane)
//   circular     ISO 230-4 G(b), G CW, G CCW, H; scope = the plane (the readings' `axis`)
// A tolerance FIGURE.SCOPE applies to that scope; FIGURE alone to every scope, except the
// positioning figures of a rotary axis (arc-seconds), which take only FIGURE.AXIS.
// Each figure is stated rounded to 0.01 (µm, or arc-seconds on a rotary axis), and pass/fail
// compares that stated value with the tolerance: pass when figure ≤ tolerance; no tolerance, no
// verdict. The results hold no measurement uncertainty: the certificate says "not evaluated".
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "volcomp/metrology/certificate_info.hpp"
#include "volcomp/metrology/compare.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::metrology {

/// What the certificate says about the compensation table; all empty when not given.
struct CertificateTable {
  std::string source;  // the image file or the saved status file
  std::string origin;  // "image" (read from the image) or "status" (the board's active table)
  std::optional<uint32_t> table_id;
  std::optional<uint32_t> crc32;
  std::string same_as_image;  // origin "status": the image it was checked against, if any
};

struct CertificateFigure {
  std::string test;      // the compared result's name ("positioning_X")
  std::string id;        // CertificateFigureIds() entry ("iso230-2.A")
  std::string scope;     // "X", "XY", "body"
  std::string standard;  // "ISO 230-2:2014"
  std::string symbol;    // "A", "G(b)"
  std::string meaning;   // short: "accuracy of positioning"
  std::string unit;      // "µm" or "″"
  double before = 0.0;   // rounded to 0.01 as stated
  double after = 0.0;
  std::optional<double> tolerance;
  std::string tolerance_from;  // "info.ini:12"
  std::optional<bool> before_pass, after_pass;
  std::optional<double> u_before, u_after;  // U (k = 2) where the evaluations state it
};

struct CertificateTest {
  std::string name;   // "positioning_X"
  std::string kind;   // "positioning", "diagonal", "circular"
  std::string title;  // "Positioning accuracy, X axis"
  std::string label;  // short, for the conditions table: "X axis", "diagonals", "XY circle"
  std::string before_source, after_source;
  std::vector<std::pair<std::string, std::string>> conditions_before, conditions_after;
};

struct Certificate {
  std::string tool_version;  // as `volcomp --version` prints it, without "volcomp "
  std::string date;          // YYYY-MM-DD
  CertificateInfo info;
  CertificateTable table;
  std::vector<CertificateTest> tests;
  std::vector<CertificateFigure> figures;
  std::vector<std::string> warnings;  // from the comparison, and tolerances that match no figure
  int Toleranced() const;             // figures with a tolerance
  int FailedAfter() const;            // ... whose after figure exceeds it
  bool AnyUncertainty() const;        // some figure carries a U
};

/// The uncertainty column's text, and why.
extern const char* const kUncertaintyNotEvaluated;
extern const char* const kUncertaintyWhereStated;

/// The certificate of `comparison`.
Certificate BuildCertificate(const Comparison& comparison,
                             CertificateInfo info,
                             CertificateTable table,
                             std::string tool_version,
                             std::string date);

/// `date` is YYYY-MM-DD and a calendar date; a failure naming it otherwise.
Outcome CheckCertificateDate(const std::string& date);

/// Every figure and field of the page (docs/pc-tool.md lists the keys).
tools::JsonValue CertificateJson(const Certificate& certificate);
/// The text view: the figures and the verdict, from CertificateJson().
void WriteCertificateText(std::ostream& out, const tools::JsonValue& certificate);
/// The page: self-contained HTML with a print stylesheet (A4, one page).
std::string CertificateHtml(const Certificate& certificate);

}  // namespace volcomp::metrology
