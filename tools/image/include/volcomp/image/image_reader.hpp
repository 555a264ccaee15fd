// Hosted image reading for the PC tool: load a file into aligned memory, validate it with the
// firmware's parser, and evaluate corrections with the firmware's lookup code. Failures are
// Expected (kIoError for files, kInputInvalid for images).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/config/board_config.hpp"
#include "volcomp/control/compensator.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp::image {

/// A validated image in 4-byte aligned memory. Move-only (the view points into the storage).
class LoadedImage {
 public:
  /// Validates `bytes` with the firmware's parser; the failure (kInputInvalid) reads
  /// "SOURCE: invalid table image: TEXT (kName)".
  static Expected<LoadedImage> FromBytes(const std::vector<uint8_t>& bytes,
                                         const std::string& source);
  LoadedImage(LoadedImage&&) = default;
  LoadedImage& operator=(LoadedImage&&) = default;
  LoadedImage(const LoadedImage&) = delete;
  LoadedImage& operator=(const LoadedImage&) = delete;

  const table::TableView& view() const { return view_; }
  const uint8_t* data() const { return reinterpret_cast<const uint8_t*>(storage_.data()); }
  uint32_t size() const { return view_.image_size; }

 private:
  LoadedImage() = default;
  std::vector<uint32_t> storage_;
  table::TableView view_;
};

/// Reads and validates the image file at `path` (kIoError when it cannot be read).
Expected<LoadedImage> ReadImageFile(const std::string& path);

/// A board configuration whose axes are exactly the image's (for tools and the simulator).
BoardConfig BoardConfigFor(const table::TableView& view);

/// The table's correction target at a position, computed by the firmware's code (GridLookup +
/// AxisLookup via PreparedTable), before the board's clamp and rate limiter. Reads the image's
/// memory: `image` must outlive the evaluator.
class ImageEvaluator {
 public:
  /// Prepares the firmware's lookup on `image` for BoardConfigFor(its view); kInputInvalid when
  /// the firmware refuses the table.
  static Expected<ImageEvaluator> Create(const LoadedImage& image);
  /// `pos_steps` and `reverse` per image axis; writes Q24.8 steps per image axis.
  void CorrectionQ8(const int32_t* pos_steps, const bool* reverse, int32_t* out_q8) const;
  uint8_t axis_count() const { return axis_count_; }

 private:
  explicit ImageEvaluator(uint8_t axis_count) : axis_count_(axis_count) {}
  PreparedTable table_;
  uint8_t axis_count_;
};

}  // namespace volcomp::image
