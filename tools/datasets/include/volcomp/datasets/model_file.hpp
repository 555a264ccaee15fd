// A model file of any format `--model FILE` takes: the model config (model_config.hpp), the Etalon
// exchange format (etalon_exchange.hpp) or ISG-CSV (isg_csv.hpp), recognised by content or named.
//
// Recognition, from the first line that is not blank and not a comment (`#` or `//`): `[` opens
// an Etalon block; a line with `=` is a config key; anything else is an ISG-CSV header.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/rigid_body.hpp"

namespace volcomp::datasets {

enum class ModelFileFormat { kConfig, kEtalon, kIsgCsv };

/// "conf", "etalon", "isg": the names `--format` takes.
const char* ModelFileFormatName(ModelFileFormat format);

ModelFileFormat DetectModelFileFormat(const std::string& text);

struct LoadedModel {
  model::Model model;
  ModelFileFormat format = ModelFileFormat::kConfig;
  bool format_detected = true;        // false when `forced`
  std::vector<std::string> warnings;  // from the ISO 230-1 mapping (iso230_set.hpp)
};

/// Reads `path` in `forced` format, or the one its content shows. Failures as the format's reader
/// gives them (file and line), kIoError when the file cannot be read.
Expected<LoadedModel> LoadModelFile(const std::string& path,
                                    std::optional<ModelFileFormat> forced = std::nullopt);

}  // namespace volcomp::datasets
