// Table image validation. Every check reads through a bounds-checked cursor.
#include "volcomp/table/table_image.hpp"

#include "volcomp/base/byte_order.hpp"
#include "volcomp/base/crc32.hpp"

namespace volcomp::table {
namespace {

bool IsAxisName(uint8_t c) {
  for (const char* p = kAxisNames; *p != '\0'; ++p) {
    if (static_cast<uint8_t>(*p) == c) return true;
  }
  return false;
}

bool IsFinite(float f) {
  uint32_t bits;
  __builtin_memcpy(&bits, &f, sizeof bits);
  return (bits & 0x7F800000u) != 0x7F800000u;
}

// Largest |element| allowed for the type and fraction bits (table::kMaxCorrectionSteps in LSBs).
int64_t MaxElementMagnitude(uint8_t frac_bits) {
  return static_cast<int64_t>(kMaxCorrectionSteps) << frac_bits;
}

// Checks `count` elements of `type` starting at `p` for finiteness and range.
Status CheckElements(const uint8_t* p, uint32_t count, ElementType type, uint8_t frac_bits) {
  const int64_t max_lsb = MaxElementMagnitude(frac_bits);
  for (uint32_t i = 0; i < count; ++i) {
    switch (type) {
      case ElementType::kInt16: {
        const int64_t v = static_cast<int16_t>(LoadLe16(p + 2u * i));
        if (v > max_lsb || v < -max_lsb) return Error::kValueOutOfRange;
        break;
      }
      case ElementType::kInt32: {
        const int64_t v = LoadLeI32(p + 4u * i);
        if (v > max_lsb || v < -max_lsb) return Error::kValueOutOfRange;
        break;
      }
      case ElementType::kFloat32: {
        const float v = LoadLeF32(p + 4u * i);
        if (!IsFinite(v)) return Error::kValueNotFinite;
        if (v > static_cast<float>(kMaxCorrectionSteps) ||
            v < -static_cast<float>(kMaxCorrectionSteps)) {
          return Error::kValueOutOfRange;
        }
        break;
      }
    }
  }
  return Status::Ok();
}

Status CheckElementEncoding(uint8_t type_byte, uint8_t frac_bits, ElementType* type) {
  if (type_byte < 1 || type_byte > 3) return Error::kElementBadType;
  *type = static_cast<ElementType>(type_byte);
  const uint8_t max_frac = (*type == ElementType::kFloat32) ? 0 : kMaxFracBits;
  if (frac_bits > max_frac) return Error::kElementBadFracBits;
  return Status::Ok();
}

// Checks a lattice dimension: spacing >= 1 and origin + (nodes-1)*spacing within int32.
Status CheckDimension(const Dimension& d) {
  if (d.spacing_steps == 0) return Error::kBadSpacing;
  const uint64_t extent = static_cast<uint64_t>(d.nodes - 1u) * d.spacing_steps;
  if (extent > kMaxExtentSteps) return Error::kBadSpacing;
  if (static_cast<int64_t>(d.origin_steps) + static_cast<int64_t>(extent) > INT32_MAX) {
    return Error::kGridExtentOverflow;
  }
  return Status::Ok();
}

// Byte size of `count` elements padded to 4, or 0 on overflow beyond the image limit.
uint64_t ArrayBytes(uint64_t count, ElementType type) { return count * ElementSize(type); }
uint64_t Pad4(uint64_t n) { return (n + 3u) & ~uint64_t{3}; }

// Padding after `used` bytes up to the 4-byte boundary must be zero (images are canonical).
Status CheckPadding(const uint8_t* body, uint64_t used) {
  for (uint64_t i = used; i < Pad4(used); ++i) {
    if (body[i] != 0) return Error::kImageReservedNotZero;
  }
  return Status::Ok();
}

Status ParseAxes(const uint8_t* body, uint32_t length, TableView* view) {
  if (length < axes::kRecordsOffset) return Error::kSectionBadLength;
  const uint8_t count = body[axes::kCountOffset];
  if (count < 1 || count > kMaxAxes) return Error::kAxesBadCount;
  if (body[1] != 0 || body[2] != 0 || body[3] != 0) return Error::kImageReservedNotZero;
  if (length != axes::kRecordsOffset + count * axes::kRecordSize) return Error::kSectionBadLength;
  for (uint8_t i = 0; i < count; ++i) {
    const uint8_t* r = body + axes::kRecordsOffset + i * axes::kRecordSize;
    AxisInfo& a = view->axes[i];
    if (!IsAxisName(r[axes::kNameOffset])) return Error::kAxesBadName;
    for (uint8_t j = 0; j < i; ++j) {
      if (static_cast<uint8_t>(view->axes[j].name) == r[axes::kNameOffset]) {
        return Error::kAxesBadName;
      }
    }
    if (r[axes::kKindOffset] > 1) return Error::kAxesBadKind;
    if (LoadLe16(r + axes::kReservedOffset) != 0) return Error::kImageReservedNotZero;
    a.name = static_cast<char>(r[axes::kNameOffset]);
    a.kind = static_cast<AxisKind>(r[axes::kKindOffset]);
    a.resolution_e9 = LoadLe32(r + axes::kResolutionOffset);
    if (a.resolution_e9 == 0) return Error::kAxesBadResolution;
  }
  view->axis_count = count;
  return Status::Ok();
}

// GRID3 and AXIS1D refer to axes by index, so they are checked after AXES (second pass).
Status ParseGrid3(const uint8_t* body, uint32_t length, TableView* view) {
  if (length < grid3::kDataOffset) return Error::kSectionBadLength;
  Grid3View& g = view->grid;
  VOLCOMP_TRY(
      CheckElementEncoding(body[grid3::kElementTypeOffset], body[grid3::kFracBitsOffset], &g.type));
  g.frac_bits = body[grid3::kFracBitsOffset];
  for (int d = 0; d < 3; ++d) {
    g.axis[d] = body[grid3::kAxisOffset + d];
    if (g.axis[d] >= view->axis_count) return Error::kAxisIndexInvalid;
    for (int e = 0; e < d; ++e) {
      if (g.axis[e] == g.axis[d]) return Error::kGridDuplicateAxis;
    }
    if (body[grid3::kReservedOffset + d] != 0) return Error::kImageReservedNotZero;
  }
  uint64_t total = 1;
  for (int d = 0; d < 3; ++d) {
    Dimension& dim = g.dim[d];
    dim.nodes = LoadLe32(body + grid3::kNodesOffset + 4 * d);
    dim.origin_steps = LoadLeI32(body + grid3::kOriginOffset + 4 * d);
    dim.spacing_steps = LoadLe32(body + grid3::kSpacingOffset + 4 * d);
    if (dim.nodes < grid3::kMinNodes || dim.nodes > grid3::kMaxNodes) {
      return Error::kGridBadNodeCount;
    }
    VOLCOMP_TRY(CheckDimension(dim));
    total *= dim.nodes;
  }
  if (total > grid3::kMaxTotalNodes) return Error::kGridBadNodeCount;
  const uint64_t data_bytes = ArrayBytes(total * 3u, g.type);
  if (length != grid3::kDataOffset + Pad4(data_bytes)) return Error::kSectionBadLength;
  g.data = body + grid3::kDataOffset;
  VOLCOMP_TRY(CheckPadding(g.data, data_bytes));
  VOLCOMP_TRY(CheckElements(g.data, static_cast<uint32_t>(total * 3u), g.type, g.frac_bits));
  g.present = true;
  return Status::Ok();
}

Status ParseAxis1d(const uint8_t* body, uint32_t length, TableView* view) {
  if (length < axis1d::kDataOffset) return Error::kSectionBadLength;
  Axis1dView& t = view->axis1d[view->axis1d_count];
  t.axis = body[axis1d::kAxisOffset];
  if (t.axis >= view->axis_count) return Error::kAxisIndexInvalid;
  for (uint8_t i = 0; i < view->axis1d_count; ++i) {
    if (view->axis1d[i].axis == t.axis) return Error::kSectionDuplicate;
  }
  VOLCOMP_TRY(CheckElementEncoding(body[axis1d::kElementTypeOffset], body[axis1d::kFracBitsOffset],
                                   &t.type));
  t.frac_bits = body[axis1d::kFracBitsOffset];
  t.flags = body[axis1d::kFlagsOffset];
  if ((t.flags & ~axis1d::kKnownFlags) != 0) return Error::kAxis1dBadFlags;
  t.dim.nodes = LoadLe32(body + axis1d::kNodesOffset);
  t.dim.origin_steps = LoadLeI32(body + axis1d::kOriginOffset);
  t.dim.spacing_steps = LoadLe32(body + axis1d::kSpacingOffset);
  t.period_steps = LoadLe32(body + axis1d::kPeriodOffset);
  t.backlash_q8 = LoadLeI32(body + axis1d::kBacklashOffset);
  if (t.dim.nodes < axis1d::kMinNodes || t.dim.nodes > axis1d::kMaxNodes) {
    return Error::kAxis1dBadNodeCount;
  }
  VOLCOMP_TRY(CheckDimension(t.dim));
  if (t.backlash_q8 > kMaxCorrectionQ8 || t.backlash_q8 < -kMaxCorrectionQ8) {
    return Error::kValueOutOfRange;
  }
  const bool has_reverse = (t.flags & axis1d::kFlagReverse) != 0;
  const uint64_t one = ArrayBytes(t.dim.nodes, t.type);
  if (length != axis1d::kDataOffset + Pad4(one * (has_reverse ? 2u : 1u))) {
    return Error::kSectionBadLength;
  }
  t.forward = body + axis1d::kDataOffset;
  t.reverse = has_reverse ? t.forward + one : nullptr;
  VOLCOMP_TRY(CheckPadding(t.forward, one * (has_reverse ? 2u : 1u)));
  VOLCOMP_TRY(CheckElements(t.forward, t.dim.nodes, t.type, t.frac_bits));
  if (has_reverse) VOLCOMP_TRY(CheckElements(t.reverse, t.dim.nodes, t.type, t.frac_bits));
  const uint64_t extent = static_cast<uint64_t>(t.dim.nodes - 1u) * t.dim.spacing_steps;
  if ((t.flags & axis1d::kFlagWrap) != 0) {
    if (t.period_steps == 0 || t.period_steps != extent) return Error::kAxis1dBadPeriod;
    const uint32_t last = t.dim.nodes - 1u;
    const uint32_t size = ElementSize(t.type);
    const uint8_t* arrays[2] = {t.forward, t.reverse};
    for (const uint8_t* a : arrays) {
      if (a != nullptr && __builtin_memcmp(a, a + last * size, size) != 0) {
        return Error::kAxis1dWrapDiscontinuous;
      }
    }
  } else if (t.period_steps != 0) {
    return Error::kAxis1dBadPeriod;
  }
  ++view->axis1d_count;
  return Status::Ok();
}

Status ParseInfo(const uint8_t* body, uint32_t length, TableView* view) {
  if (length > kMaxInfoBytes) return Error::kSectionBadLength;
  // Text, then zero padding to the 4-byte boundary.
  uint32_t text = length;
  while (text > 0 && body[text - 1] == 0) --text;
  if (length - text > 3) return Error::kSectionBadLength;
  for (uint32_t i = 0; i < text; ++i) {
    const uint8_t c = body[i];
    if (c < 0x20 && c != '\n' && c != '\t') return Error::kInfoBadText;
    if (c == 0x7F) return Error::kInfoBadText;
  }
  view->info = reinterpret_cast<const char*>(body);
  view->info_size = text;
  return Status::Ok();
}

// THERMAL refers to the axis count, so it is checked after AXES; its values by the one model
// validator, ValidateThermalModel().
Status ParseThermal(const uint8_t* body, uint32_t length, TableView* view) {
  namespace ts = thermal_section;
  if (length < ts::kAxisRecordsOffset) return Error::kSectionBadLength;
  if (body[ts::kVersionOffset] != ts::kVersion) return Error::kThermalBadVersion;
  if (body[ts::kAxisCountOffset] != view->axis_count) return Error::kThermalBadAxisCount;
  if (body[ts::kReservedOffset] != 0) return Error::kImageReservedNotZero;
  if (length != ts::kAxisRecordsOffset + view->axis_count * ts::kAxisRecordSize) {
    return Error::kSectionBadLength;
  }
  const thermal::ThermalModel model = ReadThermal(body);
  VOLCOMP_TRY(thermal::ValidateThermalModel(model));
  // Its terms are micrometres of a linear axis: a rotary axis has none.
  for (uint8_t a = 0; a < view->axis_count; ++a) {
    if (view->axes[a].kind != AxisKind::kRotary) continue;
    for (uint8_t j = 0; j < thermal::kMaxChannels; ++j) {
      if (model.axis[a].offset_um_per_K[j] != 0.0f || model.axis[a].slope_um_per_K_m[j] != 0.0f)
        return Error::kThermalOnRotaryAxis;
    }
  }
  view->thermal = body;
  return Status::Ok();
}

}  // namespace

thermal::ThermalModel ReadThermal(const uint8_t* body) {
  namespace ts = thermal_section;
  static_assert(ts::kChannels == thermal::kMaxChannels, "THERMAL carries every channel");
  thermal::ThermalModel m;
  m.axis_count = body[ts::kAxisCountOffset];
  m.channel_mask = body[ts::kChannelMaskOffset];
  m.slew_um_s = LoadLeF32(body + ts::kSlewOffset);
  m.hold_ms = LoadLe32(body + ts::kHoldOffset);
  for (uint32_t j = 0; j < ts::kChannels; ++j) {
    m.reference_cC[j] = static_cast<int16_t>(LoadLe16(body + ts::kReferenceOffset + 2 * j));
    m.calibrated_low_cC[j] =
        static_cast<int16_t>(LoadLe16(body + ts::kCalibratedLowOffset + 2 * j));
    m.calibrated_high_cC[j] =
        static_cast<int16_t>(LoadLe16(body + ts::kCalibratedHighOffset + 2 * j));
  }
  for (uint8_t a = 0; a < m.axis_count && a < thermal::kMaxModelAxes; ++a) {
    const uint8_t* r = body + ts::kAxisRecordsOffset + a * ts::kAxisRecordSize;
    thermal::AxisModel& x = m.axis[a];
    x.p0_mm = LoadLeF32(r + ts::kP0Offset);
    x.reach_mm = LoadLeF32(r + ts::kReachOffset);
    for (uint32_t j = 0; j < ts::kChannels; ++j) {
      x.offset_um_per_K[j] = LoadLeF32(r + ts::kOffsetCoefficientsOffset + 4 * j);
      x.slope_um_per_K_m[j] = LoadLeF32(r + ts::kSlopeCoefficientsOffset + 4 * j);
    }
  }
  return m;
}

Result<uint32_t> PeekImageSize(const uint8_t* data, size_t available) {
  if (available < kHeaderSize) return Error::kImageTooShort;
  if (LoadLe32(data + header::kMagicOffset) != kMagic) return Error::kImageBadMagic;
  const uint32_t size = LoadLe32(data + header::kImageSizeOffset);
  if (size < kHeaderSize + kTrailerSize) return Error::kImageSizeMismatch;
  if (size > kMaxImageSize || size > available) return Error::kImageTooLarge;
  return size;
}

Result<TableView> ParseImage(const uint8_t* data, size_t size) {
  TableView view;
  if (data == nullptr || size < kHeaderSize + kTrailerSize) return Error::kImageTooShort;
  if ((reinterpret_cast<uintptr_t>(data) & 3u) != 0) return Error::kImageMisaligned;
  if (LoadLe32(data + header::kMagicOffset) != kMagic) return Error::kImageBadMagic;
  if (data[header::kVersionMajorOffset] != kVersionMajor) return Error::kImageUnsupportedVersion;
  if (LoadLe16(data + header::kHeaderSizeOffset) != kHeaderSize) return Error::kImageBadHeaderSize;
  view.image_size = LoadLe32(data + header::kImageSizeOffset);
  if (size > kMaxImageSize) return Error::kImageTooLarge;
  if (view.image_size != size) return Error::kImageSizeMismatch;
  if ((size & 3u) != 0) return Error::kImageSizeMismatch;
  const uint32_t body_end = view.image_size - kTrailerSize;
  view.crc32 = LoadLe32(data + body_end);
  if (ComputeCrc32(data, body_end) != view.crc32) return Error::kImageBadCrc;
  if (LoadLe16(data + header::kFlagsOffset) != 0 || LoadLe32(data + header::kReservedOffset) != 0) {
    return Error::kImageReservedNotZero;
  }
  view.version_minor = data[header::kVersionMinorOffset];
  view.table_id = LoadLe32(data + header::kTableIdOffset);
  const uint16_t section_count = LoadLe16(data + header::kSectionCountOffset);
  if (section_count == 0 || section_count > kMaxSections) return Error::kImageBadSectionCount;

  // Pass 1: walk the section headers, find AXES. Pass 2: parse the others against it.
  struct Span {
    uint16_t type;
    uint16_t flags;
    uint32_t offset;
    uint32_t length;
  } spans[kMaxSections];
  uint32_t pos = kHeaderSize;
  int axes_index = -1;
  for (uint16_t i = 0; i < section_count; ++i) {
    if (body_end - pos < kSectionHeaderSize) return Error::kSectionTruncated;
    Span& s = spans[i];
    s.type = LoadLe16(data + pos + section::kTypeOffset);
    s.flags = LoadLe16(data + pos + section::kFlagsOffset);
    s.length = LoadLe32(data + pos + section::kLengthOffset);
    s.offset = pos + kSectionHeaderSize;
    if ((s.flags & ~section::kFlagOptional) != 0) return Error::kImageReservedNotZero;
    if ((s.length & 3u) != 0) return Error::kSectionBadLength;
    if (s.length > body_end - s.offset) return Error::kSectionTruncated;
    pos = s.offset + s.length;
    if (s.type == static_cast<uint16_t>(SectionType::kAxes)) {
      if (axes_index >= 0) return Error::kSectionDuplicate;
      axes_index = i;
    }
  }
  if (pos != body_end) return Error::kImageTrailingBytes;
  if (axes_index < 0) return Error::kAxesMissing;
  VOLCOMP_TRY(ParseAxes(data + spans[axes_index].offset, spans[axes_index].length, &view));

  for (uint16_t i = 0; i < section_count; ++i) {
    const Span& s = spans[i];
    const uint8_t* body = data + s.offset;
    switch (static_cast<SectionType>(s.type)) {
      case SectionType::kAxes:
        break;
      case SectionType::kGrid3:
        if (view.grid.present) return Error::kSectionDuplicate;
        VOLCOMP_TRY(ParseGrid3(body, s.length, &view));
        break;
      case SectionType::kAxis1d:
        VOLCOMP_TRY(ParseAxis1d(body, s.length, &view));
        break;
      case SectionType::kInfo:
        if (view.info != nullptr) return Error::kSectionDuplicate;
        VOLCOMP_TRY(ParseInfo(body, s.length, &view));
        break;
      case SectionType::kThermal:
        if (view.thermal != nullptr) return Error::kSectionDuplicate;
        VOLCOMP_TRY(ParseThermal(body, s.length, &view));
        break;
      default:
        if ((s.flags & section::kFlagOptional) == 0) return Error::kSectionUnknown;
        break;
    }
  }
  if (!view.grid.present && view.axis1d_count == 0 && view.thermal == nullptr) {
    return Error::kImageNoCorrection;
  }
  return view;
}

double ElementSteps(const uint8_t* array, ElementType type, uint8_t frac_bits, uint32_t index) {
  const double scale = 1.0 / static_cast<double>(1u << frac_bits);
  switch (type) {
    case ElementType::kInt16:
      return static_cast<int16_t>(LoadLe16(array + 2u * index)) * scale;
    case ElementType::kInt32:
      return LoadLeI32(array + 4u * index) * scale;
    case ElementType::kFloat32:
      return static_cast<double>(LoadLeF32(array + 4u * index));
  }
  return 0.0;
}

}  // namespace volcomp::table
