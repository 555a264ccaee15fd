// Exact on-wire length of a classic CAN frame (ISO 11898-1 bit layout, CRC-15, bit stuffing).
#include "volcomp/can/can_frame.hpp"

namespace volcomp {
namespace {

// Walks the stuffed region (SOF .. end of the CRC sequence) bit by bit: feeds the CRC-15 with the
// bits before the CRC field and counts the stuff bits the transmitter inserts (a bit of opposite
// polarity after five equal bits; the stuff bit itself starts the next run).
class StuffCounter {
 public:
  // Appends the `count` low bits of `value`, most significant first, to the CRC-covered part.
  void Field(uint32_t value, unsigned count) {
    for (unsigned i = count; i-- > 0;) {
      const bool bit = ((value >> i) & 1u) != 0;
      const bool crc_next = bit != ((crc_ >> 14) & 1u);
      crc_ = static_cast<uint16_t>((crc_ << 1) & 0x7FFFu);
      if (crc_next) crc_ = static_cast<uint16_t>(crc_ ^ 0x4599u);
      Emit(bit);
    }
  }
  // Appends the CRC sequence (not fed to the CRC itself).
  void Crc() {
    const uint16_t crc = crc_;
    for (unsigned i = 15; i-- > 0;) Emit(((crc >> i) & 1u) != 0);
  }
  uint32_t bits() const { return bits_; }
  uint32_t stuff_bits() const { return stuff_; }

 private:
  void Emit(bool bit) {
    ++bits_;
    if (run_ > 0 && bit == last_) {
      ++run_;
    } else {
      last_ = bit;
      run_ = 1;
    }
    if (run_ == 5) {  // stuff bit of opposite polarity, which starts a new run of length 1
      ++stuff_;
      last_ = !bit;
      run_ = 1;
    }
  }

  uint16_t crc_ = 0;
  uint32_t bits_ = 0;
  uint32_t stuff_ = 0;
  unsigned run_ = 0;
  bool last_ = false;
};

// CRC delimiter (1) + ACK slot (1) + ACK delimiter (1) + EOF (7) + intermission (3).
constexpr uint32_t kTrailerBits = 13;

}  // namespace

uint32_t CanFrameBits(const CanFrame& frame) {
  const unsigned dlc = frame.dlc > 8 ? 8u : frame.dlc;  // DLC 9..15 still carry 8 data bytes
  const uint32_t rtr = frame.rtr ? 1u : 0u;
  StuffCounter s;
  s.Field(0, 1);  // SOF (dominant)
  if (frame.extended) {
    const uint32_t id = frame.id & 0x1FFFFFFFu;
    s.Field(id >> 18, 11);       // base identifier
    s.Field(1, 1);               // SRR (recessive)
    s.Field(1, 1);               // IDE (recessive: extended)
    s.Field(id & 0x3FFFFu, 18);  // identifier extension
    s.Field(rtr, 1);             // RTR
    s.Field(0, 2);               // r1, r0
  } else {
    s.Field(frame.id & 0x7FFu, 11);
    s.Field(rtr, 1);  // RTR
    s.Field(0, 2);    // IDE (dominant: standard), r0
  }
  s.Field(frame.dlc & 0xFu, 4);
  if (!frame.rtr) {
    for (unsigned i = 0; i < dlc; ++i) s.Field(frame.data[i], 8);
  }
  s.Crc();
  return s.bits() + s.stuff_bits() + kTrailerBits;
}

}  // namespace volcomp
