// The board application's CANopen node end to end on the mock HAL: table upload by block
// download, activation rules (0x08000022), write protection (0x08000020), status objects, EMCY,
// stored settings and NMT reset.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>

#include "board_bench.hpp"
#include "frames.hpp"
#include "test_tables.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen_client/node_objects.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/hal/mock/mock_step_io.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp {
namespace {

using bench::Bench;
using bench::InputLine;
using bench::kNode;
using bench::ObjectId;
using bench::SdoClient;
using bench::TableCommand;
using bench::TransferResult;
using bench::UniformImage;

TEST_F(Bench, UploadIsRefusedWhileWriteProtectedAndAllowedWhenUnlocked) {
  Boot();
  const testing::AlignedBytes img = UniformImage(5, 42);
  TransferResult r = Upload(img);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(canopen_client::AbortOf(r), canopen::SdoAbort::kCannotStore);
  EXPECT_EQ(CountEmcy(canopen::kEmcyRefused), 1);
  EXPECT_EQ(Read(ObjectId::kRefusedActions), 1u);
  EXPECT_EQ(Read(ObjectId::kWriteAccess), 0u);
  // Wrong signature: refused; right one: writable for 60 s.
  EXPECT_EQ(canopen_client::AbortOf(Write(ObjectId::kUnlock, 0x12345678)),
            canopen::SdoAbort::kInvalidValue);
  ASSERT_TRUE(Write(ObjectId::kUnlock, canopen::kUnlockSignature).ok());
  EXPECT_EQ(Read(ObjectId::kWriteAccess), 1u);
  r = Upload(img);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(Read(ObjectId::kStagedBytes), img.size());
  clock_.Advance(61ull * 1000 * 1000 * 1000);
  Step(50);
  EXPECT_EQ(Read(ObjectId::kWriteAccess), 0u);
  // The hardware write-enable input works without unlocking.
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  EXPECT_EQ(Read(ObjectId::kWriteAccess), 1u);
}

TEST_F(Bench, ActivationNeedsReferencedAxesAtRest) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  const testing::AlignedBytes img = UniformImage(6, 77);
  ASSERT_TRUE(Upload(img).ok());
  ASSERT_TRUE(Command(TableCommand::kVerify).ok());  // verify
  const uint32_t status = Read(ObjectId::kTableStatus);
  EXPECT_EQ(canopen::DecodeTableStatus(status).staged, canopen::StagedState::kVerified)
      << std::hex << status;
  EXPECT_EQ(Read(ObjectId::kStagedTableCrc), LoadLe32(img.data() + img.size() - 4));
  EXPECT_EQ(Read(ObjectId::kStagedTableId), 77u);
  // Not referenced: refused with 0x08000022 and an EMCY.
  TransferResult r = Command(TableCommand::kActivate);
  EXPECT_EQ(canopen_client::AbortOf(r), canopen::SdoAbort::kDeviceState);
  EXPECT_NE(r.error().message.find("not allowed in the present device state"), std::string::npos);
  EXPECT_EQ(CountEmcy(canopen::kEmcyRefused), 1);
  // Reference over CAN, then move an axis: still refused while moving.
  ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok());
  EXPECT_TRUE(app_.control_tick().all_referenced());
  step_io_.add_steps(0, 100);
  Step(1);
  EXPECT_EQ(canopen_client::AbortOf(Command(TableCommand::kActivate)),
            canopen::SdoAbort::kDeviceState);
  Step(10000);  // 200 ms at rest
  r = Command(TableCommand::kActivate);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(Read(ObjectId::kActiveTableCrc), LoadLe32(img.data() + img.size() - 4));
  EXPECT_EQ(Read(ObjectId::kActiveTableId), 77u);
  Step(20000);
  EXPECT_EQ(step_io_.drive(0).position(), 100 + 6);
  const uint32_t state = Read(ObjectId::kDeviceState);
  EXPECT_TRUE(canopen::DecodeDeviceState(state).engaged);
  EXPECT_TRUE(canopen::DecodeDeviceState(state).table_active);
  EXPECT_EQ(static_cast<int32_t>(Read(ObjectId::kAppliedCorrection1)), 6 * 256);
  EXPECT_EQ(Read(ObjectId::kCommandedPosition1), 100u);
  // Deactivate: ramps out, and stays off after a reset.
  ASSERT_TRUE(Command(TableCommand::kDeactivate).ok());
  Step(20000);
  EXPECT_EQ(step_io_.drive(0).position(), 100);
  EXPECT_EQ(Read(ObjectId::kActiveTableCrc), 0u);
}

TEST_F(Bench, ActiveTableSurvivesAResetAndBadUploads) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  const testing::AlignedBytes good = UniformImage(3, 1);
  ASSERT_TRUE(Upload(good).ok());
  ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok());
  Step(10000);
  ASSERT_TRUE(Command(TableCommand::kActivate).ok());
  const uint32_t crc = Read(ObjectId::kActiveTableCrc);
  // A corrupt image and an image for another board are staged but never become active.
  testing::AlignedBytes corrupt = UniformImage(9, 2);
  corrupt[60] ^= 0x01;
  ASSERT_TRUE(Upload(corrupt).ok());  // the transfer itself is fine
  EXPECT_EQ(canopen_client::AbortOf(Command(TableCommand::kVerify)),
            canopen::SdoAbort::kCannotStore);
  EXPECT_EQ(canopen_client::AbortOf(Command(TableCommand::kActivate)), canopen::SdoAbort::kNoData);
  EXPECT_EQ(canopen::DecodeTableStatus(Read(ObjectId::kTableStatus)).error, Error::kImageBadCrc);
  ASSERT_TRUE(Upload(UniformImage(9, 3, 500000)).ok());
  EXPECT_EQ(canopen_client::AbortOf(Command(TableCommand::kVerify)),
            canopen::SdoAbort::kCannotStore);
  EXPECT_EQ(canopen::DecodeTableStatus(Read(ObjectId::kTableStatus)).error,
            Error::kConfigResolutionMismatch);
  EXPECT_EQ(Read(ObjectId::kActiveTableCrc), crc);
  // NMT reset node: the stored active table comes back.
  can_.Inject(CanFrame{0x000, false, false, 2, {0x81, kNode}});
  Step(100);
  EXPECT_EQ(Read(ObjectId::kActiveTableCrc), crc);
  EXPECT_TRUE(app_.stored_table_status().ok());
}

TEST_F(Bench, SettingsAreStoredAndAppliedAfterReset) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  EXPECT_EQ(Read(ObjectId::kAxisMaxCorrection2), 1000u);
  ASSERT_TRUE(Write(ObjectId::kAxisMaxCorrection2, 250).ok());
  EXPECT_EQ(canopen_client::AbortOf(Write(ObjectId::kAxisMaxCorrection2, 1u << 20)),
            canopen::SdoAbort::kValueTooHigh);
  EXPECT_TRUE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).settings_pending);
  EXPECT_EQ(app_.settings().board.axis[1].max_correction_steps, 1000);
  EXPECT_EQ(canopen_client::AbortOf(Write(ObjectId::kStoreAll, 0x12345678)),
            canopen::SdoAbort::kCannotStore);
  ASSERT_TRUE(Write(ObjectId::kStoreAll, canopen::kSaveSignature).ok());
  can_.Inject(CanFrame{0x000, false, false, 2, {0x81, 0}});
  Step(100);
  EXPECT_EQ(app_.settings().board.axis[1].max_correction_steps, 250);
  EXPECT_FALSE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).settings_pending);
  // Restore defaults, reset: back to the defaults.
  ASSERT_TRUE(Write(ObjectId::kRestoreAll, canopen::kLoadSignature).ok());
  can_.Inject(CanFrame{0x000, false, false, 2, {0x81, 0}});
  Step(100);
  EXPECT_EQ(app_.settings().board.axis[1].max_correction_steps, 1000);
}

