// `volcomp reproduce [--seed ID] [--table ID] [--mismatches-only] [--json]`: every reproducible
// printed table of the seed documents, each printed value against the tool's computed value
// (reproduce/reproduction.hpp), known misprints flagged and explained. Exit code 1 when any value
// is a mismatch (beyond tolerance and unexplained), 2 for an unknown seed or table.
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "volcomp/reproduce/reproduction.hpp"

namespace volcomp::cli {
namespace {

namespace r = volcomp::reproduce;

JsonValue CountsJson(const r::Counts& n) {
  JsonValue j = JsonValue::Object();
  j.Set("tables", n.tables)
      .Set("reproduced", n.reproduced)
      .Set("misprints", n.misprints)
      .Set("mismatches", n.mismatches)
      .Set("not_reproducible", n.not_reproducible);
  return j;
}

JsonValue CellJson(const r::Cell& c) {
  JsonValue j = JsonValue::Object();
  j.Set("row", c.row)
      .Set("column", c.column)
      .Set("unit", c.unit)
      .Set("printed", c.printed)
      .Set("computed", c.computed)
      .Set("difference", c.computed - c.printed)
      .Set("tolerance", c.tolerance)
      .Set("verdict", r::VerdictName(r::Judge(c)));
  if (!c.misprint.empty()) j.Set("misprint", c.misprint);
  return j;
}

JsonValue TableJson(const r::Table& t, bool differences_only) {
  JsonValue j = JsonValue::Object();
  j.Set("seed", t.seed).Set("id", t.id).Set("title", t.title).Set("source", t.source);
  r::SeedReproduction alone;
  alone.tables.push_back(t);
  j.Set("counts", CountsJson(r::Count(alone)));
  JsonValue cells = JsonValue::Array();
  for (const r::Cell& c : t.cells) {
    if (differences_only && r::Judge(c) == r::CellVerdict::kReproduced) continue;
    cells.Push(CellJson(c));
  }
  JsonValue notes = JsonValue::Array();
  for (const std::string& note : t.notes) notes.Push(note);
  j.Set("cells", std::move(cells)).Set("notes", std::move(notes));
  return j;
}

JsonValue ReproductionJson(const std::vector<std::string>& seeds,
                           const std::vector<r::SeedReproduction>& parts,
                           bool differences_only) {
  JsonValue j = JsonValue::Object();
  j.Set("command", "reproduce");
  JsonValue per_seed = JsonValue::Array();
  JsonValue tables = JsonValue::Array();
  JsonValue left_out = JsonValue::Array();
  r::SeedReproduction all;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    JsonValue seed = CountsJson(r::Count(parts[i]));
    seed.Set("seed", seeds[i]);
    per_seed.Push(std::move(seed));
    for (const r::Table& t : parts[i].tables) {
      tables.Push(TableJson(t, differences_only));
      all.tables.push_back(t);
    }
    for (const r::NotReproducible& n : parts[i].not_reproduced) {
      JsonValue e = JsonValue::Object();
      e.Set("seed", n.seed).Set("id", n.id).Set("title", n.title).Set("reason", n.reason);
      left_out.Push(std::move(e));
      all.not_reproduced.push_back(n);
    }
  }
  j.Set("seeds", std::move(per_seed))
      .Set("tables", std::move(tables))
      .Set("not_reproduced", std::move(left_out))
      .Set("summary", CountsJson(r::Count(all)));
  j.Set("mismatches_only", differences_only);
  return j;
}

// ---- text view: reads only the JSON ----

const std::string& Str(const JsonValue& v, const char* key) {
  static const std::string kEmpty;
  const JsonValue* m = v.get(key);
  return m != nullptr && m->is_string() ? m->string : kEmpty;
}

double Num(const JsonValue& v, const char* key) {
  const JsonValue* m = v.get(key);
  return m != nullptr && m->is_number() ? m->number : 0.0;
}

// Decimals that show a value to its tolerance (0.005 → 2, 0.0005 → 3, 0 → 0).
int DecimalsOf(double tolerance) {
  if (!(tolerance > 0.0)) return 0;
  const int d = static_cast<int>(std::ceil(-std::log10(2.0 * tolerance) - 1e-6));
  return d < 0 ? 0 : (d > 6 ? 6 : d);
}

std::string Fixed(double value, int decimals, bool sign = false) {
  char text[64];
  if (std::fabs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;  // no "-0.000"
  std::snprintf(text, sizeof text, sign ? "%+.*f" : "%.*f", decimals, value);
  return text;
}

std::string CountsLine(const JsonValue& n) {
  return Fixed(Num(n, "reproduced"), 0) + " values reproduced, " + Fixed(Num(n, "misprints"), 0) +
         " known misprints, " + Fixed(Num(n, "mismatches"), 0) + " mismatches; " +
         Fixed(Num(n, "not_reproducible"), 0) + " tables not reproducible";
}

void TableText(const JsonValue& t, std::ostream& out) {
  out << "== " << Str(t, "seed") << " " << Str(t, "id") << ": " << Str(t, "title") << "\n"
      << "source: " << Str(t, "source") << "\n"
      << "row | column | printed | computed | difference | verdict\n";
  std::vector<std::string> footnotes;
  for (const JsonValue& c : t.get("cells")->array) {
    const int d = DecimalsOf(Num(c, "tolerance"));
    const std::string unit = Str(c, "unit").empty() ? "" : " " + Str(c, "unit");
    out << Str(c, "row") << " | " << Str(c, "column") << " | " << Fixed(Num(c, "printed"), d)
        << unit << " | " << Fixed(Num(c, "computed"), d + 1) << " | "
        << Fixed(Num(c, "difference"), d + 1, true) << " | " << Str(c, "verdict");
    if (!Str(c, "misprint").empty()) {
      footnotes.push_back(Str(c, "row") + ", " + Str(c, "column") + ": " + Str(c, "misprint"));
      out << " [" << footnotes.size() << "]";
    }
    out << "\n";
  }
  for (std::size_t i = 0; i < footnotes.size(); ++i) {
    out << "  [" << i + 1 << "] " << footnotes[i] << "\n";
  }
  for (const JsonValue& note : t.get("notes")->array) out << "  note: " << note.string << "\n";
  const JsonValue& n = *t.get("counts");
  out << "table " << Str(t, "seed") << " " << Str(t, "id") << ": " << Fixed(Num(n, "reproduced"), 0)
      << " reproduced, " << Fixed(Num(n, "misprints"), 0) << " known misprints, "
      << Fixed(Num(n, "mismatches"), 0) << " mismatches\n\n";
}

void ReproduceText(const JsonValue& data, std::ostream& out) {
  if (data.get("mismatches_only")->boolean) {
    out << "(only the values that differ from the print beyond tolerance are listed)\n\n";
  }
  for (const JsonValue& t : data.get("tables")->array) TableText(t, out);
  const auto& left_out = data.get("not_reproduced")->array;
  if (!left_out.empty()) out << "not reproducible:\n";
  for (const JsonValue& n : left_out) {
    out << "  " << Str(n, "seed") << " " << Str(n, "id") << ": " << Str(n, "title") << " — "
        << Str(n, "reason") << "\n";
  }
  if (!left_out.empty()) out << "\n";
  for (const JsonValue& s : data.get("seeds")->array) {
    out << Str(s, "seed") << ": " << Fixed(Num(s, "tables"), 0) << " tables; " << CountsLine(s)
        << "\n";
  }
  out << "total: " << CountsLine(*data.get("summary")) << " (listed)\n";
}

Expected<Output> RunReproduce(Args& args, Context& /*ctx*/) {
  args.Flag("--json");  // the command layer prints the data as JSON
  const std::string seed = args.Value("--seed").value_or("");
  const std::string table = args.Value("--table").value_or("");
  const bool differences_only = args.Flag("--mismatches-only");
  VOLCOMP_TRY(args.Finish());
  if (!args.Positionals().empty()) return UsageFailure("reproduce takes no file arguments");
  Expected<r::SeedReproduction> all = r::Reproduce(seed, table);
  if (!all.ok() && all.error().code == Error::kInvalidArgument) {
    return UsageFailure(all.error().message);  // an unknown seed or table, the known ids listed
  }
  if (!all.ok()) return Fail(all.error());
  // Per seed, in the seeds' order: each selected seed (with --table, those that have it).
  std::vector<std::string> seeds;
  std::vector<r::SeedReproduction> parts;
  for (const std::string& id : r::SeedIds()) {
    if (!seed.empty() && seed != id) continue;
    r::SeedReproduction part;
    for (const r::Table& t : all->tables) {
      if (t.seed == id) part.tables.push_back(t);
    }
    for (const r::NotReproducible& n : all->not_reproduced) {
      if (n.seed == id) part.not_reproduced.push_back(n);
    }
    if (!table.empty() && part.tables.empty() && part.not_reproduced.empty()) continue;
    seeds.push_back(id);
    parts.push_back(std::move(part));
  }
  JsonValue data = ReproductionJson(seeds, parts, differences_only);
  const bool mismatch = Num(*data.get("summary"), "mismatches") > 0;
  return Output{std::move(data), ReproduceText, {}, mismatch ? tools::kExitFailed : tools::kExitOk};
}

}  // namespace

const Command& ReproduceCommand() {
  static const Command kCommand{
      "reproduce",
      "the seed documents' printed tables against the tool's computation, misprints explained",
      "",
      {{"--seed", nullptr, "ID", nullptr, nullptr,
        "one seed: gost27843, iso230-6, iso230-7 or dissertation (default: all)"},
       {"--table", nullptr, "ID", nullptr, nullptr,
        "one printed table of the seed(s), e.g. example, F, 3.7 (default: all)"},
       {"--mismatches-only", nullptr, nullptr, nullptr, nullptr,
        "list only the values that differ beyond tolerance (known misprints and mismatches); "
        "the counts still cover all"},
       {"--json", nullptr, nullptr, nullptr, nullptr,
        "tables, every value with its verdict, the tables not reproducible and the counts"}},
      RunReproduce,
      "Each printed value is shown as printed, computed, difference (computed − printed) and\n"
      "verdict: reproduced (within half a unit of the last printed digit, or the table's stated\n"
      "tolerance), misprint (a known misprint, explained in a footnote) or mismatch.\n"
      "Exit code: 0 when no value is a mismatch; 1 when any is (or a seed's computation failed);\n"
      "2 for an unknown seed or table (the message lists the known ids)."};
  return kCommand;
}

}  // namespace volcomp::cli
