// The board's compensation tables in flash: the active image and the staging of a new one, on a
// power-loss-safe DualBankStore.
//
// Upload: BeginUpload -> UploadData ... -> FinishUpload(true) (complete) -> Verify (the firmware's
// image validation plus the board match) -> Activate (one atomic commit). Any failure along the
// way leaves the staged image unusable and the active image untouched. Deactivate revokes the
// active image (persistently: after a reset the board runs pass-through until a new activation).
#pragma once

#include <cstdint>

#include "volcomp/board_config.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/firmware/dual_bank_store.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/status.hpp"
#include "volcomp/table_image.hpp"

namespace volcomp::firmware {

/// The staging bank's state, as reported in 0x2102.
using canopen::StagedState;

class TableStore {
 public:
  Status Init(hal::Flash* flash, uint32_t bank_size);

  /// Power-up: mounts the banks; returns the active image if one is committed, intact and made
  /// for `config` (the error says why not otherwise: kNotFound when nothing is committed).
  Result<table::TableView> MountActive(const BoardConfig& config);

  /// Starts staging an image of `size` bytes (0 = not indicated). kImageTooLarge if it cannot
  /// fit; kIoError on a flash failure.
  Status BeginUpload(uint32_t size);
  Status UploadData(const uint8_t* data, uint32_t size);
  /// Ends the upload; `complete` = the transfer succeeded.
  Status FinishUpload(bool complete);
  /// Validates the complete staged image (format, CRC, board match).
  Status Verify(const BoardConfig& config);
  /// Commits the verified staged image; returns its view (in flash, valid while active).
  Result<table::TableView> Activate();
  /// Revokes the active image.
  Status Deactivate();
  /// Forgets the staged image.
  void Clear();

  StagedState staged_state() const { return state_; }
  uint32_t staged_bytes() const { return bank_.staged_size(); }
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

  DualBankStore bank_;
  StagedState state_ = StagedState::kEmpty;
  uint32_t expected_size_ = 0;
  uint32_t staged_crc_ = 0;
  uint32_t staged_id_ = 0;
  Error last_error_ = Error::kOk;
};

}  // namespace volcomp::firmware
