// G-code subset reader.
#include "volcomp/sim/gcode.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace volcomp::sim {
namespace {

struct Word {
  char letter;
  double value;
};

Unexpected<Failure> Refuse(const std::string& source, int line, const std::string& what) {
  return Fail(Error::kInputInvalid, source + ":" + std::to_string(line) + ": " + what);
}

// Removes comments and splits a line into words; refuses malformed numbers.
Expected<std::vector<Word>> Words(const std::string& raw, const std::string& source, int line) {
  std::string s;
  int depth = 0;
  for (char c : raw) {
    if (depth == 0 && c == ';') break;
    if (c == '(') {
      ++depth;
    } else if (c == ')') {
      if (depth == 0) return Refuse(source, line, "')' without '('");
      --depth;
    } else if (depth == 0) {
      s += c;
    }
  }
  if (depth != 0) return Refuse(source, line, "unclosed comment");
  std::vector<Word> words;
  size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (std::isspace(static_cast<unsigned char>(c)) || c == '%') {
      ++i;
      continue;
    }
    if (!std::isalpha(static_cast<unsigned char>(c))) {
      return Refuse(source, line, std::string("unexpected '") + c + "'");
    }
    size_t j = i + 1;
    while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
    size_t k = j;
    while (k < s.size() && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '.' ||
                            s[k] == '-' || s[k] == '+')) {
      ++k;
    }
    const std::string number = s.substr(j, k - j);
    char* end = nullptr;
    const double v = number.empty() ? NAN : std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(v)) {
      return Refuse(source, line, std::string("word ") + c + " needs a number");
    }
    words.push_back({static_cast<char>(std::toupper(static_cast<unsigned char>(c))), v});
    i = k;
  }
  return words;
}

bool IsCode(double v, double code) { return std::fabs(v - code) < 1e-9; }

// Checks and stores an arc's words: I J K in the plane or R, not both.
Outcome ArcWords(
    ProgramBlock& b, bool has_offset, double r, int plane, const std::string& source, int line) {
  const char* const kPlaneName = plane == 17 ? "G17" : plane == 18 ? "G18" : "G19";
  const std::array<int, 3> axes = plane == 18   ? std::array<int, 3>{2, 0, 1}
                                  : plane == 19 ? std::array<int, 3>{1, 2, 0}
                                                : std::array<int, 3>{0, 1, 2};
  if (has_offset && !std::isnan(r)) return Refuse(source, line, "an arc with both I/J/K and R");
  if (!has_offset && std::isnan(r)) {
    return Refuse(source, line,
                  "G" + std::string(b.clockwise ? "2" : "3") +
                      " needs the centre (I, J, K) or the radius (R)");
  }
  if (has_offset && b.has_offset[static_cast<size_t>(axes[2])]) {
    return Refuse(source, line,
                  std::string(1, static_cast<char>('I' + axes[2])) + " is not in the " +
                      kPlaneName + " plane");
  }
  if (!std::isnan(r) && r == 0) return Refuse(source, line, "R must not be 0");
  b.plane = plane;
  b.radius_form = !std::isnan(r);
  b.radius_mm = b.radius_form ? r : 0;
  return {};
}

}  // namespace

