// Power-loss-safe A/B blob store on NOR flash.
#include "volcomp/firmware/dual_bank_store.hpp"

#include "volcomp/base/byte_order.hpp"
#include "volcomp/base/crc32.hpp"

namespace volcomp::firmware {
namespace {
constexpr uint32_t kCommitMagic = 0x4D4D4F43;   // "COMM"
constexpr uint32_t kRevokeMagic = 0x4B564552;   // "REVK"
constexpr uint32_t kDiscardMagic = 0x43534944;  // "DISC": the staged blob was cleared or failed
constexpr uint32_t kCommitFromEnd = 64;
constexpr uint32_t kRevokeFromEnd = 32;

uint32_t CheckWord(uint32_t magic, uint32_t seq, uint32_t size, uint32_t crc) {
  return ~(magic ^ (seq * 0x9E3779B1u) ^ (size * 5u) ^ (crc * 3u));
}
}  // namespace

Status DualBankStore::Init(hal::Flash* flash,
                           uint32_t bank_size,
                           uint8_t* buffer,
                           uint32_t buffer_bytes) {
  flash_ = flash;
  bank_size_ = bank_size;
  sector_ = flash->sector_size();
  unit_ = flash->program_unit();
  buffer_ = buffer;
  buffer_bytes_ = buffer_bytes;
  if (sector_ == 0 || bank_size % sector_ != 0 || 2ull * bank_size > flash->size() || unit_ == 0 ||
      unit_ > kMaxProgramUnit || 32 % unit_ != 0 || bank_size < 2 * kRecordBytes ||
      sector_ < kRecordBytes || buffer == nullptr || buffer_bytes == 0 ||
      buffer_bytes % unit_ != 0) {
    return Error::kInvalidArgument;
  }
  committed_ = staging_ = -1;
  staging_open_ = staged_complete_ = staging_records_blank_ = false;
  staged_size_ = 0;
  return Status::Ok();
}

bool DualBankStore::ReadRecord(int bank, uint32_t offset_in_bank, uint32_t magic, Record* r) const {
  const uint8_t* p = flash_->Map(BankBase(bank) + offset_in_bank);
  r->magic = LoadLe32(p);
  r->sequence = LoadLe32(p + 4);
  r->size = LoadLe32(p + 8);
  r->crc32 = LoadLe32(p + 12);
  return r->magic == magic &&
         LoadLe32(p + 16) == CheckWord(r->magic, r->sequence, r->size, r->crc32);
}

bool DualBankStore::RecordsBlank(int bank) const {
  const uint8_t* p = flash_->Map(BankBase(bank) + bank_size_ - kRecordBytes);
  for (uint32_t i = 0; i < kRecordBytes; ++i) {
    if (p[i] != 0xFF) return false;
  }
  return true;
}

Status DualBankStore::ProgramRecord(int bank, uint32_t offset_in_bank, const Record& r) {
  uint8_t rec[32] = {};
  StoreLe32(rec, r.magic);
  StoreLe32(rec + 4, r.sequence);
  StoreLe32(rec + 8, r.size);
  StoreLe32(rec + 12, r.crc32);
  StoreLe32(rec + 16, CheckWord(r.magic, r.sequence, r.size, r.crc32));
  if (!flash_->Program(BankBase(bank) + offset_in_bank, rec, 32).ok()) return Error::kIoError;
  return Status::Ok();
}

void DualBankStore::Mount() {
  committed_ = -1;
  committed_size_ = committed_crc_ = 0;
  highest_seq_ = 0;
  int best = -1;
  Record best_rec{};
  for (int b = 0; b < 2; ++b) {
    Record r;
    if (!ReadRecord(b, bank_size_ - kCommitFromEnd, kCommitMagic, &r)) continue;
    if (r.sequence > highest_seq_) highest_seq_ = r.sequence;
    if (best < 0 || r.sequence > best_rec.sequence) {
      best = b;
      best_rec = r;
    }
  }
  if (best < 0) return;
  Record rv;
  if (ReadRecord(best, bank_size_ - kRevokeFromEnd, kRevokeMagic, &rv) &&
      rv.sequence == best_rec.sequence) {
    return;  // the newest commit was revoked
  }
  if (best_rec.size > capacity() ||
      ComputeCrc32(flash_->Map(BankBase(best)), best_rec.size) != best_rec.crc32) {
    return;  // damaged: nothing committed rather than an older blob
  }
  committed_ = best;
  committed_seq_ = best_rec.sequence;
  committed_size_ = best_rec.size;
  committed_crc_ = best_rec.crc32;
}

const uint8_t* DualBankStore::committed_data() const {
  return committed_ < 0 ? nullptr : flash_->Map(BankBase(committed_));
}

const uint8_t* DualBankStore::staged_data() const {
  return staging_ < 0 ? nullptr : flash_->Map(BankBase(staging_));
}

Status DualBankStore::EraseNextSector() {
  const uint32_t record_sector = bank_size_ - sector_;  // erased by BeginStaging
  if (erased_until_ != record_sector && !flash_->Erase(BankBase(staging_) + erased_until_).ok()) {
    return Error::kIoError;
  }
  erased_until_ += sector_;
  return Status::Ok();
}

Status DualBankStore::EnsureErased(uint32_t bank_offset_end) {
  while (erased_until_ < bank_offset_end) VOLCOMP_TRY(EraseNextSector());
  return Status::Ok();
}

Status DualBankStore::BeginStaging() {
  staging_open_ = staged_complete_ = staging_records_blank_ = false;
  staging_ = StagingBank();
  staged_size_ = 0;
  buffer_len_ = flushed_ = 0;
  erased_until_ = 0;
  if (!flash_->Erase(BankBase(staging_) + bank_size_ - sector_).ok()) return Error::kIoError;
  staging_records_blank_ = true;
  // The first sector now, so whatever blob was in the bank is gone before the bank looks staged.
  VOLCOMP_TRY(EnsureErased(1));
  staging_open_ = true;
  return Status::Ok();
}

void DualBankStore::DiscardStaging() {
  staging_open_ = staged_complete_ = false;
  if (staging_ < 0 || !staging_records_blank_) return;
  staging_records_blank_ = false;
  const Record r{kDiscardMagic, 0, 0, 0};
  (void)ProgramRecord(staging_, bank_size_ - kRevokeFromEnd, r);
}

const uint8_t* DualBankStore::MountStaging() const {
  const int bank = StagingBank();
  return RecordsBlank(bank) ? flash_->Map(BankBase(bank)) : nullptr;
}

Status DualBankStore::AdoptStaging(uint32_t size) {
  if (MountStaging() == nullptr) return Error::kNotReady;
  if (size > capacity()) return Error::kImageTooLarge;
  staging_ = StagingBank();
  staged_size_ = size;
  staging_open_ = false;
  staged_complete_ = true;
  staging_records_blank_ = true;
  return Status::Ok();
}

Status DualBankStore::Append(const uint8_t* data, uint32_t size) {
  if (!staging_open_) return Error::kNotReady;
  if (size > capacity() - staged_size_) return Error::kImageTooLarge;
  for (uint32_t i = 0; i < size; ++i) {
    if (buffer_len_ == buffer_bytes_) VOLCOMP_TRY(FlushAll());  // nobody flushed in time
    buffer_[buffer_len_++] = data[i];
    ++staged_size_;
  }
  return Status::Ok();
}

Status DualBankStore::FlushStep(bool* done) {
  *done = false;
  if (!staging_open_) return Error::kNotReady;
  const uint32_t whole = buffer_len_ / unit_ * unit_;
  const uint32_t base = staged_size_ - buffer_len_;  // bank offset of buffer_[0]
  if (flushed_ < whole) {
    if (erased_until_ < base + flushed_ + unit_) {
      if (!EraseNextSector().ok()) {
        staging_open_ = false;
        return Error::kIoError;
      }
      return Status::Ok();  // one erase is a step
    }
    for (uint32_t n = 0; n < kUnitsPerFlushStep && flushed_ < whole; ++n) {
      const uint32_t at = base + flushed_;
      if (at + unit_ > erased_until_) return Status::Ok();  // the next sector first
      if (!flash_->Program(BankBase(staging_) + at, buffer_ + flushed_, unit_).ok()) {
        staging_open_ = false;
        return Error::kIoError;
      }
      flushed_ += unit_;
    }
    if (flushed_ < whole) return Status::Ok();
  }
  // Everything whole is programmed: the partial unit moves to the front.
  for (uint32_t i = flushed_; i < buffer_len_; ++i) buffer_[i - flushed_] = buffer_[i];
  buffer_len_ -= flushed_;
  flushed_ = 0;
  *done = true;
  return Status::Ok();
}

Status DualBankStore::FlushAll() {
  for (bool done = false; !done;) VOLCOMP_TRY(FlushStep(&done));
  return Status::Ok();
}

Status DualBankStore::FinishStaging() {
  if (!staging_open_) return Error::kNotReady;
  VOLCOMP_TRY(FlushAll());
  if (buffer_len_ > 0) {
    for (uint32_t i = buffer_len_; i < unit_; ++i) buffer_[i] = 0xFF;
    const uint32_t at = staged_size_ - buffer_len_;
    const Status s = EnsureErased(at + unit_);
    if (!s.ok() || !flash_->Program(BankBase(staging_) + at, buffer_, unit_).ok()) {
      staging_open_ = false;
      return Error::kIoError;
    }
    buffer_len_ = 0;
  }
  staging_open_ = false;
  staged_complete_ = true;
  return Status::Ok();
}

Status DualBankStore::Commit() {
  if (!staged_complete_ || staging_ < 0) return Error::kNotReady;
  const uint32_t crc32 = ComputeCrc32(flash_->Map(BankBase(staging_)), staged_size_);
  const Record r{kCommitMagic, highest_seq_ + 1, staged_size_, crc32};
  VOLCOMP_TRY(ProgramRecord(staging_, bank_size_ - kCommitFromEnd, r));
  committed_ = staging_;
  staging_records_blank_ = false;
  committed_seq_ = highest_seq_ = r.sequence;
  committed_crc_ = crc32;
  committed_size_ = staged_size_;
  staging_ = -1;
  staged_complete_ = false;
  return Status::Ok();
}

Status DualBankStore::Revoke() {
  if (committed_ < 0) return Status::Ok();
  const Record r{kRevokeMagic, committed_seq_, 0, 0};
  VOLCOMP_TRY(ProgramRecord(committed_, bank_size_ - kRevokeFromEnd, r));
  committed_ = -1;
  committed_size_ = committed_crc_ = 0;
  return Status::Ok();
}

}  // namespace volcomp::firmware
