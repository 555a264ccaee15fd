// HTML report page.
#include "volcomp/report/html_page.hpp"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "volcomp/report/format.hpp"

namespace volcomp::report {

HtmlPage::HtmlPage(std::string title) : title_(std::move(title)) {}

void HtmlPage::Heading(int level, const std::string& text) {
  if (level < 1) level = 1;
  if (level > 4) level = 4;
  const std::string tag = "h" + std::to_string(level);
  body_ += "<" + tag + ">" + EscapeXml(text) + "</" + tag + ">\n";
}

void HtmlPage::Paragraph(const std::string& text) { body_ += "<p>" + EscapeXml(text) + "</p>\n"; }

void HtmlPage::List(const std::vector<std::string>& items) {
  if (items.empty()) return;
  body_ += "<ul>\n";
  for (const auto& i : items) body_ += "<li>" + EscapeXml(i) + "</li>\n";
  body_ += "</ul>\n";
}

void HtmlPage::Table(const std::vector<std::string>& header,
                     const std::vector<std::vector<std::string>>& rows) {
  body_ += "<table>\n<thead><tr>";
  for (const auto& h : header) body_ += "<th>" + EscapeXml(h) + "</th>";
  body_ += "</tr></thead>\n<tbody>\n";
  for (const auto& r : rows) {
    body_ += "<tr>";
    for (std::size_t i = 0; i < std::max(r.size(), header.size()); ++i) {
      body_ += "<td>" + (i < r.size() ? EscapeXml(r[i]) : std::string()) + "</td>";
    }
    body_ += "</tr>\n";
  }
  body_ += "</tbody></table>\n";
}

void HtmlPage::Preformatted(const std::string& text) {
  body_ += "<pre>" + EscapeXml(text) + "</pre>\n";
}

void HtmlPage::Figure(const std::string& svg, const std::string& caption) {
  body_ += "<figure>\n" + svg + "<figcaption>" + EscapeXml(caption) + "</figcaption></figure>\n";
}

std::string HtmlPage::Render() const {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
         EscapeXml(title_) +
         "</title>\n<style>\n"
         "body{font-family:sans-serif;margin:2em;max-width:1100px;color:#222}\n"
         "table{border-collapse:collapse;margin:0.5em 0 1.5em 0;font-size:90%}\n"
         "th,td{border:1px solid #bbb;padding:2px 8px;text-align:right}\n"
         "th{background:#f0f0f0}\n"
         "td:first-child,th:first-child{text-align:left}\n"
         "figure{margin:1em 0}figcaption{font-size:85%;color:#555}\n"
         "pre{background:#f7f7f7;padding:0.5em}\n"
         "</style>\n</head>\n<body>\n<h1>" +
         EscapeXml(title_) + "</h1>\n" + body_ + "</body>\n</html>\n";
}

Outcome HtmlPage::WriteFile(const std::string& path) const {
  std::ofstream f(path, std::ios::binary);
  if (!f) return Fail(Error::kIoError, path + ": cannot open for writing");
  f << Render();
  f.close();
  if (!f) return Fail(Error::kIoError, path + ": write failed");
  return Outcome::Ok();
}

Expected<std::string> PrepareReportPath(const std::string& dir, const std::string& file_name) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir, ec)) {
    return Fail(Error::kIoError, dir + ": cannot create report directory" +
                                     (ec ? " (" + ec.message() + ")" : std::string()));
  }
  return (std::filesystem::path(dir) / file_name).string();
}

}  // namespace volcomp::report
