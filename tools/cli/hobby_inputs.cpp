// The hobby exports' shared inputs (see hobby_inputs.hpp).
#include "hobby_inputs.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>

#include "positioning_input.hpp"

namespace volcomp::cli {
namespace {

struct PlaneSpec {
  const char* plane;   // "xy"
  const char* name;    // "C0Y"
  const char* option;  // "--squareness-xy-urad"
};

constexpr PlaneSpec kPlanes[] = {{"xy", "C0Y", "--squareness-xy-urad"},
                                 {"xz", "B0Z", "--squareness-xz-urad"},
                                 {"yz", "A0Z", "--squareness-yz-urad"}};

std::optional<exporters::PlaneSquareness>* PlaneOf(exporters::HobbySquareness& s, int i) {
  return i == 0 ? &s.xy : i == 1 ? &s.xz : &s.yz;
}

const std::optional<exporters::PlaneSquareness>& PlaneOf(const exporters::HobbySquareness& s,
                                                         int i) {
  return i == 0 ? s.xy : i == 1 ? s.xz : s.yz;
}

const std::optional<double>& ValueOf(const exporters::SkewValues& v, int i) {
  return i == 0 ? v.xy : i == 1 ? v.xz : v.yz;
}

}  // namespace

const Options& SquarenessOptions() {
  static const Options kOptions = {
      {"--model", nullptr, "s500|FILE", nullptr, nullptr,
       "21-parameter model (config, Etalon or ISG-CSV, recognised by content): its squareness "
       "C0Y, B0Z, A0Z"},
      {"--squareness-xy-urad", nullptr, "C0Y", "µrad", nullptr,
       "XY squareness: the angle from +X to +Y is 90 deg + C0Y (replaces the model's)"},
      {"--squareness-xz-urad", nullptr, "B0Z", "µrad", nullptr,
       "XZ squareness: the angle from +X to +Z is 90 deg - B0Z (replaces the model's)"},
      {"--squareness-yz-urad", nullptr, "A0Z", "µrad", nullptr,
       "YZ squareness: the angle from +Y to +Z is 90 deg + A0Z (replaces the model's)"}};
  return kOptions;
}

Options BacklashOptions() {
  return Join({PositioningFileOptions(),
               AllowFewRuns(),
               PositioningFormatOptions(),
               {{"--negate-tests", nullptr, nullptr, nullptr, nullptr,
                 "negate the tests' deviations first (an instrument that counted the other "
                 "way)"}}});
}

Expected<HobbyArgs> ReadHobbyArgs(Args& args, bool squareness, bool backlash) {
  HobbyArgs a;
  if (squareness) {
    a.model = args.Value("--model");
    a.xy_urad = args.Number(kPlanes[0].option);
    a.xz_urad = args.Number(kPlanes[1].option);
    a.yz_urad = args.Number(kPlanes[2].option);
  }
  if (backlash) {
    // No test file is fine here (a squareness alone); PositioningInputs refuses only that.
    Expected<std::vector<AxisInput>> tests = PositioningInputs(args);
    if (tests.ok()) a.tests = *tests;
    VOLCOMP_TRY_ASSIGN(a.read, ParsePositioningReadOptions(args));
    a.grouping.allow_few_approaches = args.Flag("--allow-few-runs");
    a.negate_tests = args.Flag("--negate-tests");
  }
  VOLCOMP_TRY(args.status());
  return a;
}

Expected<exporters::HobbySquareness> LoadSquareness(const HobbyArgs& a, Context& ctx) {
  exporters::HobbySquareness s;
  if (a.model) {
    VOLCOMP_TRY_ASSIGN(const model::Model m, LoadModelArgument(*a.model, ctx));
    const double values[] = {m.squareness.c0y_urad, m.squareness.b0z_urad, m.squareness.a0z_urad};
    for (int i = 0; i < 3; ++i) {
      *PlaneOf(s, i) = exporters::PlaneSquareness{
          values[i], "model " + *a.model + " (" + std::string(kPlanes[i].name) + ")"};
    }
  }
  const std::optional<double> options[] = {a.xy_urad, a.xz_urad, a.yz_urad};
  for (int i = 0; i < 3; ++i) {
    if (options[i]) *PlaneOf(s, i) = exporters::PlaneSquareness{*options[i], kPlanes[i].option};
  }
  for (int i = 0; i < 3; ++i) {
    const auto& p = *PlaneOf(s, i);
    if (p && !(std::fabs(p->urad) <= kMaxSquarenessUrad)) {
      return Fail(Error::kInputInvalid, std::string(kPlanes[i].name) + " = " +
                                            exporters::FixedDecimals(p->urad, 1) + " urad (" +
                                            p->source + ") is beyond the plausible +-" +
                                            exporters::FixedDecimals(kMaxSquarenessUrad, 0) +
                                            " urad (0.1 rad): the value must be in urad");
    }
  }
  return s;
}

Expected<std::vector<exporters::AxisBacklash>> LoadBacklash(const HobbyArgs& a, Context& ctx) {
  std::vector<exporters::AxisBacklash> result;
  for (const AxisInput& in : a.tests) {
    VOLCOMP_TRY_ASSIGN(const model::PositioningData data,
                       LoadAxisTest(in, a.read, a.grouping, ctx));
    const Expected<exporters::AxisBacklash> b =
        exporters::BacklashFromTest(in.axis, in.path, data, a.negate_tests);
    if (!b.ok()) return Fail(Error::kInputInvalid, b.error().message);
    result.push_back(*b);
  }
  return result;
}

Expected<HobbyInputs> LoadHobbyInputs(const HobbyArgs& a, Context& ctx) {
  HobbyInputs in;
  VOLCOMP_TRY_ASSIGN(in.squareness, LoadSquareness(a, ctx));
  if (!in.squareness.any() && a.tests.empty()) {
    return UsageFailure(
        "give a squareness (--model FILE, --squareness-xy-urad ...) or a test (--x FILE ...)");
  }
  VOLCOMP_TRY_ASSIGN(in.backlash, LoadBacklash(a, ctx));
  return in;
}

JsonValue HobbyJson(const char* firmware,
                    const std::string& output,
                    bool negated,
                    const HobbyInputs& in,
                    const exporters::SkewValues& values,
                    const char* value_key) {
  JsonValue j = JsonValue::Object();
  j.Set("firmware", firmware)
      .Set("output", output)
      .Set("negated", negated)
      .Set("squareness", SquarenessJson(in.squareness, values, value_key))
      .Set("backlash", BacklashJson(in.backlash));
  return j;
}

JsonValue SquarenessJson(const exporters::HobbySquareness& s,
                         const exporters::SkewValues& values,
                         const char* value_key) {
  JsonValue planes = JsonValue::Array();
  for (int i = 0; i < 3; ++i) {
    const auto& p = PlaneOf(s, i);
    if (!p) continue;
    JsonValue j = JsonValue::Object();
    j.Set("plane", kPlanes[i].plane)
        .Set("name", kPlanes[i].name)
        .Set("urad", p->urad)
        .Set("source", p->source)
        .Set(value_key, *ValueOf(values, i));
    planes.Push(std::move(j));
  }
  return planes;
}

JsonValue BacklashJson(const std::vector<exporters::AxisBacklash>& axes) {
  JsonValue list = JsonValue::Array();
  for (const exporters::AxisBacklash& b : axes) {
    JsonValue j = JsonValue::Object();
    j.Set("axis", std::string(1, b.axis))
        .Set("source", b.source)
        .Set("rotary", b.rotary)
        .Set("targets", b.targets)
        .Set("backlash_um", b.lost_motion_um)
        .Set("reversal_mean_um", b.reversal_mean_um)
        .Set("reversal_max_um", b.reversal_max_um)
        .Set("spread_um", b.spread_um)
        .Set("test_negated", b.test_negated)
        .Set("value", exporters::BacklashInFileUnits(b))
        .Set("unit", b.rotary ? "deg" : "mm");
    list.Push(std::move(j));
  }
  return list;
}

void HobbyInputsText(const JsonValue& d, const char* value_key, std::ostream& out) {
  char line[400];
  if (const JsonValue* planes = d.get("squareness")) {
    for (const JsonValue& p : planes->array) {
      std::snprintf(line, sizeof line, "  %s: %s = %.1f urad -> %s %.9f",
                    p.get("plane")->string.c_str(), p.get("name")->string.c_str(),
                    p.get("urad")->number, value_key, p.get(value_key)->number);
      out << line << " (" << p.get("source")->string << ")\n";
    }
  }
  if (const JsonValue* axes = d.get("backlash")) {
    for (const JsonValue& b : axes->array) {
      const bool rotary = b.get("rotary")->boolean;
      const char* u = rotary ? "arcsec" : "um";
      std::snprintf(line, sizeof line,
                    "  backlash %s: %.2f %s = %.5f %s (mean reversal %+.2f %s, largest |B_j| "
                    "%.2f %s, a constant leaves up to %.2f %s; %lld targets%s)",
                    b.get("axis")->string.c_str(), b.get("backlash_um")->number, u,
                    b.get("value")->number, b.get("unit")->string.c_str(),
                    b.get("reversal_mean_um")->number, u, b.get("reversal_max_um")->number, u,
                    b.get("spread_um")->number, u,
                    static_cast<long long>(b.get("targets")->integer),
                    b.get("test_negated")->boolean ? ", test negated" : "");
      out << line << " (" << b.get("source")->string << ")\n";
    }
  }
}

}  // namespace volcomp::cli
