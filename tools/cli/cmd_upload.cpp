// `volcomp upload IMAGE`: writes a table image to a board over CAN (an SDO block download).
//
// The image is validated locally, checked against the board's installation (board_fit.hpp:
// refused when the board would refuse, clamp or rate-limit it, unless --allow-clamp), skipped if
// the board already has it active, then written with the staging protocol of
// canopen_client/table_staging.hpp (unlock, clear the staging bank, block transfer into 0x2100,
// verify on the board, check the staged CRC-32), and optionally activated (0x2101 = 1). A transfer
// that broke (a protocol abort) or a link that failed is retried from the start (--retries),
// which is always safe: staging never touches the active table; each retry first waits for the
// board to show it is there (a heartbeat or its boot-up), at most 1, 2, 4, 8 s. The messages and
// the progress stream as the upload goes (on stderr with --json, whose object comes at the end).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include "board_fit.hpp"
#include "can_options.hpp"
#include "commands.hpp"
#include "sdo_failure.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::cli {
namespace {

using canopen::ObjectId;
using canopen_client::CanSession;
using tools::Hex32;

struct UploadRequest {
  CanConnection can;
  std::string file;
  bool activate = false;
  bool allow_clamp = false;
  bool force = false;
  bool quiet = false;
  long long retries = 2;
};

// What one attempt ended with.
struct Written {
  const char* result = "staged";  // "staged", "active" or "already active"
  double transfer_s = 0;          // 0 when nothing was transferred
  JsonValue replaced;             // the staged table this upload replaced (null: none)
};

// Why an attempt failed, and whether another one can succeed.
struct AttemptFailure {
  enum class Kind : uint8_t {
    kRefused,   // the board or the table says no: reported as it is, no retry
    kTransfer,  // an object access failed: "upload failed: ...", retried when it broke
    kLink,      // no answer or no link: reconnect and retry
  };
  Kind kind = Kind::kRefused;
  bool retryable = false;
  Failure failure;
};

// A failure of the tool's own or of a library: no link is worth a retry; an object access the
// board refused is reported as an upload failure; anything else is a refusal.
Unexpected<AttemptFailure> Refused(Failure f) {
  switch (f.code) {
    case Error::kCommunication:
      return Fail(AttemptFailure{AttemptFailure::Kind::kLink, true, std::move(f)});
    case Error::kTransferAborted:
      return Fail(AttemptFailure{AttemptFailure::Kind::kTransfer, false, std::move(f)});
    default:
      return Fail(AttemptFailure{AttemptFailure::Kind::kRefused, false, std::move(f)});
  }
}

// An object access that failed: the link, or a transfer retried when a fresh one can succeed.
Unexpected<AttemptFailure> Broken(const canopen_client::SdoFailure& f) {
  if (f.code == Error::kCommunication) {
    return Fail(AttemptFailure{AttemptFailure::Kind::kLink, true, ToFailure(f)});
  }
  return Fail(AttemptFailure{AttemptFailure::Kind::kTransfer, canopen::IsProtocolAbort(f.abort),
                             ToFailure(f)});
}

// The value of an object access (its failure already says which step).
template <typename T>
Expected<T, AttemptFailure> FromSdo(canopen_client::SdoExpected<T> r) {
  if (!r.ok()) return Broken(r.error());
  if constexpr (std::is_void_v<T>) {
    return Expected<T, AttemptFailure>();
  } else {
    return std::move(r).value();
  }
}

// ... explained by `step`.
template <typename T>
Expected<T, AttemptFailure> FromSdo(canopen_client::SdoExpected<T> r, const std::string& step) {
  return FromSdo(canopen_client::Explain(std::move(r), step));
}

template <typename T>
Expected<T, AttemptFailure> FromTool(Expected<T> r) {
  if (!r.ok()) return Refused(r.error());
  if constexpr (std::is_void_v<T>) {
    return Expected<T, AttemptFailure>();
  } else {
    return std::move(r).value();
  }
}

bool IsTerminal(const std::ostream& out) {
  if (&out == &std::cout) return isatty(STDOUT_FILENO) != 0;
  if (&out == &std::cerr) return isatty(STDERR_FILENO) != 0;
  return false;
}

// A bar redrawn in place on a terminal; every tenth of the way on a line of its own otherwise.
class ProgressBar {
 public:
  ProgressBar(uint32_t total, std::ostream& out)
      : total_(total), out_(out), tty_(IsTerminal(out)), start_(std::chrono::steady_clock::now()) {}
  void Update(uint32_t done) {
    const double s = Seconds();
    const double rate = s > 0 ? done / s : 0;
    char line[160];
    if (tty_) {
      const int width = 30, filled = total_ ? static_cast<int>(width * double(done) / total_) : 0;
      std::snprintf(line, sizeof line, "\r  [%-*s] %3d%%  %u/%u B  %.1f kB/s  %.1f s left ", width,
                    std::string(static_cast<size_t>(filled), '#').c_str(),
                    total_ ? static_cast<int>(100.0 * done / total_) : 100, done, total_,
                    rate / 1000, rate > 0 ? (total_ - done) / rate : 0.0);
      out_ << line << std::flush;
      return;
    }
    const int decile = total_ ? static_cast<int>(10.0 * done / total_) : 10;
    if (decile <= last_decile_) return;
    last_decile_ = decile;
    std::snprintf(line, sizeof line, "  %3d%%  %u/%u bytes  %.1f kB/s\n", decile * 10, done, total_,
                  rate / 1000);
    out_ << line << std::flush;
  }
  void Finish() {
    if (tty_) out_ << "\n";
  }
  double Seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  uint32_t total_;
  std::ostream& out_;
  bool tty_;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_;
};

// Stages the image: unlock, clear, block transfer into 0x2100, verify. Returns the seconds the
// transfer took.
// The staged table a new upload is about to replace (complete or verified, not active yet), said
// before it goes; null when nothing is staged.
Expected<JsonValue, AttemptFailure> StagedToReplace(CanSession& s, std::ostream& msg) {
  VOLCOMP_TRY_ASSIGN(const uint32_t status,
                     FromSdo(s.Read(ObjectId::kTableStatus), "reading the table status (0x2102)"));
  const canopen::StagedState staged = canopen::DecodeTableStatus(status).staged;
  if (staged != canopen::StagedState::kVerified && staged != canopen::StagedState::kComplete) {
    return JsonValue();
  }
  VOLCOMP_TRY_ASSIGN(const uint32_t id, FromSdo(s.Read(ObjectId::kStagedTableId),
                                                "reading the staged table id (0x2107)"));
  VOLCOMP_TRY_ASSIGN(const uint32_t crc, FromSdo(s.Read(ObjectId::kStagedTableCrc),
                                                 "reading the staged CRC-32 (0x2105)"));
  const char* state = canopen::kStagedStateNames[static_cast<int>(staged)];
  msg << "replacing the staged table of node " << unsigned{s.node()} << " (id " << id << ", CRC-32 "
      << Hex32(crc) << ", " << state << ", not active)\n";
  JsonValue r = JsonValue::Object();
  r.Set("table_id", uint64_t{id});
  r.Set("crc32", Hex32(crc));
  r.Set("state", state);
  return r;
}

Expected<double, AttemptFailure> WriteTable(CanSession& s,
                                            const image::LoadedImage& img,
                                            bool quiet,
                                            std::ostream& msg) {
  VOLCOMP_TRY(FromSdo(canopen_client::PrepareStaging(s)));
  const std::vector<uint8_t> bytes(img.data(), img.data() + img.size());
  ProgressBar bar(static_cast<uint32_t>(bytes.size()), msg);
  canopen_client::SdoOutcome written =
      s.WriteDomain(ObjectId::kTableData, bytes, [&](uint32_t done, uint32_t) {
        if (!quiet) bar.Update(done);
      });
  if (!quiet) bar.Finish();
  VOLCOMP_TRY(FromSdo(canopen_client::WithStagingReason(s, std::move(written)),
                      "block download into 0x2100"));
  const double secs = bar.Seconds();
  char line[128];
  std::snprintf(line, sizeof line, "transferred %zu bytes in %.2f s (%.1f kB/s)\n", bytes.size(),
                secs, secs > 0 ? static_cast<double>(bytes.size()) / secs / 1000 : 0.0);
  msg << line << std::flush;
  VOLCOMP_TRY(FromSdo(canopen_client::VerifyStaged(s, img.view().crc32)));
  return secs;
}

Expected<Written, AttemptFailure> Activate(CanSession& s,
                                           const UploadRequest& req,
                                           const image::LoadedImage& img,
                                           std::ostream& msg) {
  const uint32_t crc = img.view().crc32;
  VOLCOMP_TRY(FromSdo(canopen_client::WriteTableCommand(s, canopen::TableCommand::kActivate)));
  VOLCOMP_TRY_ASSIGN(const uint32_t active,
                     FromSdo(s.Read(ObjectId::kActiveTableCrc), "reading the active CRC-32"));
  if (active != crc) {
    return Refused(Failure{Error::kInputInvalid,
                           "activation did not take: active CRC-32 is " + Hex32(active)});
  }
  msg << "activated: node " << unsigned{req.can.node} << " compensates with table "
      << img.view().table_id << " (CRC-32 " << Hex32(crc) << ")\n";
  return Written{"active", 0, {}};
}

// How long a retry waits for the board at most: 1 s, doubled per attempt, 8 s at the most.
std::chrono::milliseconds RetryWait(long long attempt) {
  return std::chrono::milliseconds(1000LL << std::min<long long>(attempt, 3));
}

// Before a retry: waits until the node shows it is there (a heartbeat or its boot-up: a board
// that reset or lost power comes back with one), at most `bound`, reconnecting while the link is
// down; says what it saw. A node whose heartbeat is off (0x1017 = 0) is silent: then the retry
// comes after `bound`.
void WaitForBoard(const CanConnection& can, std::chrono::milliseconds bound, std::ostream& err) {
  using Clock = std::chrono::steady_clock;
  const auto end = Clock::now() + bound;
  const double bound_s = std::chrono::duration<double>(bound).count();
  char line[160];
  std::snprintf(line, sizeof line, "waiting up to %.0f s for node %u (heartbeat or boot-up)\n",
                bound_s, unsigned{can.node});
  err << line;
  for (auto now = Clock::now(); now < end; now = Clock::now()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - now);
    Expected<std::unique_ptr<CanSession>> session = OpenSession(can);
    Expected<std::optional<uint8_t>> seen =
        session.ok() ? (*session)->WaitForHeartbeat(left) : Fail(session.error());
    if (seen.ok() && seen->has_value()) {
      err << "node " << unsigned{can.node}
          << " is there (heartbeat: " << canopen_client::NmtStateName(**seen) << ")\n";
      return;
    }
    if (!seen.ok()) {  // no link yet: try again shortly
      std::this_thread::sleep_for(std::min(left, std::chrono::milliseconds(100)));
    }
  }
  std::snprintf(line, sizeof line,
                "nothing from node %u within %.0f s (its heartbeat may be off: 0x1017 = 0)\n",
                unsigned{can.node}, bound_s);
  err << line;
}

