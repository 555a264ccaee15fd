// `volcomp upload IMAGE` and `volcomp verify IMAGE`: table transfer to a board over CAN.
//
// Upload: validate the image locally, check it against the board's installation (board_fit.hpp:
// refused when the board would refuse, clamp or rate-limit it, unless --allow-clamp), skip if the
// board already has it active, then the staging protocol of canopen_client/table_staging.hpp
// (unlock, clear the staging bank, block-download into 0x2100, verify on the board, check the
// staged CRC-32), and optionally activate (0x2101 = 1). A failed or cut transfer is retried from
// the start (--retries), which is always safe: the active table is never touched by staging.
//
// Verify: which table the board has active or staged; --readback reads the image it names back
// (the active one from 0x2109, or with --staged the staged one from 0x2100) and compares it byte
// by byte. Exit 1 for a different or absent table, 3 when the board cannot be reached.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include "board_fit.hpp"
#include "can_options.hpp"
#include "commands.hpp"
#include "sdo_failure.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/hex.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {
namespace {

using canopen::ObjectId;
using canopen_client::CanSession;
using canopen_client::SdoResult;

class ProgressBar {
 public:
  ProgressBar(uint32_t total, FILE* out)
      : total_(total), out_(out), tty_(isatty(fileno(out)) != 0) {
    start_ = std::chrono::steady_clock::now();
  }
  void Update(uint32_t done) {
    const double s = Seconds();
    const double rate = s > 0 ? done / s : 0;
    if (tty_) {
      const int width = 30, filled = total_ ? static_cast<int>(width * double(done) / total_) : 0;
      std::fprintf(out_, "\r  [%-*s] %3d%%  %u/%u B  %.1f kB/s  %.1f s left ", width,
                   std::string(filled, '#').c_str(),
                   total_ ? static_cast<int>(100.0 * done / total_) : 100, done, total_,
                   rate / 1000, rate > 0 ? (total_ - done) / rate : 0.0);
      std::fflush(out_);
    } else {
      const int decile = total_ ? static_cast<int>(10.0 * done / total_) : 10;
      if (decile > last_decile_) {
        last_decile_ = decile;
        std::fprintf(out_, "  %3d%%  %u/%u bytes  %.1f kB/s\n", decile * 10, done, total_,
                     rate / 1000);
        std::fflush(out_);
      }
    }
  }
  void Finish() {
    if (tty_) std::fprintf(out_, "\n");
  }
  double Seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  uint32_t total_;
  FILE* out_;
  bool tty_;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_;
};

uint32_t ReadOr(CanSession& s, ObjectId id, const std::string& what) {
  uint32_t v = 0;
  Check(s.Read(id, &v), "reading " + what);
  return v;
}

// One complete attempt; throws on failure. Returns the transfer's seconds.
double UploadOnce(
    CanSession& s, const std::vector<uint8_t>& bytes, uint32_t crc, bool quiet, FILE* out) {
  Require(canopen_client::PrepareStaging(s));
  ProgressBar bar(static_cast<uint32_t>(bytes.size()), out);
  const SdoResult r = s.Download(ObjectId::kTableData, bytes, [&](uint32_t done, uint32_t) {
    if (!quiet) bar.Update(done);
  });
  if (!quiet) bar.Finish();
  Check(canopen_client::WithStagingReason(s, r), "block download into 0x2100");
  const double secs = bar.Seconds();
  std::fprintf(out, "transferred %zu bytes in %.2f s (%.1f kB/s)\n", bytes.size(), secs,
               secs > 0 ? static_cast<double>(bytes.size()) / secs / 1000 : 0.0);
  Require(canopen_client::VerifyStaged(s, crc));
  return secs;
}

// --json: one object on stdout at the end (the messages go to stderr); failures are reported by
// RunCommand as {"command", "exit_code", "error"}.
void PrintUploadJson(uint8_t node,
                     const std::string& file,
                     const image::LoadedImage& img,
                     const char* result,
                     double secs) {
  JsonWriter w(std::cout);
  w.begin_object();
  w.key("command").value("upload");
  w.key("node").value(unsigned{node});
  w.key("image").begin_object();
  w.key("file").value(file);
  w.key("bytes").value(uint64_t{img.size()});
  w.key("table_id").value(uint64_t{img.view().table_id});
  w.key("crc32").value(Hex32(img.view().crc32));
  w.end_object();
  w.key("result").value(result);
  if (secs > 0) {
    w.key("transfer_s").value(secs);
    w.key("rate_bytes_s").value(static_cast<double>(img.size()) / secs);
  }
  w.key("exit_code").value(kExitOk);
  w.end_object();
  std::cout << "\n";
}

}  // namespace

