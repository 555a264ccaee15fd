// Value checks of writes against the object dictionary.
#include "volcomp/canopen_client/value_check.hpp"

#include <cerrno>
#include <cstdlib>

namespace volcomp::canopen_client {

using canopen::DataType;

namespace {

ValueRange TypeRange(DataType t) {
  switch (t) {
    case DataType::kBoolean:
      return {0, 1};
    case DataType::kInteger8:
      return {INT8_MIN, INT8_MAX};
    case DataType::kInteger16:
      return {INT16_MIN, INT16_MAX};
    case DataType::kInteger32:
      return {INT32_MIN, INT32_MAX};
    case DataType::kUnsigned8:
      return {0, UINT8_MAX};
    case DataType::kUnsigned16:
      return {0, UINT16_MAX};
    case DataType::kUnsigned32:
      return {0, UINT32_MAX};
    default:
      return {0, 0};
  }
}

const char* TypeName(DataType t) {
  switch (t) {
    case DataType::kBoolean:
      return "BOOLEAN";
    case DataType::kInteger8:
      return "INTEGER8";
    case DataType::kInteger16:
      return "INTEGER16";
    case DataType::kInteger32:
      return "INTEGER32";
    case DataType::kUnsigned8:
      return "UNSIGNED8";
    case DataType::kUnsigned16:
      return "UNSIGNED16";
    case DataType::kUnsigned32:
      return "UNSIGNED32";
    case DataType::kVisibleString:
      return "VISIBLE_STRING";
    case DataType::kDomain:
      return "DOMAIN";
  }
  return "?";
}

}  // namespace

ValueRange WritableRange(const canopen::ObjectEntry& e) {
  ValueRange r = TypeRange(e.type);
  if (e.limited) {
    r.low = e.low_limit > r.low ? e.low_limit : r.low;
    r.high = e.high_limit < r.high ? e.high_limit : r.high;
  }
  return r;
}

Expected<std::vector<uint8_t>> EncodeWriteValue(const canopen::ObjectEntry& e,
                                                const std::string& text) {
  const std::string object = std::string("\"") + e.name + "\"";
  if (e.access == canopen::Access::kRo || e.access == canopen::Access::kConst) {
    return Fail(Error::kInvalidArgument, object + " is read-only");
  }
  const uint32_t size = canopen::FixedSize(e.type);
  if (size == 0) {
    return Fail(Error::kInvalidArgument,
                object + " is a " + TypeName(e.type) + " object: `sdo write` writes numbers only");
  }
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(begin, &end, 0);
  if (text.empty() || *end != '\0' || errno == ERANGE) {
    return Fail(Error::kInvalidArgument,
                "\"" + text + "\" is not an integer (decimal, 0x-hex or negative)");
  }
  const ValueRange r = WritableRange(e);
  if (v < r.low || v > r.high) {
    return Fail(Error::kInvalidArgument,
                text + " is outside what " + object + " (" + TypeName(e.type) +
                    ") accepts: " + std::to_string(r.low) + ".." + std::to_string(r.high));
  }
  std::vector<uint8_t> payload(size, 0);
  const uint64_t bits = static_cast<uint64_t>(v);
  for (uint32_t i = 0; i < size; ++i) payload[i] = static_cast<uint8_t>(bits >> (8 * i));
  return payload;
}

}  // namespace volcomp::canopen_client
