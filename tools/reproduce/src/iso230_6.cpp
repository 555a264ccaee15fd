// ReproduceIso2306(): the GOST ISO 230-6 draft (seed 003, diagonal displacement tests) prints no
// numeric example or result table, so nothing is recomputed; each printed table and figure is
// listed with why (the tool's diagonal evaluation is checked on hand-worked data instead:
// tests/tools/metrology/diagonal_test.cpp).
#include "volcomp/reproduce/reproduction.hpp"

namespace volcomp::reproduce {

Expected<SeedReproduction> ReproduceIso2306() {
  const char* seed = "iso230-6";
  SeedReproduction out;
  out.not_reproduced = {
      {seed, "fig1", "Figure 1: the four body diagonals of a rectangular prism",
       "seed 003 line 166: a drawing without numbers (image missing); nothing to compute"},
      {seed, "fig2", "Figure 2: examples of face diagonals",
       "seed 003 line 181: a drawing without numbers (image missing); nothing to compute"},
      {seed, "fig3", "Figure 3: evaluation of E_i and B_i",
       "seed 003 line 202: the image is missing, and the definitions around it (3.4-3.7, lines "
       "187-208: E_d = max[E_1..E_4], B_d = max[B_1..B_4]) print formulas, no numbers"},
      {seed, "5.2", "5.2: positions of the measurement points (P_1, P_2, D, X_v, I_x = I_d·X_v/D)",
       "seed 003 lines 278-296: formulas only, no worked numbers (the tool's PlanDiagonal is "
       "checked on a hand-worked 3-4-12 box in tests/tools/metrology/diagonal_test.cpp)"},
      {seed, "3.8", "3.8 note: \"(reduced volume) = 0,012 mm\"",
       "seed 003 line 212: an example of how to state a value, not a result of printed data"},
      {seed, "ДА.1", "Table ДА.1: referenced international and interstate standards",
       "seed 003 lines 420-427: a list of standards, no numbers"},
  };
  return out;
}

}  // namespace volcomp::reproduce
