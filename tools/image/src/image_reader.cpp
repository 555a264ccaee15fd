// Hosted image reading and evaluation.
#include "volcomp/image/image_reader.hpp"

#include <cstring>

#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::image {

Expected<LoadedImage> LoadedImage::FromBytes(const std::vector<uint8_t>& bytes,
                                             const std::string& source) {
  LoadedImage image;
  image.storage_.resize((bytes.size() + 3) / 4);
  if (!bytes.empty()) std::memcpy(image.storage_.data(), bytes.data(), bytes.size());
  const Result<table::TableView> v = table::ParseImage(image.data(), bytes.size());
  if (!v.ok()) {
    return Fail(Error::kInputInvalid, source + ": invalid table image: " + ErrorText(v.error()) +
                                          " (" + ErrorName(v.error()) + ")");
  }
  image.view_ = *v;
  return image;
}

Expected<LoadedImage> ReadImageFile(const std::string& path) {
  VOLCOMP_TRY_ASSIGN(const std::vector<uint8_t> bytes, tools::ReadFileBytes(path));
  return LoadedImage::FromBytes(bytes, path);
}

BoardConfig BoardConfigFor(const table::TableView& view) {
  BoardConfig c = DefaultBoardConfig();
  c.axis_count = view.axis_count;
  for (uint8_t i = 0; i < view.axis_count; ++i) {
    c.axis[i] = AxisConfig();
    c.axis[i].name = view.axes[i].name;
    c.axis[i].kind = view.axes[i].kind;
    c.axis[i].resolution_e9 = view.axes[i].resolution_e9;
    c.axis[i].max_correction_steps = table::kMaxCorrectionSteps;
    c.axis[i].drive.max_rate_hz = 4000000;
    c.axis[i].drive.pulse_width_ns = c.axis[i].drive.step_space_ns = 100;
  }
  return c;
}

Expected<ImageEvaluator> ImageEvaluator::Create(const LoadedImage& image) {
  ImageEvaluator e(image.view().axis_count);
  const Status s = e.table_.Prepare(image.view(), BoardConfigFor(image.view()));
  if (!s.ok()) return Fail(Error::kInputInvalid, std::string("image: ") + ErrorText(s.error()));
  return e;
}

void ImageEvaluator::CorrectionQ8(const int32_t* pos_steps,
                                  const bool* reverse,
                                  int32_t* out_q8) const {
  int32_t axis_pos[table::kMaxAxes];
  for (uint8_t a = 0; a < axis_count_; ++a) {
    axis_pos[a] = pos_steps[a];
    const int8_t i = table_.axis_table_of[a];
    if (i >= 0 && table_.axis_table[i].wraps()) {
      WrapTracker w;
      w.Init(pos_steps[a], table_.axis_table[i].origin_steps(),
             table_.axis_table[i].period_steps());
      axis_pos[a] = w.position();
    }
  }
  table_.TargetsQ8(pos_steps, axis_pos, reverse, axis_count_, out_q8);
}

}  // namespace volcomp::image
