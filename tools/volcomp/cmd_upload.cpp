// `volcomp upload IMAGE` and `volcomp verify IMAGE`: table transfer to a board over CAN.
//
// Upload: validate the image locally, skip if the board already has it active, unlock, clear the
// staging bank, block-download the image into 0x2100, verify on the board (0x2101 = 4), check the
// staged CRC-32, and optionally activate (0x2101 = 1). A failed or cut transfer is retried from
// the start (--retries), which is always safe: the active table is never touched by staging.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include "can_options.hpp"
#include "commands.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/image/image_reader.hpp"

namespace volcomp::tools {
namespace {

using canopen::ObjectId;
using canopen_client::CanSession;
using canopen_client::SdoResult;

constexpr uint32_t kUnlockSignature = 0x6B6C6E75;  // "unlk", see firmware/board_objects.hpp

class ProgressBar {
 public:
  explicit ProgressBar(uint32_t total) : total_(total), tty_(isatty(STDOUT_FILENO) != 0) {
    start_ = std::chrono::steady_clock::now();
  }
  void Update(uint32_t done) {
    const double s = Seconds();
    const double rate = s > 0 ? done / s : 0;
    if (tty_) {
      const int width = 30, filled = total_ ? static_cast<int>(width * double(done) / total_) : 0;
      std::printf("\r  [%-*s] %3d%%  %u/%u B  %.1f kB/s  %.1f s left ", width,
                  std::string(filled, '#').c_str(),
                  total_ ? static_cast<int>(100.0 * done / total_) : 100, done, total_, rate / 1000,
                  rate > 0 ? (total_ - done) / rate : 0.0);
      std::fflush(stdout);
    } else {
      const int decile = total_ ? static_cast<int>(10.0 * done / total_) : 10;
      if (decile > last_decile_) {
        last_decile_ = decile;
        std::printf("  %3d%%  %u/%u bytes  %.1f kB/s\n", decile * 10, done, total_, rate / 1000);
        std::fflush(stdout);
      }
    }
  }
  void Finish() {
    if (tty_) std::printf("\n");
  }
  double Seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  uint32_t total_;
  bool tty_;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_;
};

std::string Hex32(uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08X", v);
  return b;
}

// An SDO failure; `retryable` when a fresh attempt can succeed (protocol errors, timeouts).
class SdoFailure : public InputError {
 public:
  SdoFailure(const std::string& message, uint32_t code)
      : InputError(message), retryable((code >> 16) == 0x0504 || code == 0x05030000) {}
  bool retryable;
};

// Throws SdoFailure with the SDO failure explained (and what to do about the common ones).
void Check(const SdoResult& r, const std::string& what) {
  if (r.ok) return;
  std::string hint;
  if (r.abort_code == canopen::kAbortCannotStore) {
    hint = "; the board is write-protected: set its write-enable input or let the tool unlock it";
  } else if (r.abort_code == canopen::kAbortDeviceState) {
    hint =
        "; the axes must be referenced (homed) and at rest: home the machine, then run "
        "`volcomp activate`";
  } else if (r.abort_code == canopen::kAbortNoData) {
    hint = "; no verified table is staged: upload one first";
  }
  throw SdoFailure(what + ": " + r.message + hint, r.abort_code);
}

uint32_t ReadOr(CanSession& s, ObjectId id, const std::string& what) {
  uint32_t v = 0;
  Check(s.Read(id, &v), "reading " + what);
  return v;
}

void Unlock(CanSession& s) {
  uint32_t writable = 0;
  Check(s.Read(ObjectId::kWriteAccess, &writable), "reading write access (0x2111)");
  if (writable == 0) Check(s.Write(ObjectId::kUnlock, kUnlockSignature), "unlocking (0x2110)");
}

// One complete attempt; throws on failure.
void UploadOnce(CanSession& s, const std::vector<uint8_t>& bytes, uint32_t crc, bool quiet) {
  Unlock(s);
  Check(s.Write(ObjectId::kTableControl, 3), "clearing the staging bank (0x2101 = 3)");
  ProgressBar bar(static_cast<uint32_t>(bytes.size()));
  const SdoResult r = s.Download(ObjectId::kTableData, bytes, [&](uint32_t done, uint32_t) {
    if (!quiet) bar.Update(done);
  });
  if (!quiet) bar.Finish();
  Check(r, "block download into 0x2100");
  const double secs = bar.Seconds();
  std::printf("transferred %zu bytes in %.2f s (%.1f kB/s)\n", bytes.size(), secs,
              secs > 0 ? static_cast<double>(bytes.size()) / secs / 1000 : 0.0);
  Check(s.Write(ObjectId::kTableControl, 4), "verifying on the board (0x2101 = 4)");
  const uint32_t staged = ReadOr(s, ObjectId::kStagedTableCrc, "the staged CRC-32 (0x2105)");
  if (staged != crc) {
    throw InputError("the board staged CRC-32 " + Hex32(staged) + ", expected " + Hex32(crc));
  }
}

}  // namespace

int RunUpload(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const bool activate = args.flag("--activate");
  const bool force = args.flag("--force");
  const bool quiet = args.flag("--quiet");
  const long long retries = args.integer("--retries").value_or(2);
  const auto pos = args.positionals();
  args.finish();
  if (pos.size() != 1) throw UsageError("expected one IMAGE file");
  const image::LoadedImage img = image::LoadImageFile(pos[0]);
  const std::vector<uint8_t> bytes(img.data(), img.data() + img.size());
  const uint32_t crc = img.view().crc32;
  std::printf("image %s: %u bytes, table id %u, CRC-32 %s\n", pos[0].c_str(), img.size(),
              img.view().table_id, Hex32(crc).c_str());

  for (long long attempt = 0;; ++attempt) {
    try {
      auto session = OpenSession(can);
      CanSession& s = *session;
      const uint32_t active = ReadOr(s, ObjectId::kActiveTableCrc, "the active CRC-32 (0x2104)");
      if (active == crc && !force) {
        std::printf("node %u already has this table active (CRC-32 %s): nothing to do\n", can.node,
                    Hex32(crc).c_str());
        return 0;
      }
      const uint32_t capacity = ReadOr(s, ObjectId::kTableBankSize, "the bank size (0x2108)");
      if (bytes.size() > capacity) {
        throw InputError("image of " + std::to_string(bytes.size()) +
                         " bytes does not fit the board's table bank of " +
                         std::to_string(capacity) + " bytes");
      }
      UploadOnce(s, bytes, crc, quiet);
      std::printf("staged and verified on node %u\n", can.node);
      if (activate) {
        Check(s.Write(ObjectId::kTableControl, 1), "activating (0x2101 = 1)");
        const uint32_t now_active = ReadOr(s, ObjectId::kActiveTableCrc, "the active CRC-32");
        if (now_active != crc)
          throw InputError("activation did not take: active CRC-32 is " + Hex32(now_active));
        std::printf("activated: node %u compensates with table %u (CRC-32 %s)\n", can.node,
                    img.view().table_id, Hex32(crc).c_str());
      }
      return 0;
    } catch (const SdoFailure& e) {
      if (!e.retryable || attempt >= retries) {
        throw InputError(std::string("upload failed: ") + e.what());
      }
      std::fprintf(stderr, "upload attempt %lld failed: %s\nretrying from the start...\n",
                   attempt + 1, e.what());
    } catch (const InputError&) {
      throw;
    } catch (const std::runtime_error& e) {  // the link itself failed (cut connection, bus-off)
      if (attempt >= retries) throw InputError(std::string("upload failed: ") + e.what());
      std::fprintf(stderr, "upload attempt %lld failed: %s\nreconnecting and retrying...\n",
                   attempt + 1, e.what());
      std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
  }
}

int RunVerify(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const bool readback = args.flag("--readback");
  const auto pos = args.positionals();
  args.finish();
  if (pos.size() != 1) throw UsageError("expected one IMAGE file");
  const image::LoadedImage img = image::LoadImageFile(pos[0]);
  const uint32_t crc = img.view().crc32;
  auto session = OpenSession(can);
  CanSession& s = *session;
  const uint32_t active = ReadOr(s, ObjectId::kActiveTableCrc, "the active CRC-32 (0x2104)");
  const uint32_t staged = ReadOr(s, ObjectId::kStagedTableCrc, "the staged CRC-32 (0x2105)");
  std::printf("image CRC-32 %s; node %u: active %s, staged %s\n", Hex32(crc).c_str(), can.node,
              Hex32(active).c_str(), Hex32(staged).c_str());
  if (readback) {
    std::vector<uint8_t> data;
    Check(s.UploadDomain(ObjectId::kTableData, &data),
          "reading back the table (0x2100: the staged image, or the active one)");
    const bool same = data.size() == img.size() && std::equal(data.begin(), data.end(), img.data());
    std::printf("read back %zu bytes from the board: %s\n", data.size(),
                same ? "identical to the image" : "DIFFERENT from the image");
    if (!same) return 1;
  }
  if (active == crc) {
    std::printf("verified: the image is the active table\n");
    return 0;
  }
  if (staged == crc) {
    std::printf("the image is staged and verified but not active (run `volcomp activate`)\n");
    return 1;
  }
  std::printf("the image is neither active nor staged on node %u\n", can.node);
  return 1;
}

}  // namespace volcomp::tools
