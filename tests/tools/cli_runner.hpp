// Runs a `volcomp` command in-process with captured stdout/stderr (tests of the PC tool).
#pragma once

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::testing {

struct CliResult {
  int code = 0;
  std::string out;
  std::string err;
};

/// Runs `volcomp WORDS...` like main() does (the same command table and error mapping).
inline CliResult RunCli(const std::vector<std::string>& words, const std::string& stdin_text = "") {
  CliResult r;
  std::istringstream in(stdin_text);
  std::ostringstream out, err;
  auto* old_in = std::cin.rdbuf(in.rdbuf());
  auto* old_out = std::cout.rdbuf(out.rdbuf());
  auto* old_err = std::cerr.rdbuf(err.rdbuf());
  const tools::Command* found = nullptr;
  size_t used = 0;
  for (const tools::Command& c : tools::Commands()) {
    std::istringstream name(c.name);
    std::vector<std::string> parts;
    for (std::string p; name >> p;) parts.push_back(p);
    if (parts.size() <= words.size() && parts.size() > used &&
        std::equal(parts.begin(), parts.end(), words.begin())) {
      found = &c;
      used = parts.size();
    }
  }
  if (found == nullptr) {
    r.code = 2;
  } else {
    tools::Args args(
        std::vector<std::string>(words.begin() + static_cast<long>(used), words.end()));
    try {
      r.code = found->run(args);
    } catch (const tools::UsageError& e) {
      std::cerr << e.what();
      r.code = 2;
    } catch (const std::exception& e) {
      std::cerr << e.what();
      r.code = 1;
    }
  }
  std::cin.rdbuf(old_in);
  std::cout.rdbuf(old_out);
  std::cerr.rdbuf(old_err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

}  // namespace volcomp::testing
