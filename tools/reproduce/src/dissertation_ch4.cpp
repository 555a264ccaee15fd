// TODO
#include "dissertation_tables.hpp"

namespace volcomp::reproduce::dissertation {

Expected<void> AddChapter4(SeedReproduction& out) {
  (void)out;
  return {};
}

}  // namespace volcomp::reproduce::dissertation
