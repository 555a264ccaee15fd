// One image from two: the GRID3 of one image and the AXIS1D tables of another (e.g. `volcomp
// build grid` or `build model` and `build axis`), after checking that they belong together: every
// axis of the AXIS1D image is an axis of the GRID3 image with the same kind and units per step
// (the joined image keeps the GRID3 image's AXES, so its AXIS1D tables are re-indexed by axis
// name), the table ids agree unless a new one is given, and no section is given twice. The
// sections are copied element by element with their own encoding (element type, fraction bits,
// backlash, wrap), so the joined image corrects exactly as its parts. Failures are kInputInvalid
// naming both sources and the mismatch.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/image/image_reader.hpp"

namespace volcomp::image {

struct JoinPart {
  std::string source;  // names the part in messages and in the INFO section
  const LoadedImage* image = nullptr;
};

struct JoinOptions {
  std::optional<uint32_t> table_id;         // default: the parts' common id
  std::map<std::string, std::string> info;  // added to the INFO section
};

struct JoinedImage {
  std::vector<uint8_t> bytes;
  std::vector<std::string> warnings;  // e.g. the parts' INFO left out for want of room
};

/// `grid` must hold a GRID3, `axis` one or more AXIS1D tables (and no GRID3); AXIS1D tables of
/// `grid` are kept unless `axis` has one for the same axis (then the join is refused). The INFO
/// section records both sources, `options.info` and the parts' own INFO lines prefixed "grid."
/// and "axis." (left out, with a warning, when they do not fit the 4 KiB section).
Expected<JoinedImage> JoinImages(const JoinPart& grid,
                                 const JoinPart& axis,
                                 const JoinOptions& options);

}  // namespace volcomp::image
