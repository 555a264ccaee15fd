// The table image format: the one definition of its offsets, types and limits, shared by firmware,
// simulator, PC tool and docs/table-image-format.md (the byte-level description: where the two
// disagree, this header is right). A little-endian image: header | sections | CRC-32 trailer.
// Units: positions in input steps of their axis; an element v with `frac_bits` f is v * 2^-f steps
// (float32 elements are steps, f = 0).
#pragma once

#include <cstddef>
#include <cstdint>

namespace volcomp::table {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "volcomp assumes a little-endian CPU");

// ---- Header --------------------------------------------------------------------------------
inline constexpr uint32_t kMagic = 0x42544356u;     // "VCTB" as bytes 'V','C','T','B'
inline constexpr uint8_t kVersionMajor = 1;         // incompatible changes bump this
inline constexpr uint8_t kVersionMinor = 0;         // an image of sections minor 0 knows
inline constexpr uint8_t kVersionMinorThermal = 1;  // an image with a THERMAL section
inline constexpr uint32_t kHeaderSize = 24;
inline constexpr uint32_t kTrailerSize = 4;  // CRC-32
inline constexpr uint32_t kMaxImageSize = 4u * 1024u * 1024u;
inline constexpr uint32_t kMaxSections = 16;

namespace header {
inline constexpr uint32_t kMagicOffset = 0;          // u32 kMagic
inline constexpr uint32_t kVersionMajorOffset = 4;   // u8
inline constexpr uint32_t kVersionMinorOffset = 5;   // u8
inline constexpr uint32_t kHeaderSizeOffset = 6;     // u16 = kHeaderSize
inline constexpr uint32_t kImageSizeOffset = 8;      // u32 total bytes incl. header and trailer
inline constexpr uint32_t kTableIdOffset = 12;       // u32 user-chosen table id
inline constexpr uint32_t kSectionCountOffset = 16;  // u16 1..kMaxSections
inline constexpr uint32_t kFlagsOffset = 18;         // u16 reserved, 0
inline constexpr uint32_t kReservedOffset = 20;      // u32 reserved, 0
}  // namespace header

// ---- Sections ------------------------------------------------------------------------------
inline constexpr uint32_t kSectionHeaderSize = 8;
namespace section {
inline constexpr uint32_t kTypeOffset = 0;    // u16 SectionType
inline constexpr uint32_t kFlagsOffset = 2;   // u16 bit 0 = optional (unknown types may be skipped)
inline constexpr uint32_t kLengthOffset = 4;  // u32 body length in bytes, multiple of 4
inline constexpr uint16_t kFlagOptional = 0x0001;
}  // namespace section

enum class SectionType : uint16_t {
  kAxes = 1,     // axis configuration: once, mandatory
  kGrid3 = 2,    // volumetric grid: at most once
  kAxis1d = 3,   // per-axis table: at most once per axis
  kInfo = 4,     // UTF-8 "key=value\n" text for people: at most once, optional
  kThermal = 5,  // the thermal model (lib/thermal thermal_model.hpp): at most once, mandatory
};

enum class ElementType : uint8_t { kInt16 = 1, kInt32 = 2, kFloat32 = 3 };
enum class AxisKind : uint8_t { kLinear = 0, kRotary = 1 };

/// Size in bytes of one element.
constexpr uint32_t ElementSize(ElementType t) { return t == ElementType::kInt16 ? 2u : 4u; }
/// The element type's name in docs/table-image-format.md and the tools ("int16", "int32",
/// "float32"; "?" for a value outside the enum).
constexpr const char* ElementTypeName(ElementType t) {
  switch (t) {
    case ElementType::kInt16:
      return "int16";
    case ElementType::kInt32:
      return "int32";
    case ElementType::kFloat32:
      return "float32";
  }
  return "?";
}

inline constexpr uint32_t kMaxAxes = 6;
/// Axis names a table may use (ISO 841 letters).
inline constexpr char kAxisNames[] = "XYZABCUVW";

// AXES body: u8 axis_count, 3 bytes reserved, then axis_count records of kAxisRecordSize.
namespace axes {
inline constexpr uint32_t kCountOffset = 0;
inline constexpr uint32_t kRecordsOffset = 4;
inline constexpr uint32_t kRecordSize = 8;
inline constexpr uint32_t kNameOffset = 0;        // u8 ASCII letter from kAxisNames
inline constexpr uint32_t kKindOffset = 1;        // u8 AxisKind
inline constexpr uint32_t kReservedOffset = 2;    // u16 0
inline constexpr uint32_t kResolutionOffset = 4;  // u32 units per step x 1e9 (pm or ndeg), > 0
}  // namespace axes