// 0x2137: the machine position, the table's coordinate: the home position (0x2018) at the
// reference edge plus the input steps since; before referencing, the input since start.
TEST_F(Bench, MachinePositionIsTheHomePositionPlusTheInputSinceReferencing) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  ASSERT_TRUE(Write(ObjectId::kAxisHome1, static_cast<uint32_t>(-5000)).ok());
  ASSERT_TRUE(Write(ObjectId::kStoreAll, canopen::kSaveSignature).ok());
  can_.Inject(CanFrame{0x000, false, false, 2, {0x81, 0}});
  Step(100);
  step_io_.add_steps(0, 700);
  Step(10);
  EXPECT_EQ(static_cast<int32_t>(Read(ObjectId::kCommandedPosition1)), 700);
  EXPECT_EQ(static_cast<int32_t>(Read(ObjectId::kMachinePosition1)), 700);  // not referenced
  Home();
  step_io_.add_steps(0, 1234);
  step_io_.add_steps(1, -17);
  Step(10);
  EXPECT_EQ(static_cast<int32_t>(Read(ObjectId::kMachinePosition1)), -5000 + 1234);
  EXPECT_EQ(static_cast<int32_t>(Read(ObjectId::kMachinePosition2)), -17);  // home 0
  EXPECT_EQ(static_cast<int32_t>(Read(ObjectId::kCommandedPosition1)), 700 + 1234);
}

TEST_F(Bench, DiagnosticsAndIdentity) {
  Boot();
  EXPECT_EQ(Read(ObjectId::kVendorId), 0x564F4C43u);
  SdoClient c(kNode);
  c.StartRead(0x1008, 0);
  const TransferResult name = Run(c);
  ASSERT_TRUE(name.ok());
  EXPECT_EQ(std::string(name->begin(), name->end()), "volcomp");
  EXPECT_GT(Read(ObjectId::kCanRxFrames), 0u);
  EXPECT_GT(Read(ObjectId::kTicks), 100u);
  EXPECT_EQ(Read(ObjectId::kOutputOverruns), 0u);
  EXPECT_EQ(Read(ObjectId::kEmcySuppressed), 0u);
  // Heartbeat: 1000 ms by default, state pre-operational.
  sent_.clear();
  can_.TakeSent();
  Step(50 * 1100);
  int hb = 0;
  for (const CanFrame& f : can_.TakeSent()) hb += f.id == 0x700u + kNode && f.data[0] == 0x7F;
  EXPECT_EQ(hb, 1);
}

using Frames = std::vector<std::string>;

bool Contains(const Frames& frames, const std::string& f) {
  return std::find(frames.begin(), frames.end(), f) != frames.end();
}

// NMT reset communication puts the stored 0x1017 back in force (CiA 301): an unsaved write does
// not survive it; a stored one (0x1010 "save") survives it and a reset node.
TEST_F(Bench, ResetCommunicationRestoresTheStoredHeartbeatTime) {
  Boot();
  EXPECT_EQ(Exchange("2B17100064000000"), Frames{"590#6017100000000000"});  // 0x1017 = 100 ms
  EXPECT_EQ(Exchange("4017100000000000"), Frames{"590#4B17100064000000"});
  EXPECT_TRUE(Contains(Nmt(0x82), "710#00"));  // reset communication: boot-up
  EXPECT_EQ(Exchange("4017100000000000"), Frames{"590#4B171000E8030000"});  // 1000 ms again
  // Heartbeats 1000 ms apart, not 100.
  can_.TakeSent();
  Step(50 * 950);
  int hb = 0;
  for (const CanFrame& f : can_.TakeSent()) hb += f.id == 0x700u + kNode;
  EXPECT_EQ(hb, 0);

  // 500 ms, 0x1015 = 0, stored: both survive the resets.
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  EXPECT_EQ(Exchange("2B171000F4010000"), Frames{"590#6017100000000000"});
  EXPECT_EQ(Exchange("2B15100000000000"), Frames{"590#6015100000000000"});
  EXPECT_EQ(Exchange("2310100173617665"), Frames{"590#6010100100000000"});  // "save"
  EXPECT_FALSE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).settings_pending);
  EXPECT_TRUE(Contains(Nmt(0x82), "710#00"));
  EXPECT_EQ(Exchange("4017100000000000"), Frames{"590#4B171000F4010000"});
  EXPECT_EQ(Exchange("4015100000000000"), Frames{"590#4B15100000000000"});
  EXPECT_TRUE(Contains(Nmt(0x81), "710#00"));  // reset node: from the stored settings
  EXPECT_EQ(Exchange("4017100000000000"), Frames{"590#4B171000F4010000"});
  EXPECT_EQ(Exchange("4015100000000000"), Frames{"590#4B15100000000000"});
}

// "Restore defaults" (0x1011:1 = "load"): the next reset communication brings the default
// communication parameters back, not the ones stored before (CiA 301 7.5.2.14).
TEST_F(Bench, RestoreDefaultsReachesTheCommunicationReset) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  EXPECT_EQ(Exchange("2B171000F4010000"), Frames{"590#6017100000000000"});  // 0x1017 = 500 ms
  EXPECT_EQ(Exchange("2310100173617665"), Frames{"590#6010100100000000"});  // "save"
  EXPECT_EQ(Exchange("231110016C6F6164"), Frames{"590#6011100100000000"});  // "load"
  EXPECT_EQ(Exchange("4017100000000000"), Frames{"590#4B171000F4010000"});  // in force until reset
  EXPECT_TRUE(Contains(Nmt(0x82), "710#00"));
  EXPECT_EQ(Exchange("4017100000000000"), Frames{"590#4B171000E8030000"});  // 1000 ms: default
}

// A reset communication in the middle of a table upload ends it: 0x2102 says aborted (error 80),
// not "receiving" until the next upload.
TEST_F(Bench, ResetCommunicationDuringAnUploadEndsItAsAborted) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  EXPECT_EQ(Exchange("C600210014000000"), Frames{"590#A40021007F000000"});
  EXPECT_EQ(Exchange("0130313233343536"), Frames{});
  EXPECT_TRUE(Contains(Nmt(0x82), "710#00"));
  // Result 7 (transfer) << 1 = 0x0E, failed 0x04, error 80 = 0x50.
  EXPECT_EQ(Exchange("4002210000000000"), Frames{"590#430221000E045000"});
}

// 0x2102 after a transfer that broke says how: bits 1-7 result, 8-15 staged state (4 failed),
// 16-31 the volcomp error (error_codes.def): aborted 80, CRC-16 81; never "I/O error".
TEST_F(Bench, TableStatusSaysATransferWasAbortedOrFailedItsCrc) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  // Block download of 20 bytes, aborted by the client after the first segment, with its own
  // timeout (0x05040000) and CRC (0x05040004) codes and a general one: each recorded as the
  // client's abort (result 7 << 1 = 0x0E, failed 0x04, error 83 = 0x53) with its code in 0x210A,
  // and no EMCY (the board detected nothing).
  for (const char* code : {"00000405", "04000405", "00000008"}) {
    EXPECT_EQ(Exchange("C600210014000000"), Frames{"590#A40021007F000000"});
    EXPECT_EQ(Exchange("0130313233343536"), Frames{});
    EXPECT_EQ(Exchange(std::string("80002100") + code), Frames{});
    Step(2000);  // 200 ms: the discard window closes, an EMCY would have left
    EXPECT_EQ(Exchange("4002210000000000"), Frames{"590#430221000E045300"});
    EXPECT_EQ(Exchange("400A210000000000"), Frames{std::string("590#430A2100") + code});
  }
  EXPECT_EQ(Exchange("4001100000000000"), Frames{"590#4F01100000000000"});  // 0x1001 clear
  EXPECT_EQ(Exchange("4003100000000000"), Frames{"590#4F03100000000000"});  // no history
  EXPECT_EQ(CountEmcy(canopen::kEmcySdoTransferFailed), 0);
  EXPECT_EQ(sent_.size() - std::count_if(sent_.begin(), sent_.end(),
                                         [](const CanFrame& f) { return f.id != 0x80u + kNode; }),
            0u);  // no EMCY of any code
  // The same 20 bytes with a wrong CRC-16 (0x34F1 is right).
  EXPECT_EQ(Exchange("C600210014000000"), Frames{"590#A40021007F000000"});
  EXPECT_EQ(Exchange("0130313233343536"), Frames{});
  EXPECT_EQ(Exchange("0237383941424344"), Frames{});
  EXPECT_EQ(Exchange("8345464748494A00"), Frames{"590#A2037F0000000000"});
  EXPECT_EQ(Exchange("C5F1350000000000"), Frames{"590#8000210004000405"});
  // Result 3 (CRC) << 1 = 0x06, failed 0x04, error 81 = 0x51; the board's own abort code.
  EXPECT_EQ(Exchange("4002210000000000"), Frames{"590#4302210006045100"});
  EXPECT_EQ(Exchange("400A210000000000"), Frames{"590#430A210004000405"});
  // Silence: the board times the transfer out (0x05040000), error 82 = 0x52.
  EXPECT_EQ(Exchange("C600210014000000"), Frames{"590#A40021007F000000"});
  EXPECT_EQ(Exchange("0130313233343536"), Frames{});
  Step(50 * 1200);
  Frames quiet;
  for (const CanFrame& f : can_.TakeSent()) quiet.push_back(testing::ToString(f));
  EXPECT_TRUE(Contains(quiet, "590#A2017F0000000000"));  // re-ack of the partial sub-block
  EXPECT_TRUE(Contains(quiet, "590#8000210000000405"));  // timed out
  EXPECT_EQ(Exchange("4002210000000000"), Frames{"590#430221000E045200"});
}

