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

}  // namespace

Expected<Program> ParseGcode(const std::string& text, const std::string& source) {
  Program program;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  bool incremental = false;
  int motion = -1;  // 0, 1 or unset
  double feed_mm_s = 0;
  while (std::getline(in, raw)) {
    ++line;
    VOLCOMP_TRY_ASSIGN(const std::vector<Word> words, Words(raw, source, line));
    ProgramBlock block;
    block.line = line;
    bool has_coord = false, dwell = false, end = false;
    int new_motion = -1;
    double p = NAN;
    for (const Word& w : words) {
      switch (w.letter) {
        case 'N':
          break;
        case 'G':
          if (IsCode(w.value, 0) || IsCode(w.value, 1)) {
            new_motion = static_cast<int>(w.value);
          } else if (IsCode(w.value, 4)) {
            dwell = true;
          } else if (IsCode(w.value, 90)) {
            incremental = false;
          } else if (IsCode(w.value, 91)) {
            incremental = true;
          } else if (IsCode(w.value, 20)) {
            return Refuse(source, line, "G20 (inches) is not supported; use G21");
          } else if (IsCode(w.value, 21) || IsCode(w.value, 17) || IsCode(w.value, 40) ||
                     IsCode(w.value, 49) || IsCode(w.value, 54) || IsCode(w.value, 61) ||
                     IsCode(w.value, 64) || IsCode(w.value, 80) || IsCode(w.value, 94)) {
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
    if (has_coord) {
      if (motion < 0) return Refuse(source, line, "coordinates without G0 or G1");
      block.incremental = incremental;
      if (motion == 0) {
        block.kind = ProgramBlock::Kind::kRapid;
      } else {
        if (!(feed_mm_s > 0)) return Refuse(source, line, "G1 without a feed (F)");
        block.kind = ProgramBlock::Kind::kLinear;
        block.feed_mm_s = feed_mm_s;
      }
      program.push_back(block);
    }
    if (end) break;
  }
  return program;
}

}  // namespace volcomp::sim
