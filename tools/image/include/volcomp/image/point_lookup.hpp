// The correction of an image at points read from a CSV, as `volcomp lookup` writes it.
//
// Input columns, per image axis: a position, <x>_steps or <x>_mm (<a>_deg on a rotary axis;
// rounded to whole steps), and optionally dir_<x> (+1 forward, -1 reverse; default +1) for the
// axes with AXIS1D tables. Output CSV: <x>_steps per axis, then per axis d<x>_steps (the exact
// Q8 value) and d<x>_um (d<a>_arcsec on a rotary axis). Failures name the input's line
// (kInputInvalid).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::image {

class PointLookup {
 public:
  /// The columns of `points` for the axes of `image` (a failure names a missing column). Reads
  /// the image's memory: `image` must outlive the lookup.
  static Expected<PointLookup> Create(const LoadedImage& image, const tools::CsvTable& points);

  /// The output's header line, with its line end.
  std::string Header() const;
  /// The output line of one input row, with its line end.
  Expected<std::string> Row(const tools::CsvRow& row) const;

 private:
  struct AxisColumns {
    std::string position;  // column name
    bool in_steps = false;
    double units_per_step = 0;
    bool rotary = false;
    std::string direction;  // "" when absent
  };
  PointLookup(ImageEvaluator evaluator, std::string source)
      : evaluator_(std::move(evaluator)), source_(std::move(source)) {}

  ImageEvaluator evaluator_;
  std::string source_;  // the points' source, for failures
  std::vector<char> names_;
  std::vector<AxisColumns> columns_;
};

}  // namespace volcomp::image