// Verification (0x2101 = 4) refused says what is wrong with the staged data (CiA 301 7.2.4.3.17),
// never 0x06090030 (4 is a valid value of 0x2101): nothing complete staged 0x08000024, an image
// that fails the checks 0x08000020 (with EMCY 0x6300 and the error in 0x2102).
TEST_F(Bench, VerifyRefusalsSayWhatIsWrongWithTheStagedData) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  EXPECT_EQ(Exchange("2F01210004000000"), Frames{"590#8001210024000008"});
  EXPECT_EQ(CountEmcy(canopen::kEmcyRefused), 1);
  // An upload the client aborted is no image either.
  EXPECT_EQ(Exchange("C600210014000000"), Frames{"590#A40021007F000000"});
  EXPECT_EQ(Exchange("0130313233343536"), Frames{});
  EXPECT_EQ(Exchange("8000210000000405"), Frames{});
  Step(2000);
  EXPECT_EQ(Exchange("2F01210004000000"), Frames{"590#8001210024000008"});
  // 20 bytes that are no image: complete, then refused by the checks.
  EXPECT_EQ(Exchange("C600210014000000"), Frames{"590#A40021007F000000"});
  EXPECT_EQ(Exchange("0130313233343536"), Frames{});
  EXPECT_EQ(Exchange("0237383941424344"), Frames{});
  EXPECT_EQ(Exchange("8345464748494A00"), Frames{"590#A2037F0000000000"});
  EXPECT_EQ(Exchange("C5F1340000000000"), Frames{"590#A100000000000000"});
  EXPECT_EQ(Exchange("2F01210004000000"), Frames{"590#8001210020000008"});
  Step(1000);  // the EMCY pair leaves as the inhibit time (0x1015) allows
  Exchange("4000100000000000");
  EXPECT_EQ(CountEmcy(canopen::kEmcyTableInvalid), 1);
  EXPECT_EQ(canopen::DecodeTableStatus(Read(ObjectId::kTableStatus)).staged,
            canopen::StagedState::kFailed);
  EXPECT_EQ(Exchange("400A210000000000"), Frames{"590#430A210000000000"});  // no transfer broke
}

// The PC tool explains a client's abort with its code (0x2102 error 83, 0x210A), and a refused
// verification as a problem of the staged data, not as write protection.
TEST_F(Bench, StagingReasonsNameTheClientsAbortCodeAndTheVerifyRefusal) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  EXPECT_EQ(Exchange("C600210014000000"), Frames{"590#A40021007F000000"});
  EXPECT_EQ(Exchange("0130313233343536"), Frames{});
  EXPECT_EQ(Exchange("8000210000000405"), Frames{});
  Step(2000);
  const canopen_client::FrameLink link = Link();
  canopen_client::NodeObjects node(link, kNode);
  EXPECT_EQ(canopen_client::StagingFailureReason(node),
            "the transfer was aborted by the client (its abort code: 0x210A) "
            "(kTransferAbortedByClient): aborted by the client, code 0x05040000 (SDO protocol "
            "timed out)");
  ASSERT_TRUE(Upload(UniformImage(9, 0x4F, 500000)).ok());  // for another board
  const canopen_client::SdoOutcome r =
      canopen_client::WriteTableCommand(node, TableCommand::kVerify);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().abort, canopen::SdoAbort::kCannotStore);
  EXPECT_EQ(r.error().message.rfind("verifying on the board (0x2101 = 4): ", 0), 0u)
      << r.error().message;
  EXPECT_NE(r.error().message.find("; the staged image is not valid for this board"),
            std::string::npos)
      << r.error().message;
  EXPECT_EQ(r.error().message.find("write-protected"), std::string::npos) << r.error().message;
}

// 0x2105-0x2107 describe what is staged now. A verified staged image is in flash: after a reset
// node it is mounted, verified again and reported as before; once cleared it is gone, also after
// a reset.
TEST_F(Bench, StagedImageSurvivesAResetAndItsIdsDoNotOutliveIt) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  const testing::AlignedBytes img = UniformImage(5, 0x4D);
  const uint32_t crc = LoadLe32(img.data() + img.size() - 4);
  char crc_hex[9], size_hex[9];
  std::snprintf(crc_hex, sizeof crc_hex, "%02X%02X%02X%02X", crc & 0xFF, (crc >> 8) & 0xFF,
                (crc >> 16) & 0xFF, crc >> 24);
  const uint32_t size = static_cast<uint32_t>(img.size());
  std::snprintf(size_hex, sizeof size_hex, "%02X%02X%02X%02X", size & 0xFF, (size >> 8) & 0xFF,
                (size >> 16) & 0xFF, size >> 24);
  ASSERT_TRUE(Upload(img).ok());
  ASSERT_TRUE(Command(TableCommand::kVerify).ok());
  const Frames staged_crc{std::string("590#43052100") + crc_hex};
  const Frames staged_size{std::string("590#43062100") + size_hex};
  const Frames staged_id{"590#430721004D000000"};
  const Frames verified{"590#4302210000030000"};  // staged state 3, result ok
  EXPECT_EQ(Exchange("4005210000000000"), staged_crc);
  EXPECT_EQ(Exchange("4006210000000000"), staged_size);
  EXPECT_EQ(Exchange("4007210000000000"), staged_id);
  EXPECT_EQ(Exchange("4002210000000000"), verified);

  EXPECT_TRUE(Contains(Nmt(0x81), "710#00"));  // reset node
  EXPECT_EQ(Exchange("4005210000000000"), staged_crc);
  EXPECT_EQ(Exchange("4006210000000000"), staged_size);
  EXPECT_EQ(Exchange("4007210000000000"), staged_id);
  EXPECT_EQ(Exchange("4002210000000000"), verified);
  EXPECT_TRUE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).staged_verified);

  // Cleared (0x2101 = 3): nothing staged, before and after a reset.
  EXPECT_EQ(Exchange("2F01210003000000"), Frames{"590#6001210000000000"});
  const Frames empty{"590#4302210000000000"};
  for (int reset = 0; reset < 2; ++reset) {
    EXPECT_EQ(Exchange("4005210000000000"), Frames{"590#4305210000000000"}) << reset;
    EXPECT_EQ(Exchange("4006210000000000"), Frames{"590#4306210000000000"}) << reset;
    EXPECT_EQ(Exchange("4007210000000000"), Frames{"590#4307210000000000"}) << reset;
    EXPECT_EQ(Exchange("4002210000000000"), empty) << reset;
    if (reset == 0) {
      EXPECT_TRUE(Contains(Nmt(0x81), "710#00"));
    }
  }

  // Complete but not verified: verified at mount. Activated: nothing staged (the bank with the
  // table active before is not a staged image), also after a reset.
  ASSERT_TRUE(Upload(img).ok());
  EXPECT_TRUE(Contains(Nmt(0x81), "710#00"));
  EXPECT_EQ(Exchange("4002210000000000"), verified);
  ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok());
  Step(10000);
  ASSERT_TRUE(Command(TableCommand::kActivate).ok());
  ASSERT_TRUE(Upload(UniformImage(7, 0x4E)).ok());
  ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok());
  Step(10000);
  ASSERT_TRUE(Command(TableCommand::kActivate).ok());
  EXPECT_TRUE(Contains(Nmt(0x81), "710#00"));
  EXPECT_EQ(Exchange("4003210000000000"), Frames{"590#430321004E000000"});  // active id
  EXPECT_EQ(Exchange("4002210000000000"), empty);
  EXPECT_EQ(Exchange("4007210000000000"), Frames{"590#4307210000000000"});
  // An upload cut by a reset node: the bank it went to held the table active before (0x4D), which
  // must not come back as staged.
  EXPECT_EQ(Exchange("C600210014000000"), Frames{"590#A40021007F000000"});
  EXPECT_EQ(Exchange("0130313233343536"), Frames{});
  EXPECT_TRUE(Contains(Nmt(0x81), "710#00"));
  EXPECT_EQ(Exchange("4002210000000000"), empty);
  EXPECT_EQ(Exchange("4007210000000000"), Frames{"590#4307210000000000"});

  // An image for another board fails verification and does not come back after a reset; nor does
  // an upload cut by an abort.
  ASSERT_TRUE(Upload(UniformImage(9, 0x4F, 500000)).ok());
  EXPECT_EQ(canopen_client::AbortOf(Command(TableCommand::kVerify)),
            canopen::SdoAbort::kCannotStore);
  EXPECT_TRUE(Contains(Nmt(0x81), "710#00"));
  EXPECT_EQ(Exchange("4002210000000000"), empty);
  EXPECT_EQ(Exchange("C600210014000000"), Frames{"590#A40021007F000000"});
  EXPECT_EQ(Exchange("0130313233343536"), Frames{});
  EXPECT_EQ(Exchange("8000210000000008"), Frames{});
  EXPECT_TRUE(Contains(Nmt(0x81), "710#00"));
  EXPECT_EQ(Exchange("4002210000000000"), empty);
}

