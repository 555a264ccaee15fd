// PLACEHOLDER for building repro-core alone: the real ReproduceDissertation() is written in
// tools/reproduce/src/dissertation_*.cpp on another branch; the lead deletes this file at merge.
#include "volcomp/reproduce/reproduction.hpp"

namespace volcomp::reproduce {

Expected<SeedReproduction> ReproduceDissertation() { return SeedReproduction{}; }

}  // namespace volcomp::reproduce