// GRID3 body: a 3-D lattice of 3-component correction vectors.
namespace grid3 {
inline constexpr uint32_t kElementTypeOffset = 0;  // u8 ElementType
inline constexpr uint32_t kFracBitsOffset = 1;     // u8
inline constexpr uint32_t kAxisOffset = 2;         // u8[3] axis index of dimension/component 0..2
inline constexpr uint32_t kReservedOffset = 5;     // u8[3] 0
inline constexpr uint32_t kNodesOffset = 8;        // u32[3] node count per dimension
inline constexpr uint32_t kOriginOffset = 20;      // i32[3] position of node 0, steps
inline constexpr uint32_t kSpacingOffset = 32;     // u32[3] node spacing, steps
inline constexpr uint32_t kDataOffset = 44;        // elements; padded to 4 bytes at the end
inline constexpr uint32_t kMinNodes = 2;
inline constexpr uint32_t kMaxNodes = 1024;
inline constexpr uint32_t kMaxTotalNodes = 1u << 20;
}  // namespace grid3

// AXIS1D body: forward table, optional reverse table, backlash, optional rotary wrap.
namespace axis1d {
inline constexpr uint32_t kAxisOffset = 0;         // u8 axis index
inline constexpr uint32_t kElementTypeOffset = 1;  // u8 ElementType
inline constexpr uint32_t kFracBitsOffset = 2;     // u8
inline constexpr uint32_t kFlagsOffset = 3;        // u8 kFlag*
inline constexpr uint32_t kNodesOffset = 4;        // u32 node count
inline constexpr uint32_t kOriginOffset = 8;       // i32 steps
inline constexpr uint32_t kSpacingOffset = 12;     // u32 steps
inline constexpr uint32_t kPeriodOffset = 16;      // u32 steps; 0 unless kFlagWrap
inline constexpr uint32_t kBacklashOffset = 20;    // i32 backlash in Q8 steps, added when reversing
inline constexpr uint32_t kDataOffset = 24;        // forward[n], then reverse[n] if kFlagReverse
inline constexpr uint8_t kFlagReverse = 0x01;      // a separate table for negative motion
inline constexpr uint8_t kFlagWrap = 0x02;         // rotary: position taken modulo the period
inline constexpr uint8_t kKnownFlags = kFlagReverse | kFlagWrap;
inline constexpr uint32_t kMinNodes = 2;
inline constexpr uint32_t kMaxNodes = 65535;
}  // namespace axis1d

inline constexpr uint32_t kMaxInfoBytes = 4096;

// THERMAL body (version 1): the thermal model of thermal::ThermalModel in physical units (um,
// mm, cC: the coefficients are what a user reads and the builder fits; the board converts them
// with the AXES resolution). 8 channels (thermal::kMaxChannels), one record per image axis.
namespace thermal_section {
inline constexpr uint8_t kVersion = 1;
inline constexpr uint32_t kVersionOffset = 0;          // u8 kVersion
inline constexpr uint32_t kAxisCountOffset = 1;        // u8 = the AXES count
inline constexpr uint32_t kChannelMaskOffset = 2;      // u8 channels the model uses
inline constexpr uint32_t kReservedOffset = 3;         // u8 0
inline constexpr uint32_t kSlewOffset = 4;             // f32 um/s
inline constexpr uint32_t kHoldOffset = 8;             // u32 ms
inline constexpr uint32_t kReferenceOffset = 12;       // i16[8] cC
inline constexpr uint32_t kCalibratedLowOffset = 28;   // i16[8] cC
inline constexpr uint32_t kCalibratedHighOffset = 44;  // i16[8] cC
inline constexpr uint32_t kAxisRecordsOffset = 60;
inline constexpr uint32_t kChannels = 8;
// Axis record: f32 p0_mm, f32 reach_mm, f32[8] offset um/K, f32[8] slope um/(K m).
inline constexpr uint32_t kP0Offset = 0;
inline constexpr uint32_t kReachOffset = 4;
inline constexpr uint32_t kOffsetCoefficientsOffset = 8;
inline constexpr uint32_t kSlopeCoefficientsOffset = 8 + 4 * kChannels;
inline constexpr uint32_t kAxisRecordSize = 8 + 8 * kChannels;
}  // namespace thermal_section

// ---- Value ranges --------------------------------------------------------------------------
/// Corrections leave the interpolators as Q24.8 steps (int32, 1/256 step).
inline constexpr int kCorrectionFracBits = 8;
/// Largest fraction bits an element may carry (finer than the Q8 output would be pointless).
inline constexpr uint8_t kMaxFracBits = 8;
/// Largest correction magnitude any table value may hold, in steps. Bounds the Q8 interpolation
/// error to < 1 LSB (see docs/table-image-format.md, "Accuracy").
inline constexpr int32_t kMaxCorrectionSteps = 65536;
inline constexpr int32_t kMaxCorrectionQ8 = kMaxCorrectionSteps << kCorrectionFracBits;
/// Largest grid/table extent (nodes-1)*spacing, in steps (2^31 - 1).
inline constexpr uint32_t kMaxExtentSteps = 0x7FFFFFFFu;

}  // namespace volcomp::table
