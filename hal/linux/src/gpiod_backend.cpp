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

  Expected<void> Open(const GpioConfig& config) override {
    Release();
    for (int i = 0; i < kInputLineCount; ++i) {
      const Expected<void> r = Request(config.input[i], config.consumer, false,
                                       InputLineName(static_cast<InputLine>(i)), &in_[i]);
      if (!r.ok()) return r;
    }
    for (int i = 0; i < kOutputLineCount; ++i) {
      const Expected<void> r = Request(config.output[i], config.consumer, true,
                                       OutputLineName(static_cast<OutputLine>(i)), &out_[i]);
      if (!r.ok()) return r;
    }
    return Expected<void>::Ok();
  }

  Expected<void> ReadInputs(bool* levels) override {
    Expected<void> result = Expected<void>::Ok();
    for (int i = 0; i < kInputLineCount; ++i) {
      if (in_[i].line == nullptr) {
        levels[i] = false;
        continue;
      }
      const int v = gpiod_line_get_value(in_[i].line);
      if (v < 0) {
        result =
            Fail(Error::kIoError, std::string("gpio ") + InputLineName(static_cast<InputLine>(i)) +
                                      ": read failed: " + std::strerror(errno));
        continue;
      }
      levels[i] = v != 0;
    }
    return result;
  }

  Expected<void> WriteOutput(OutputLine line, bool active) override {
    const int i = static_cast<int>(line);
    if (i < 0 || i >= kOutputLineCount || out_[i].line == nullptr) return Expected<void>::Ok();
    if (gpiod_line_set_value(out_[i].line, active ? 1 : 0) != 0) {
      return Fail(Error::kIoError, std::string("gpio ") + OutputLineName(line) +
                                       ": write failed: " + std::strerror(errno));
    }
    return Expected<void>::Ok();
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

  static Expected<void> Request(const GpioLineSpec& spec,
                                const std::string& consumer,
                                bool output,
                                const char* what,
                                Held* held) {
    if (!spec.used) return Expected<void>::Ok();
    const std::string where = FormatGpioLineSpec(spec);
    auto fail = [&](Error code, const std::string& why) {
      return Fail(code, std::string("gpio ") + what + " (" + where + "): " + why);
    };
    if (spec.chip.empty()) {
      errno = 0;
      held->line = gpiod_line_find(spec.line_name.c_str());
      if (held->line == nullptr) {
        return fail(Error::kNotFound, errno != 0 ? std::strerror(errno) : "no line with this name");
      }
      held->found = true;
    } else {
      held->chip = gpiod_chip_open_lookup(spec.chip.c_str());
      if (held->chip == nullptr) {
        return fail(Error::kNotFound,
                    "cannot open chip '" + spec.chip + "': " + std::strerror(errno));
      }
      held->line = gpiod_chip_get_line(held->chip, spec.offset);
      if (held->line == nullptr) {
        return fail(Error::kNotFound, "no line " + std::to_string(spec.offset) + " on " +
                                          spec.chip + ": " + std::strerror(errno));
      }
    }
    int flags = spec.active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0;
    if (spec.bias == Bias::kPullUp) flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP;
    if (spec.bias == Bias::kPullDown) flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN;
    if (spec.bias == Bias::kDisable) flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE;
    const int r = output ? gpiod_line_request_output_flags(held->line, consumer.c_str(), flags, 0)
                         : gpiod_line_request_input_flags(held->line, consumer.c_str(), flags);
    if (r != 0) {
      const bool busy = errno == EBUSY;
      return fail(busy ? Error::kBusy : Error::kIoError,
                  std::string("request failed: ") + std::strerror(errno) +
                      (busy ? " (line in use: see gpioinfo)" : ""));
    }
    return Expected<void>::Ok();
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
