// The Etalon LaserTRACER / TRAC-CAL "exchange format" of ISO 230-1 parameters, both ways, as the
// ISG kernel / Beckhoff TF5280 reads it (file_format ETALON_EXCHANGE; Etalon's "Vendor" variant):
// https://infosys.beckhoff.com/content/1033/tf5280_volumetric_comp/296430091.html
// (data-formats.md A3, [manual]; no real Etalon file has been seen).
//
//   // comment (to the end of the line)
//   [C0Y]                      one block per parameter (iso230_set.hpp names)
//   VALUE = 0.000022355737     a position error: one value
//   [EXY]
//   Gridpoints = {             a component error: `argument value` pairs, argument = the
//     -280.0 -0.001358635132   position of the parameter's own axis (EXY: Y)
//     -270.0 -0.000240680764
//   }
//
// Units mm and rad, arguments mm; error = actual − nominal (iso230_set.hpp).
// Failures (kInputInvalid) name the source and line: text outside a block, an unknown key, a
// block with neither or both VALUE and Gridpoints, a Gridpoints not closed, an odd number of
// numbers in it, a word that is not a number; then CheckIso230Set's (unknown name, repeat, limit).
#pragma once

#include <string>
#include <vector>

#include "volcomp/datasets/iso230_set.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::datasets {

Expected<Iso230Set> ParseEtalonExchange(const std::string& text, const std::string& source);

/// The file text: `header` lines as `//` comments, then one block per parameter in the set's
/// order; arguments with 6 decimals (1 nm), values with 12 (1e-9 µm, 1e-6 µrad).
std::string FormatEtalonExchange(const Iso230Set& set, const std::vector<std::string>& header);

}  // namespace volcomp::datasets
