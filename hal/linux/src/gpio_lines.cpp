// GPIO line names and line-spec parsing.
#include "volcomp/hal/linux/gpio_lines.hpp"

#include <sstream>

namespace volcomp::hal::linux_board {
namespace {

const char* const kInputNames[kInputLineCount] = {"home0",       "home1",       "home2",  "home3",
                                                  "home4",       "home5",       "enable", "estop",
                                                  "drive_alarm", "write_enable"};
const char* const kOutputNames[kOutputLineCount] = {"ready", "compensating", "fault"};

bool ParseOffset(const std::string& s, unsigned* out) {
  if (s.empty() || s.size() > 6) return false;
  unsigned v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + static_cast<unsigned>(c - '0');
  }
  *out = v;
  return true;
}

}  // namespace

Expected<GpioLineSpec> ParseGpioLineSpec(const std::string& text) {
  auto bad = [](const std::string& why) { return Fail(Error::kInvalidArgument, why); };
  std::istringstream in(text);
  std::string where;
  if (!(in >> where)) return bad("empty line spec (expected CHIP:OFFSET or a line name)");
  GpioLineSpec spec;
  spec.used = true;
  const size_t colon = where.rfind(':');
  if (colon != std::string::npos) {
    spec.chip = where.substr(0, colon);
    if (spec.chip.empty() || !ParseOffset(where.substr(colon + 1), &spec.offset)) {
      return bad("bad line '" + where + "' (expected CHIP:OFFSET, e.g. gpiochip0:17)");
    }
  } else {
    spec.line_name = where;
  }
  std::string flag;
  bool have_bias = false;
  while (in >> flag) {
    Bias bias = Bias::kAsIs;
    if (flag == "active-low") {
      spec.active_low = true;
      continue;
    } else if (flag == "pull-up") {
      bias = Bias::kPullUp;
    } else if (flag == "pull-down") {
      bias = Bias::kPullDown;
    } else if (flag == "bias-disable") {
      bias = Bias::kDisable;
    } else {
      return bad("unknown line flag '" + flag +
                 "' (expected active-low, pull-up, pull-down or bias-disable)");
    }
    if (have_bias) return bad("more than one bias flag");
    have_bias = true;
    spec.bias = bias;
  }
  return spec;
}

std::string FormatGpioLineSpec(const GpioLineSpec& spec) {
  if (!spec.used) return "";
  std::string s =
      spec.chip.empty() ? spec.line_name : spec.chip + ":" + std::to_string(spec.offset);
  if (spec.active_low) s += " active-low";
  if (spec.bias == Bias::kPullUp) s += " pull-up";
  if (spec.bias == Bias::kPullDown) s += " pull-down";
  if (spec.bias == Bias::kDisable) s += " bias-disable";
  return s;
}

const char* InputLineName(InputLine line) {
  const int i = static_cast<int>(line);
  return i >= 0 && i < kInputLineCount ? kInputNames[i] : "?";
}

const char* OutputLineName(OutputLine line) {
  const int i = static_cast<int>(line);
  return i >= 0 && i < kOutputLineCount ? kOutputNames[i] : "?";
}

bool InputLineFromName(const std::string& name, InputLine* line) {
  for (int i = 0; i < kInputLineCount; ++i) {
    if (name == kInputNames[i]) {
      *line = static_cast<InputLine>(i);
      return true;
    }
  }
  return false;
}

bool OutputLineFromName(const std::string& name, OutputLine* line) {
  for (int i = 0; i < kOutputLineCount; ++i) {
    if (name == kOutputNames[i]) {
      *line = static_cast<OutputLine>(i);
      return true;
    }
  }
  return false;
}

}  // namespace volcomp::hal::linux_board
