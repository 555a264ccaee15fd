// Input-to-output step latency.
#include "volcomp/sim/latency_meter.hpp"

#include <algorithm>

namespace volcomp::sim {

LatencyMeter::LatencyMeter(uint64_t tick_ns)
    : tick_ns_(tick_ns), bins_(static_cast<size_t>(kBinsPerTick * kMaxTicks + 1), 0) {}

void LatencyMeter::OnInput(int axis, uint64_t t_ns, int dir, int64_t count_after) {
  Queue& q = pending_[static_cast<size_t>(axis)];
  if (q.head > 4096 && q.head * 2 > q.items.size()) {  // drop the consumed front now and then
    q.items.erase(q.items.begin(), q.items.begin() + static_cast<std::ptrdiff_t>(q.head));
    q.head = 0;
  }
  q.items.push_back({t_ns, count_after, dir});
}

void LatencyMeter::Record(uint64_t latency_ns) {
  const uint64_t bin = latency_ns * kBinsPerTick / tick_ns_;
  bins_[static_cast<size_t>(std::min<uint64_t>(bin, bins_.size() - 1))]++;
  ++samples_;
  sum_ns_ += static_cast<double>(latency_ns);
  max_ns_ = std::max(max_ns_, latency_ns);
  if (latency_ns > 2 * tick_ns_) ++over_2_ticks_;
}

void LatencyMeter::Carry(int axis, uint64_t t_ns, int64_t served) {
  auto& q = pending_[static_cast<size_t>(axis)];
  while (!q.empty()) {
    const Pending& p = q.front();
    const bool carried = p.dir > 0 ? served >= p.count : served <= p.count;
    if (!carried) break;
    Record(t_ns >= p.t_ns ? t_ns - p.t_ns : 0);
    q.pop();
  }
}

void LatencyMeter::OnOutput(int axis, uint64_t t_ns, int64_t served) { Carry(axis, t_ns, served); }

void LatencyMeter::EndOfTick(int axis, uint64_t tick_ns, int64_t served) {
  Carry(axis, tick_ns, served);
  auto& q = pending_[static_cast<size_t>(axis)];
  while (!q.empty() && q.front().t_ns + 1000 * tick_ns_ < tick_ns) {
    ++unmatched_;
    q.pop();
  }
}

LatencySummary LatencyMeter::Summarize() const {
  LatencySummary s;
  s.samples = samples_;
  s.unmatched = unmatched_;
  if (samples_ == 0) return s;
  s.max_ticks = static_cast<double>(max_ns_) / static_cast<double>(tick_ns_);
  s.mean_ticks = sum_ns_ / static_cast<double>(samples_) / static_cast<double>(tick_ns_);
  // Percentiles: upper edge of the bin holding the quantile (conservative by < 1/100 tick).
  auto quantile = [&](double q) {
    const double want = q * static_cast<double>(samples_);
    uint64_t acc = 0;
    for (size_t i = 0; i < bins_.size(); ++i) {
      acc += bins_[i];
      if (static_cast<double>(acc) >= want) {
        return std::min(static_cast<double>(i + 1) / kBinsPerTick, s.max_ticks);
      }
    }
    return s.max_ticks;
  };
  s.p50_ticks = quantile(0.5);
  s.p90_ticks = quantile(0.9);
  s.p99_ticks = quantile(0.99);
  s.p999_ticks = quantile(0.999);
  s.over_2_ticks = over_2_ticks_;
  return s;
}

}  // namespace volcomp::sim
