// The checked-in golden stream (golden_vectors.inc) as sections, and a sink that compares a
// computed stream with it. Shared by the host test and the QEMU image.
#pragma once

#include <cstdint>

#include "golden.hpp"

namespace volcomp::target {

struct GoldenView {
  const uint32_t* words;
  uint32_t count;
};

/// The checked-in words of section `s`.
GoldenView GoldenFor(GoldenSection s);

/// Compares a computed section with the checked-in one; remembers the first difference.
class CompareSink final : public GoldenSink {
 public:
  void Begin(GoldenSection s) override {
    expected_ = GoldenFor(s);
    index_ = 0;
    first_diff_ = ~0u;
  }
  bool Put(uint32_t word) override {
    if (index_ >= expected_.count || expected_.words[index_] != word) {
      if (first_diff_ == ~0u) {
        first_diff_ = index_;
        got_ = word;
        want_ = index_ < expected_.count ? expected_.words[index_] : 0u;
      }
    }
    ++index_;
    return true;
  }
  bool ok() const { return first_diff_ == ~0u && index_ == expected_.count; }
  uint32_t computed() const { return index_; }
  uint32_t expected() const { return expected_.count; }
  uint32_t first_diff() const { return first_diff_; }
  uint32_t got() const { return got_; }
  uint32_t want() const { return want_; }

 private:
  GoldenView expected_{nullptr, 0};
  uint32_t index_ = 0;
  uint32_t first_diff_ = ~0u;
  uint32_t got_ = 0;
  uint32_t want_ = 0;
};

}  // namespace volcomp::target