// The PC tool's staging steps (tools/canopen_client table_staging.hpp, used by `volcomp upload` and
// the simulator's demo) against the real board objects.
TEST_F(Bench, StagingStepsUnlockStageAndVerify) {
  Boot();
  const testing::AlignedBytes img = UniformImage(5, 42);
  const uint32_t crc = LoadLe32(img.data() + img.size() - 4);
  const canopen_client::FrameLink link = Link();
  canopen_client::NodeObjects node(link, kNode);
  canopen_client::SdoOutcome r = canopen_client::PrepareStaging(node);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(unlock_requests_, 1);  // write-protected: the steps unlocked it
  EXPECT_EQ(Read(ObjectId::kWriteAccess), 1u);
  r = node.WriteDomain(ObjectId::kTableData,
                       std::vector<uint8_t>(img.data(), img.data() + img.size()));
  ASSERT_TRUE(r.ok()) << r.error().message;
  r = canopen_client::VerifyStaged(node, crc);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(Read(ObjectId::kStagedTableCrc), crc);
  EXPECT_EQ(Read(ObjectId::kStagedTableId), 42u);
  // A CRC that is not the image's: a failure of its own (no abort code), naming both values.
  r = canopen_client::VerifyStaged(node, crc ^ 1u);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().abort, canopen::SdoAbort::kNone);
  EXPECT_EQ(r.error().code, Error::kImageBadCrc);
  EXPECT_NE(r.error().message.find("staged CRC-32 " + tools::Hex32(crc) + ", expected " +
                                   tools::Hex32(crc ^ 1u)),
            std::string::npos)
      << r.error().message;
  // Activation before referencing: the step, the board's reason and what to do.
  r = canopen_client::Explain(
      node.Write(ObjectId::kTableControl, canopen::Value(TableCommand::kActivate)), "activating");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().abort, canopen::SdoAbort::kDeviceState);
  EXPECT_TRUE(r.error().by_server);
  EXPECT_EQ(r.error().code, Error::kTransferAborted);
  EXPECT_EQ(r.error().message.rfind("activating: ", 0), 0u) << r.error().message;
  EXPECT_NE(r.error().message.find("; the axes must be referenced (homed) and at rest"),
            std::string::npos)
      << r.error().message;
  // Already writable (hardware input): no unlock request.
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  ASSERT_TRUE(canopen_client::EnsureWritable(node).ok());
  EXPECT_EQ(unlock_requests_, 1);
}

TEST_F(Bench, StagingStepsNameTheStepThatFailed) {
  Boot();
  const canopen_client::FrameLink link = Link();
  canopen_client::NodeObjects node(link, kNode);
  ASSERT_TRUE(canopen_client::PrepareStaging(node).ok());
  // Nothing was downloaded: the board's verification refuses.
  const canopen_client::SdoOutcome r = canopen_client::VerifyStaged(node, 0x12345678u);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(canopen_client::AbortOf(r), canopen::SdoAbort::kNone);
  EXPECT_EQ(r.error().message.rfind("verifying on the board (0x2101 = 4): ", 0), 0u)
      << r.error().message;
}

// Doing less than the table asks is visible: a table asking 100 steps on axis 1 of a board whose
// max correction is 50 is applied as 50, flagged clamped (0x2134), counted (0x2135) and reported
// by one EMCY 0xFF20 naming axis 1, however long it stays clamped. The ramp-in at rest runs at the
// rate limit (counted in 0x2136) without an EMCY; a ramp while the axes move sends one.
TEST_F(Bench, ClampingAndRateLimitingAreFlaggedCountedAndReportedOnce) {
  config_.axis[0].max_correction_steps = 50;
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  ASSERT_TRUE(Upload(UniformImage(100, 9)).ok());
  ASSERT_TRUE(Command(TableCommand::kVerify).ok());
  ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok());
  Step(10000);
  sent_.clear();
  ASSERT_TRUE(Command(TableCommand::kActivate).ok());
  Step(20000);  // 400 ms: the ramp to the clamped 50 steps takes about 35 ms
  EXPECT_EQ(static_cast<int32_t>(Read(ObjectId::kAppliedCorrection1)), 50 * 256);
  EXPECT_EQ(Read(ObjectId::kCorrectionLimited1), uint32_t{canopen::kLimitClamped});
  EXPECT_EQ(Read(ObjectId::kCorrectionLimited2), 0u);
  const uint32_t clamped = Read(ObjectId::kClampedRefreshes1);
  // One refresh of axis 1 every 6 compensation runs (one run every CompensationDivider() ticks),
  // all clamped.
  EXPECT_GT(clamped, 20000u / (6 * CompensationDivider(config_.tick_hz)) - 100);
  EXPECT_EQ(Read(ObjectId::kClampedRefreshes2), 0u);
  EXPECT_GT(Read(ObjectId::kRateLimitedRefreshes1), 0u);  // the ramp in
  EXPECT_EQ(Read(ObjectId::kRateLimitedRefreshes2), 0u);
  Step(20000);
  EXPECT_GT(Read(ObjectId::kClampedRefreshes1), clamped);
  ASSERT_EQ(CountEmcy(canopen::kEmcyCorrectionLimited), 1);
  for (const CanFrame& f : sent_) {
    canopen::Emcy e;
    if (!canopen::DecodeEmcy(f, kNode, &e) || e.code != canopen::kEmcyCorrectionLimited) continue;
    EXPECT_EQ(e.clamped_axes(), 0x01);
    EXPECT_EQ(e.rate_limited_axes(), 0x00);  // the ramp was at rest
  }
  // Compensation off: the correction ramps out, the flags clear after the hold time.
  ASSERT_TRUE(Write(ObjectId::kCompensationEnable, 0).ok());
  Step(20000);
  EXPECT_EQ(Read(ObjectId::kAppliedCorrection1), 0u);
  EXPECT_EQ(Read(ObjectId::kCorrectionLimited1), 0u);
  // On again while axis 1 moves: clamped again (one EMCY), and the ramp in is rate limited in
  // motion (one more EMCY), both naming axis 1.
  sent_.clear();
  step_io_.add_steps(0, 10);
  Step(1);
  ASSERT_TRUE(Write(ObjectId::kCompensationEnable, 1).ok());
  for (int i = 0; i < 40; ++i) {  // 10 steps per ms for 40 ms
    step_io_.add_steps(0, 10);
    Step(50);
  }
  for (const CanFrame& f : can_.TakeSent()) sent_.push_back(f);
  ASSERT_EQ(CountEmcy(canopen::kEmcyCorrectionLimited), 2);
  uint8_t clamped_axes = 0, limited_axes = 0;
  for (const CanFrame& f : sent_) {
    canopen::Emcy e;
    if (!canopen::DecodeEmcy(f, kNode, &e) || e.code != canopen::kEmcyCorrectionLimited) continue;
    clamped_axes |= e.clamped_axes();
    limited_axes |= e.rate_limited_axes();
  }
  EXPECT_EQ(clamped_axes, 0x01);
  EXPECT_EQ(limited_axes, 0x01);
}

