// `volcomp nmt reset|reset-comm|start|stop|pre-op`: an NMT command to the node (frame 0x000
// [command, node-ID]), confirmed by its boot-up (the resets) or its heartbeat (the others).
// No confirmation in time is a communication failure (exit 3); a heartbeat in another state a
// result that is not ok (exit 1).
#include <chrono>
#include <ostream>

#include "can_options.hpp"
#include "commands.hpp"

namespace volcomp::cli {
namespace {

struct Choice {
  const char* word;
  canopen::NmtCommand command;
  canopen::NmtState state;  // confirmed by (heartbeat), or boot-up for the resets
  const char* what;
};

const Choice* FindChoice(const std::vector<std::string>& words) {
  static const Choice kChoices[] = {
      {"reset", canopen::NmtCommand::kResetNode, canopen::NmtState::kInitialising, "reset node"},
      {"reset-comm", canopen::NmtCommand::kResetCommunication, canopen::NmtState::kInitialising,
       "reset communication"},
      {"start", canopen::NmtCommand::kStart, canopen::NmtState::kOperational, "start"},
      {"stop", canopen::NmtCommand::kStop, canopen::NmtState::kStopped, "stop"},
      {"pre-op", canopen::NmtCommand::kEnterPreOperational, canopen::NmtState::kPreOperational,
       "enter pre-operational"},
  };
  for (const Choice& c : kChoices) {
    if (words.size() == 1 && words[0] == c.word) return &c;
  }
  return nullptr;
}

void NmtText(const JsonValue& d, std::ostream& out) {
  out << "node " << d.get("node")->integer << ": " << d.get("command")->string;
  const std::string& confirmation = d.get("confirmation")->string;
  if (confirmation == "none") {
    out << " sent (not confirmed: --no-wait)\n";
  } else if (confirmation == "boot-up") {
    const int64_t boot = d.get("boot_node")->integer;
    if (boot != d.get("node")->integer) {
      out << ": boot-up as node " << boot << " (its stored node-ID)\n";
    } else {
      out << ": boot-up seen, pre-operational\n";
    }
  } else if (d.get("confirmed")->boolean) {
    out << ": heartbeat reports " << d.get("state")->string << "\n";
  } else {
    out << " sent, but the heartbeat reports " << d.get("state")->string << "\n";
  }
}

// Waits for what confirms `c`; fills the confirmation into `d`.
Outcome Confirm(canopen_client::CanSession& s, const Choice& c, long long wait_ms, JsonValue& d) {
  const auto wait = std::chrono::milliseconds(wait_ms);
  if (c.state == canopen::NmtState::kInitialising) {
    VOLCOMP_TRY_ASSIGN(const std::optional<uint8_t> boot, s.WaitForBootUp(s.node(), wait));
    if (!boot) {
      return CommunicationFailure(std::string(c.what) + " sent, but no boot-up within " +
                                  std::to_string(wait_ms) + " ms");
    }
    d.Set("confirmation", "boot-up");
    d.Set("boot_node", unsigned{*boot});
    d.Set("confirmed", true);
    return Outcome::Ok();
  }
  VOLCOMP_TRY_ASSIGN(const std::optional<uint8_t> state,
                     s.WaitForState(static_cast<uint8_t>(c.state), wait));
  if (!state) {
    return CommunicationFailure(std::string(c.what) + " sent, but no heartbeat within " +
                                std::to_string(wait_ms) +
                                " ms to confirm it (heartbeat off? 0x1017; --no-wait only sends)");
  }
  d.Set("confirmation", "heartbeat");
  d.Set("state", canopen_client::NmtStateName(*state));
  d.Set("confirmed", *state == static_cast<uint8_t>(c.state));
  return Outcome::Ok();
}

Expected<Output> RunNmt(Args& args, Context&) {
  VOLCOMP_TRY_ASSIGN(const CanConnection can, ParseCanOptions(args));
  const bool no_wait = args.Flag("--no-wait");
  const long long wait_ms = args.Integer("--wait-ms").value_or(2500);
  const auto words = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (wait_ms < 1 || wait_ms > 60000) return UsageFailure("--wait-ms must be 1..60000");
  const Choice* c = FindChoice(words);
  if (c == nullptr) return UsageFailure("expected one of reset, reset-comm, start, stop, pre-op");
  VOLCOMP_TRY_ASSIGN(const auto session, OpenSession(can));
  VOLCOMP_TRY(session->SendNmt(c->command));
  JsonValue d = JsonValue::Object();
  d.Set("node", unsigned{can.node});
  d.Set("command", c->what);
  if (no_wait) {
    d.Set("confirmation", "none");
    d.Set("confirmed", false);
    return Output{std::move(d), NmtText, {}};
  }
  VOLCOMP_TRY(Confirm(*session, *c, wait_ms, d));
  const int code = d.get("confirmed")->boolean ? tools::kExitOk : tools::kExitFailed;
  return Output{std::move(d), NmtText, {}, code};
}

}  // namespace

const Command& NmtCommand() {
  static const Command kCommand{
      "nmt",
      "NMT command to the node, confirmed by its boot-up or heartbeat",
      "reset|reset-comm|start|stop|pre-op",
      Join({CanOptions(),
            {{"--wait-ms", nullptr, "N", "ms", "2500",
              "how long to wait for the boot-up or the heartbeat confirming the command"},
             {"--no-wait", nullptr, nullptr, nullptr, nullptr, "send only"}}}),
      RunNmt,
      "reset: reset node (the stored settings come into force; positions and references are\n"
      "lost); reset-comm: reset communication; start: operational; stop: stopped (only NMT and\n"
      "heartbeat answered); pre-op: pre-operational. Frame 0x000 [command, node-ID]."};
  return kCommand;
}

}  // namespace volcomp::cli