// One complete attempt over a fresh session.
Expected<Written, AttemptFailure> UploadOnce(const UploadRequest& req,
                                             const image::LoadedImage& img,
                                             std::ostream& msg,
                                             std::ostream& warnings) {
  VOLCOMP_TRY_ASSIGN(const auto session, FromTool(OpenSession(req.can)));
  CanSession& s = *session;
  VOLCOMP_TRY(FromTool(RequireTableFits(s, img.view(), req.allow_clamp, warnings)));
  const uint32_t crc = img.view().crc32;
  VOLCOMP_TRY_ASSIGN(const uint32_t active, FromSdo(s.Read(ObjectId::kActiveTableCrc),
                                                    "reading the active CRC-32 (0x2104)"));
  if (active == crc && !req.force) {
    msg << "node " << unsigned{req.can.node} << " already has this table active (CRC-32 "
        << Hex32(crc) << "): nothing to do\n";
    return Written{"already active", 0, {}};
  }
  VOLCOMP_TRY_ASSIGN(const uint32_t capacity,
                     FromSdo(s.Read(ObjectId::kTableBankSize), "reading the bank size (0x2108)"));
  if (img.size() > capacity) {
    return Refused(
        Failure{Error::kInvalidArgument, "image of " + std::to_string(img.size()) +
                                             " bytes does not fit the board's table bank of " +
                                             std::to_string(capacity) + " bytes"});
  }
  VOLCOMP_TRY_ASSIGN(JsonValue replaced, StagedToReplace(s, msg));
  VOLCOMP_TRY_ASSIGN(const double secs, WriteTable(s, img, req.quiet, msg));
  msg << "staged and verified on node " << unsigned{req.can.node} << "\n";
  Written w{"staged", secs, {}};
  if (req.activate) {
    VOLCOMP_TRY_ASSIGN(w, Activate(s, req, img, msg));
  }
  w.transfer_s = secs;
  w.replaced = std::move(replaced);
  return w;
}

