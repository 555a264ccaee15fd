// The table-against-installation check of `upload` and `activate`.
#include "board_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sdo_failure.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen_client/board_settings_io.hpp"
#include "volcomp/hosted/settings_ini.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/image/table_demands.hpp"

namespace volcomp::cli {
namespace {

using canopen::ObjectId;

Expected<uint32_t> ReadObject(canopen_client::NodeObjects& node, ObjectId id) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  char what[96];
  std::snprintf(what, sizeof what, "%s (0x%04X:%u)", e.name, e.index, e.sub);
  return ReadNumber(node, id, what);
}

std::string Fixed(double v, int digits) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

}  // namespace

Expected<BoardInstallation> ReadInstallation(canopen_client::NodeObjects& node) {
  // The configuration the board runs with (0x2124), which decides what it clamps, not the edited
  // objects (they differ while settings are pending).
  VOLCOMP_TRY_ASSIGN(const uint32_t state, ReadObject(node, ObjectId::kDeviceState));
  VOLCOMP_TRY_ASSIGN(const BoardSettings s, canopen_client::ReadSettingsInForce(node));
  BoardInstallation b = InstallationOf(s);
  b.settings_pending = canopen::DecodeDeviceState(state).settings_pending;
  return b;
}

BoardInstallation InstallationOf(const BoardSettings& s) {
  BoardInstallation b;
  for (size_t a = 0; a < s.board.axis_count && a < table::kMaxAxes; ++a) {
    const AxisConfig& c = s.board.axis[a];
    BoardAxis x;
    x.name = c.name;
    x.kind = static_cast<uint32_t>(c.kind);
    x.resolution_e9 = c.resolution_e9;
    x.max_correction_steps = c.max_correction_steps;
    x.max_rate_steps_s = c.max_correction_rate_steps_s;
    x.max_input_rate_hz = c.max_input_rate_hz;
    b.axes.push_back(x);
  }
  return b;
}

std::vector<FitProblem> CheckTableFits(const table::TableView& v, const BoardInstallation& board) {
  std::vector<FitProblem> out;
  if (v.axis_count > board.axes.size()) {
    out.push_back({false, "the table has " + std::to_string(v.axis_count) + " axes, the board " +
                              std::to_string(board.axes.size()) + " (0x2000:4)"});
    return out;
  }
  for (uint8_t a = 0; a < v.axis_count; ++a) {
    const table::AxisInfo& t = v.axes[a];
    const BoardAxis& b = board.axes[a];
    const std::string axis = "axis " + std::to_string(a + 1) + " (" + std::string(1, t.name) + ")";
    if (t.name != b.name || static_cast<uint32_t>(t.kind) != b.kind) {
      out.push_back({false, axis + ": the table's axis is " + std::string(1, t.name) +
                                (t.kind == table::AxisKind::kRotary ? " rotary" : " linear") +
                                ", the board's " + std::string(1, b.name) +
                                (b.kind == 1 ? " rotary" : " linear") +
                                " (0x2010/0x2011:" + std::to_string(a + 1) + ")"});
    }
    if (t.resolution_e9 != b.resolution_e9) {
      // The table's kind decides the unit (a kind mismatch is said above).
      const bool rotary = t.kind == table::AxisKind::kRotary;
      out.push_back({false, axis + ": the table was built for " +
                                image::ResolutionText(t.resolution_e9, rotary) +
                                ", the board runs " +
                                image::ResolutionText(b.resolution_e9, rotary) +
                                " (0x2012:" + std::to_string(a + 1) + ")"});
    }
  }
  if (!out.empty()) return out;
  const std::vector<image::AxisDemand> demand = image::TableDemands(v);
  for (uint8_t a = 0; a < v.axis_count; ++a) {
    const BoardAxis& b = board.axes[a];
    const std::string axis =
        "axis " + std::to_string(a + 1) + " (" + std::string(1, v.axes[a].name) + ")";
    const std::string sub = std::to_string(a + 1);
    if (demand[a].max_correction_steps > b.max_correction_steps) {
      out.push_back(
          {true, axis + ": the table asks for up to " + Fixed(demand[a].max_correction_steps, 1) +
                     " steps of correction, the board's max correction (0x2015:" + sub + ") is " +
                     std::to_string(b.max_correction_steps) + " steps: it would be clamped"});
    }
    double rate = 0;
    std::string worst;
    for (uint8_t in = 0; in < v.axis_count; ++in) {
      const double r = demand[a].gradient[in] * board.axes[in].max_input_rate_hz;
      rate += r;
      if (r > 0) {
        worst += std::string(worst.empty() ? "" : ", ") + v.axes[in].name + " " +
                 Fixed(demand[a].gradient[in] * 1e6, 1) + " ppm x " +
                 std::to_string(board.axes[in].max_input_rate_hz) + " steps/s";
      }
    }
    if (rate > b.max_rate_steps_s) {
      out.push_back({true, axis + ": the table's correction changes up to " + Fixed(rate, 0) +
                               " steps/s at the fastest input rates (0x201E; gradient along " +
                               worst + "), the board's max correction rate (0x2016:" + sub +
                               ") is " + std::to_string(b.max_rate_steps_s) +
                               " steps/s: it would be rate limited"});
    }
  }
  return out;
}

