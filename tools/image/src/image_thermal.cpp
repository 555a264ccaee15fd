// A new image with a new THERMAL section.
#include "volcomp/image/image_thermal.hpp"

#include <algorithm>

#include "section_copy.hpp"

namespace volcomp::image {
namespace {

// The image's INFO lines without its earlier thermal model's.
std::string KeptInfo(const table::TableView& v) {
  const std::string all = PrefixedInfo(v, "");
  std::string out;
  std::size_t start = 0;
  while (start < all.size()) {
    const std::size_t end = all.find('\n', start);
    const std::string line = all.substr(start, end - start + 1);
    if (line.compare(0, 8, "thermal.") != 0) out += line;
    start = end + 1;
  }
  return out;
}

}  // namespace

Expected<ThermalImage> WithThermalModel(const LoadedImage& image,
                                        const std::string& source,
                                        const thermal::ThermalModel& model,
                                        const ThermalImageOptions& options) {
  const table::TableView& v = image.view();
  if (model.axis_count != v.axis_count) {
    return Fail(Error::kInputInvalid, source + ": the thermal model has " +
                                          std::to_string(model.axis_count) + " axes, the image " +
                                          std::to_string(v.axis_count));
  }
  table::ImageSpec spec;
  spec.table_id = options.table_id.value_or(v.table_id);
  if (spec.table_id == 0) {
    return Fail(Error::kInputInvalid, "table id 0 means no table active: give an id from 1");
  }
  spec.axis_count = v.axis_count;
  for (uint8_t i = 0; i < v.axis_count; ++i) spec.axes[i] = v.axes[i];
  SectionCopy copy;
  if (v.grid.present) CopyGrid(v, &copy, &spec);
  for (uint8_t i = 0; i < v.axis1d_count; ++i)
    CopyAxis1d(v.axis1d[i], v.axis1d[i].axis, &copy, &spec);
  spec.thermal = &model;

  ThermalImage out;
  out.replaced = v.thermal != nullptr;
  std::string info = "thermal.builder=volcomp build thermal\n";
  for (const auto& [k, value] : options.info) info += "thermal." + k + "=" + value + "\n";
  std::string info_text;
  VOLCOMP_TRY(SetInfo(info, KeptInfo(v), source, &info_text, &out.warnings, &spec));
  Expected<std::vector<uint8_t>> bytes = WriteSpec(spec);
  if (!bytes.ok()) return Fail(bytes.error().Prefixed(source + " with the thermal model"));
  out.bytes = std::move(*bytes);
  return out;
}

std::optional<std::pair<double, double>> TableSpan(const table::TableView& view, uint8_t axis) {
  std::optional<std::pair<double, double>> span;
  const double unit = view.axes[axis].resolution_e9 * 1e-9;
  auto add = [&](const table::Dimension& d) {
    const double a = d.origin_steps * unit;
    const double b = (d.origin_steps + static_cast<double>(d.spacing_steps) * (d.nodes - 1)) * unit;
    if (!span) span = std::make_pair(a, b);
    span->first = std::min(span->first, a);
    span->second = std::max(span->second, b);
  };
  if (view.grid.present) {
    for (int d = 0; d < 3; ++d) {
      if (view.grid.axis[d] == axis) add(view.grid.dim[d]);
    }
  }
  for (uint8_t i = 0; i < view.axis1d_count; ++i) {
    if (view.axis1d[i].axis == axis) add(view.axis1d[i].dim);
  }
  return span;
}

std::map<char, std::pair<double, double>> LinearAxisSpans(const table::TableView& view) {
  std::map<char, std::pair<double, double>> spans;
  for (uint8_t i = 0; i < view.axis_count; ++i) {
    if (view.axes[i].kind != table::AxisKind::kLinear) continue;
    if (const auto span = TableSpan(view, i)) spans[view.axes[i].name] = *span;
  }
  return spans;
}

}  // namespace volcomp::image