Expected<UploadRequest> ParseUpload(Args& args) {
  UploadRequest req;
  VOLCOMP_TRY_ASSIGN(req.can, ParseCanOptions(args));
  req.activate = args.Flag("--activate");
  req.allow_clamp = args.Flag("--allow-clamp");
  req.force = args.Flag("--force");
  const bool json = args.Flag("--json");
  req.quiet = args.Flag("--quiet") || json;
  req.retries = args.Integer("--retries").value_or(2);
  const auto files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (files.size() != 1) return UsageFailure("expected one IMAGE file");
  req.file = files[0];
  return req;
}

JsonValue UploadData(const UploadRequest& req, const image::LoadedImage& img, const Written& w) {
  JsonValue d = JsonValue::Object();
  d.Set("command", "upload");
  d.Set("node", unsigned{req.can.node});
  JsonValue& image = d["image"] = JsonValue::Object();
  image.Set("file", req.file);
  image.Set("bytes", uint64_t{img.size()});
  image.Set("table_id", uint64_t{img.view().table_id});
  image.Set("crc32", Hex32(img.view().crc32));
  d.Set("result", w.result);
  if (!w.replaced.is_null()) d["replaced_staged"] = w.replaced;
  if (w.transfer_s > 0) {
    d.Set("transfer_s", w.transfer_s);
    d.Set("rate_bytes_s", static_cast<double>(img.size()) / w.transfer_s);
  }
  d.Set("exit_code", tools::kExitOk);
  return d;
}

