// A new image with a new thermal model: the GRID3 and AXIS1D sections of an image copied element
// by element with their own encoding (so the new image corrects exactly as the old one where no
// thermal correction applies) and the THERMAL section written from the model, replacing the one
// the image had (docs/thermal.md "In the table image": a new thermal model is a new image, not a
// thermal-only image combined on the board). Failures are kInputInvalid naming the source.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/thermal/thermal_model.hpp"

namespace volcomp::image {

struct ThermalImageOptions {
  std::optional<uint32_t> table_id;         // default: the image's id
  std::map<std::string, std::string> info;  // INFO lines of the new model, written "thermal.KEY"
};

struct ThermalImage {
  std::vector<uint8_t> bytes;
  bool replaced = false;              // the image had a THERMAL section
  std::vector<std::string> warnings;  // e.g. the image's INFO left out for want of room
};

/// `model.axis_count` must be the image's axis count (its axis records in the image's axis
/// order); the writer validates it (ValidateThermalModel, no term on a rotary axis). The INFO
/// section keeps the image's own lines except its earlier "thermal." lines.
Expected<ThermalImage> WithThermalModel(const LoadedImage& image,
                                        const std::string& source,
                                        const thermal::ThermalModel& model,
                                        const ThermalImageOptions& options);

/// The positions the image's tables cover on its axis `axis` (GRID3 dimension and AXIS1D table of
/// that axis), lowest and highest, mm (degrees for a rotary axis); nullopt when no table covers it.
std::optional<std::pair<double, double>> TableSpan(const table::TableView& view, uint8_t axis);

/// TableSpan of every linear axis a table covers, by axis name (a thermal fit's reach covers
/// them: builders::ThermalFitOptions::travel_mm).
std::map<char, std::pair<double, double>> LinearAxisSpans(const table::TableView& view);

}  // namespace volcomp::image
