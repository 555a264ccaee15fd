// A latency histogram (hosted): exact count, minimum, maximum and mean, and percentiles at 1 us
// resolution up to 100 ms (longer values land in an overflow bucket and report as the maximum).
// Used for the gateway's per-frame forwarding latency. Thread-safety: one thread.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace volcomp::linux_board {

class LatencyStats {
 public:
  static constexpr uint32_t kBuckets = 100000;  // 1 us each

  LatencyStats() : buckets_(kBuckets + 1, 0) {}

  void Add(uint64_t ns);
  uint64_t count() const { return count_; }
  uint64_t min_ns() const { return count_ != 0 ? min_ns_ : 0; }
  uint64_t max_ns() const { return max_ns_; }
  uint64_t mean_ns() const { return count_ != 0 ? sum_ns_ / count_ : 0; }
  /// The smallest bucket upper bound below which `fraction` (0..1) of the samples lie, in ns
  /// (at most max_ns()).
  uint64_t Percentile(double fraction) const;

  /// "n 1234, min 21 us, p50 35 us, p99 80 us, p99.9 120 us, max 410 us, mean 38 us"
  std::string Summary() const;
  /// {"count":..,"min_us":..,"p50_us":..,"p99_us":..,"p999_us":..,"max_us":..,"mean_us":..}
  std::string Json() const;

 private:
  std::vector<uint64_t> buckets_;
  uint64_t count_ = 0;
  uint64_t sum_ns_ = 0;
  uint64_t min_ns_ = ~uint64_t{0};
  uint64_t max_ns_ = 0;
};

}  // namespace volcomp::linux_board
