// The board's compensation tables in flash: the active image and the staging of a new one, on a
// power-loss-safe DualBankStore.
//
// Upload: BeginUpload -> UploadData ... -> FinishUpload (complete) -> Verify (the firmware's image
// validation plus the board match) -> Activate (one atomic commit). Any failure along the way
// (AbandonUpload when the transfer broke) leaves the staged image unusable, says why in
// last_error(), and leaves the active image untouched. Deactivate revokes the active image
// (persistently: after a reset the board runs pass-through until a new activation).
//
// The staged image is in flash and survives a reset or power loss: MountActive() also mounts it
// and verifies it again (format, CRC-32, made for the board in force). If it passes it is staged
// and verified, with its id, CRC-32 and size, as before the reset; anything else in the staging
// bank (an interrupted, failed or cleared upload, an image not for this board) is forgotten:
// nothing staged, 0x2105-0x2107 read 0. The staged id, CRC-32 and size always describe what is
// staged now: 0 once it is cleared, activated or replaced.
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/firmware/dual_bank_store.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp::firmware {

/// The staging bank's state, as reported in 0x2102.
using canopen::StagedState;

class TableStore {
 public:
  Status Init(hal::Flash* flash, uint32_t bank_size);

  /// Power-up: mounts the banks and the staged image (see above); returns the active image if one
  /// is committed, intact and made for `config` (the error says why not otherwise: kNotFound when
  /// nothing is committed).
  Result<table::TableView> MountActive(const BoardConfig& config);

  /// Starts staging an image of `size` bytes (0 = not indicated). kImageTooLarge if it cannot
  /// fit; kIoError on a flash failure.
  Status BeginUpload(uint32_t size);
  Status UploadData(const uint8_t* data, uint32_t size);
  /// Bytes UploadData() buffers between two complete FlushUpload() runs without waiting for the
  /// flash (DualBankStore::append_window()); more is still taken, programmed on the spot.
  uint32_t upload_window() const { return bank_.append_window(); }
  /// One bounded step of programming the received bytes (one page erase, or up to
  /// DualBankStore::kUnitsPerFlushStep program units); `*done` = true when only a partial program
  /// unit is left (FinishUpload programs it). kNotReady unless receiving; a flash failure fails
  /// the upload as UploadData's would.
  Status FlushUpload(bool* done);
  /// Ends a complete transfer: kImageSizeMismatch when it differs from the announced size.
  Status FinishUpload();
  /// Ends a transfer that broke, for `reason` (kTransferAborted, kTransferCrcMismatch, ...: the
  /// staging error reported in 0x2102). No effect unless an upload is in progress (a failure it
  /// already reported stays the reason).
  void AbandonUpload(Error reason);
  /// Validates the complete staged image (format, CRC, board match).
  Status Verify(const BoardConfig& config);
  /// Commits the verified staged image; returns its view (in flash, valid while active).
  Result<table::TableView> Activate();
  /// Revokes the active image.
  Status Deactivate();
  /// Forgets the staged image.
  void Clear();

  StagedState staged_state() const { return state_; }
  /// Bytes received (receiving, failed) or staged; 0 when nothing is staged.
  uint32_t staged_bytes() const { return state_ == StagedState::kEmpty ? 0 : bank_.staged_size(); }
  /// The size announced for the upload in progress or last (0 = not announced).
  uint32_t expected_size() const { return expected_size_; }
  uint32_t staged_crc32() const { return staged_crc_; }
  uint32_t staged_table_id() const { return staged_id_; }
  const uint8_t* staged_data() const { return bank_.staged_data(); }
  /// The active image's bytes (null when none is committed).
  const uint8_t* active_data() const { return bank_.committed_data(); }
  uint32_t active_size() const { return bank_.committed_size(); }
  Error last_error() const { return last_error_; }
  uint32_t capacity() const { return bank_.capacity(); }

 private:
  Status Fail(Error e);
  void MountStaged(const BoardConfig& config);

  DualBankStore bank_;
  // Received table bytes not yet programmed: what the SDO server may take between two flushes
  // (one sub-block, docs/mcu-target.md "Main loop under the tick").
  static constexpr uint32_t kUploadBufferBytes = 1024;
  alignas(8) uint8_t buffer_[kUploadBufferBytes] = {};
  StagedState state_ = StagedState::kEmpty;
  uint32_t expected_size_ = 0;
  uint32_t staged_crc_ = 0;
  uint32_t staged_id_ = 0;
  Error last_error_ = Error::kOk;
};

}  // namespace volcomp::firmware