// A refused store says which rule and which axis (0x2123), before and after the refusal.
TEST_F(Bench, SettingsCheckNamesTheRuleAndTheAxis) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  EXPECT_EQ(Read(ObjectId::kSettingsCheck), 0u);
  // Axis 2's drive cannot follow the fastest input plus the correction.
  ASSERT_TRUE(Write(ObjectId::kAxisDriveMaxRate2, 1000).ok());
  EXPECT_EQ(canopen_client::AbortOf(Write(ObjectId::kStoreAll, canopen::kSaveSignature)),
            canopen::SdoAbort::kInvalidValue);
  const canopen::SettingsCheck c = canopen::DecodeSettingsCheck(Read(ObjectId::kSettingsCheck));
  EXPECT_EQ(c.finding.rule, ConfigRule::kDriveKeepsUp);
  EXPECT_EQ(c.finding.axis, 2);
  EXPECT_EQ(c.error, Error::kConfigInvalid);
  canopen_client::FrameLink link = Link();
  canopen_client::NodeObjects node(link, kNode);
  const std::string why = canopen_client::SettingsRefusalReason(node);
  EXPECT_NE(why.find("axis 2: "), std::string::npos) << why;
  EXPECT_NE(why.find("drive max rate (0x201D)"), std::string::npos) << why;
}

// The step/dir board keeps the step output's rule too: pulse width + step space of 2.5 us each
// send at most 200 kHz, so a drive max rate of 400 kHz is refused at the store (0x2123 names rule
// kPulseTiming and the axis, with the PC tool's words), 200 kHz is taken. (The CAN gateway does not
// keep it: GatewayAppMappingTest.StepPulseTimingDoesNotConcernTheGateway.)
TEST_F(Bench, StepBoardRefusesADriveRateItsPulseTimingCannotSend) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  ASSERT_TRUE(Write(ObjectId::kAxisPulseWidth1, 2500).ok());
  ASSERT_TRUE(Write(ObjectId::kAxisStepSpace1, 2500).ok());
  ASSERT_TRUE(Write(ObjectId::kAxisInputMaxRate1, 190000).ok());
  ASSERT_TRUE(Write(ObjectId::kAxisDriveMaxRate1, 400000).ok());
  EXPECT_EQ(canopen_client::AbortOf(Write(ObjectId::kStoreAll, canopen::kSaveSignature)),
            canopen::SdoAbort::kInvalidValue);
  const canopen::SettingsCheck c = canopen::DecodeSettingsCheck(Read(ObjectId::kSettingsCheck));
  EXPECT_EQ(c.finding.rule, ConfigRule::kPulseTiming);
  EXPECT_EQ(c.finding.axis, 1);
  canopen_client::FrameLink link = Link();
  canopen_client::NodeObjects node(link, kNode);
  const std::string why = canopen_client::SettingsRefusalReason(node);
  EXPECT_NE(why.find("axis 1: on a step output"), std::string::npos) << why;
  ASSERT_TRUE(Write(ObjectId::kAxisDriveMaxRate1, 200000).ok());  // 1e9 / 5000 ns: exactly
  EXPECT_EQ(Read(ObjectId::kSettingsCheck), 0u);
  EXPECT_TRUE(Write(ObjectId::kStoreAll, canopen::kSaveSignature).ok());
}

// verify --readback of the active table: 0x2109 is the active image even while another is staged.
TEST_F(Bench, ActiveTableDataIsTheActiveImageWhileAnotherIsStaged) {
  Boot();
  io_.SetInput(InputLine::kWriteEnable, true);
  const testing::AlignedBytes a = UniformImage(6, 1), b = UniformImage(7, 2);
  ASSERT_TRUE(Upload(a).ok());
  ASSERT_TRUE(Command(TableCommand::kVerify).ok());
  ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok());
  Step(10000);
  ASSERT_TRUE(Command(TableCommand::kActivate).ok());
  ASSERT_TRUE(Upload(b).ok());
  canopen_client::FrameLink link = Link();
  canopen_client::NodeObjects node(link, kNode);
  const auto active = node.ReadDomain(ObjectId::kActiveTableData);
  const auto staged = node.ReadDomain(ObjectId::kTableData);
  ASSERT_TRUE(active.ok());
  ASSERT_TRUE(staged.ok());
  EXPECT_EQ(*active, std::vector<uint8_t>(a.data(), a.data() + a.size()));
  EXPECT_EQ(*staged, std::vector<uint8_t>(b.data(), b.data() + b.size()));
}

// ---- Transmit PDOs (CiA 301; docs/canopen.md, "PDOs") ------------------------------------------
// The expected bytes are put together here from the objects' values read by SDO and the CiA 301
// layout (little-endian, in mapping order), not by the node's mapping code.

class PdoBench : public Bench {
 protected:
  using Timed = std::vector<std::pair<uint64_t, CanFrame>>;
  // The frames with CAN-ID `id` the board sends in the next `ms` main-loop passes (1 ms each),
  // with the millisecond each left.
  Timed Watch(uint32_t id, int ms) {
    Timed out;
    for (int i = 0; i < ms; ++i) {
      Step(50);
      for (const CanFrame& f : can_.TakeSent()) {
        if (f.id == id) out.push_back({clock_.now() / 1000000, f});
      }
    }
    return out;
  }
  // An expedited SDO download of `bytes` (1, 2 or 4) to (index, sub): the response frame.
  std::string Download(uint16_t index, uint8_t sub, uint32_t value, int bytes) {
    const uint8_t cs = bytes == 1 ? 0x2F : bytes == 2 ? 0x2B : 0x23;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%02X%02X%02X%02X%02X%02X%02X%02X", cs, index & 0xFF, index >> 8,
                  sub, value & 0xFF, (value >> 8) & 0xFF, (value >> 16) & 0xFF, value >> 24);
    const Frames r = Exchange(hex);
    return r.size() == 1 ? r[0] : "none";
  }
  static std::string Ok(uint16_t index, uint8_t sub) {
    char s[32];
    std::snprintf(s, sizeof s, "590#60%02X%02X%02X00000000", index & 0xFF, index >> 8, sub);
    return s;
  }
  static std::string Abort(uint16_t index, uint8_t sub, uint32_t code) {
    char s[32];
    std::snprintf(s, sizeof s, "590#80%02X%02X%02X%02X%02X%02X%02X", index & 0xFF, index >> 8, sub,
                  code & 0xFF, (code >> 8) & 0xFF, (code >> 16) & 0xFF, code >> 24);
    return s;
  }
  // Axis 1 clamped at 50 steps by a table asking 100, the board at rest.
  void ClampAxis1() {
    config_.axis[0].max_correction_steps = 50;
    Boot();
    io_.SetInput(InputLine::kWriteEnable, true);
    ASSERT_TRUE(Upload(UniformImage(100, 9)).ok());
    ASSERT_TRUE(Command(TableCommand::kVerify).ok());
    ASSERT_TRUE(Write(ObjectId::kReferenceAxes, 0x07).ok());
    Step(10000);
    ASSERT_TRUE(Command(TableCommand::kActivate).ok());
    Step(20000);
  }
};

int16_t RoundedSteps(uint32_t q8_raw) {
  const double steps = std::round(static_cast<int32_t>(q8_raw) / 256.0);
  return static_cast<int16_t>(std::clamp(steps, -32767.0, 32767.0));
}

