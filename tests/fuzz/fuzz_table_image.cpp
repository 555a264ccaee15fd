// Fuzz target: the table image parser/validator, and interpolation on every image it accepts.
// Each input is parsed as is and again with its CRC trailer recomputed (so mutations reach the
// field checks behind the CRC). Invariants: ParseImage never reads outside the buffer (ASan), and
// every accepted image prepares and is looked up without UB at any position (UBSan).
#include <cstdint>
#include <cstring>
#include <vector>

#include "volcomp/base/byte_order.hpp"
#include "volcomp/base/crc32.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/control/compensator.hpp"
#include "volcomp/table/table_image.hpp"

namespace {

void ParseAndUse(const uint8_t* p, size_t size, const uint8_t* data);

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<uint32_t> aligned((size + 3) / 4 + 1);
  if (size != 0) std::memcpy(aligned.data(), data, size);
  uint8_t* p = reinterpret_cast<uint8_t*>(aligned.data());
  ParseAndUse(p, size, data);
  // Again with the CRC trailer made right, so mutations reach the field checks behind the CRC.
  if (size >= 8) {
    volcomp::StoreLe32(p + size - 4, volcomp::ComputeCrc32(p, size - 4));
    ParseAndUse(p, size, data);
  }
  return 0;
}

namespace {

void ParseAndUse(const uint8_t* p, size_t size, const uint8_t* data) {
  const volcomp::Result<volcomp::table::TableView> view = volcomp::table::ParseImage(p, size);
  (void)volcomp::table::PeekImageSize(p, size);
  if (!view.ok()) return;
  volcomp::BoardConfig cfg = volcomp::DefaultBoardConfig();
  cfg.axis_count = view->axis_count;
  for (uint8_t i = 0; i < view->axis_count; ++i) {
    cfg.axis[i].name = view->axes[i].name;
    cfg.axis[i].kind = view->axes[i].kind;
    cfg.axis[i].resolution_e9 = view->axes[i].resolution_e9;
  }
  volcomp::PreparedTable table;
  if (!table.Prepare(*view, cfg).ok()) return;
  // Look up at positions taken from the input and at the extremes.
  int32_t pos[6] = {INT32_MIN, INT32_MAX, 0, -1, 1, 12345};
  bool reverse[6] = {false, true, false, true, false, true};
  int32_t out[6];
  table.TargetsQ8(pos, pos, reverse, view->axis_count, out);
  for (size_t off = 0; off + 24 <= size && off < 24 * 64; off += 24) {
    std::memcpy(pos, data + off, 24);
    table.TargetsQ8(pos, pos, reverse, view->axis_count, out);
  }
}

}  // namespace
