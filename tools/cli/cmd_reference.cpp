// `volcomp reference [--axes 1,2,3]`: declares axes referenced over CAN (0x2120), instead of the
// home switch edges. Axis numbers the board does not have (0x2000:4) are refused.
#include <cstdio>
#include <ostream>
#include <string>

#include "can_options.hpp"
#include "commands.hpp"
#include "sdo_failure.hpp"

namespace volcomp::cli {
namespace {

using canopen::ObjectId;

// "1,2,3" -> the bit mask of those axes (1..6); spaces are ignored.
Expected<uint32_t> AxisMask(const std::string& list) {
  const auto bad = [&] {
    return UsageFailure("--axes takes axis numbers 1..6, e.g. 1,2,3 (got \"" + list + "\")");
  };
  uint32_t mask = 0;
  bool expect_axis = true;
  for (const char c : list) {
    if (c == ' ') continue;
    if (expect_axis && c >= '1' && c <= '6') {
      mask |= 1u << (c - '1');
    } else if (expect_axis || c != ',') {
      return bad();
    }
    expect_axis = !expect_axis;
  }
  if (expect_axis) return bad();  // empty, or a trailing comma
  return mask;
}

void ReferenceText(const JsonValue& d, std::ostream& out) {
  char mask[8];
  std::snprintf(mask, sizeof mask, "0x%02X", static_cast<unsigned>(d.get("axes_mask")->integer));
  out << "node " << d.get("node")->integer << ": reference requested for axes mask " << mask
      << "\n";
}

Expected<Output> RunReference(Args& args, Context&) {
  VOLCOMP_TRY_ASSIGN(const CanConnection can, ParseCanOptions(args));
  const std::string axes = args.Value("--axes").value_or("");
  VOLCOMP_TRY(args.Finish());
  uint32_t asked = 0;
  if (!axes.empty()) {
    VOLCOMP_TRY_ASSIGN(asked, AxisMask(axes));
  }
  VOLCOMP_TRY_ASSIGN(const auto session, OpenSession(can));
  VOLCOMP_TRY_ASSIGN(const uint32_t count,
                     ReadNumber(*session, ObjectId::kAxisCountConfig, "the axis count (0x2000:4)"));
  const uint32_t all = count >= 6 ? 0x3Fu : (1u << count) - 1u;
  if ((asked & ~all) != 0) {
    return Fail(Error::kInvalidArgument, "--axes " + axes + ": node " + std::to_string(can.node) +
                                             " has " + std::to_string(count) +
                                             " axes (0x2000:4), axis numbers 1.." +
                                             std::to_string(count));
  }
  const uint32_t mask = asked != 0 ? asked : all;
  VOLCOMP_TRY(Checked(session->Write(ObjectId::kReferenceAxes, mask), "referencing"));
  JsonValue d = JsonValue::Object();
  d.Set("node", unsigned{can.node});
  d.Set("axes_mask", mask);
  return Output{std::move(d), ReferenceText, {}};
}

}  // namespace

const Command& ReferenceCommand() {
  static const Command kCommand{
      "reference", "declare axes referenced over CAN (instead of home switch edges)", "",
      Join({CanOptions(),
            {{"--axes", nullptr, "1,2,3", nullptr, nullptr,
              "axis numbers 1..N of the board's N axes (0x2000:4) to reference (default: all)"}}}),
      RunReference};
  return kCommand;
}

}  // namespace volcomp::cli
