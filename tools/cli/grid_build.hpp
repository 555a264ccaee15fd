// The end of `volcomp build model|tracker|kmtpp`: build the GRID3 image of a grid source with the
// parsed grid options, write it, and report the lattice, the node checks, the predicted
// interpolation error and the elements (text, or the same data as JSON with --json).
#pragma once

#include "build_options.hpp"
#include "command.hpp"
#include "volcomp/builders/grid_source.hpp"

namespace volcomp::cli {

/// `builder` (e.g. "volcomp build model") goes into the source's INFO entries and titles the text
/// report. A lattice the options cannot lay out is a usage failure; data the checks refuse fail
/// with the check's message (naming --max-correction-um when the bound refused).
Expected<Output> RunGridBuild(const GridCommand& command,
                              builders::GridSource source,
                              const char* builder);

}  // namespace volcomp::cli
