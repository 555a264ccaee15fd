// libgpiod 1.6 (v1 API) backend.
#include "volcomp/hal/linux/gpiod_backend.hpp"

#include <gpiod.h>

#include <cerrno>
#include <cstring>
#include <vector>

namespace volcomp::hal::linux_board {
namespace {

class GpiodBackend final : public GpioBackend {
 public:
  ~GpiodBackend() override { Release(); }

  std::string Open(const GpioConfig& config) override {
    Release();
    for (int i = 0; i < kInputLineCount; ++i) {
      const std::string why = Request(config.input[i], config.consumer, false,
                                      InputLineName(static_cast<InputLine>(i)), &in_[i]);
      if (!why.empty()) return why;
    }
    for (int i = 0; i < kOutputLineCount; ++i) {
      const std::string why = Request(config.output[i], config.consumer, true,
                                      OutputLineName(static_cast<OutputLine>(i)), &out_[i]);
      if (!why.empty()) return why;
    }
    return "";
  }

  std::string ReadInputs(bool* levels) override {
    std::string why;
    for (int i = 0; i < kInputLineCount; ++i) {
      if (in_[i].line == nullptr) {
        levels[i] = false;
        continue;
      }
      const int v = gpiod_line_get_value(in_[i].line);
      if (v < 0) {
        why = std::string("gpio ") + InputLineName(static_cast<InputLine>(i)) +
              ": read failed: " + std::strerror(errno);
        continue;
      }
      levels[i] = v != 0;
    }
    return why;
  }

  std::string WriteOutput(OutputLine line, bool active) override {
    const int i = static_cast<int>(line);
    if (i < 0 || i >= kOutputLineCount || out_[i].line == nullptr) return "";
    if (gpiod_line_set_value(out_[i].line, active ? 1 : 0) != 0) {
      return std::string("gpio ") + OutputLineName(line) +
             ": write failed: " + std::strerror(errno);
    }
    return "";
  }

  std::string Describe() const override {
    return std::string("libgpiod ") + gpiod_version_string();
  }

 private:
  struct Held {
    gpiod_line* line = nullptr;
    gpiod_chip* chip = nullptr;  // opened by us (chip:offset lines)
    bool found = false;          // line from gpiod_line_find (owns its chip)
  };

  static std::string Request(const GpioLineSpec& spec,
                             const std::string& consumer,
                             bool output,
                             const char* what,
                             Held* held) {
    if (!spec.used) return "";
    const std::string where = FormatGpioLineSpec(spec);
    if (spec.chip.empty()) {
      errno = 0;
      held->line = gpiod_line_find(spec.line_name.c_str());
      if (held->line == nullptr) {
        return std::string("gpio ") + what + " (" + where +
               "): " + (errno != 0 ? std::strerror(errno) : "no line with this name");
      }
      held->found = true;
    } else {
      held->chip = gpiod_chip_open_lookup(spec.chip.c_str());
      if (held->chip == nullptr) {
        return std::string("gpio ") + what + " (" + where + "): cannot open chip '" + spec.chip +
               "': " + std::strerror(errno);
      }
      held->line = gpiod_chip_get_line(held->chip, spec.offset);
      if (held->line == nullptr) {
        return std::string("gpio ") + what + " (" + where + "): no line " +
               std::to_string(spec.offset) + " on " + spec.chip + ": " + std::strerror(errno);
      }
    }
    int flags = spec.active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0;
    if (spec.bias == Bias::kPullUp) flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP;
    if (spec.bias == Bias::kPullDown) flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN;
    if (spec.bias == Bias::kDisable) flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE;
    const int r = output ? gpiod_line_request_output_flags(held->line, consumer.c_str(), flags, 0)
                         : gpiod_line_request_input_flags(held->line, consumer.c_str(), flags);
    if (r != 0) {
      const std::string why = std::string("gpio ") + what + " (" + where +
                              "): request failed: " + std::strerror(errno) +
                              (errno == EBUSY ? " (line in use: see gpioinfo)" : "");
      return why;
    }
    return "";
  }

  void Release() {
    for (Held* h : All()) {
      if (h->line != nullptr && gpiod_line_is_requested(h->line)) gpiod_line_release(h->line);
      if (h->found && h->line != nullptr) gpiod_line_close_chip(h->line);
      if (h->chip != nullptr) gpiod_chip_close(h->chip);
      *h = Held();
    }
  }

  std::vector<Held*> All() {
    std::vector<Held*> v;
    for (Held& h : in_) v.push_back(&h);
    for (Held& h : out_) v.push_back(&h);
    return v;
  }

  Held in_[kInputLineCount];
  Held out_[kOutputLineCount];
};

}  // namespace

std::unique_ptr<GpioBackend> MakeGpiodBackend() { return std::make_unique<GpiodBackend>(); }
bool HaveLibgpiod() { return true; }

}  // namespace volcomp::hal::linux_board