TEST_F(PdoBench, DefaultTpdosCarryStateFlagsAndCorrectionsOnlyInOperational) {
  ClampAxis1();
  EXPECT_TRUE(Watch(0x190, 300).empty());                        // pre-operational: no PDO
  can_.Inject(CanFrame{0x000, false, false, 2, {0x01, kNode}});  // NMT start
  const Timed t1 = Watch(0x190, 3);
  ASSERT_EQ(t1.size(), 1u);  // at once on entering operational
  const CanFrame& f = t1[0].second;
  const uint32_t state = Read(ObjectId::kDeviceState);
  uint8_t clamped = 0, limited = 0;
  for (uint8_t a = 0; a < 6; ++a) {
    const uint32_t flags = Read(canopen::AxisEntry(ObjectId::kCorrectionLimited1, a).id);
    clamped = static_cast<uint8_t>(clamped | ((flags & canopen::kLimitClamped) ? 1u << a : 0));
    limited = static_cast<uint8_t>(limited | ((flags & canopen::kLimitRateLimited) ? 1u << a : 0));
  }
  const int16_t c1 = RoundedSteps(Read(ObjectId::kAppliedCorrection1));
  const int16_t c2 = RoundedSteps(Read(ObjectId::kAppliedCorrection2));
  EXPECT_EQ(c1, 50);
  EXPECT_EQ(clamped, 0x01);
  EXPECT_TRUE(canopen::DecodeDeviceState(state).engaged);
  const uint8_t expected1[8] = {static_cast<uint8_t>(state),
                                static_cast<uint8_t>(state >> 8),
                                clamped,
                                limited,
                                static_cast<uint8_t>(c1),
                                static_cast<uint8_t>(c1 >> 8),
                                static_cast<uint8_t>(c2),
                                static_cast<uint8_t>(c2 >> 8)};
  ASSERT_EQ(f.dlc, 8);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(f.data[i], expected1[i]) << "byte " << i;
  // 0x2138 is 0x2131 rounded to steps.
  EXPECT_EQ(static_cast<int16_t>(Read(ObjectId::kCorrectionSteps1)), c1);

  // TPDO2: axes 3-6.
  can_.Inject(CanFrame{0x000, false, false, 2, {0x80, kNode}});  // pre-operational
  Step(100);
  can_.Inject(CanFrame{0x000, false, false, 2, {0x01, kNode}});
  const Timed t2 = Watch(0x290, 3);
  ASSERT_EQ(t2.size(), 1u);
  ASSERT_EQ(t2[0].second.dlc, 8);
  for (uint8_t a = 2; a < 6; ++a) {
    const int16_t c = RoundedSteps(Read(canopen::AxisEntry(ObjectId::kAppliedCorrection1, a).id));
    EXPECT_EQ(t2[0].second.data[2 * (a - 2)], static_cast<uint8_t>(c));
    EXPECT_EQ(t2[0].second.data[2 * (a - 2) + 1], static_cast<uint8_t>(c >> 8));
  }

  // At rest: the event timer, one frame every 100 ms.
  const Timed rest = Watch(0x190, 1000);
  EXPECT_GE(rest.size(), 9u);
  EXPECT_LE(rest.size(), 11u);
  for (size_t i = 1; i < rest.size(); ++i) {
    EXPECT_GE(rest[i].first - rest[i - 1].first, 99u);
    EXPECT_LE(rest[i].first - rest[i - 1].first, 102u);
  }
  // Stopped, pre-operational: none.
  can_.Inject(CanFrame{0x000, false, false, 2, {0x02, kNode}});
  EXPECT_TRUE(Watch(0x190, 500).empty());
  can_.Inject(CanFrame{0x000, false, false, 2, {0x80, kNode}});
  EXPECT_TRUE(Watch(0x190, 500).empty());
  EXPECT_TRUE(Watch(0x290, 10).empty());
}

TEST_F(PdoBench, InhibitTimeHoldsFramesApartEvenWithAShortEventTimer) {
  Boot();
  can_.Inject(CanFrame{0x000, false, false, 2, {0x01, kNode}});
  Step(50);
  // The event timer may change at any time; 5 ms asks more often than the 20 ms inhibit time
  // allows: frames leave every 21 ms (20 ms rounded up plus the clock's 1 ms), never sooner.
  EXPECT_EQ(Download(0x1800, 5, 5, 2), Ok(0x1800, 5));
  const Timed f = Watch(0x190, 500);
  ASSERT_GE(f.size(), 20u);
  for (size_t i = 1; i < f.size(); ++i) {
    EXPECT_GE(f[i].first - f[i - 1].first, 20u) << i;
    EXPECT_LE(f[i].first - f[i - 1].first, 23u) << i;
  }
  // Moving axis 1 changes the state (moving) and the commanded position: still no faster.
  int moved = 0;
  Timed m;
  for (int i = 0; i < 300; ++i) {
    step_io_.add_steps(0, 5);
    moved += 5;
    const Timed one = Watch(0x190, 1);
    m.insert(m.end(), one.begin(), one.end());
  }
  ASSERT_GE(m.size(), 10u);
  for (size_t i = 1; i < m.size(); ++i) EXPECT_GE(m[i].first - m[i - 1].first, 20u) << i;
}

TEST_F(PdoBench, WriteRulesAbortCodesAndRemappingBySdo) {
  Boot();
  can_.Inject(CanFrame{0x000, false, false, 2, {0x01, kNode}});
  Step(50);
  // While TPDO1 exists: COB-ID (other than bit 31), transmission type, inhibit time refused
  // (0x06090030), the mapping count too (0x08000022); the event timer may change.
  EXPECT_EQ(Download(0x1800, 1, 0x1A0, 4), Abort(0x1800, 1, 0x06090030));
  EXPECT_EQ(Download(0x1800, 2, 255, 1), Abort(0x1800, 2, 0x06090030));
  EXPECT_EQ(Download(0x1800, 3, 50, 2), Abort(0x1800, 3, 0x06090030));
  EXPECT_EQ(Download(0x1A00, 0, 0, 1), Abort(0x1A00, 0, 0x08000022));
  EXPECT_EQ(Download(0x1A00, 1, 0x21300120, 4), Abort(0x1A00, 1, 0x08000022));
  EXPECT_EQ(Download(0x1800, 5, 1000, 2), Ok(0x1800, 5));
  EXPECT_EQ(Download(0x1800, 4, 0, 1), Abort(0x1800, 4, 0x06090011));  // sub 4: none
  EXPECT_EQ(Download(0x1800, 0, 5, 1), Abort(0x1800, 0, 0x06010002));  // const
  // Bit 31 set: the PDO no longer exists, nothing is sent.
  EXPECT_EQ(Download(0x1800, 1, 0x80000190, 4), Ok(0x1800, 1));
  EXPECT_TRUE(Watch(0x190, 1200).empty());
  // SYNC types are not offered; restricted and 29-bit CAN-IDs are refused.
  EXPECT_EQ(Download(0x1800, 2, 1, 1), Abort(0x1800, 2, 0x06090030));
  EXPECT_EQ(Download(0x1800, 1, 0x80000590, 4), Abort(0x1800, 1, 0x06090030));
  EXPECT_EQ(Download(0x1800, 1, 0xA0000190, 4), Abort(0x1800, 1, 0x06090030));
  // Mapping entries only with sub 0 = 0.
  EXPECT_EQ(Download(0x1A00, 1, 0x21300120, 4), Abort(0x1A00, 1, 0x08000022));
  EXPECT_EQ(Download(0x1A00, 0, 0, 1), Ok(0x1A00, 0));
  EXPECT_EQ(Download(0x1A00, 1, 0x21300120, 4), Ok(0x1A00, 1));  // commanded position 1, I32
  EXPECT_EQ(Download(0x1A00, 2, 0x20000108, 4), Ok(0x1A00, 2));  // node-ID setting: no
  EXPECT_EQ(Download(0x1A00, 0, 2, 1), Abort(0x1A00, 0, 0x06040041));
  EXPECT_EQ(Download(0x1A00, 2, 0x21300210, 4), Ok(0x1A00, 2));  // wrong length: no
  EXPECT_EQ(Download(0x1A00, 0, 2, 1), Abort(0x1A00, 0, 0x06040041));
  EXPECT_EQ(Download(0x1A00, 2, 0x21370120, 4), Ok(0x1A00, 2));
  EXPECT_EQ(Download(0x1A00, 3, 0x21300220, 4), Ok(0x1A00, 3));
  EXPECT_EQ(Download(0x1A00, 0, 3, 1), Abort(0x1A00, 0, 0x06040042));  // 96 bits
  EXPECT_EQ(Download(0x1A00, 0, 9, 1), Abort(0x1A00, 0, 0x06040042));
  EXPECT_EQ(Download(0x1A00, 0, 2, 1), Ok(0x1A00, 0));
  // New COB-ID and type while invalid, then valid: frames follow the new mapping at once.
  EXPECT_EQ(Download(0x1800, 1, 0x800001A0, 4), Ok(0x1800, 1));
  EXPECT_EQ(Download(0x1800, 2, 255, 1), Ok(0x1800, 2));
  EXPECT_EQ(Download(0x1800, 3, 0, 2), Ok(0x1800, 3));
  step_io_.add_steps(0, 1234);
  Step(50);
  sent_.clear();
  EXPECT_EQ(Download(0x1800, 1, 0x1A0, 4), Ok(0x1800, 1));
  Timed f;  // the frame leaves in the pass that served the write (Exchange keeps it in sent_)
  for (const CanFrame& s : sent_) {
    if (s.id == 0x1A0) f.push_back({0, s});
  }
  const Timed later = Watch(0x1A0, 3);
  f.insert(f.end(), later.begin(), later.end());
  ASSERT_EQ(f.size(), 1u);
  const uint32_t commanded = Read(ObjectId::kCommandedPosition1);
  const uint32_t machine = Read(ObjectId::kMachinePosition1);
  EXPECT_EQ(static_cast<int32_t>(commanded), 1234);
  ASSERT_EQ(f[0].second.dlc, 8);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(f[0].second.data[i], static_cast<uint8_t>(commanded >> (8 * i)));
    EXPECT_EQ(f[0].second.data[4 + i], static_cast<uint8_t>(machine >> (8 * i)));
  }
  // Inhibit 0: every change leaves on the next pass.
  step_io_.add_steps(0, 1);
  EXPECT_EQ(Watch(0x1A0, 2).size(), 1u);
  EXPECT_TRUE(Watch(0x190, 10).empty());  // the old CAN-ID is gone
  EXPECT_EQ(Read(ObjectId::kTpdo1CobId), 0x1A0u);
  EXPECT_EQ(Read(ObjectId::kTpdo1Mapped), 2u);
  EXPECT_EQ(Read(ObjectId::kTpdo1Mapping2), 0x21370120u);
}

