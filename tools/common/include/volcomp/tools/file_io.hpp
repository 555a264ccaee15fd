// Whole-file reading and writing for hosted code, with failures that name the file and the
// reason (kIoError, "PATH: cannot open: No such file or directory").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::tools {

/// The bytes of the file at `path`.
Expected<std::vector<uint8_t>> ReadFileBytes(const std::string& path);
/// The text of the file at `path` ("-": standard input).
Expected<std::string> ReadTextFile(const std::string& path);
/// Writes `bytes` to `path` (created or truncated).
Outcome WriteFileBytes(const std::string& path, const std::vector<uint8_t>& bytes);
/// Writes `text` to `path` (created or truncated).
Outcome WriteTextFile(const std::string& path, const std::string& text);

}  // namespace volcomp::tools
