// A machine's error model as a config file (samples/model/s500.conf): `key = value` lines, `#`
// comments. Keys:
//   builtin = s500               start from the compiled-in S500 model (others override it)
//   name = TEXT
//   axis_x | axis_y | axis_z = FILE   axis tables (axis_table_csv.hpp), relative to the config
//   squareness_c0y_urad | squareness_b0z_urad | squareness_a0z_urad = NUMBER
//   tool_offset_mm = X, Y, Z
//   workpiece_axes = LETTERS     from the workpiece down to the base (may be empty)
//   tool_axes = LETTERS          from the base up to the tool
//   workpiece_errors = relative | carriage
//   formulation = physical | dissertation
//   order = first | exact        (dissertation: first | second)
//   dissertation_case = plus | minus
//   angle_scale = NUMBER
// Failures name the file and line ("m.conf:3: unknown key \"axis_q\""; kInputInvalid, kIoError
// when a file cannot be read). The model returned passes model::ValidateModel.
#pragma once

#include <string>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/rigid_body.hpp"

namespace volcomp::datasets {

/// `source` names the text in failures; relative axis files are resolved against `base_dir`.
Expected<model::Model> ModelFromConfigText(const std::string& text,
                                           const std::string& source,
                                           const std::string& base_dir);
Expected<model::Model> LoadModelConfig(const std::string& path);

}  // namespace volcomp::datasets
