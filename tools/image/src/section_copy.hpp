// Copying an image's sections into the spec of a new image, element by element with their own
// encoding (element type, fraction bits, backlash, wrap), so the new image corrects exactly as the
// old one; and writing such a spec. Shared by the join (image_join.cpp) and the THERMAL
// replacement (image_thermal.cpp).
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "element_storage.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/table/table_image.hpp"
#include "volcomp/table/table_writer.hpp"

namespace volcomp::image {

/// The decoded arrays a spec points into; must outlive the spec's use.
struct SectionCopy {
  table::GridSpec grid;
  std::deque<ElementStorage> values;  // a deque: adding one keeps the others' addresses
};

/// Sets spec->grid to a copy of `v`'s GRID3 (which must be present).
void CopyGrid(const table::TableView& v, SectionCopy* copy, table::ImageSpec* spec);

/// Appends a copy of the AXIS1D table `t` to spec->axis1d as a table of the spec's axis `axis`.
void CopyAxis1d(const table::Axis1dView& t,
                uint8_t axis,
                SectionCopy* copy,
                table::ImageSpec* spec);

/// The INFO lines of an image, each prefixed with `prefix` ("" for none).
std::string PrefixedInfo(const table::TableView& v, const std::string& prefix);

/// `info` + `extra` as spec->info (stored in *text): kInputInvalid for a control character in
/// `info` or `info` longer than the section; `extra` is left out (a warning naming `what`) when
/// it does not fit.
Outcome SetInfo(std::string info,
                const std::string& extra,
                const std::string& what,
                std::string* text,
                std::vector<std::string>* warnings,
                table::ImageSpec* spec);

/// Writes and validates the image of `spec` (kInputInvalid naming the writer's refusal).
Expected<std::vector<uint8_t>> WriteSpec(const table::ImageSpec& spec);

}  // namespace volcomp::image