int RunUpload(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const bool activate = args.flag("--activate");
  const bool allow_clamp = args.flag("--allow-clamp");
  const bool force = args.flag("--force");
  const bool json = args.flag("--json");
  const bool quiet = args.flag("--quiet") || json;
  FILE* out = json ? stderr : stdout;
  const long long retries = args.integer("--retries").value_or(2);
  const auto pos = args.positionals();
  args.finish();
  if (pos.size() != 1) throw UsageError("expected one IMAGE file");
  const image::LoadedImage img = image::LoadImageFile(pos[0]);
  const std::vector<uint8_t> bytes(img.data(), img.data() + img.size());
  const uint32_t crc = img.view().crc32;
  std::fprintf(out, "image %s: %u bytes, table id %u, CRC-32 %s\n", pos[0].c_str(), img.size(),
               img.view().table_id, Hex32(crc).c_str());

  for (long long attempt = 0;; ++attempt) {
    try {
      auto session = OpenSession(can);
      CanSession& s = *session;
      RequireTableFits(s, img.view(), allow_clamp);
      const uint32_t active = ReadOr(s, ObjectId::kActiveTableCrc, "the active CRC-32 (0x2104)");
      if (active == crc && !force) {
        std::fprintf(out, "node %u already has this table active (CRC-32 %s): nothing to do\n",
                     can.node, Hex32(crc).c_str());
        if (json) PrintUploadJson(can.node, pos[0], img, "already active", 0);
        return 0;
      }
      const uint32_t capacity = ReadOr(s, ObjectId::kTableBankSize, "the bank size (0x2108)");
      if (bytes.size() > capacity) {
        throw InputError("image of " + std::to_string(bytes.size()) +
                         " bytes does not fit the board's table bank of " +
                         std::to_string(capacity) + " bytes");
      }
      const double secs = UploadOnce(s, bytes, crc, quiet, out);
      std::fprintf(out, "staged and verified on node %u\n", can.node);
      if (activate) {
        Require(canopen_client::WriteTableCommand(s, canopen::TableCommand::kActivate));
        const uint32_t now_active = ReadOr(s, ObjectId::kActiveTableCrc, "the active CRC-32");
        if (now_active != crc)
          throw InputError("activation did not take: active CRC-32 is " + Hex32(now_active));
        std::fprintf(out, "activated: node %u compensates with table %u (CRC-32 %s)\n", can.node,
                     img.view().table_id, Hex32(crc).c_str());
      }
      if (json) PrintUploadJson(can.node, pos[0], img, activate ? "active" : "staged", secs);
      return 0;
    } catch (const SdoFailure& e) {
      if (!e.retryable || attempt >= retries) {
        throw InputError(std::string("upload failed: ") + e.what());
      }
      std::fprintf(stderr, "upload attempt %lld failed: %s\nretrying from the start...\n",
                   attempt + 1, e.what());
    } catch (const InputError&) {
      throw;
    } catch (const std::runtime_error& e) {  // no answer, or the link itself failed (cut, bus-off)
      if (attempt >= retries) throw CommunicationError(std::string("upload failed: ") + e.what());
      std::fprintf(stderr, "upload attempt %lld failed: %s\nreconnecting and retrying...\n",
                   attempt + 1, e.what());
      std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
  }
}

int RunVerify(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const bool readback = args.flag("--readback");
  const bool staged_only = args.flag("--staged");
  const bool json = args.flag("--json");
  FILE* out = json ? stderr : stdout;
  const auto pos = args.positionals();
  args.finish();
  if (pos.size() != 1) throw UsageError("expected one IMAGE file");
  const image::LoadedImage img = image::LoadImageFile(pos[0]);
  const uint32_t crc = img.view().crc32;
  return OverTheBus([&] {
    auto session = OpenSession(can);
    CanSession& s = *session;
    const uint32_t active = ReadOr(s, ObjectId::kActiveTableCrc, "the active CRC-32 (0x2104)");
    const uint32_t staged = ReadOr(s, ObjectId::kStagedTableCrc, "the staged CRC-32 (0x2105)");
    const canopen::TableStatus table =
        canopen::DecodeTableStatus(ReadOr(s, ObjectId::kTableStatus, "the table status (0x2102)"));
    const bool has_active =
        canopen::DecodeDeviceState(ReadOr(s, ObjectId::kDeviceState, "the device state (0x2122)"))
            .table_active;
    const bool has_staged = table.staged == canopen::StagedState::kComplete ||
                            table.staged == canopen::StagedState::kVerified;
    std::fprintf(out, "image CRC-32 %s; node %u: active %s, staged %s\n", Hex32(crc).c_str(),
                 can.node, has_active ? Hex32(active).c_str() : "none",
                 has_staged ? Hex32(staged).c_str() : "none");
    const char* bank = staged_only ? "staged" : "active";
    int64_t readback_bytes = -1;
    bool readback_same = false;
    // --json: the verdict and what it rests on, one object on stdout.
    auto done = [&](int code, const char* verdict) {
      if (json) {
        JsonWriter w(std::cout);
        w.begin_object();
        w.key("command").value("verify");
        w.key("node").value(unsigned{can.node});
        w.key("image_crc32").value(Hex32(crc));
        w.key("active_crc32");
        if (has_active)
          w.value(Hex32(active));
        else
          w.null();
        w.key("staged_crc32");
        if (has_staged)
          w.value(Hex32(staged));
        else
          w.null();
        if (readback_bytes >= 0) {
          w.key("readback").begin_object();
          w.key("table").value(bank);
          w.key("bytes").value(readback_bytes);
          w.key("identical").value(readback_same);
          w.end_object();
        }
        w.key("verdict").value(verdict);
        w.key("exit_code").value(code);
        w.end_object();
        std::cout << "\n";
      }
      return code;
    };
    if (readback) {
      if (staged_only ? !has_staged : !has_active) {
        std::fprintf(out, "no %s table on node %u to read back\n", bank, can.node);
        return done(kExitFailed, "no table to read back");
      }
      std::vector<uint8_t> data;
      Check(s.UploadDomain(staged_only ? ObjectId::kTableData : ObjectId::kActiveTableData, &data),
            staged_only ? "reading back the staged table (0x2100)"
                        : "reading back the active table (0x2109)");
      const bool same =
          data.size() == img.size() && std::equal(data.begin(), data.end(), img.data());
      std::fprintf(out, "read back the %s table, %zu bytes: %s\n", bank, data.size(),
                   same ? "identical to the image" : "DIFFERENT from the image");
      readback_bytes = static_cast<int64_t>(data.size());
      readback_same = same;
      if (!same) return done(kExitFailed, "different");
    }
    if (staged_only) {
      if (has_staged && staged == crc && table.staged == canopen::StagedState::kVerified) {
        std::fprintf(out, "verified: the image is staged and verified on node %u\n", can.node);
        return done(kExitOk, "staged");
      }
      std::fprintf(out, "the image is not the staged table of node %u\n", can.node);
      return done(kExitFailed, "not staged");
    }
    if (has_active && active == crc) {
      std::fprintf(out, "verified: the image is the active table\n");
      return done(kExitOk, "active");
    }
    if (has_staged && staged == crc) {
      std::fprintf(out,
                   "the image is staged and verified but not active (run `volcomp activate`)\n");
      return done(kExitFailed, "staged, not active");
    }
    std::fprintf(out, "the image is neither active nor staged on node %u\n", can.node);
    return done(kExitFailed, "neither active nor staged");
  });
}

}  // namespace volcomp::tools
