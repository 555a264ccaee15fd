// `volcomp model export`: a model's 21 ISO 230-1 parameters as an Etalon exchange file or as
// ISG-CSV (datasets/etalon_exchange.hpp, isg_csv.hpp; the mapping and what the formats cannot
// carry: datasets/iso230_set.hpp). The file's header comment states the sign, the units and
// their sources; whatever of the model the file does not hold is a warning.
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "build_options.hpp"
#include "choice_option.hpp"
#include "commands.hpp"
#include "option_groups.hpp"
#include "volcomp/datasets/etalon_exchange.hpp"
#include "volcomp/datasets/isg_csv.hpp"
#include "volcomp/datasets/iso230_set.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

using datasets::ModelFileFormat;

std::vector<std::string> FileHeader(ModelFileFormat format,
                                    const std::string& spec,
                                    const std::vector<std::string>& notes) {
  std::vector<std::string> h = {
      format == ModelFileFormat::kEtalon
          ? "Etalon exchange format (\"Vendor\" variant, as ISG/Beckhoff TF5280 reads it)"
          : "ISG-CSV (ISG kernel / Beckhoff TF5280 volumetric compensation, file_format ISG_CSV)",
      "written by volcomp model export from " + spec,
      "ISO 230-1 component errors E<err><axis> of X, Y, Z and the squareness C0Y, B0Z, A0Z",
      "sign: error = actual - nominal of the tool relative to the workpiece, no sign changed",
      "  (ISO 230-1 error motions, right-handed angles; the ISG volumetric compensation takes",
      "  errors and subtracts them: "
      "https://infosys.beckhoff.com/content/1033/tf5280_volumetric_comp/" +
          std::string(format == ModelFileFormat::kEtalon ? "296430091.html" : "296429067.html") +
          ")",
      "units: errors mm, angles rad, arguments mm",
      "  (https://isg-stuttgart.de/fileadmin/kernel/kernel-html/en-GB/296426379.html)",
  };
  for (const std::string& n : notes) h.push_back("not carried: " + n);
  return h;
}

void ModelExportText(const JsonValue& d, std::ostream& out) {
  out << "volcomp model export: wrote " << d.get("output")->string << " ("
      << d.get("format")->string << "), " << d.get("parameters")->array.size() << " parameters\n";
  for (const JsonValue& p : d.get("parameters")->array) {
    out << "  " << p.get("name")->string << ": ";
    if (const JsonValue* rows = p.get("rows")) {
      out << rows->integer << " rows, " << p.get("argument")->string << " "
          << p.get("from_mm")->number << " to " << p.get("to_mm")->number << " mm\n";
    } else {
      out << p.get("value")->number << " " << p.get("unit")->string << "\n";
    }
  }
}

Expected<Output> RunModelExport(Args& args, Context&) {
  VOLCOMP_TRY_ASSIGN(const auto input_format, ParseModelFormat(args, "--model-format"));
  ModelSource source;
  VOLCOMP_TRY_ASSIGN(const model::Model m, ParseModelOptions(args, input_format, &source));
  const std::string format_word = args.Required("--format");
  const std::string output_path = args.Required("-o", "--output");
  args.Flag("--json");  // the command layer prints the data as JSON
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY_ASSIGN(const ModelFileFormat format,
                     ParseChoice<ModelFileFormat>("--format", format_word,
                                                  {{"etalon", ModelFileFormat::kEtalon},
                                                   {"isg", ModelFileFormat::kIsgCsv}}));
  const datasets::Iso230FromModel exported = datasets::Iso230SetFromModel(m);
  const std::vector<std::string> header = FileHeader(format, source.spec, exported.notes);
  std::string text;
  if (format == ModelFileFormat::kEtalon) {
    text = datasets::FormatEtalonExchange(exported.set, header);
  } else {
    VOLCOMP_TRY_ASSIGN(text, datasets::FormatIsgCsv(exported.set, header));
  }
  VOLCOMP_TRY(tools::WriteTextFile(output_path, text));

  Output output;
  output.warnings = source.warnings;
  JsonValue parameters = JsonValue::Array();
  for (const datasets::Iso230Parameter& p : exported.set.parameters) {
    JsonValue j = JsonValue::Object();
    j.Set("name", p.name);
    if (p.tabulated) {
      j.Set("argument", p.argument)
          .Set("rows", uint64_t{p.values.size()})
          .Set("from_mm", p.arguments.front())
          .Set("to_mm", p.arguments.back());
    } else {
      j.Set("value", p.values.front()).Set("unit", datasets::IsIso230Angle(p.name) ? "rad" : "mm");
    }
    parameters.Push(std::move(j));
  }
  JsonValue notes = JsonValue::Array();
  for (const std::string& n : exported.notes) {
    notes.Push(n);
    output.warnings.push_back(n);
  }
  output.data = JsonValue::Object();
  output.data.Set("format", datasets::ModelFileFormatName(format))
      .Set("output", output_path)
      .Set("model", ModelSourceJson(source))
      .Set("parameters", std::move(parameters))
      .Set("not_carried", std::move(notes));
  output.text = ModelExportText;
  return output;
}

}  // namespace

const Command& ModelExportCommand() {
  static const Command kCommand{
      "model export",
      "a model's ISO 230-1 parameters as an Etalon exchange file or ISG-CSV",
      "",
      Join({ModelOptions(),
            {{"--model-format", nullptr, "conf|etalon|isg", nullptr, nullptr,
              "the --model file's format (default: recognised by content)"},
             {"--format", nullptr, "etalon|isg", nullptr, nullptr,
              "the file to write: Etalon exchange format or ISG-CSV (required)"},
             {"--output", "-o", "FILE", nullptr, nullptr, "file to write (required)"},
             {"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunModelExport,
      "Writes the 18 component errors of X, Y, Z (mm, rad; arguments mm) and C0Y, B0Z, A0Z (rad),\n"
      "error = actual - nominal, no sign changed. What the formats cannot carry (the chain, the\n"
      "tool offset, the formulation) is named in a warning and in the file's header comment;\n"
      "see docs/pc-tool.md \"Component-error sets: Etalon and ISG-CSV\"."};
  return kCommand;
}

}  // namespace volcomp::cli
