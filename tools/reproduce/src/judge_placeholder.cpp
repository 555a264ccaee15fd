// PLACEHOLDER (repro-diss branch only): Judge() as reproduction.hpp documents it, so the
// dissertation tests link before reproduction.cpp (written on another branch) is merged. The lead
// deletes this file at merge.
#include <cmath>

#include "volcomp/reproduce/reproduction.hpp"

namespace volcomp::reproduce {

CellVerdict Judge(const Cell& cell) {
  if (std::fabs(cell.computed - cell.printed) <= cell.tolerance) return CellVerdict::kReproduced;
  return cell.misprint.empty() ? CellVerdict::kMismatch : CellVerdict::kMisprint;
}

}  // namespace volcomp::reproduce
