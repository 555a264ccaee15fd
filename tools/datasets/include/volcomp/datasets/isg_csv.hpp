// ISG-CSV, the ISG kernel's / Beckhoff TF5280's own file of ISO 230-1 parameters (file_format
// ISG_CSV), both ways:
// https://infosys.beckhoff.com/content/1033/tf5280_volumetric_comp/296429067.html (data-formats.md
// B6, [manual]; no real file has been seen beyond the manual's examples).
//
//   // comment (to the end of the line)
//   X EXX EYX EZX EAX EBX ECX      header: argument column(s), then parameter names,
//   0.0 0.02 0.01 0.07 0.00 0.0042 0.003    separated by spaces or tabs; one data row per
//   10.0 0.00 -0.1 0.01 0.00 0.0011 0.002   argument value
//   #                              a `#` line alone starts a new block with its own header
//   C0Y B0Z A0Z                    a block without an argument column: one row of values
//   0.0001 -0.00005 0.00002
//
// Argument columns are axis letters (X Y Z A B C U V W); everything else in a header is a
// parameter. Units mm and rad, arguments mm (deg for rotary axes); error = actual − nominal
// (iso230_set.hpp). Read here: blocks with no argument or one. A block over several arguments
// (a volumetric grid, `X Y Z EXX ...`) is not a 21-parameter set and is refused, as are a row
// with another number of fields than its header, a word that is not a number, a block without
// rows, a constant block with more than one row; then CheckIso230Set's failures. All name the
// source and line (kInputInvalid).
#pragma once

#include <string>
#include <vector>

#include "volcomp/datasets/iso230_set.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::datasets {

Expected<Iso230Set> ParseIsgCsv(const std::string& text, const std::string& source);

/// The file text: `header` lines as `//` comments, then one block per argument (the set's
/// tabulated parameters grouped by argument; parameters of one argument must share its rows,
/// kInvalidArgument otherwise), then one block of the single values; fields separated by one
/// space, arguments with 6 decimals, values with 12.
Expected<std::string> FormatIsgCsv(const Iso230Set& set, const std::vector<std::string>& header);

}  // namespace volcomp::datasets
