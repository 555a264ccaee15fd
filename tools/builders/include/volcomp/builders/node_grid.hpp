// A GRID3 from corrections given at the nodes of a regular lattice (`volcomp build grid --csv`).
//
// CSV columns (header names, any order; extra columns ignored), with the lower-case names of the
// grid's axes:
//   positions:   x_mm, y_mm, z_mm (x_deg on a rotary axis), or x_steps, y_steps, z_steps;
//   corrections: dx_um, dy_um, dz_um (dx_arcsec on a rotary axis), or dx_steps, ...: the
//                correction ADDED to the command (command_out = command_in + correction, minus
//                the measured error).
// Every node of the lattice appears exactly once; node positions are whole steps and equally
// spaced per axis. Failures name the file and line (kInputInvalid).
#pragma once

#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::builders {

/// The GRID3 of `csv` for the three grid axes `axes` (dimension/component d ↔ image axis d).
Expected<image::GridCorrections> NodeGridFromCsv(const tools::CsvTable& csv,
                                                 const std::vector<image::AxisDef>& axes);

}  // namespace volcomp::builders