// The PDO parameters are in force at once (no reset), saved by 0x1010 with the other
// communication parameters, restored by reset communication and reset node; "load" (0x1011)
// brings the defaults back at the next reset.
TEST_F(PdoBench, StoredPdoParametersSurviveResetsAndRestoreDefaultsBringsTheDefaultsBack) {
  Boot();
  EXPECT_EQ(Download(0x1801, 1, 0x80000290, 4), Ok(0x1801, 1));
  EXPECT_EQ(Download(0x1801, 1, 0x80000391, 4), Ok(0x1801, 1));
  EXPECT_EQ(Download(0x1801, 1, 0x391, 4), Ok(0x1801, 1));
  EXPECT_EQ(Download(0x1801, 5, 40, 2), Ok(0x1801, 5));
  EXPECT_FALSE(canopen::DecodeDeviceState(Read(ObjectId::kDeviceState)).settings_pending);
  // A reset communication without a store: the defaults (nothing stored yet).
  EXPECT_TRUE(Contains(Nmt(0x82), "710#00"));
  EXPECT_EQ(Read(ObjectId::kTpdo2CobId), 0x290u);
  EXPECT_EQ(Read(ObjectId::kTpdo2EventTimer), 100u);
  // Again, stored.
  EXPECT_EQ(Download(0x1801, 1, 0x80000290, 4), Ok(0x1801, 1));
  EXPECT_EQ(Download(0x1801, 1, 0x80000391, 4), Ok(0x1801, 1));
  EXPECT_EQ(Download(0x1801, 1, 0x391, 4), Ok(0x1801, 1));
  EXPECT_EQ(Download(0x1801, 5, 40, 2), Ok(0x1801, 5));
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  EXPECT_EQ(Exchange("2310100173617665"), Frames{"590#6010100100000000"});  // "save"
  EXPECT_EQ(Download(0x1801, 5, 1000, 2), Ok(0x1801, 5));                   // in force, not stored
  EXPECT_TRUE(Contains(Nmt(0x82), "710#00"));
  EXPECT_EQ(Read(ObjectId::kTpdo2CobId), 0x391u);
  EXPECT_EQ(Read(ObjectId::kTpdo2EventTimer), 40u);
  can_.Inject(CanFrame{0x000, false, false, 2, {0x01, kNode}});
  const Timed f = Watch(0x391, 500);
  EXPECT_GE(f.size(), 11u);  // every 40 ms
  EXPECT_LE(f.size(), 14u);
  EXPECT_TRUE(Contains(Nmt(0x81), "710#00"));  // reset node: from the stored settings
  EXPECT_EQ(Read(ObjectId::kTpdo2CobId), 0x391u);
  EXPECT_EQ(Read(ObjectId::kTpdo2EventTimer), 40u);
  EXPECT_EQ(Exchange("231110016C6F6164"), Frames{"590#6011100100000000"});  // "load"
  EXPECT_EQ(Read(ObjectId::kTpdo2CobId), 0x391u);                           // until the reset
  EXPECT_TRUE(Contains(Nmt(0x82), "710#00"));
  EXPECT_EQ(Read(ObjectId::kTpdo2CobId), 0x290u);
  EXPECT_EQ(Read(ObjectId::kTpdo2EventTimer), 100u);
}

// RPDO1 (COB-ID 0x200 + node-ID) carries the command word 0x2127: each bit acts on its rising
// edge, through the same code and checks as the SDO writes of 0x2120 / 0x2101, and a refusal sends
// the same EMCY 0xFF10 with the abort code (there is no one to answer). Nothing outside
// operational; a frame of the wrong length is not processed (EMCY 0x8210 / 0x8220).
class RpdoBench : public PdoBench {
 protected:
  static constexpr uint32_t kRpdo = 0x200 + kNode;
  // One RPDO frame (`dlc` bytes of `word`, little-endian), then 30 main-loop passes (beyond twice
  // the EMCY inhibit time: a refusal's EMCY and its "error reset" both leave); the EMCYs the board
  // sent meanwhile, other than the resets.
  std::vector<canopen::Emcy> Send(uint16_t word, uint8_t dlc = 2, uint32_t id = kRpdo) {
    CanFrame f{
        id, false, false, dlc, {static_cast<uint8_t>(word), static_cast<uint8_t>(word >> 8)}};
    can_.Inject(f);
    Step(1500);
    std::vector<canopen::Emcy> out;
    for (const CanFrame& r : can_.TakeSent()) {
      sent_.push_back(r);
      canopen::Emcy e;
      if (canopen::DecodeEmcy(r, kNode, &e) && e.code != canopen::kEmcyErrorReset) out.push_back(e);
    }
    return out;
  }
  static uint32_t Detail(const canopen::Emcy& e) { return LoadLe32(e.data); }
  void Staged() {
    io_.SetInput(InputLine::kWriteEnable, true);
    ASSERT_TRUE(Upload(UniformImage(6, 77)).ok());
    ASSERT_TRUE(Command(TableCommand::kVerify).ok());
  }
  void Operational() {
    can_.Inject(CanFrame{0x000, false, false, 2, {0x01, kNode}});
    Step(100);
    can_.TakeSent();
  }
};

