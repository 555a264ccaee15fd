// Helpers for the metrology commands.
#include "volcomp/metrology/cli_support.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace volcomp::metrology {

tools::CsvTable ReadCsvArgument(const std::string& path) {
  if (path == "-") return tools::CsvTable::Parse(std::cin, "<stdin>");
  return tools::CsvTable::ParseFile(path);
}

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

std::string WriteReport(const report::HtmlPage& page,
                        const std::string& json,
                        const std::string& dir,
                        const std::string& name,
                        std::ostream& err) {
  std::string html_path;
  try {
    html_path = report::PrepareReportPath(dir, name + ".html");
    std::error_code ec;
    const bool replaced = std::filesystem::exists(html_path, ec);
    page.WriteFile(html_path);
    err << "report written to " << html_path;
    if (!json.empty()) {
      const std::string json_path = report::PrepareReportPath(dir, name + ".json");
      WriteTextOutput(json, json_path, err);
      err << " and " << json_path;
    }
    err << (replaced ? " (replacing the earlier report of that name)" : "") << "\n";
  } catch (const std::runtime_error& e) {
    throw tools::InputError(e.what());
  }
  return html_path;
}

void PrintWarnings(std::ostream& err, const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) err << "warning: " << w << "\n";
}

void WriteTextOutput(const std::string& text, const std::string& path, std::ostream& out) {
  if (path == "-") {
    out << text;
    return;
  }
  std::ofstream f(path, std::ios::binary);
  if (!f) throw tools::InputError(path + ": cannot open for writing");
  f << text;
  f.close();
  if (!f) throw tools::InputError(path + ": write failed");
}

}  // namespace volcomp::metrology
