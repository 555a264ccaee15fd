// Runs a `volcomp` command in-process with captured stdout/stderr (tests of the PC tool).
#pragma once

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"

namespace volcomp::testing {

struct CliResult {
  int code = 0;
  std::string out;
  std::string err;
};

/// Runs `volcomp WORDS...` exactly as main() does (tools::RunCommandLine: the same command
/// table, option tables, help and exit codes).
inline CliResult RunCli(const std::vector<std::string>& words, const std::string& stdin_text = "") {
  CliResult r;
  std::istringstream in(stdin_text);
  std::ostringstream out, err;
  auto* old_in = std::cin.rdbuf(in.rdbuf());
  auto* old_out = std::cout.rdbuf(out.rdbuf());
  auto* old_err = std::cerr.rdbuf(err.rdbuf());
  r.code = cli::RunCommandLine(words);
  std::cin.rdbuf(old_in);
  std::cout.rdbuf(old_out);
  std::cerr.rdbuf(old_err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

/// `words` with `more` after them (a command line with options added).
inline std::vector<std::string> Appended(std::vector<std::string> words,
                                         const std::vector<std::string>& more) {
  words.insert(words.end(), more.begin(), more.end());
  return words;
}

}  // namespace volcomp::testing