TEST_F(RpdoBench, CommandWordActsOnRisingEdgesWithTheSdoWritesChecksAndEmcy) {
  Boot();
  Staged();
  const uint32_t crc = Read(ObjectId::kStagedTableCrc);
  // Pre-operational: not processed at all.
  EXPECT_TRUE(Send(canopen::kCommandActivate).empty());
  EXPECT_EQ(Read(ObjectId::kCommandWord), 0u);
  EXPECT_EQ(app_.node().rpdo_received(), 0u);
  Operational();
  // Not referenced: refused as the SDO write of 0x2101 = 1 is (0x08000022), same EMCY.
  std::vector<canopen::Emcy> e = Send(canopen::kCommandActivate);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].code, canopen::kEmcyRefused);
  EXPECT_EQ(Detail(e[0]), 0x08000022u);
  EXPECT_EQ(Read(ObjectId::kCommandWord), canopen::kCommandActivate);  // taken: no retry by holding
  sent_.clear();
  EXPECT_EQ(canopen_client::AbortOf(Command(TableCommand::kActivate)),
            canopen::SdoAbort::kDeviceState);
  Step(1000);  // past the EMCY inhibit time
  for (const CanFrame& f : can_.TakeSent()) sent_.push_back(f);
  ASSERT_EQ(CountEmcy(canopen::kEmcyRefused), 1);
  for (const CanFrame& f : sent_) {
    canopen::Emcy sdo;
    if (canopen::DecodeEmcy(f, kNode, &sdo) && sdo.code == canopen::kEmcyRefused) {
      EXPECT_EQ(sdo.error_register, e[0].error_register);
      EXPECT_EQ(std::vector<uint8_t>(sdo.data, sdo.data + 5),
                std::vector<uint8_t>(e[0].data, e[0].data + 5));
    }
  }
  // Held (a master sending the word cyclically): nothing more.
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(Send(canopen::kCommandActivate).empty());
  // Reference and activate rising in one word: the reference takes effect at the next tick, so
  // the activation is refused (not referenced yet); then activate falls.
  EXPECT_TRUE(Send(0).empty());
  e = Send(0x0007 | canopen::kCommandActivate);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(Detail(e[0]), 0x08000022u);
  EXPECT_TRUE(Send(0x0007).empty());
  Step(200);
  EXPECT_TRUE(app_.control_tick().all_referenced());
  Step(10000);  // 200 ms at rest
  // Activate rises: the staged table becomes active.
  EXPECT_TRUE(Send(0x0007 | canopen::kCommandActivate).empty());
  EXPECT_EQ(Read(ObjectId::kActiveTableCrc), crc);
  Step(20000);
  EXPECT_EQ(step_io_.drive(0).position(), 6);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(Send(0x0007 | canopen::kCommandActivate).empty());
  EXPECT_EQ(Read(ObjectId::kActiveTableCrc), crc);
  // Deactivate rises (activate falls): ramps out.
  EXPECT_TRUE(Send(canopen::kCommandDeactivate).empty());
  Step(20000);
  EXPECT_EQ(step_io_.drive(0).position(), 0);
  EXPECT_EQ(Read(ObjectId::kActiveTableCrc), 0u);
  // Activate rises again: the activation consumed the staged table, "no data" (0x08000024).
  e = Send(canopen::kCommandDeactivate | canopen::kCommandActivate);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(Detail(e[0]), 0x08000024u);
  // Both rising at once, or a bit with no meaning: refused (0x06090030) and not taken.
  EXPECT_TRUE(Send(0).empty());
  e = Send(canopen::kCommandDeactivate | canopen::kCommandActivate);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(Detail(e[0]), 0x06090030u);
  e = Send(0x8000);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(Detail(e[0]), 0x06090030u);
  EXPECT_EQ(Read(ObjectId::kCommandWord), 0u);
  // Write access off: refused as the SDO path refuses (0x08000020).
  io_.SetInput(InputLine::kWriteEnable, false);
  Step(100);
  e = Send(canopen::kCommandDeactivate);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(Detail(e[0]), 0x08000020u);
  // The wrong length: not processed, EMCY 0x8210 (shorter) / 0x8220 (longer), byte 3 the DLC.
  EXPECT_TRUE(Send(0).empty());
  const uint32_t received = app_.node().rpdo_received();
  e = Send(canopen::kCommandActivate, 1);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].code, canopen::kEmcyPdoLength);
  EXPECT_EQ(e[0].data[0], 1);
  e = Send(canopen::kCommandActivate, 3);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].code, canopen::kEmcyPdoLengthExceeded);
  EXPECT_EQ(e[0].data[0], 3);
  EXPECT_EQ(app_.node().rpdo_received(), received);
  EXPECT_EQ(app_.node().rpdo_length_errors(), 2u);
  EXPECT_EQ(Read(ObjectId::kCommandWord), 0u);
  // Stopped: not processed.
  can_.Inject(CanFrame{0x000, false, false, 2, {0x02, kNode}});
  Step(100);
  EXPECT_TRUE(Send(0x0001).empty());
  EXPECT_EQ(app_.node().rpdo_received(), received);
}

// 0x1400:1-2 follow the TPDOs' rules; 0x1600 is the static mapping (read-only). Stored by
// "save", restored by the resets.
TEST_F(RpdoBench, ParametersFollowTheCia301RulesAndAreStored) {
  Boot();
  Operational();
  EXPECT_EQ(Read(ObjectId::kRpdo1CobId), kRpdo);
  EXPECT_EQ(Read(ObjectId::kRpdo1Type), 254u);
  EXPECT_EQ(Read(ObjectId::kRpdo1Mapped), 1u);
  EXPECT_EQ(Read(ObjectId::kRpdo1Mapping1), 0x21270010u);
  EXPECT_EQ(Download(0x1600, 1, 0x21200008, 4), Abort(0x1600, 1, 0x06010002));
  EXPECT_EQ(Download(0x1600, 0, 0, 1), Abort(0x1600, 0, 0x06010002));
  EXPECT_EQ(Download(0x1400, 0, 2, 1), Abort(0x1400, 0, 0x06010002));
  EXPECT_EQ(Download(0x1400, 1, 0x301, 4), Abort(0x1400, 1, 0x06090030));  // valid: no new ID
  EXPECT_EQ(Download(0x1400, 2, 255, 1), Abort(0x1400, 2, 0x06090030));
  EXPECT_EQ(Download(0x1400, 1, 0x80000000u | kRpdo, 4), Ok(0x1400, 1));
  EXPECT_TRUE(Send(0x0001).empty());
  EXPECT_EQ(app_.node().rpdo_received(), 0u);                          // the PDO does not exist
  EXPECT_EQ(Download(0x1400, 2, 1, 1), Abort(0x1400, 2, 0x06090030));  // SYNC: not offered
  EXPECT_EQ(Download(0x1400, 1, 0x80000601, 4), Abort(0x1400, 1, 0x06090030));
  EXPECT_EQ(Download(0x1400, 1, 0x80000301, 4), Ok(0x1400, 1));
  EXPECT_EQ(Download(0x1400, 2, 255, 1), Ok(0x1400, 2));
  EXPECT_EQ(Download(0x1400, 1, 0x301, 4), Ok(0x1400, 1));
  EXPECT_TRUE(Send(0x0001).empty());  // the old CAN-ID: not the RPDO any more
  EXPECT_EQ(app_.node().rpdo_received(), 0u);
  EXPECT_TRUE(Send(0x0001, 2, 0x301).empty());
  EXPECT_EQ(app_.node().rpdo_received(), 1u);
  EXPECT_EQ(Read(ObjectId::kCommandWord), 1u);
  // Stored by "save"; a reset communication brings the stored ones back.
  io_.SetInput(InputLine::kWriteEnable, true);
  Step(100);
  EXPECT_EQ(Exchange("2310100173617665"), Frames{"590#6010100100000000"});
  EXPECT_EQ(Download(0x1400, 1, 0x80000301, 4), Ok(0x1400, 1));  // in force, not stored
  EXPECT_TRUE(Contains(Nmt(0x82), "710#00"));
  EXPECT_EQ(Read(ObjectId::kRpdo1CobId), 0x301u);
  EXPECT_EQ(Read(ObjectId::kRpdo1Type), 255u);
  EXPECT_EQ(Exchange("231110016C6F6164"), Frames{"590#6011100100000000"});  // "load"
  EXPECT_TRUE(Contains(Nmt(0x82), "710#00"));
  EXPECT_EQ(Read(ObjectId::kRpdo1CobId), kRpdo);
  EXPECT_EQ(Read(ObjectId::kRpdo1Type), 254u);
}

}  // namespace
}  // namespace volcomp