Expected<Program> ParseGcode(const std::string& text, const std::string& source) {
  Program program;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  bool incremental = false;
  int motion = -1;  // 0, 1, 2, 3 or unset
  int plane = 17;
  double feed_mm_s = 0;
  while (std::getline(in, raw)) {
    ++line;
    VOLCOMP_TRY_ASSIGN(const std::vector<Word> words, Words(raw, source, line));
    ProgramBlock block;
    block.line = line;
    bool has_coord = false, has_offset = false, dwell = false, end = false;
    int new_motion = -1;
    double p = NAN, r = NAN;
    for (const Word& w : words) {
      switch (w.letter) {
        case 'N':
          break;
        case 'G':
          if (IsCode(w.value, 0) || IsCode(w.value, 1) || IsCode(w.value, 2) ||
              IsCode(w.value, 3)) {
            new_motion = static_cast<int>(w.value);
          } else if (IsCode(w.value, 17) || IsCode(w.value, 18) || IsCode(w.value, 19)) {
            plane = static_cast<int>(std::lround(w.value));
          } else if (IsCode(w.value, 4)) {
            dwell = true;
          } else if (IsCode(w.value, 90)) {
            incremental = false;
          } else if (IsCode(w.value, 91)) {
            incremental = true;
          } else if (IsCode(w.value, 20)) {
            return Refuse(source, line, "G20 (inches) is not supported; use G21");
          } else if (IsCode(w.value, 21) || IsCode(w.value, 40) || IsCode(w.value, 49) ||
                     IsCode(w.value, 54) || IsCode(w.value, 61) || IsCode(w.value, 64) ||
                     IsCode(w.value, 80) || IsCode(w.value, 94)) {
          } else {
            std::ostringstream g;
            g << "G" << w.value << " is not supported";
            return Refuse(source, line, g.str());
          }
          break;
        case 'M':
          if (IsCode(w.value, 2) || IsCode(w.value, 30)) {
            end = true;
          } else if (!(IsCode(w.value, 0) || IsCode(w.value, 1) || IsCode(w.value, 3) ||
                       IsCode(w.value, 4) || IsCode(w.value, 5) || IsCode(w.value, 8) ||
                       IsCode(w.value, 9))) {
            std::ostringstream m;
            m << "M" << w.value << " is not supported";
            return Refuse(source, line, m.str());
          }
          break;
        case 'F':
          if (!(w.value > 0)) return Refuse(source, line, "F must be positive");
          feed_mm_s = w.value / 60.0;
          break;
        case 'P':
          p = w.value;
          break;
        case 'X':
        case 'Y':
        case 'Z': {
          const int a = w.letter - 'X';
          block.value_mm[static_cast<size_t>(a)] = w.value;
          block.has[static_cast<size_t>(a)] = true;
          has_coord = true;
          break;
        }
        case 'I':
        case 'J':
        case 'K':
          block.centre_offset_mm[static_cast<size_t>(w.letter - 'I')] = w.value;
          block.has_offset[static_cast<size_t>(w.letter - 'I')] = true;
          has_offset = true;
          break;
        case 'R':
          r = w.value;
          break;
        default:
          return Refuse(source, line, std::string("word ") + w.letter + " is not supported");
      }
    }
    if (new_motion >= 0) motion = new_motion;
    if (dwell) {
      if (has_coord) return Refuse(source, line, "G4 with coordinates");
      if (!(p >= 0)) return Refuse(source, line, "G4 needs P<seconds> >= 0");
      block.kind = ProgramBlock::Kind::kDwell;
      block.dwell_s = p;
      program.push_back(block);
    } else if (!std::isnan(p)) {
      return Refuse(source, line, "P without G4");
    }
    const bool arc_words = has_offset || !std::isnan(r);
    if (arc_words && motion != 2 && motion != 3) {
      return Refuse(source, line, "I, J, K or R without G2 or G3");
    }
    if (has_coord || arc_words) {
      if (motion < 0) return Refuse(source, line, "coordinates without G0, G1, G2 or G3");
      block.incremental = incremental;
      if (motion == 0) {
        block.kind = ProgramBlock::Kind::kRapid;
      } else {
        if (!(feed_mm_s > 0)) {
          return Refuse(source, line, "G" + std::to_string(motion) + " without a feed (F)");
        }
        block.kind = motion == 1 ? ProgramBlock::Kind::kLinear : ProgramBlock::Kind::kArc;
        block.clockwise = motion == 2;
        block.feed_mm_s = feed_mm_s;
      }
      if (block.kind == ProgramBlock::Kind::kArc) {
        VOLCOMP_TRY(ArcWords(block, has_offset, r, plane, source, line));
      }
      program.push_back(block);
    }
    if (end) break;
  }
  return program;
}

}  // namespace volcomp::sim

namespace volcomp::sim {

PathRequest RequestOf(const ProgramBlock& b, const Point3& position_mm, const Point3& step_mm) {
  PathRequest r;
  for (size_t a = 0; a < 3; ++a) {
    double v = position_mm[a];
    if (b.has[a]) v = b.incremental ? v + b.value_mm[a] : b.value_mm[a];
    r.end_mm[a] = static_cast<double>(std::llround(v / step_mm[a])) * step_mm[a];
  }
  r.arc = b.kind == ProgramBlock::Kind::kArc;
  r.clockwise = b.clockwise;
  r.plane = b.plane;
  r.centre_offset_mm = b.centre_offset_mm;
  r.radius_form = b.radius_form;
  r.radius_mm = b.radius_mm;
  return r;
}

Outcome CheckProgramPaths(const Program& program,
                          const Point3& start_mm,
                          const Point3& step_mm,
                          const std::string& source) {
  Point3 at = start_mm;
  for (const ProgramBlock& b : program) {
    if (b.kind == ProgramBlock::Kind::kDwell) continue;
    const PathRequest r = RequestOf(b, at, step_mm);
    const Expected<PathSegment> segment = PathSegment::Resolve(at, r);
    if (!segment.ok()) {
      return Fail(Error::kInputInvalid,
                  source + ":" + std::to_string(b.line) + ": " + segment.error().message);
    }
    at = r.end_mm;
  }
  return {};
}

}  // namespace volcomp::sim
