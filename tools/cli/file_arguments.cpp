// File arguments: "-" is standard input or output.
#include "file_arguments.hpp"

#include <ostream>

#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {

Expected<tools::CsvTable> ReadCsvArgument(const std::string& path, Context& ctx) {
  if (path == "-") return tools::CsvTable::Read(ctx.in, "<stdin>");
  return tools::CsvTable::ReadFile(path);
}

Outcome WriteTextArgument(const std::string& text, const std::string& path, Context& ctx) {
  if (path != "-") return tools::WriteTextFile(path, text);
  ctx.out << text;
  return Outcome::Ok();
}

}  // namespace volcomp::cli
