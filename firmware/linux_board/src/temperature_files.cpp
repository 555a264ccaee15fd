// The Linux board's temperature files (see temperature_files.hpp).
#include "volcomp/linux_board/temperature_files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstring>

#include "volcomp/hosted/ini.hpp"

namespace volcomp::linux_board {
namespace {

using hosted::Trim;

// A whole decimal integer (optional '-'), at most 9 digits: millidegrees.
bool ParseMillidegrees(const std::string& s, int64_t* out) {
  size_t i = 0;
  const bool negative = !s.empty() && s[0] == '-';
  if (negative) i = 1;
  if (i == s.size() || s.size() - i > 9) return false;
  int64_t v = 0;
  for (; i < s.size(); ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
    v = v * 10 + (s[i] - '0');
  }
  *out = negative ? -v : v;
  return true;
}

// The text as written, for a message: one line, at most 40 characters.
std::string Quoted(const std::string& text) {
  std::string q;
  for (char c : text.substr(0, 40)) q += c == '\n' ? ' ' : c;
  return "'" + Trim(q) + (text.size() > 40 ? "...'" : "'");
}

}  // namespace

Expected<int16_t> ParseTemperatureText(const std::string& text) {
  std::string number = Trim(text);
  const size_t t = number.rfind("t=");
  if (t != std::string::npos) {  // w1_slave
    const size_t eol = number.find('\n');
    const std::string first = Trim(number.substr(0, eol));
    if (eol == std::string::npos || first.size() < 3 ||
        first.compare(first.size() - 3, 3, "YES") != 0) {
      return Fail(Error::kInputInvalid, "w1_slave CRC check failed: " + Quoted(text));
    }
    number = Trim(number.substr(t + 2));
  }
  int64_t milli = 0;
  if (!ParseMillidegrees(number, &milli)) {
    return Fail(
        Error::kInputInvalid,
        "not a temperature in millidegrees C (hwmon, w1 temperature or w1_slave): " + Quoted(text));
  }
  const int64_t centi = milli >= 0 ? (milli + 5) / 10 : -((-milli + 5) / 10);
  if (centi < -32767 || centi > 32767) {
    return Fail(Error::kOutOfRange,
                std::to_string(milli) + " millidegrees C is outside +-327.67 C: " + Quoted(text));
  }
  return static_cast<int16_t>(centi);
}

Expected<std::string> ReadSmallFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return Fail(Error::kIoError, "cannot open: " + std::string(std::strerror(errno)));
  std::string text;
  char buf[256];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int e = errno;
      ::close(fd);
      return Fail(Error::kIoError, "read: " + std::string(std::strerror(e)));
    }
    if (n == 0) break;
    text.append(buf, static_cast<size_t>(n));
    if (text.size() > 4096) break;
  }
  ::close(fd);
  return text;
}

TemperatureFiles::TemperatureFiles(const std::array<std::string, thermal::kMaxChannels>& paths,
                                   uint32_t period_ms)
    : period_ms_(period_ms) {
  for (uint8_t ch = 0; ch < thermal::kMaxChannels; ++ch) slot_[ch].path = paths[ch];
}

TemperatureFiles::~TemperatureFiles() { Stop(); }

void* TemperatureFiles::ThreadMain(void* arg) {
  const Reader* r = static_cast<const Reader*>(arg);
  r->self->Run(r->channel);
  return nullptr;
}

void TemperatureFiles::Start() {
  Stop();
  stopping_ = false;
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, 64 * 1024);
  for (uint8_t ch = 0; ch < thermal::kMaxChannels; ++ch) {
    if (slot_[ch].path.empty()) continue;
    reader_[ch] = {this, ch};
    pthread_t t;
    if (pthread_create(&t, &attr, ThreadMain, &reader_[ch]) == 0) {
      threads_.push_back(t);
    } else {
      std::lock_guard<std::mutex> lock(mutex_);
      log_.push_back("[sensors] temperature_file." + std::to_string(ch + 1) +
                     ": cannot start its reader thread (the channel has no readings)");
    }
  }
  pthread_attr_destroy(&attr);
}

void TemperatureFiles::Stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (pthread_t t : threads_) pthread_join(t, nullptr);
  threads_.clear();
}

void TemperatureFiles::Run(uint8_t channel) {
  for (;;) {
    const auto start = std::chrono::steady_clock::now();
    ReadOnce(channel);
    std::unique_lock<std::mutex> lock(mutex_);
    if (wake_.wait_until(lock, start + std::chrono::milliseconds(period_ms_),
                         [this] { return stopping_; })) {
      return;
    }
  }
}

void TemperatureFiles::ReadOnce(uint8_t channel) {
  Slot& s = slot_[channel];
  const std::string key = "[sensors] temperature_file." + std::to_string(channel + 1);
  Expected<int16_t> value = Fail(Error::kIoError, "");
  const Expected<std::string> text = ReadSmallFile(s.path);
  if (text.ok()) {
    value = ParseTemperatureText(*text);
  } else {
    value = Fail(text.error().code, text.error().message);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  const std::string failure = value.ok() ? "" : value.error().message;
  if (failure != s.failure) {
    if (!failure.empty()) {
      log_.push_back(key + " " + s.path + ": " + failure + " (channel " +
                     std::to_string(channel + 1) + " has no reading)");
    } else {
      log_.push_back(key + " " + s.path + ": reading again");
    }
    s.failure = failure;
  }
  s.value_cC = value.ok() ? *value : thermal::kNoReading_cC;
  ++s.published;
}

std::vector<std::string> TemperatureFiles::TakeLog() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> out;
  out.swap(log_);
  return out;
}

bool TemperatureFiles::DoTake(uint8_t channel, thermal::ChannelSource source, int16_t* value_cC) {
  if (channel >= thermal::kMaxChannels || source != thermal::ChannelSource::kLinuxFile) {
    return false;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  Slot& s = slot_[channel];
  if (s.published == s.taken) return false;
  s.taken = s.published;
  *value_cC = s.value_cC;
  return true;
}

}  // namespace volcomp::linux_board
