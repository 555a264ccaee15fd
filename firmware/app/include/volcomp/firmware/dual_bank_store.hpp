// Two banks of NOR flash holding one committed blob, switched atomically and safe against power
// loss at any flash operation.
//
// Layout of the region: bank 0 then bank 1, each `bank_size` bytes (a multiple of the sector size).
// The last 64 bytes of a bank hold two 32-byte records: COMMIT (magic, sequence, blob size, blob
// CRC-32, check word, zeros) and REVOKE (magic, sequence, zeros, check word, zeros). The blob
// starts at offset 0 of the bank and may use everything before the records.
//
// The committed blob is the bank whose COMMIT record is valid and has the highest sequence; if
// that bank is revoked or its bytes do not match the record's size and CRC-32, there is no
// committed blob (never a fall-back to an older one). Staging always writes the other bank, so the
// committed blob's bytes are never erased or programmed while it is committed; the switch is the
// single program operation of the COMMIT record, whose check word makes a partly programmed record
// invalid. Hence after a power loss at any point the store holds exactly the old or the new blob.
//
// Staging erases lazily: BeginStaging erases the record sector and the first sector (so an older
// blob left in the bank can never be taken for a staged one), then each further sector is erased
// just before the first byte is programmed into it.
//
// Appended bytes go to a RAM buffer the owner provides (Init); FlushStep() programs them in bounded
// steps
// (one sector erase, or up to kUnitsPerFlushStep program units), so the caller decides when the
// flash's busy time is spent (the CAN receive path: between sub-blocks, docs/mcu-target.md).
// Append() programs the buffer itself only when it is full (correct, but then the caller waits
// for the flash), FinishStaging() programs what is left.
//
// A staged blob survives a reset: the staging bank is the one that is not committed; while its
// records are blank (erased by BeginStaging, nothing committed or discarded since) its bytes from
// offset 0 are what was staged, and MountStaging() gives them back (the caller knows the blob's
// format, hence its size, and checks it before AdoptStaging()). DiscardStaging() (a cleared or
// failed staging) programs a DISCARD record into the staging bank's REVOKE slot, so the blob is
// not found again.
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/hal/flash.hpp"

namespace volcomp::firmware {

class DualBankStore {
 public:
  static constexpr uint32_t kRecordBytes = 64;
  static constexpr uint32_t kMaxProgramUnit = 16;
  static constexpr uint32_t kUnitsPerFlushStep = 8;

  /// Uses `flash` offsets [0, 2 * bank_size) and `buffer` (owned by the caller, alive as long as
  /// the store) for appended bytes not yet programmed. kInvalidArgument if the geometry does not
  /// fit or `buffer_bytes` is not a non-zero multiple of the flash's program unit.
  Status Init(hal::Flash* flash, uint32_t bank_size, uint8_t* buffer, uint32_t buffer_bytes);
  /// Finds the committed blob after power-up (reads only; checks the blob's CRC-32).
  void Mount();

  bool has_committed() const { return committed_ >= 0; }
  /// The committed blob in place (valid until the next Commit/Revoke); null if none.
  const uint8_t* committed_data() const;
  uint32_t committed_size() const { return committed_size_; }
  uint32_t committed_crc32() const { return committed_crc_; }
  uint32_t capacity() const { return bank_size_ - kRecordBytes; }

  // ---- Staging (into the bank that is not committed) ----
  /// Starts a new blob: erases the staging bank's record sector. kIoError on flash failure.
  Status BeginStaging();
  /// Appends bytes (into the RAM buffer; programs it first when it is full); kImageTooLarge past
  /// capacity(), kIoError on flash failure, kNotReady if no staging is open.
  Status Append(const uint8_t* data, uint32_t size);
  /// Bytes Append() takes between two complete flushes without programming flash itself.
  uint32_t append_window() const { return buffer_bytes_ - (unit_ - 1); }
  /// One bounded step of programming the buffer: one sector erase, or up to kUnitsPerFlushStep
  /// program units. `*done` = true when less than one program unit is left in the buffer.
  /// kIoError on flash failure (the staging is then closed), kNotReady if no staging is open.
  Status FlushStep(bool* done);
  /// Flushes the last partial program unit; the staged blob is then complete.
  Status FinishStaging();
  /// Marks the staging as abandoned (the bank content is ignored until the next BeginStaging) and
  /// persistently so (the DISCARD record; a flash failure there only leaves a blob that the
  /// caller's check at mount refuses, or that was valid). Its bytes stay readable until then.
  void DiscardStaging();
  /// After Mount(): the staging bank's bytes (capacity() of them) if it holds a staged blob that
  /// was neither committed nor discarded (its records are blank), else null.
  const uint8_t* MountStaging() const;
  /// Takes the first `size` bytes of MountStaging() as the complete staged blob (Commit() may
  /// follow). kNotReady if there is none, kImageTooLarge past capacity().
  Status AdoptStaging(uint32_t size);
  bool staging_open() const { return staging_open_; }
  bool staged_complete() const { return staged_complete_; }
  uint32_t staged_size() const { return staged_size_; }
  const uint8_t* staged_data() const;

  /// Commits the complete staged blob (the caller has validated its content): one program of the
  /// COMMIT record carrying its size and CRC-32. kNotReady if nothing complete is staged.
  Status Commit();
  /// Revokes the committed blob (program of its REVOKE record): afterwards nothing is committed.
  Status Revoke();

 private:
  struct Record {
    uint32_t magic, sequence, size, crc32;
  };
  bool ReadRecord(int bank, uint32_t offset_in_bank, uint32_t magic, Record* r) const;
  bool RecordsBlank(int bank) const;
  int StagingBank() const { return committed_ == 0 ? 1 : 0; }
  Status ProgramRecord(int bank, uint32_t offset_in_bank, const Record& r);
  Status EnsureErased(uint32_t bank_offset_end);
  Status EraseNextSector();
  Status FlushAll();
  uint32_t BankBase(int bank) const { return static_cast<uint32_t>(bank) * bank_size_; }

  hal::Flash* flash_ = nullptr;
  uint32_t bank_size_ = 0;
  uint32_t sector_ = 0;
  uint32_t unit_ = 8;

  int committed_ = -1;  // bank index or -1
  uint32_t committed_seq_ = 0;
  uint32_t committed_size_ = 0;
  uint32_t committed_crc_ = 0;
  uint32_t highest_seq_ = 0;

  int staging_ = -1;
  bool staging_open_ = false;
  bool staged_complete_ = false;
  bool staging_records_blank_ = false;  // the staging bank's REVOKE slot may still be programmed
  uint32_t staged_size_ = 0;
  uint32_t erased_until_ = 0;  // bytes of the staging bank known erased from offset 0
  // The last buffer_len_ staged bytes (bank offset staged_size_ - buffer_len_ at buffer_[0]); the
  // first flushed_ of them are programmed (whole units).
  uint8_t* buffer_ = nullptr;
  uint32_t buffer_bytes_ = 0;
  uint32_t buffer_len_ = 0;
  uint32_t flushed_ = 0;
};

}  // namespace volcomp::firmware
