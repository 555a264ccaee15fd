// ISO 230-6 diagonal names.
#include <cctype>
#include <cmath>

#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology {
namespace {

int AxisIndex(char c) {
  switch (std::toupper(static_cast<unsigned char>(c))) {
    case 'X':
      return 0;
    case 'Y':
      return 1;
    case 'Z':
      return 2;
    default:
      return -1;
  }
}

std::optional<DiagonalName> Finish(std::array<int, 3> signs,
                                   int offset_axis,
                                   const std::string& offset_value) {
  DiagonalName d;
  d.signs = signs;
  int used = 0;
  for (int s : signs) used += s != 0;
  if (used < 2) return std::nullopt;
  d.body = used == 3;
  static const char* kAxes = "XYZ";
  for (int a = 0; a < 3; ++a) {
    if (signs[a] == 0) continue;
    d.text += signs[a] > 0 ? '+' : '-';
    d.text += kAxes[a];
    if (!d.body) d.plane += kAxes[a];
  }
  if (offset_axis >= 0) {
    if (d.body || signs[offset_axis] != 0) return std::nullopt;
    d.offset = std::string(1, kAxes[offset_axis]) + offset_value;
    d.text += " " + d.offset;
  }
  return d;
}

}  // namespace

std::optional<DiagonalName> ParseDiagonalName(const std::string& raw) {
  std::string t;
  for (char c : raw) {
    if (c != ' ' && c != '\t') t += c;
  }
  if (t.empty()) return std::nullopt;
  std::array<int, 3> signs{0, 0, 0};
  if (t[0] == '+' || t[0] == '-') {
    // Signed-axis form: (+|-)(X|Y|Z) pairs, then an optional offset like Z300.
    std::size_t i = 0;
    while (i + 1 < t.size() && (t[i] == '+' || t[i] == '-')) {
      const int a = AxisIndex(t[i + 1]);
      if (a < 0 || signs[a] != 0) return std::nullopt;
      signs[a] = t[i] == '+' ? 1 : -1;
      i += 2;
    }
    int offset_axis = -1;
    std::string value;
    if (i < t.size()) {
      offset_axis = AxisIndex(t[i]);
      value = t.substr(i + 1);
      if (offset_axis < 0 || !tools::ParseDouble(value)) return std::nullopt;
    }
    return Finish(signs, offset_axis, value);
  }
  // N/P form: three letters (body, X Y Z) or two letters (face XY) and an optional Z value.
  std::size_t i = 0;
  while (i < t.size() && i < 3 &&
         (std::toupper(static_cast<unsigned char>(t[i])) == 'N' ||
          std::toupper(static_cast<unsigned char>(t[i])) == 'P')) {
    signs[i] = std::toupper(static_cast<unsigned char>(t[i])) == 'P' ? 1 : -1;
    ++i;
  }
  if (i == 3) {
    return i == t.size() ? Finish(signs, -1, "") : std::nullopt;
  }
  if (i != 2) return std::nullopt;
  if (i == t.size()) return Finish(signs, -1, "");
  const std::string value = t.substr(i);
  if (!tools::ParseDouble(value)) return std::nullopt;
  return Finish(signs, 2, value);
}

namespace {

constexpr double kSameCoordinateMm = 1e-6;

double Coordinate(const Vec3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

}  // namespace

std::optional<DiagonalName> DiagonalNameFor(const Vec3& p1, const Vec3& p2) {
  static const char* kAxes = "XYZ";
  std::string text;
  std::string offset;
  for (int a = 0; a < 3; ++a) {
    const double d = Coordinate(p2, a) - Coordinate(p1, a);
    if (std::fabs(d) <= kSameCoordinateMm) {
      offset += std::string(1, kAxes[a]) + report::FormatNumber(Coordinate(p1, a));
      continue;
    }
    text += d < 0 ? '+' : '-';  // the start corner lies at the end P1 is at
    text += kAxes[a];
  }
  if (text.size() < 4) return std::nullopt;
  if (!offset.empty()) text += " " + offset;
  return ParseDiagonalName(text);
}

std::optional<std::string> DiagonalNameMismatch(const DiagonalName& given,
                                                const Vec3& p1,
                                                const Vec3& p2) {
  const auto derived = DiagonalNameFor(p1, p2);
  if (!derived) return std::string("P1 and P2 differ in fewer than two axes: not a diagonal");
  if (given.signs != derived->signs) {
    return "\"" + given.text + "\" does not name the diagonal from P1 to P2, which starts at the " +
           derived->text + " corner (" + (derived->body ? "body" : "face") + " diagonal " +
           derived->text + ")";
  }
  if (!given.body && !given.offset.empty()) {
    const int axis = given.offset[0] == 'X' ? 0 : given.offset[0] == 'Y' ? 1 : 2;
    const auto value = tools::ParseDouble(given.offset.substr(1));
    if (!value || std::fabs(*value - Coordinate(p1, axis)) > kSameCoordinateMm) {
      return "\"" + given.text + "\" places the face diagonal at " + given.offset +
             " but P1 and P2 lie at " + derived->offset;
    }
  }
  return std::nullopt;
}

std::string DiagonalFileToken(const DiagonalName& name) {
  std::string letters;
  for (int s : name.signs) {
    if (s != 0) letters += s > 0 ? 'P' : 'N';
  }
  if (name.body) return letters;
  std::string token = name.plane + "_" + letters;
  if (!name.offset.empty()) token += "_" + name.offset;
  return token;
}

}  // namespace volcomp::metrology