Expected<std::vector<FitProblem>> RequireTableFits(canopen_client::NodeObjects& node,
                                                   const table::TableView& view,
                                                   bool allow_limits,
                                                   std::ostream& warnings) {
  VOLCOMP_TRY_ASSIGN(const BoardInstallation board, ReadInstallation(node));
  if (board.settings_pending) {
    warnings << "warning: node " << unsigned{node.node()}
             << " has settings edits not yet in force (store and reset node): the table is "
                "checked against the settings in force (0x2124), which the edits will replace\n";
  }
  std::vector<FitProblem> problems = CheckTableFits(view, board);
  bool refuse = false;
  std::string text;
  for (const FitProblem& p : problems) {
    refuse = refuse || !p.limit || !allow_limits;
    text += "\n  " + p.message;
  }
  if (refuse) {
    const bool mismatch = !problems.empty() && !problems.front().limit;
    return Fail(Error::kInvalidArgument,
                std::string(mismatch ? "the table is not for this board:"
                                     : "the board would not apply the whole table:") +
                    text +
                    (mismatch ? ""
                              : "\n(--allow-clamp applies it anyway; the board then shows "
                                "the limit in force in `volcomp status`)"));
  }
  for (const FitProblem& p : problems) warnings << "warning: " << p.message << "\n";
  return problems;
}

std::vector<std::string> HomeOutsideLattice(const table::TableView& v, const BoardSettings& s) {
  std::vector<std::string> out;
  for (uint8_t a = 0; a < v.axis_count && a < s.board.axis_count; ++a) {
    const AxisConfig& ax = s.board.axis[a];
    const table::Dimension* dim = nullptr;
    for (int d = 0; d < 3 && v.grid.present; ++d) {
      if (v.grid.axis[d] == a) dim = &v.grid.dim[d];
    }
    for (uint8_t i = 0; dim == nullptr && i < v.axis1d_count; ++i) {
      if (v.axis1d[i].axis == a && v.axis1d[i].period_steps == 0) dim = &v.axis1d[i].dim;
    }
    if (dim == nullptr || dim->nodes == 0) continue;
    const int64_t first = dim->origin_steps;
    const int64_t last = first + int64_t{dim->spacing_steps} * (dim->nodes - 1);
    const int64_t home = ax.home_position_steps;
    if (home >= first && home <= last) continue;
    const double u = ax.resolution_e9 * 1e-9;
    const char* unit = ax.kind == table::AxisKind::kRotary ? "deg" : "mm";
    char b[320];
    std::snprintf(b, sizeof b,
                  "[axis %c]: the home position %lld steps (%.4f %s), where the board references, "
                  "lies outside the table's %c range %.4f..%.4f %s: the board holds the edge "
                  "value there (build the lattice over the whole travel and the home)",
                  ax.name, static_cast<long long>(home), static_cast<double>(home) * u, unit,
                  ax.name, static_cast<double>(first) * u, static_cast<double>(last) * u, unit);
    out.push_back(b);
  }
  return out;
}

Expected<std::optional<BoardFileCheck>> ParseBoardFileCheck(Args& args) {
  const std::optional<std::string> path = args.Value("--board");
  const std::optional<long long> bank = args.Integer("--bank-bytes");
  const bool allow = args.Flag("--allow-clamp");
  if (!path) {
    if (bank || allow) return UsageFailure("--bank-bytes and --allow-clamp need --board FILE");
    return std::optional<BoardFileCheck>();
  }
  if (bank && (*bank < 1 || *bank > 0xFFFFFFFFll)) {
    return UsageFailure("--bank-bytes must be 1..4294967295");
  }
  const hosted::IniExpected<BoardSettings> file = hosted::ReadSettingsIniFile(*path);
  if (!file.ok()) return Fail(file.error().ToFailure());
  BoardFileCheck c;
  c.path = *path;
  c.settings = *file;
  c.bank_bytes = bank ? static_cast<uint32_t>(*bank) : 0u;
  c.allow_clamp = allow;
  return std::optional<BoardFileCheck>(std::move(c));
}

Outcome CheckImageAgainstBoardFile(const BoardFileCheck& check,
                                   const std::vector<uint8_t>& bytes,
                                   std::vector<std::string>* warnings,
                                   JsonValue* report) {
  VOLCOMP_TRY_ASSIGN(const image::LoadedImage img, image::LoadedImage::FromBytes(bytes, "image"));
  const std::vector<FitProblem> fits = CheckTableFits(img.view(), InstallationOf(check.settings));
  std::vector<std::string> refused, warned;
  for (const FitProblem& p : fits) {
    (p.limit && check.allow_clamp ? warned : refused).push_back(p.message);
  }
  if (check.bank_bytes != 0 && bytes.size() > check.bank_bytes) {
    refused.push_back("the image of " + std::to_string(bytes.size()) +
                      " bytes does not fit the board's table bank of " +
                      std::to_string(check.bank_bytes) + " bytes (--bank-bytes)");
  }
  for (std::string& w : HomeOutsideLattice(img.view(), check.settings)) {
    warned.push_back(std::move(w));
  }
  JsonValue r = JsonValue::Object();
  JsonValue problems = JsonValue::Array(), said = JsonValue::Array();
  for (const std::string& p : refused) problems.Push(p);
  for (const std::string& w : warned) said.Push(w);
  r.Set("file", check.path)
      .Set("image_bytes", uint64_t{bytes.size()})
      .Set("bank_bytes", uint64_t{check.bank_bytes})
      .Set("problems", std::move(problems))
      .Set("warnings", std::move(said));
  *report = std::move(r);
  if (!refused.empty()) {
    std::string text;
    for (const std::string& p : refused) text += "\n  " + p;
    const bool limits_only =
        std::all_of(fits.begin(), fits.end(), [](const FitProblem& p) { return p.limit; });
    return Fail(Error::kInvalidArgument,
                "the image does not fit the board of " + check.path + " (nothing written):" + text +
                    (limits_only && !check.allow_clamp
                         ? "\n(--allow-clamp writes it anyway; the board then shows the limit in "
                           "force in `volcomp status`)"
                         : ""));
  }
  for (std::string& w : warned) warnings->push_back(std::move(w));
  return Outcome::Ok();
}

}  // namespace volcomp::cli
