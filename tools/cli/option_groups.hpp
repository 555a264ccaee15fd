// Option groups shared by several commands of the `volcomp` tool (declared once, so the help and
// the parser agree everywhere they appear).
#pragma once

#include <initializer_list>
#include <vector>

#include "volcomp/args/args.hpp"

namespace volcomp::cli {

using Options = std::vector<args::OptionSpec>;

/// The options of `parts`, in order.
Options Join(std::initializer_list<Options> parts);

const Options& CanOptions();
const Options& ResolutionOptions();
const Options& ImageOptions();
const Options& GridOptions();
/// `--board FILE`, `--bank-bytes N`, `--allow-clamp` of the builds (board_fit.hpp).
const Options& BoardFileOptions();
const Options& ModelOptions();
/// --format conf|etalon|isg: the model file's format when its content should not decide.
const Options& ModelFormatOptions();
const Options& JsonReport();
const Options& PositioningFileOptions();
const char* PositioningFileNotes();
const Options& AllowFewRuns();
const Options& TemplateOutput();
const char* GridNotes();

}  // namespace volcomp::cli
