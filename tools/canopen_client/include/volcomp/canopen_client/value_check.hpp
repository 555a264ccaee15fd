// What a numeric object accepts, from the object dictionary (od_entries.def): the range of its
// CiA 301 type intersected with the entry's own limits (the same limits the board checks and the
// EDS lists as LowLimit/HighLimit), so a value is refused before anything is sent instead of being
// truncated to the type's size on the way.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::canopen_client {

struct ValueRange {
  int64_t low = 0;
  int64_t high = 0;
};

/// The values a write to `entry` may carry: its type's range, narrowed by the entry's limits.
/// Only for numeric types (FixedSize(entry.type) != 0).
ValueRange WritableRange(const canopen::ObjectEntry& entry);

/// Checks `text` as a value for `entry` and encodes it as the write's payload (little-endian, the
/// type's size). A refusal (kInvalidArgument) names the value and the limit or the reason
/// (read-only object, string or domain object, not an integer).
Expected<std::vector<uint8_t>> EncodeWriteValue(const canopen::ObjectEntry& entry,
                                                const std::string& text);

}  // namespace volcomp::canopen_client
