// The files of a metrology report.
#include "volcomp/metrology/report_files.hpp"

#include <cctype>
#include <filesystem>
#include <system_error>

#include "volcomp/tools/file_io.hpp"

namespace volcomp::metrology {

std::string SafeName(const std::string& text) {
  std::string out;
  for (char c : text) {
    const bool keep =
        std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '+' || c == '-';
    out += keep ? c : '_';
  }
  return out.empty() ? "_" : out;
}

std::string SourceStem(const std::string& source) {
  if (source == "-" || source == "<stdin>") return "stdin";
  return SafeName(std::filesystem::path(source).stem().string());
}

Expected<ReportFiles> WriteReportFiles(const report::HtmlPage& page,
                                       const std::string& json,
                                       const std::string& dir,
                                       const std::string& name) {
  ReportFiles files;
  VOLCOMP_TRY_ASSIGN(files.html, report::PrepareReportPath(dir, name + ".html"));
  std::error_code ec;
  files.replaced = std::filesystem::exists(files.html, ec);
  VOLCOMP_TRY(page.WriteFile(files.html));
  if (!json.empty()) {
    VOLCOMP_TRY_ASSIGN(files.json, report::PrepareReportPath(dir, name + ".json"));
    VOLCOMP_TRY(tools::WriteTextFile(files.json, json));
  }
  return files;
}

}  // namespace volcomp::metrology
