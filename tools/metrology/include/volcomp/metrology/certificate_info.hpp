// The integrator's fields of a certificate (`volcomp report certificate --info FILE`): who the
// customer is, which machine was tested, who tested it, and the tolerance of each figure.
//
// The file is a small INI file (samples/certificate_info.ini, docs/pc-tool.md):
//   [customer]  name, address, order
//   [machine]   maker, model, serial, location
//   [test]      certificate, tested_by, accepted_by, place, remarks
//   [tolerance] FIGURE[.SCOPE] = VALUE   (value in the figure's unit: µm, arc-seconds on a rotary
//               axis; > 0). FIGURE is one of CertificateFigureIds() ("iso230-2.A"); SCOPE names
//               an axis ("X"), a plane ("XY") or "body", and wins over the unscoped line.
// `# ...` and `; ...` lines are comments; a comment may also follow a [section] and, in
// [tolerance], the value.
// A field not given stays empty (the certificate prints a line to fill in by hand); nothing is
// invented. Errors (kInputInvalid) name FILE:LINE and the key: a line that is not `key = value`
// or `[section]`, an unknown section or key, a key given twice, a tolerance that is not a
// positive number.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::metrology {

/// The sections and their keys, in the order the certificate prints them.
const std::vector<std::pair<std::string, std::vector<std::string>>>& CertificateFieldKeys();

/// The figures a certificate states and a tolerance may name: "iso230-2.A", "iso230-2.E",
/// "iso230-2.B", "iso230-2.M", "iso230-2.R", "gost27843.A", "gost27843.R_max",
/// "gost27843.B_max", "iso230-6.E_d", "iso230-6.B_d", "iso230-4.G_b", "iso230-4.G_cw",
/// "iso230-4.G_ccw", "iso230-4.H".
const std::vector<std::string>& CertificateFigureIds();

struct ToleranceEntry {
  std::string figure;  // "iso230-2.A"
  std::string scope;   // "X", "XY", "body"; empty: every axis/plane
  double value = 0.0;  // in the figure's unit, > 0
  std::string where;   // "info.ini:12"
};

struct CertificateInfo {
  std::string source;  // the file, or empty when none was given
  // (section, key) -> value, only the keys given with a non-empty value
  std::vector<std::pair<std::pair<std::string, std::string>, std::string>> fields;
  std::vector<ToleranceEntry> tolerances;

  /// The value of section.key, or "" when not given.
  std::string Field(const std::string& section, const std::string& key) const;
  /// The tolerance of `figure` for `scope`: the scoped entry, else the unscoped one, else null.
  const ToleranceEntry* Tolerance(const std::string& figure, const std::string& scope) const;
};

/// Parses the text of an info file; `source` names it in errors.
Expected<CertificateInfo> ParseCertificateInfo(const std::string& text, const std::string& source);

/// Reads and parses `path` (kIoError when it cannot be read).
Expected<CertificateInfo> ReadCertificateInfo(const std::string& path);

}  // namespace volcomp::metrology
