// TODO
#include "dissertation_tables.hpp"

namespace volcomp::reproduce::dissertation {

Expected<void> AddAppendicesBVG(SeedReproduction& out) {
  (void)out;
  return {};
}

}  // namespace volcomp::reproduce::dissertation
