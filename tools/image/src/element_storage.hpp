// Typed storage for one element array of a table image (int16, int32 or float32), as the image
// writer takes it: the builder fills it from encoded values, the join from a part's decoded bytes.
#pragma once

#include <cstdint>
#include <vector>

#include "volcomp/table/table_writer.hpp"

namespace volcomp::image {

struct ElementStorage {
  std::vector<int16_t> i16;
  std::vector<int32_t> i32;
  std::vector<float> f32;

  table::ElementArray view(table::ElementType type) const {
    table::ElementArray a;
    a.type = type;
    a.i16 = i16.data();
    a.i32 = i32.data();
    a.f32 = f32.data();
    return a;
  }
};

}  // namespace volcomp::image
