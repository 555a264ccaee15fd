// Helpers for the metrology commands.
#include "volcomp/metrology/cli_support.hpp"

#include <fstream>
#include <iostream>
#include <stdexcept>

namespace volcomp::metrology {

tools::CsvTable ReadCsvArgument(const std::string& path) {
  if (path == "-") return tools::CsvTable::Parse(std::cin, "<stdin>");
  return tools::CsvTable::ParseFile(path);
}

std::string WriteReport(const report::HtmlPage& page,
                        const std::string& dir,
                        const std::string& file_name) {
  try {
    const std::string path = report::PrepareReportPath(dir, file_name);
    page.WriteFile(path);
    return path;
  } catch (const std::runtime_error& e) {
    throw tools::InputError(e.what());
  }
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
