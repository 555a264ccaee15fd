// Options whose value is one word of a fixed set (--order first|exact, --sigma formula|range, ...):
// the value the word stands for, or the usage failure that lists the words.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include "command.hpp"

namespace volcomp::cli {

template <typename T>
struct Choice {
  const char* word;
  T value;
  bool listed = true;  // false: an alias the failure does not list ("gost" for "gost27843")
};

/// The value `word` stands for among `choices`; another word is a usage failure
/// "OPTION must be A, B or C" (the listed words), followed by " (NOTE)" when `note` is given.
template <typename T>
Expected<T> ParseChoice(const std::string& option,
                        const std::string& word,
                        std::initializer_list<Choice<T>> choices,
                        const char* note = nullptr) {
  std::vector<const char*> listed;
  for (const Choice<T>& c : choices) {
    if (word == c.word) return c.value;
    if (c.listed) listed.push_back(c.word);
  }
  std::string message = option + " must be ";
  for (std::size_t i = 0; i < listed.size(); ++i) {
    if (i > 0) message += i + 1 == listed.size() ? " or " : ", ";
    message += listed[i];
  }
  if (note != nullptr) message += std::string(" (") + note + ")";
  return UsageFailure(message);
}

}  // namespace volcomp::cli
