// The certificate's info file.
#include "volcomp/metrology/certificate_info.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "volcomp/tools/file_io.hpp"

namespace volcomp::metrology {
namespace {

std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return std::string();
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::string Join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : ", ") + i;
  return out;
}

const std::vector<std::string>* SectionKeys(const std::string& section) {
  for (const auto& [name, keys] : CertificateFieldKeys()) {
    if (name == section) return &keys;
  }
  return nullptr;
}

bool ScopeWord(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
}

}  // namespace

const std::vector<std::pair<std::string, std::vector<std::string>>>& CertificateFieldKeys() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> kKeys = {
      {"customer", {"name", "address", "order"}},
      {"machine", {"maker", "model", "serial", "location"}},
      {"test", {"certificate", "tested_by", "accepted_by", "place", "remarks"}},
  };
  return kKeys;
}

const std::vector<std::string>& CertificateFigureIds() {
  static const std::vector<std::string> kIds = {
      "iso230-2.A",   "iso230-2.E",      "iso230-2.B",      "iso230-2.M",   "iso230-2.R",
      "gost27843.A",  "gost27843.R_max", "gost27843.B_max", "iso230-6.E_d", "iso230-6.B_d",
      "iso230-4.G_b", "iso230-4.G_cw",   "iso230-4.G_ccw",  "iso230-4.H"};
  return kIds;
}

std::string CertificateInfo::Field(const std::string& section, const std::string& key) const {
  for (const auto& [k, v] : fields) {
    if (k.first == section && k.second == key) return v;
  }
  return std::string();
}

const ToleranceEntry* CertificateInfo::Tolerance(const std::string& figure,
                                                 const std::string& scope) const {
  const ToleranceEntry* general = nullptr;
  for (const ToleranceEntry& t : tolerances) {
    if (t.figure != figure) continue;
    if (t.scope.empty()) general = &t;
    if (!scope.empty() && t.scope == scope) return &t;
  }
  return general;
}

Expected<CertificateInfo> ParseCertificateInfo(const std::string& text, const std::string& source) {
  CertificateInfo info;
  info.source = source;
  std::string section;
  std::vector<std::pair<std::string, std::string>> seen;  // "section.key", where
  // A UTF-8 byte order mark (Windows editors write one) is not part of the first line.
  std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  int line_no = 0;
  auto fail = [&](const std::string& message) {
    return Fail(Error::kInputInvalid, source + ":" + std::to_string(line_no) + ": " + message);
  };
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = Trim(text.substr(start, end - start));
    start = end + 1;
    ++line_no;
    if (line.empty() || line[0] == '#' || line[0] == ';') continue;
    const std::string where = source + ":" + std::to_string(line_no);
    if (line[0] == '[') {
      const auto close = line.find(']');
      const std::string rest = close == std::string::npos ? "" : Trim(line.substr(close + 1));
      if (close == std::string::npos || (!rest.empty() && rest[0] != '#' && rest[0] != ';')) {
        return fail("'" + line + "': a section line is [name]");
      }
      section = Trim(line.substr(1, close - 1));
      if (section != "tolerance" && SectionKeys(section) == nullptr) {
        std::vector<std::string> names;
        for (const auto& s : CertificateFieldKeys()) names.push_back("[" + s.first + "]");
        names.push_back("[tolerance]");
        return fail("unknown section [" + section + "] (known: " + Join(names) + ")");
      }
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos) return fail("'" + line + "': expected key = value");
    const std::string key = Trim(line.substr(0, eq));
    std::string value = Trim(line.substr(eq + 1));
    if (key.empty()) return fail("'" + line + "': no key before '='");
    if (section.empty()) return fail("key '" + key + "' before any [section]");
    for (const auto& [k, w] : seen) {
      if (k == section + "." + key)
        return fail("key '" + key + "' given twice (first at " + w + ")");
    }
    seen.emplace_back(section + "." + key, where);
    if (section != "tolerance") {
      const auto* keys = SectionKeys(section);
      if (std::find(keys->begin(), keys->end(), key) == keys->end()) {
        return fail("unknown key '" + key + "' in [" + section + "] (known: " + Join(*keys) + ")");
      }
      if (!value.empty()) info.fields.push_back({{section, key}, value});
      continue;
    }
    // [tolerance] FIGURE[.SCOPE] = VALUE [# comment]
    const auto comment = value.find_first_of("#;");
    if (comment != std::string::npos) value = Trim(value.substr(0, comment));
    const auto& ids = CertificateFigureIds();
    std::string figure, scope;
    for (const std::string& id : ids) {
      if (key == id) figure = id;
      if (key.size() > id.size() + 1 && key.compare(0, id.size(), id) == 0 &&
          key[id.size()] == '.') {
        figure = id;
        scope = key.substr(id.size() + 1);
      }
    }
    if (figure.empty() || (!scope.empty() && !ScopeWord(scope))) {
      return fail("unknown tolerance '" + key + "' (known: " + Join(ids) +
                  ", each optionally followed by .AXIS, .PLANE or .body)");
    }
    if (value.empty()) return fail("tolerance '" + key + "' has no value");
    errno = 0;
    char* endp = nullptr;
    const double v = std::strtod(value.c_str(), &endp);
    if (errno != 0 || endp == value.c_str() || *endp != '\0' || !std::isfinite(v) || v <= 0.0) {
      return fail("tolerance '" + key + "' = '" + value +
                  "': expected a positive number (in the figure's unit, µm or arc-seconds)");
    }
    info.tolerances.push_back({figure, scope, v, where});
  }
  return info;
}

Expected<CertificateInfo> ReadCertificateInfo(const std::string& path) {
  VOLCOMP_TRY_ASSIGN(const std::string text, tools::ReadTextFile(path));
  return ParseCertificateInfo(text, path);
}

}  // namespace volcomp::metrology
