// Randomized fault campaign (seeded, reproducible): table uploads over the simulated bus with
// dropped, duplicated, corrupted and destroyed (error-frame) frames, delays, aborts from either
// side, timeouts, a jammed bus (bus-off-like), and power loss at a random flash operation. After
// every trial the board is power-cycled and must boot with a valid table that is exactly the old
// or the new one (the new one only if the activation had completed); the PC side must have a
// clear failure message when it failed, and a retry over a clean bus must finish the upload.
//
// 1 000 trials by default; VOLCOMP_FAULT_TRIALS=10000 for the long run (VOLCOMP_FAULT_SEED).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>

#include "volcomp/base/byte_order.hpp"
#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen/sdo_protocol.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/sim/sim_sdo_host.hpp"
#include "volcomp/table/table_image.hpp"
#include "xyz_image.hpp"

namespace volcomp {
namespace {

using canopen::ObjectId;
using canopen::TableCommand;
using canopen_client::SdoClient;

constexpr uint8_t kNode = 0x10;

std::vector<uint8_t> Image(uint32_t id, int16_t offset, uint32_t nodes) {
  std::vector<int16_t> v(size_t{nodes} * nodes * nodes * 3);
  for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<int16_t>(offset + (i * 37) % 200);
  return testing::XyzImage(id, nodes, -50000, 100000 / (nodes - 1), v);
}

uint32_t TrailerCrc(const std::vector<uint8_t>& img) {
  return LoadLe32(img.data() + img.size() - 4);
}

enum class Fault {
  kNone,
  kDrop,
  kDuplicate,
  kCorrupt,
  kDestroy,
  kDelay,
  kClientAbort,
  kClientSilent,
  kJammedBus,
  kPowerLoss,
  kCount
};
const char* kFaultNames[] = {"none",  "drop",         "duplicate",     "corrupt",    "error frames",
                             "delay", "client abort", "client silent", "jammed bus", "power loss"};

// One simulated board with a PC endpoint, in virtual time.
class Rig {
 public:
  explicit Rig(std::vector<uint8_t> flash) : bus_(1000000) {
    sim::SimulatedBoardOptions o;
    o.table_flash_bytes = 128 * 1024;
    o.write_enable_input = true;
    o.initial_table_flash = std::move(flash);
    board_ = std::make_unique<sim::SimulatedBoard>(bus_, o);
    pc_ = &bus_.Attach("pc");
    host_ = std::make_unique<sim::SimSdoHost>(bus_, *board_, *pc_, kNode);
    EXPECT_TRUE(board_->Start().ok());
    host_->Idle(2000000);
  }
  sim::SimBus& bus() { return bus_; }
  sim::SimulatedBoard& board() { return *board_; }

  // The PC tool's sequence: its staging steps (write access, clear), the block download (event by
  // event, so the PC can stall or abort), its verification steps, reference, activate.
  canopen_client::SdoOutcome Upload(const std::vector<uint8_t>& img,
                                    const std::function<bool(uint64_t)>& pc_alive = {},
                                    bool client_abort = false,
                                    std::mt19937_64* rng = nullptr) {
    canopen_client::NodeObjects pc_tool(host_->Link(), kNode);
    VOLCOMP_TRY(canopen_client::PrepareStaging(pc_tool));
    const canopen::ObjectEntry& data = canopen::Entry(ObjectId::kTableData);
    SdoClient c(kNode);
    c.StartWrite(data.index, data.sub, img);
    if (client_abort) {
      // Abort after a random share of the transfer.
      const uint64_t stop = bus_.now() + 1000000ull + (*rng)() % 20000000ull;
      host_->Run(c, stop - bus_.now(), pc_alive);
      if (!c.done()) {
        CanFrame f;
        f.id = canopen::sdo::kRequestCobBase + kNode;
        f.dlc = 8;
        f.data[0] = canopen::sdo::kAbort;
        StoreLe16(f.data + 1, data.index);
        f.data[3] = data.sub;
        StoreLe32(f.data + 4, canopen::Code(canopen::SdoAbort::kGeneral));
        pc_->Send(f);
        host_->Idle(5000000);
        canopen_client::SdoFailure a;
        a.code = Error::kTransferAborted;
        a.message = "upload aborted by the PC (sent abort 0x08000000: general error)";
        a.abort = canopen::SdoAbort::kGeneral;
        return Fail(a);
      }
    } else {
      host_->Run(c, 30000000000ull, pc_alive);
    }
    if (!c.done()) {  // the PC side went silent: there is nobody to report; the board recovers
      return canopen_client::SdoFail(Error::kCommunication, "PC silent (no abort 0x sent)");
    }
    if (!c.result().ok()) return Fail(c.result().error());
    VOLCOMP_TRY(canopen_client::VerifyStaged(pc_tool, TrailerCrc(img)));
    VOLCOMP_TRY(pc_tool.Write(ObjectId::kReferenceAxes, 7));
    host_->Idle(150000000);
    return canopen_client::WriteTableCommand(pc_tool, TableCommand::kActivate);
  }

