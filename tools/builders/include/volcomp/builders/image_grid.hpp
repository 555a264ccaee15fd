// The GRID3 of an image as a correction grid in mm: what the board adds (trilinear, clamped) for
// the part of a table that depends on all three positions. Used to build on a table that was in
// force while something was measured (`volcomp build tracker --lattice FILE --through IMAGE`).
#pragma once

#include <string>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/model/lattice.hpp"

namespace volcomp::builders {

/// The image's GRID3, lattice and corrections in mm (the stored elements, fraction bits applied).
/// kInputInvalid naming `source` when the image has no GRID3, its dimensions are not X, Y, Z in
/// order or an axis is rotary.
Expected<model::CorrectionGrid> GridOfImage(const image::LoadedImage& image,
                                            const std::string& source);

}  // namespace volcomp::builders
