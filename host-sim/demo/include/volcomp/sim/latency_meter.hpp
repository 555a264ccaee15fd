// Latency from an input step to the output pulse that carries it, measured from the outside: the
// served input count after each output pulse is drive position minus the board's whole-step
// correction (docs/simulator.md "Latency"). Kept as a histogram in 1/100 tick bins up to 10 ticks
// (percentiles are a bin's upper edge) and the exact maximum; steps not carried within 1000 ticks
// are unmatched. Times ns. Thread-safety: none (the simulation's thread).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace volcomp::sim {

struct LatencySummary {
  uint64_t samples = 0;
  uint64_t unmatched = 0;
  double p50_ticks = 0, p90_ticks = 0, p99_ticks = 0, p999_ticks = 0, max_ticks = 0;
  double mean_ticks = 0;
  uint64_t over_2_ticks = 0;  // samples above 2 ticks
};

class LatencyMeter {
 public:
  static constexpr int kBinsPerTick = 100;
  static constexpr int kMaxTicks = 10;

  explicit LatencyMeter(uint64_t tick_ns);

  void OnInput(int axis, uint64_t t_ns, int dir, int64_t count_after);
  void OnOutput(int axis, uint64_t t_ns, int64_t served);
  /// After each tick's pulses: carries absorbed steps, drops stale ones.
  void EndOfTick(int axis, uint64_t tick_ns, int64_t served);

  LatencySummary Summarize() const;
  /// Counts per bin of 1/kBinsPerTick tick; the last bin holds everything beyond kMaxTicks.
  const std::vector<uint64_t>& histogram() const { return bins_; }
  uint64_t tick_ns() const { return tick_ns_; }

 private:
  struct Pending {
    uint64_t t_ns;
    int64_t count;
    int dir;
  };
  // A FIFO per axis: entries [head, size) are pending (cheaper than std::deque per step).
  struct Queue {
    std::vector<Pending> items;
    size_t head = 0;
    bool empty() const { return head == items.size(); }
    const Pending& front() const { return items[head]; }
    void pop() {
      if (++head == items.size()) {
        items.clear();
        head = 0;
      }
    }
  };
  void Record(uint64_t latency_ns);
  void Carry(int axis, uint64_t t_ns, int64_t served);

  uint64_t tick_ns_;
  std::array<Queue, 3> pending_;
  std::vector<uint64_t> bins_;
  uint64_t samples_ = 0;
  uint64_t unmatched_ = 0;
  uint64_t max_ns_ = 0;
  uint64_t over_2_ticks_ = 0;
  double sum_ns_ = 0;
};

}  // namespace volcomp::sim
