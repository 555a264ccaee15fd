// ISO 230-6 diagonal names.
#include <cctype>

#include "volcomp/metrology/diagonal.hpp"
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

}  // namespace volcomp::metrology
