// Latency histogram.
#include "volcomp/linux_board/latency_stats.hpp"

#include <cstdio>

namespace volcomp::linux_board {

void LatencyStats::Add(uint64_t ns) {
  const uint64_t us = ns / 1000u;
  ++buckets_[us < kBuckets ? us : kBuckets];
  ++count_;
  sum_ns_ += ns;
  if (ns < min_ns_) min_ns_ = ns;
  if (ns > max_ns_) max_ns_ = ns;
}

uint64_t LatencyStats::Percentile(double fraction) const {
  if (count_ == 0) return 0;
  const double want = fraction * static_cast<double>(count_);
  uint64_t seen = 0;
  for (uint32_t i = 0; i <= kBuckets; ++i) {
    seen += buckets_[i];
    if (static_cast<double>(seen) >= want && seen != 0) {
      const uint64_t upper = (uint64_t{i} + 1) * 1000u;
      return i == kBuckets || upper > max_ns_ ? max_ns_ : upper;
    }
  }
  return max_ns_;
}

namespace {
std::string Us(uint64_t ns) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", static_cast<double>(ns) / 1000.0);
  return b;
}
}  // namespace

std::string LatencyStats::Summary() const {
  if (count_ == 0) return "n 0";
  return "n " + std::to_string(count_) + ", min " + Us(min_ns()) + " us, p50 " +
         Us(Percentile(0.5)) + " us, p99 " + Us(Percentile(0.99)) + " us, p99.9 " +
         Us(Percentile(0.999)) + " us, max " + Us(max_ns_) + " us, mean " + Us(mean_ns()) + " us";
}

std::string LatencyStats::Json() const {
  return "{\"count\":" + std::to_string(count_) + ",\"min_us\":" + Us(min_ns()) +
         ",\"p50_us\":" + Us(Percentile(0.5)) + ",\"p99_us\":" + Us(Percentile(0.99)) +
         ",\"p999_us\":" + Us(Percentile(0.999)) + ",\"max_us\":" + Us(max_ns_) +
         ",\"mean_us\":" + Us(mean_ns()) + "}";
}

}  // namespace volcomp::linux_board
