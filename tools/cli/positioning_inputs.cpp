// Inputs of the exports from positioning tests (see positioning_inputs.hpp).
#include "positioning_inputs.hpp"

#include "volcomp/image/axis_units.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::cli {

Expected<std::vector<std::pair<char, std::string>>> PositioningFiles(Args& args) {
  std::vector<std::pair<char, std::string>> inputs;
  for (int i = 0; kPositioningAxes[i] != '\0'; ++i) {
    const char axis = kPositioningAxes[i];
    const std::string opt = std::string("--") + static_cast<char>(axis - 'A' + 'a');
    if (auto p = args.Value(opt)) inputs.emplace_back(axis, *p);
  }
  if (inputs.empty()) return UsageFailure("give at least one axis file, e.g. --x x.csv");
  return inputs;
}

Expected<std::map<char, int>> ParseAxisNumberMap(const std::optional<std::string>& text,
                                                 const std::string& option,
                                                 const std::string& what,
                                                 int first,
                                                 int min,
                                                 int max) {
  std::map<char, int> number;
  for (int i = 0; kPositioningAxes[i] != '\0'; ++i) number[kPositioningAxes[i]] = first + i;
  if (!text) return number;
  VOLCOMP_TRY_ASSIGN(const auto assignments, image::ParseAxisAssignments(*text, option));
  for (const auto& [name, value] : assignments) {
    const auto v = tools::ParseInteger(value);
    if (!v || *v < min || *v > max) {
      return UsageFailure(option + ": " + what + " of " + std::string(1, name) + " must be " +
                          std::to_string(min) + ".." + std::to_string(max));
    }
    number[name] = static_cast<int>(*v);
  }
  return number;
}

}  // namespace volcomp::cli
