// Judge, the seed list and the selection behind `volcomp reproduce` (reproduction.hpp).
#include "volcomp/reproduce/reproduction.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace volcomp::reproduce {
namespace {

using Producer = Expected<SeedReproduction> (*)();

struct Seed {
  const char* id;
  Producer produce;
};

const std::vector<Seed>& Seeds() {
  static const std::vector<Seed> kSeeds = {
      {"gost27843", ReproduceGost27843},
      {"iso230-6", ReproduceIso2306},
      {"iso230-7", ReproduceIso2307},
      {"dissertation", ReproduceDissertation},
  };
  return kSeeds;
}

std::string Joined(const std::vector<std::string>& ids) {
  std::string text;
  for (const std::string& id : ids) text += (text.empty() ? "" : ", ") + id;
  return text.empty() ? "(none)" : text;
}

}  // namespace

CellVerdict Judge(const Cell& cell) {
  const double difference = std::fabs(cell.computed - cell.printed);
  // A NaN on either side is never "within tolerance".
  if (difference <= cell.tolerance) return CellVerdict::kReproduced;
  return cell.misprint.empty() ? CellVerdict::kMismatch : CellVerdict::kMisprint;
}

const char* VerdictName(CellVerdict verdict) {
  switch (verdict) {
    case CellVerdict::kReproduced:
      return "reproduced";
    case CellVerdict::kMisprint:
      return "misprint";
    case CellVerdict::kMismatch:
      return "mismatch";
  }
  return "mismatch";
}

Counts Count(const SeedReproduction& reproduction) {
  Counts n;
  for (const Table& table : reproduction.tables) {
    ++n.tables;
    for (const Cell& cell : table.cells) {
      switch (Judge(cell)) {
        case CellVerdict::kReproduced:
          ++n.reproduced;
          break;
        case CellVerdict::kMisprint:
          ++n.misprints;
          break;
        case CellVerdict::kMismatch:
          ++n.mismatches;
          break;
      }
    }
  }
  n.not_reproducible = static_cast<int>(reproduction.not_reproduced.size());
  return n;
}

const std::vector<std::string>& SeedIds() {
  static const std::vector<std::string> kIds = [] {
    std::vector<std::string> ids;
    for (const Seed& seed : Seeds()) ids.emplace_back(seed.id);
    return ids;
  }();
  return kIds;
}

Expected<SeedReproduction> Reproduce(const std::string& seed, const std::string& table_id) {
  if (!seed.empty()) {
    bool known = false;
    for (const Seed& s : Seeds()) known = known || seed == s.id;
    if (!known) {
      return Fail(Error::kInvalidArgument,
                  "unknown seed '" + seed + "'; known seeds: " + Joined(SeedIds()));
    }
  }
  SeedReproduction result;
  std::vector<std::string> known_tables;  // "seed:id" of every table looked at
  for (const Seed& s : Seeds()) {
    if (!seed.empty() && seed != s.id) continue;
    Expected<SeedReproduction> one = s.produce();
    if (!one.ok()) {
      // Not a selection error: kInvalidArgument stays reserved for unknown ids.
      return Fail(Error::kInputInvalid, std::string("seed ") + s.id + ": " + one.error().message);
    }
    // The seed id is the producer's, whatever its entries say (`volcomp reproduce` groups by it).
    for (Table& table : one->tables) {
      table.seed = s.id;
      known_tables.push_back(std::string(s.id) + ":" + table.id);
      if (table_id.empty() || table.id == table_id) result.tables.push_back(std::move(table));
    }
    for (NotReproducible& left : one->not_reproduced) {
      left.seed = s.id;
      known_tables.push_back(std::string(s.id) + ":" + left.id);
      if (table_id.empty() || left.id == table_id) {
        result.not_reproduced.push_back(std::move(left));
      }
    }
  }
  if (!table_id.empty() && result.tables.empty() && result.not_reproduced.empty()) {
    return Fail(Error::kInvalidArgument,
                "unknown table '" + table_id + "'" +
                    (seed.empty() ? "" : " of seed '" + seed + "'") +
                    "; known tables (seed:table): " + Joined(known_tables));
  }
  return result;
}

}  // namespace volcomp::reproduce
