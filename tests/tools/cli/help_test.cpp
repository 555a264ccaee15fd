// `volcomp help COMMAND` shows every option a command accepts, with unit and default, and the
// parser accepts exactly those (the same table drives both).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "cli_runner.hpp"

namespace volcomp::tools {
namespace {

using args::OptionSpec;
using volcomp::testing::RunCli;

std::vector<std::string> Words(const std::string& name) {
  std::istringstream s(name);
  std::vector<std::string> out;
  for (std::string w; s >> w;) out.push_back(w);
  return out;
}

TEST(VolcompHelp, EveryOptionWithUnitAndDefault) {
  for (const cli::Command* command : cli::Commands()) {
    const cli::Command& c = *command;
    auto words = Words(c.name);
    words.insert(words.begin(), "help");
    const auto r = RunCli(words);
    ASSERT_EQ(r.code, kExitOk) << c.name;
    for (const OptionSpec& o : c.options) {
      const std::size_t at = r.out.find(std::string(o.name) + (o.value ? " " : "\n"));
      ASSERT_NE(at, std::string::npos) << c.name << " " << o.name << "\n" << r.out;
      const std::string entry = r.out.substr(at, r.out.find("\n  -", at + 1) - at);
      if (o.value != nullptr) {
        EXPECT_NE(entry.find(o.value), std::string::npos) << entry;
      }
      if (o.unit != nullptr) {
        EXPECT_NE(entry.find(std::string("unit: ") + o.unit), std::string::npos) << entry;
      }
      if (o.default_value != nullptr) {
        EXPECT_NE(entry.find(std::string("default: ") + o.default_value), std::string::npos)
            << entry;
      }
      if (o.alias != nullptr) {
        EXPECT_NE(r.out.find(std::string(o.alias) + ", " + o.name), std::string::npos);
      }
    }
    EXPECT_NE(r.out.find("exit codes: 0 ok, 1 refused or failed, 2 usage, 3 communication"),
              std::string::npos);
    // `CMD --help` is the same text.
    words.erase(words.begin());
    words.push_back("--help");
    EXPECT_EQ(RunCli(words).out, r.out) << c.name;
  }
}

TEST(VolcompHelp, EveryCommandRefusesAnUndeclaredOption) {
  for (const cli::Command* command : cli::Commands()) {
    const cli::Command& c = *command;
    auto words = Words(c.name);
    words.push_back("--no-such-option");
    const auto r = RunCli(words);
    EXPECT_EQ(r.code, kExitUsage) << c.name;
    EXPECT_NE(r.err.find("unknown option \"--no-such-option\""), std::string::npos) << r.err;
  }
}

// Every option name written in a command's source is declared in the table, so no code path can
// take an option the help does not show (at run time such a query is a std::logic_error).
TEST(VolcompHelp, OptionsUsedInTheSourcesAreDeclared) {
  const char* root = std::getenv("VOLCOMP_SOURCE_DIR");
  ASSERT_NE(root, nullptr);
  std::set<std::string> declared;
  for (const cli::Command* c : cli::Commands()) {
    for (const OptionSpec& o : c->options) {
      declared.insert(o.name);
      if (o.alias != nullptr) declared.insert(o.alias);
    }
  }
  const std::regex option_literal("\"(--?[a-z][a-z0-9-]*)\"");
  // The command layer (every command with its options) and any library that still reads options.
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(root) + "/tools/cli")) {
    files.push_back("tools/cli/" + entry.path().filename().string());
  }
  if (std::filesystem::exists(std::string(root) + "/tools/model/src/build_cli.cpp")) {
    files.push_back("tools/model/src/build_cli.cpp");  // TRANSITION
  }
  int literals = 0;
  for (const std::string& f : files) {
    std::ifstream in(std::string(root) + "/" + f);
    ASSERT_TRUE(in) << f;
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    for (std::sregex_iterator it(s.begin(), s.end(), option_literal), end; it != end; ++it) {
      const std::string name = (*it)[1];
      if (name == "--" || name == "-h" || name == "--help" || name == "--version") continue;
      ++literals;
      EXPECT_TRUE(declared.count(name)) << f << ": " << name << " is not in the option table";
    }
  }
  EXPECT_GT(literals, 50);
}

TEST(VolcompHelp, ToolHelpAndExitCodes) {
  auto r = RunCli({"help"});
  EXPECT_EQ(r.code, kExitOk);
  EXPECT_NE(r.out.find("3 communication"), std::string::npos);
  EXPECT_NE(r.out.find("report compare"), std::string::npos);
  EXPECT_EQ(RunCli({}).code, kExitUsage);
  r = RunCli({"frobnicate"});
  EXPECT_EQ(r.code, kExitUsage);
  EXPECT_NE(r.err.find("unknown command \"frobnicate\""), std::string::npos);
  r = RunCli({"inspect", "/nonexistent.vct"});
  EXPECT_EQ(r.code, kExitFailed);
}

}  // namespace
}  // namespace volcomp::tools