 private:
  sim::SimBus bus_;
  std::unique_ptr<sim::SimulatedBoard> board_;
  sim::Endpoint* pc_ = nullptr;
  std::unique_ptr<sim::SimSdoHost> host_;
};

uint32_t EnvOr(const char* name, uint32_t fallback) {
  const char* v = std::getenv(name);
  return v ? static_cast<uint32_t>(std::strtoul(v, nullptr, 10)) : fallback;
}

TEST(FaultCampaign, EveryTrialEndsWithTheOldOrTheNewTableAndAnUploadCanFinish) {
  const uint32_t trials = EnvOr("VOLCOMP_FAULT_TRIALS", 1000);
  std::mt19937_64 rng(EnvOr("VOLCOMP_FAULT_SEED", 2026));
  const std::vector<uint8_t> images[2] = {Image(1, 10, 6), Image(2, -20, 7)};
  // Start with image 0 active.
  std::vector<uint8_t> flash;
  {
    Rig rig({});
    ASSERT_TRUE(rig.Upload(images[0]).ok());
    flash = rig.board().table_flash().raw();
  }
  int active = 0;
  std::map<std::string, int> outcome;
  int failures = 0, switched = 0, kept = 0;
  for (uint32_t t = 0; t < trials; ++t) {
    const int next = 1 - active;
    const Fault fault = static_cast<Fault>(rng() % static_cast<int>(Fault::kCount));
    Rig rig(flash);
    sim::RandomFaultRates rates;
    std::function<bool(uint64_t)> alive;
    bool client_abort = false;
    const double p = 0.002 + static_cast<double>(rng() % 1000) * 1e-5;  // 0.2 % .. 1.2 % per frame
    switch (fault) {
      case Fault::kDrop:
        rates.drop = p;
        break;
      case Fault::kDuplicate:
        rates.duplicate = p;
        break;
      case Fault::kCorrupt:
        rates.corrupt = p;
        break;
      case Fault::kDestroy:
        rates.destroy = p;
        break;
      case Fault::kDelay: {  // the PC stalls 50..550 ms in the middle
        const uint64_t at = rig.bus().now() + 2000000 + rng() % 20000000;
        const uint64_t len = 50000000 + rng() % 500000000;
        alive = [at, len](uint64_t now) { return now < at || now > at + len; };
        break;
      }
      case Fault::kClientAbort:
        client_abort = true;
        break;
      case Fault::kClientSilent: {  // the PC disappears for good
        const uint64_t at = rig.bus().now() + 2000000 + rng() % 20000000;
        alive = [at](uint64_t now) { return now < at; };
        break;
      }
      case Fault::kJammedBus: {  // every frame destroyed for 0.3..1.5 s
        const uint64_t from = rig.bus().now() + 2000000 + rng() % 20000000;
        const uint64_t to = from + 300000000 + rng() % 1200000000;
        rig.bus().SetFaultHook([&rig, from, to](const CanFrame&, const sim::Endpoint&) {
          sim::FaultDecision d;
          if (rig.bus().now() >= from && rig.bus().now() < to)
            d.action = sim::FaultAction::kDestroy;
          return d;
        });
        break;
      }
      case Fault::kPowerLoss: {
        // Cut the power at a random flash operation of this upload (the image takes ~300).
        rig.board().table_flash().InjectPowerLossAfter(static_cast<uint32_t>(rng() % 400));
        break;
      }
      default:
        break;
    }
    if (rates.drop + rates.duplicate + rates.corrupt + rates.destroy > 0) {
      rig.bus().SetFaultHook(sim::RandomFaults(rng(), rates, [](const CanFrame& f) {
        return f.id == canopen::sdo::kRequestCobBase + kNode ||
               f.id == canopen::sdo::kResponseCobBase + kNode;  // SDO traffic of the node
      }));
    }
    const canopen_client::SdoOutcome r = rig.Upload(images[next], alive, client_abort, &rng);
    if (!r.ok()) {
      ++failures;
      ASSERT_FALSE(r.error().message.empty()) << "trial " << t;
      ASSERT_NE(r.error().message.find("abort 0x"), std::string::npos)
          << "trial " << t << ": " << r.error().message;
    }
    // Power cycle: a new board on the same flash.
    std::vector<uint8_t> after = rig.board().table_flash().raw();
    Rig reboot(after);
    const auto& tables = reboot.board().app().tables();
    ASSERT_TRUE(reboot.board().app().stored_table_status().ok())
        << "trial " << t << " (" << kFaultNames[static_cast<int>(fault)] << "): no valid table";
    const auto view = table::ParseImage(tables.active_data(), tables.active_size());
    ASSERT_TRUE(view.ok()) << "trial " << t;
    const uint32_t crc = view->crc32;
    ASSERT_TRUE(crc == TrailerCrc(images[0]) || crc == TrailerCrc(images[1])) << "trial " << t;
    const int now_active = crc == TrailerCrc(images[next]) ? next : active;
    if (r.ok()) {
      ASSERT_EQ(now_active, next) << "trial " << t << ": activation reported but lost";
    }
    (now_active == next ? switched : kept)++;
    ++outcome[std::string(kFaultNames[static_cast<int>(fault)]) + (r.ok() ? " ok" : " failed")];
    // The PC tool can finish the upload afterwards (clean bus).
    if (now_active != next) {
      const auto retry = reboot.Upload(images[next]);
      ASSERT_TRUE(retry.ok()) << "trial " << t << " retry: " << retry.error().message;
      flash = reboot.board().table_flash().raw();
    } else {
      flash = after;
    }
    active = next;
  }
  std::printf(
      "[ metric ] fault campaign: %u trials, %d uploads failed cleanly, %d boots with the "
      "new table, %d with the old (then finished by a retry), 0 invalid or mixed\n",
      trials, failures, switched, kept);
  for (const auto& [name, n] : outcome) std::printf("[ metric ]   %-20s %d\n", name.c_str(), n);
}

}  // namespace
}  // namespace volcomp
