// A self-contained HTML report page: headings, paragraphs, tables, preformatted text and inline
// SVG, with a small embedded stylesheet. No external resources, so the file can be archived.
// File failures are returned (kIoError, naming the path), never thrown.
#pragma once

#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::report {

class HtmlPage {
 public:
  explicit HtmlPage(std::string title);

  /// Level 1..4. Text is escaped.
  void Heading(int level, const std::string& text);
  void Paragraph(const std::string& text);
  /// A bulleted list; items are escaped.
  void List(const std::vector<std::string>& items);
  /// A table; cells are escaped. Rows shorter than the header are padded.
  void Table(const std::vector<std::string>& header,
             const std::vector<std::vector<std::string>>& rows);
  void Preformatted(const std::string& text);
  /// An SVG element (from Svg::str(), XyChart::Render(), ...), inserted verbatim in a figure.
  void Figure(const std::string& svg, const std::string& caption);

  std::string Render() const;
  /// Writes Render() to `path`.
  Outcome WriteFile(const std::string& path) const;

 private:
  std::string title_;
  std::string body_;
};

/// Creates `dir` (and parents) if needed and returns dir + "/" + file_name; a failure naming the
/// directory when it cannot be created.
Expected<std::string> PrepareReportPath(const std::string& dir, const std::string& file_name);

}  // namespace volcomp::report