Expected<Output> RunUpload(Args& args, Context& ctx) {
  VOLCOMP_TRY_ASSIGN(const UploadRequest req, ParseUpload(args));
  VOLCOMP_TRY_ASSIGN(const image::LoadedImage img, image::ReadImageFile(req.file));
  std::ostream& msg = ctx.json ? ctx.err : ctx.out;  // with --json stdout carries the object only
  msg << "image " << req.file << ": " << img.size() << " bytes, table id " << img.view().table_id
      << ", CRC-32 " << Hex32(img.view().crc32) << "\n";
  for (long long attempt = 0;; ++attempt) {
    Expected<Written, AttemptFailure> w = UploadOnce(req, img, msg, ctx.err);
    if (w.ok()) return Output{UploadData(req, img, *w), nullptr, {}};
    const AttemptFailure& f = w.error();
    if (f.kind == AttemptFailure::Kind::kRefused) return Fail(f.failure);
    const bool link = f.kind == AttemptFailure::Kind::kLink;
    if (!f.retryable || attempt >= req.retries) {
      return Fail(link ? Error::kCommunication : f.failure.code,
                  "upload failed: " + f.failure.message);
    }
    ctx.err << "upload attempt " << attempt + 1 << " failed: " << f.failure.message << "\n";
    WaitForBoard(req.can, RetryWait(attempt), ctx.err);
    ctx.err << (link ? "reconnecting and retrying...\n" : "retrying from the start...\n");
  }
}

}  // namespace

const Command& UploadCommand() {
  static const Command kCommand{
      "upload",
      "upload a table image to a board over CAN (block transfer), verify, activate",
      "IMAGE",
      Join({CanOptions(),
            {{"--activate", nullptr, nullptr, nullptr, nullptr, "activate it after the upload"},
             {"--allow-clamp", nullptr, nullptr, nullptr, nullptr,
              "upload a table the board would clamp (0x2015) or rate-limit (0x2016); a warning"},
             {"--force", nullptr, nullptr, nullptr, nullptr,
              "upload even when the board already has this table"},
             {"--retries", nullptr, "N", nullptr, "2", "repeat a failed transfer up to N times"}},
            JsonResultOption(),
            {{"--quiet", nullptr, nullptr, nullptr, nullptr, "no progress bar"}}}),
      RunUpload,
      "Before the transfer the image is checked against the board's installation: axis count,\n"
      "names and units per step (0x2012) must match; a table whose largest correction exceeds\n"
      "the max correction (0x2015), or whose gradient times the fastest input rates (0x201E)\n"
      "exceeds the max correction rate (0x2016), is refused (exit 1, naming the axis, the\n"
      "table's value and the board's limit) unless --allow-clamp."};
  return kCommand;
}

}  // namespace volcomp::cli
