// `volcomp report certificate BEFORE AFTER -o DIR [--info FILE] [--table IMAGE] [--status FILE]
// [--date YYYY-MM-DD]`: the one-page certificate of a compensation (metrology/certificate.hpp),
// DIR/certificate.html and DIR/certificate.json; its figures as text or JSON.
#include <cstdlib>
#include <ctime>
#include <ostream>
#include <sstream>

#include "commands.hpp"
#include "version.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/metrology/certificate.hpp"
#include "volcomp/metrology/compare.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/file_io.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::cli {
namespace {

namespace m = volcomp::metrology;

std::string Today() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", &local);
  return text;
}

void CertificateText(const JsonValue& data, std::ostream& out) {
  m::WriteCertificateText(out, data);
}

// The board's active table from a saved `volcomp status --json`.
Expected<m::CertificateTable> TableFromStatus(const std::string& path) {
  VOLCOMP_TRY_ASSIGN(const std::string text, tools::ReadTextFile(path));
  VOLCOMP_TRY_ASSIGN(const JsonValue status, tools::ParseJson(text, path));
  const JsonValue* active = status.get("active_table");
  const JsonValue* present = active != nullptr ? active->get("present") : nullptr;
  const JsonValue* id = active != nullptr ? active->get("id") : nullptr;
  const JsonValue* crc = active != nullptr ? active->get("crc32") : nullptr;
  if (present == nullptr || id == nullptr || crc == nullptr || !id->is_number() ||
      !crc->is_string()) {
    return Fail(Error::kInputInvalid,
                path +
                    ": not the output of `volcomp status --json` (no active_table.present, "
                    ".id and .crc32)");
  }
  if (!present->boolean) {
    return Fail(Error::kInputInvalid, path + ": the board had no active table when it was saved");
  }
  char* end = nullptr;
  const unsigned long value = std::strtoul(crc->string.c_str(), &end, 16);
  if (end == crc->string.c_str() || *end != '\0' || value > 0xFFFFFFFFul) {
    return Fail(Error::kInputInvalid, path + ": active_table.crc32 '" + crc->string +
                                          "' is not a 32-bit hexadecimal value");
  }
  if (!id->is_int || id->integer < 0 || id->integer > 0xFFFFFFFF) {
    return Fail(Error::kInputInvalid, path + ": active_table.id is not a 32-bit table id");
  }
  m::CertificateTable table;
  table.source = path;
  table.origin = "status";
  table.table_id = static_cast<uint32_t>(id->integer);
  table.crc32 = static_cast<uint32_t>(value);
  return table;
}

Expected<m::CertificateTable> Table(const std::optional<std::string>& image_path,
                                    const std::optional<std::string>& status_path) {
  m::CertificateTable from_image, from_status;
  if (image_path) {
    VOLCOMP_TRY_ASSIGN(const image::LoadedImage img, image::ReadImageFile(*image_path));
    from_image.source = *image_path;
    from_image.origin = "image";
    from_image.table_id = img.view().table_id;
    from_image.crc32 = img.view().crc32;
  }
  if (status_path) {
    VOLCOMP_TRY_ASSIGN(from_status, TableFromStatus(*status_path));
  }
  if (image_path && status_path &&
      (from_image.table_id != from_status.table_id || from_image.crc32 != from_status.crc32)) {
    return Fail(Error::kInputInvalid, "the board's active table in " + *status_path + " (id " +
                                          std::to_string(*from_status.table_id) + ", CRC-32 " +
                                          tools::Hex32(*from_status.crc32) + ") is not " +
                                          *image_path + " (id " +
                                          std::to_string(*from_image.table_id) + ", CRC-32 " +
                                          tools::Hex32(*from_image.crc32) + ")");
  }
  if (image_path && status_path) from_status.same_as_image = *image_path;
  return status_path ? from_status : from_image;
}

Expected<Output> RunReportCertificate(Args& args, Context& ctx) {
  args.Flag("--json");  // the command layer prints the data as JSON
  const std::string out_dir = args.Required("--output", "-o");
  const auto info_path = args.Value("--info");
  const auto image_path = args.Value("--table");
  const auto status_path = args.Value("--status");
  const auto date_option = args.Value("--date");
  const auto pos = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (pos.size() != 2) return UsageFailure("give BEFORE and AFTER (report directories or .json)");
  const std::string date = date_option ? *date_option : Today();
  VOLCOMP_TRY(m::CheckCertificateDate(date));
  m::CertificateInfo info;
  if (info_path) {
    VOLCOMP_TRY_ASSIGN(info, m::ReadCertificateInfo(*info_path));
  }
  VOLCOMP_TRY_ASSIGN(const m::CertificateTable table, Table(image_path, status_path));
  VOLCOMP_TRY_ASSIGN(const auto before, m::LoadResults(pos[0]));
  VOLCOMP_TRY_ASSIGN(const auto after, m::LoadResults(pos[1]));
  VOLCOMP_TRY_ASSIGN(const m::Comparison comparison, m::CompareResults(before, after));
  const m::Certificate certificate =
      m::BuildCertificate(comparison, std::move(info), table, ToolVersion(), date);
  JsonValue data = m::CertificateJson(certificate);
  VOLCOMP_TRY_ASSIGN(const std::string html_path,
                     report::PrepareReportPath(out_dir, "certificate.html"));
  VOLCOMP_TRY_ASSIGN(const std::string json_path,
                     report::PrepareReportPath(out_dir, "certificate.json"));
  VOLCOMP_TRY(tools::WriteTextFile(html_path, m::CertificateHtml(certificate)));
  std::ostringstream json;
  tools::WriteJson(data, json);
  VOLCOMP_TRY(tools::WriteTextFile(json_path, json.str()));
  ctx.err << "certificate written to " << html_path << " and " << json_path << "\n";
  return Output{std::move(data), CertificateText, certificate.warnings};
}

}  // namespace

const Command& ReportCertificateCommand() {
  static const Command kCommand{
      "report certificate",
      "one printable page the customer signs: figures before/after, tolerances, pass/fail",
      "BEFORE AFTER",
      {{"--output", "-o", "DIR", nullptr, nullptr,
        "directory for certificate.html and certificate.json (required)"},
       {"--info", nullptr, "FILE", nullptr, nullptr,
        "customer, machine, tester and tolerances (INI; samples/certificate_info.ini); fields "
        "not given print as lines to fill in"},
       {"--table", nullptr, "IMAGE", nullptr, nullptr,
        "the compensation table image: its table id and CRC-32 on the certificate"},
       {"--status", nullptr, "FILE", nullptr, nullptr,
        "a saved `volcomp status --json`: the board's active table id and CRC-32 (must match "
        "--table when both are given)"},
       {"--date", nullptr, "YYYY-MM-DD", nullptr, nullptr,
        "the certificate's date (default: today)"},
       {"--json", nullptr, nullptr, nullptr, nullptr, "every figure and field as JSON on stdout"}},
      RunReportCertificate,
      "BEFORE and AFTER are report directories written by `evaluate ... --report DIR` (or single\n"
      ".json results), paired by name as `report compare` pairs them. Pass/fail: the figure as\n"
      "stated (0.01) <= its tolerance; no tolerance, no verdict (\"—\")."};
  return kCommand;
}

}  // namespace volcomp::cli
