// ReproduceIso2307(): GOST R ISO 230-7-2021 (seed 004). The numbers it prints that the tool
// computes are the Annex F factors (metrology/error_motion_uncertainty.hpp); Table 2, Table H.1,
// the Annex H speed limits and the Annex A examples have no computation in the tool and are
// listed with why (../shared/reference/iso230-7.md §4 "Numeric content", §7 errata).
#include <string>

#include "volcomp/metrology/error_motion_uncertainty.hpp"
#include "volcomp/reproduce/reproduction.hpp"

namespace volcomp::reproduce {
namespace {

constexpr double kInputUm = 10.0;  // any positive input: the printed figures are ratios

Cell Factor(const char* row, const char* column, double printed, double computed) {
  Cell c;
  c.row = row;
  c.column = column;
  c.printed = printed;
  c.computed = computed;
  c.tolerance = 0.05 + 1e-9;  // printed to one decimal
  return c;
}

Expected<Table> AnnexF() {
  metrology::ErrorMotionUncertaintyInputs calibration_free;
  calibration_free.device_range_um = kInputUm;  // F.2: no calibration certificate
  calibration_free.drift_range_um = kInputUm;   // F.3: a drift test of range E_VE
  Expected<metrology::ErrorMotionUncertainty> u =
      metrology::ErrorMotionU(calibration_free, 20, 1.0);
  if (!u.ok()) return Fail(u.error().Prefixed("ISO 230-7 Annex F"));
  Table t;
  t.seed = "iso230-7";
  t.id = "F";
  t.title = "Annex F: factors of the uncertainty of error-motion plots and values";
  t.source = "seed 004, lines 1683-1790 (formulas F.2, F.3, F.7)";
  t.cells.push_back(
      Factor("F.2 (line 1685)", "U_DEVICE / R_DEVICE", 0.6, u->device_basis / kInputUm));
  t.cells.push_back(Factor("F.3 (line 1714)", "U_EVE / E_VE", 0.6, u->eve / kInputUm));
  t.cells.push_back(Factor("F.7 (line 1783)", "U_sync value / U_sync plot", 1.4,
                           u->synchronous_value / u->synchronous_plot));
  t.notes = {
      "Computed by the tool's error-motion uncertainty (metrology ErrorMotionU, behind the "
      "instrument and drift options of `evaluate rotary`) with R_DEVICE = E_VE = 10 µm, n = 20, "
      "no setup term.",
      "F.4 and F.5 print formulas without numbers. F.6 as printed, sqrt(U_single² + U_EVE²/n), "
      "contradicts its own argument of two independent extremes and F.7 (digest iso230-7.md §7 "
      "note 32): the tool uses 1.4·U_single and offers the printed formula as an option.",
  };
  return t;
}

}  // namespace

Expected<SeedReproduction> ReproduceIso2307() {
  const char* seed = "iso230-7";
  SeedReproduction out;
  VOLCOMP_TRY_ASSIGN(Table f, AnnexF());
  out.tables.push_back(std::move(f));
  out.not_reproduced = {
      {seed, "2", "Table 2: recommended minimum axial separation between spheres/sensors for tilt",
       "seed 004 lines 779-791: a recommendation (spindle diameter class → distance), not a "
       "result of data; the tool takes the separation L as measured and has no rule to recompute"},
      {seed, "H.1", "Table H.1: bearing frequencies of a typical rolling bearing",
       "seed 004 lines 1932-1935: the tool has no bearing-frequency computation; the textbook "
       "defect orders for 15 balls, d = 8 mm, D = 72,5 mm, contact angle 0 give 6,67, 8,33, "
       "0,445, 4,48 against the printed 6,68, 8,32, 0,45, 4,52 (digest §2.13), so the printed "
       "values rest on an unstated contact angle or rounding"},
      {seed, "H",
       "Annex H: sensor bandwidth against speed (600 000, 200 000, 75 000, 70 000 min⁻¹)",
       "seed 004 lines 1887-1930: the tool has no bandwidth computation; n_max = 60·f/q "
       "reproduces 600 000 (q = 1), 200 000 (q = 3), 75 000 (q = 8) and 72 115 for 8,32× where "
       "the seed rounds down to 70 000 (digest §2.13); 4.3 a) line 638 says 50 UPR where 10 kHz "
       "at 6000 min⁻¹ gives 100 (digest §7 note 8)"},
      {seed, "A.1", "A.1 example: sensitive error of a non-sensitive motion, E_S = E_N²/(2R)",
       "seed 004 line 1122: the tool has no such computation; 0,02²/(2·10) = 2·10⁻⁵ mm = "
       "0,02 µm, printed \"0.02 mm\" (digest §7 note 18)"},
      {seed, "A.7", "A.7 example: roughness R_t = s²/(8 r_ε) of a turned surface",
       "seed 004 line 1327: the tool has no such computation; 0,02²/(8·5) = 1·10⁻⁵ mm = "
       "0,01 µm as printed"},
      {seed, "figures", "Figures 1-15, A.1-A.15, H.1",
       "all figure images are missing from the seed; none prints numbers (digest §4.3)"},
  };
  return out;
}

}  // namespace volcomp::reproduce
