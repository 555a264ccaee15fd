// Corrections at the nodes of a lattice as `volcomp build grid --csv` reads them
// (volcomp/builders/node_grid.hpp), for tests that need a small valid input.
#pragma once

namespace volcomp::testing {

/// The smallest lattice: 2x2x2 nodes 10 steps apart, every node's correction (1, 2, 3) steps.
inline constexpr char kSmallGridCsv[] =
    "x_steps,y_steps,z_steps,dx_steps,dy_steps,dz_steps\n0,0,0,1,2,3\n10,0,0,1,2,3\n"
    "0,10,0,1,2,3\n10,10,0,1,2,3\n0,0,10,1,2,3\n10,0,10,1,2,3\n0,10,10,1,2,3\n"
    "10,10,10,1,2,3\n";

}  // namespace volcomp::testing
