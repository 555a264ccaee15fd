// Table image writer: layout, element encoding, CRC, then validation by the real parser.
#include "volcomp/table/table_writer.hpp"

#include "volcomp/base/byte_order.hpp"
#include "volcomp/base/crc32.hpp"

namespace volcomp::table {
namespace {

uint32_t Pad4(uint32_t n) { return (n + 3u) & ~3u; }

uint64_t GridElements(const GridSpec& g) {
  return static_cast<uint64_t>(g.dim[0].nodes) * g.dim[1].nodes * g.dim[2].nodes * 3u;
}

uint64_t GridBodySize(const GridSpec& g) {
  return grid3::kDataOffset + ((GridElements(g) * ElementSize(g.values.type) + 3u) & ~uint64_t{3});
}

uint64_t Axis1dBodySize(const Axis1dSpec& a) {
  const uint64_t one = static_cast<uint64_t>(a.dim.nodes) * ElementSize(a.forward.type);
  return axis1d::kDataOffset + ((one * (a.has_reverse ? 2u : 1u) + 3u) & ~uint64_t{3});
}

bool ArrayPresent(const ElementArray& a) {
  switch (a.type) {
    case ElementType::kInt16:
      return a.i16 != nullptr;
    case ElementType::kInt32:
      return a.i32 != nullptr;
    case ElementType::kFloat32:
      return a.f32 != nullptr;
  }
  return false;
}

uint8_t* WriteArray(uint8_t* p, const ElementArray& a, uint64_t count) {
  for (uint64_t i = 0; i < count; ++i) {
    switch (a.type) {
      case ElementType::kInt16:
        StoreLe16(p, static_cast<uint16_t>(a.i16[i]));
        p += 2;
        break;
      case ElementType::kInt32:
        StoreLe32(p, static_cast<uint32_t>(a.i32[i]));
        p += 4;
        break;
      case ElementType::kFloat32:
        StoreLeF32(p, a.f32[i]);
        p += 4;
        break;
    }
  }
  return p;
}

uint32_t ThermalBodySize(const thermal::ThermalModel& m) {
  return thermal_section::kAxisRecordsOffset + m.axis_count * thermal_section::kAxisRecordSize;
}

void WriteThermal(uint8_t* p, const thermal::ThermalModel& m) {
  namespace ts = thermal_section;
  p[ts::kVersionOffset] = ts::kVersion;
  p[ts::kAxisCountOffset] = m.axis_count;
  p[ts::kChannelMaskOffset] = m.channel_mask;
  StoreLeF32(p + ts::kSlewOffset, m.slew_um_s);
  StoreLe32(p + ts::kHoldOffset, m.hold_ms);
  for (uint32_t j = 0; j < ts::kChannels; ++j) {
    StoreLe16(p + ts::kReferenceOffset + 2 * j, static_cast<uint16_t>(m.reference_cC[j]));
    StoreLe16(p + ts::kCalibratedLowOffset + 2 * j, static_cast<uint16_t>(m.calibrated_low_cC[j]));
    StoreLe16(p + ts::kCalibratedHighOffset + 2 * j,
              static_cast<uint16_t>(m.calibrated_high_cC[j]));
  }
  for (uint8_t a = 0; a < m.axis_count; ++a) {
    uint8_t* r = p + ts::kAxisRecordsOffset + a * ts::kAxisRecordSize;
    const thermal::AxisModel& x = m.axis[a];
    StoreLeF32(r + ts::kP0Offset, x.p0_mm);
    StoreLeF32(r + ts::kReachOffset, x.reach_mm);
    for (uint32_t j = 0; j < ts::kChannels; ++j) {
      StoreLeF32(r + ts::kOffsetCoefficientsOffset + 4 * j, x.offset_um_per_K[j]);
      StoreLeF32(r + ts::kSlopeCoefficientsOffset + 4 * j, x.slope_um_per_K_m[j]);
    }
  }
}

uint8_t* WriteSectionHeader(uint8_t* p, SectionType type, uint32_t length) {
  StoreLe16(p + section::kTypeOffset, static_cast<uint16_t>(type));
  StoreLe16(p + section::kFlagsOffset, type == SectionType::kInfo ? section::kFlagOptional : 0);
  StoreLe32(p + section::kLengthOffset, length);
  return p + kSectionHeaderSize;
}

}  // namespace

Result<uint32_t> ImageSize(const ImageSpec& spec) {
  if (spec.axis_count < 1 || spec.axis_count > kMaxAxes || spec.axis1d_count > kMaxAxes) {
    return Error::kWriterBadArgument;
  }
  uint64_t size = kHeaderSize + kTrailerSize + kSectionHeaderSize + axes::kRecordsOffset +
                  spec.axis_count * axes::kRecordSize;
  if (spec.grid != nullptr) {
    if (!ArrayPresent(spec.grid->values)) return Error::kWriterBadArgument;
    size += kSectionHeaderSize + GridBodySize(*spec.grid);
  }
  for (uint8_t i = 0; i < spec.axis1d_count; ++i) {
    const Axis1dSpec& a = spec.axis1d[i];
    if (!ArrayPresent(a.forward) ||
        (a.has_reverse && (!ArrayPresent(a.reverse) || a.reverse.type != a.forward.type))) {
      return Error::kWriterBadArgument;
    }
    size += kSectionHeaderSize + Axis1dBodySize(a);
  }
  if (spec.info != nullptr) {
    if (spec.info_size > kMaxInfoBytes - 3u) return Error::kWriterBadArgument;
    size += kSectionHeaderSize + Pad4(spec.info_size);
  }
  if (spec.thermal != nullptr) {
    if (spec.thermal->axis_count != spec.axis_count) return Error::kWriterBadArgument;
    size += kSectionHeaderSize + ThermalBodySize(*spec.thermal);
  }
  if (size > kMaxImageSize) return Error::kImageTooLarge;
  return static_cast<uint32_t>(size);
}

Result<uint32_t> WriteImage(const ImageSpec& spec, uint8_t* out, size_t capacity) {
  const Result<uint32_t> size = ImageSize(spec);
  if (!size.ok()) return size;
  if (capacity < *size) return Error::kWriterBufferTooSmall;
  if ((reinterpret_cast<uintptr_t>(out) & 3u) != 0) return Error::kImageMisaligned;
  __builtin_memset(out, 0, *size);

  StoreLe32(out + header::kMagicOffset, kMagic);
  out[header::kVersionMajorOffset] = kVersionMajor;
  out[header::kVersionMinorOffset] = spec.thermal ? kVersionMinorThermal : kVersionMinor;
  StoreLe16(out + header::kHeaderSizeOffset, kHeaderSize);
  StoreLe32(out + header::kImageSizeOffset, *size);
  StoreLe32(out + header::kTableIdOffset, spec.table_id);
  const uint16_t sections =
      static_cast<uint16_t>(1u + (spec.grid != nullptr ? 1u : 0u) + spec.axis1d_count +
                            (spec.info ? 1u : 0u) + (spec.thermal ? 1u : 0u));
  StoreLe16(out + header::kSectionCountOffset, sections);
  uint8_t* p = out + kHeaderSize;

  p = WriteSectionHeader(p, SectionType::kAxes,
                         axes::kRecordsOffset + spec.axis_count * axes::kRecordSize);
  p[axes::kCountOffset] = spec.axis_count;
  p += axes::kRecordsOffset;
  for (uint8_t i = 0; i < spec.axis_count; ++i, p += axes::kRecordSize) {
    p[axes::kNameOffset] = static_cast<uint8_t>(spec.axes[i].name);
    p[axes::kKindOffset] = static_cast<uint8_t>(spec.axes[i].kind);
    StoreLe32(p + axes::kResolutionOffset, spec.axes[i].resolution_e9);
  }

  if (spec.grid != nullptr) {
    const GridSpec& g = *spec.grid;
    const uint32_t body = static_cast<uint32_t>(GridBodySize(g));
    p = WriteSectionHeader(p, SectionType::kGrid3, body);
    p[grid3::kElementTypeOffset] = static_cast<uint8_t>(g.values.type);
    p[grid3::kFracBitsOffset] = g.frac_bits;
    for (int d = 0; d < 3; ++d) {
      p[grid3::kAxisOffset + d] = g.axis[d];
      StoreLe32(p + grid3::kNodesOffset + 4 * d, g.dim[d].nodes);
      StoreLe32(p + grid3::kOriginOffset + 4 * d, static_cast<uint32_t>(g.dim[d].origin_steps));
      StoreLe32(p + grid3::kSpacingOffset + 4 * d, g.dim[d].spacing_steps);
    }
    WriteArray(p + grid3::kDataOffset, g.values, GridElements(g));
    p += body;
  }

  for (uint8_t i = 0; i < spec.axis1d_count; ++i) {
    const Axis1dSpec& a = spec.axis1d[i];
    const uint32_t body = static_cast<uint32_t>(Axis1dBodySize(a));
    p = WriteSectionHeader(p, SectionType::kAxis1d, body);
    p[axis1d::kAxisOffset] = a.axis;
    p[axis1d::kElementTypeOffset] = static_cast<uint8_t>(a.forward.type);
    p[axis1d::kFracBitsOffset] = a.frac_bits;
    p[axis1d::kFlagsOffset] = static_cast<uint8_t>((a.has_reverse ? axis1d::kFlagReverse : 0) |
                                                   (a.period_steps ? axis1d::kFlagWrap : 0));
    StoreLe32(p + axis1d::kNodesOffset, a.dim.nodes);
    StoreLe32(p + axis1d::kOriginOffset, static_cast<uint32_t>(a.dim.origin_steps));
    StoreLe32(p + axis1d::kSpacingOffset, a.dim.spacing_steps);
    StoreLe32(p + axis1d::kPeriodOffset, a.period_steps);
    StoreLe32(p + axis1d::kBacklashOffset, static_cast<uint32_t>(a.backlash_q8));
    uint8_t* q = WriteArray(p + axis1d::kDataOffset, a.forward, a.dim.nodes);
    if (a.has_reverse) WriteArray(q, a.reverse, a.dim.nodes);
    p += body;
  }

  if (spec.info != nullptr) {
    p = WriteSectionHeader(p, SectionType::kInfo, Pad4(spec.info_size));
    __builtin_memcpy(p, spec.info, spec.info_size);
    p += Pad4(spec.info_size);
  }

  if (spec.thermal != nullptr) {
    const uint32_t body = ThermalBodySize(*spec.thermal);
    p = WriteSectionHeader(p, SectionType::kThermal, body);
    WriteThermal(p, *spec.thermal);
    p += body;
  }

  const uint32_t body_end = *size - kTrailerSize;
  StoreLe32(out + body_end, ComputeCrc32(out, body_end));
  const Result<TableView> check = ParseImage(out, *size);
  if (!check.ok()) return check.status();
  return size;
}

}  // namespace volcomp::table
