// Model files of any format (see model_file.hpp).
#include "volcomp/datasets/model_file.hpp"

#include <sstream>
#include <utility>

#include "trim.hpp"
#include "volcomp/datasets/etalon_exchange.hpp"
#include "volcomp/datasets/isg_csv.hpp"
#include "volcomp/datasets/model_config.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::datasets {

const char* ModelFileFormatName(ModelFileFormat format) {
  switch (format) {
    case ModelFileFormat::kEtalon:
      return "etalon";
    case ModelFileFormat::kIsgCsv:
      return "isg";
    case ModelFileFormat::kConfig:
      break;
  }
  return "conf";
}

ModelFileFormat DetectModelFileFormat(const std::string& text) {
  std::istringstream in(text);
  for (std::string raw; std::getline(in, raw);) {
    const std::string line = Trim(raw);
    if (line.empty() || line[0] == '#' || line.rfind("//", 0) == 0) continue;
    if (line[0] == '[') return ModelFileFormat::kEtalon;
    if (line.find('=') != std::string::npos) return ModelFileFormat::kConfig;
    return ModelFileFormat::kIsgCsv;
  }
  return ModelFileFormat::kConfig;
}

Expected<LoadedModel> LoadModelFile(const std::string& path,
                                    std::optional<ModelFileFormat> forced) {
  const auto text = tools::ReadTextFile(path);
  if (!text.ok()) return Fail(Error::kIoError, path + ": cannot open the model file");
  LoadedModel loaded;
  loaded.format = forced ? *forced : DetectModelFileFormat(*text);
  loaded.format_detected = !forced;
  if (loaded.format == ModelFileFormat::kConfig) {
    VOLCOMP_TRY_ASSIGN(loaded.model, LoadModelConfig(path));
    return loaded;
  }
  VOLCOMP_TRY_ASSIGN(const Iso230Set set, loaded.format == ModelFileFormat::kEtalon
                                              ? ParseEtalonExchange(*text, path)
                                              : ParseIsgCsv(*text, path));
  VOLCOMP_TRY_ASSIGN(ModelFromIso230 mapped, ModelFromIso230Set(set));
  loaded.model = std::move(mapped.model);
  loaded.warnings = std::move(mapped.warnings);
  return loaded;
}

}  // namespace volcomp::datasets
