// Table staging and activation on the dual-bank store.
#include "volcomp/firmware/table_store.hpp"

namespace volcomp::firmware {

Status TableStore::Init(hal::Flash* flash, uint32_t bank_size) {
  state_ = StagedState::kEmpty;
  expected_size_ = staged_crc_ = staged_id_ = 0;
  last_error_ = Error::kOk;
  return bank_.Init(flash, bank_size, buffer_, sizeof buffer_);
}

Result<table::TableView> TableStore::MountActive(const BoardConfig& config) {
  bank_.Mount();
  MountStaged(config);
  if (!bank_.has_committed()) return Error::kNotFound;
  const Result<table::TableView> v =
      table::ParseImage(bank_.committed_data(), bank_.committed_size());
  if (!v.ok()) return v;
  VOLCOMP_TRY(CheckImageMatchesBoard(*v, config));
  return v;
}

void TableStore::MountStaged(const BoardConfig& config) {
  state_ = StagedState::kEmpty;
  staged_crc_ = staged_id_ = 0;
  last_error_ = Error::kOk;
  const uint8_t* bytes = bank_.MountStaging();
  if (bytes == nullptr) return;
  // Verified again, as Verify() would: a staged image is only ever reported verified when it
  // passed these checks on this boot.
  const Result<uint32_t> size = table::PeekImageSize(bytes, bank_.capacity());
  if (!size.ok()) return;
  const Result<table::TableView> v = table::ParseImage(bytes, *size);
  if (!v.ok() || !CheckImageMatchesBoard(*v, config).ok()) return;
  if (!bank_.AdoptStaging(*size).ok()) return;
  staged_crc_ = v->crc32;
  staged_id_ = v->table_id;
  state_ = StagedState::kVerified;
}

Status TableStore::Fail(Error e) {
  last_error_ = e;
  state_ = StagedState::kFailed;
  staged_crc_ = staged_id_ = 0;
  bank_.DiscardStaging();
  return e;
}

Status TableStore::BeginUpload(uint32_t size) {
  if (size > bank_.capacity()) return Fail(Error::kImageTooLarge);
  expected_size_ = size;
  staged_crc_ = staged_id_ = 0;
  last_error_ = Error::kOk;
  const Status s = bank_.BeginStaging();
  if (!s.ok()) return Fail(s.error());
  state_ = StagedState::kReceiving;
  return Status::Ok();
}

Status TableStore::UploadData(const uint8_t* data, uint32_t size) {
  if (state_ != StagedState::kReceiving) return Error::kNotReady;
  const Status s = bank_.Append(data, size);
  return s.ok() ? s : Fail(s.error());
}

Status TableStore::FlushUpload(bool* done) {
  *done = true;
  if (state_ != StagedState::kReceiving) return Error::kNotReady;
  const Status s = bank_.FlushStep(done);
  return s.ok() ? s : Fail(s.error());
}

Status TableStore::FinishUpload() {
  if (state_ != StagedState::kReceiving) return Error::kNotReady;
  if (expected_size_ != 0 && bank_.staged_size() != expected_size_) {
    return Fail(Error::kImageSizeMismatch);
  }
  const Status s = bank_.FinishStaging();
  if (!s.ok()) return Fail(s.error());
  state_ = StagedState::kComplete;
  return Status::Ok();
}

void TableStore::AbandonUpload(Error reason) {
  if (state_ == StagedState::kReceiving) Fail(reason).IgnoreError();
}

Status TableStore::Verify(const BoardConfig& config) {
  if (state_ == StagedState::kVerified) return Status::Ok();
  if (state_ != StagedState::kComplete) return Error::kNotReady;
  const Result<table::TableView> v = table::ParseImage(bank_.staged_data(), bank_.staged_size());
  if (!v.ok()) return Fail(v.error());
  const Status match = CheckImageMatchesBoard(*v, config);
  if (!match.ok()) return Fail(match.error());
  staged_crc_ = v->crc32;
  staged_id_ = v->table_id;
  state_ = StagedState::kVerified;
  return Status::Ok();
}

Result<table::TableView> TableStore::Activate() {
  if (state_ != StagedState::kVerified) return Error::kNotReady;
  const Status s = bank_.Commit();
  if (!s.ok()) return Fail(s.error());
  state_ = StagedState::kEmpty;
  staged_crc_ = staged_id_ = 0;
  return table::ParseImage(bank_.committed_data(), bank_.committed_size());
}

Status TableStore::Deactivate() { return bank_.Revoke(); }

void TableStore::Clear() {
  bank_.DiscardStaging();
  state_ = StagedState::kEmpty;
  expected_size_ = staged_crc_ = staged_id_ = 0;
  last_error_ = Error::kOk;
}

}  // namespace volcomp::firmware
