// The native component's load-time configuration (see the header).
#include "native/instance_config.hpp"

#include <cctype>
#include <optional>

#include "volcomp/hosted/linuxcnc_units.hpp"

namespace volcomp::linuxcnc {
namespace {

// HAL names: printable, no spaces, up to 47 characters (HAL_NAME_LEN); the longest name an
// instance makes is its parameter "<name>.axis.x.max-correction-accel" (or the
// "direction-hysteresis" one, as long).
constexpr size_t kMaxNameLength = 47 - (sizeof(".axis.x.max-correction-accel") - 1);

}  // namespace

Expected<std::vector<std::string>> InstanceNames(int count, const std::vector<std::string>& names) {
  if (count != 0 && !names.empty()) {
    return Fail(Error::kInvalidArgument, "count= and names= cannot be used together");
  }
  std::vector<std::string> out;
  if (!names.empty()) {
    out = names;
  } else {
    if (count < 0) return Fail(Error::kInvalidArgument, "count= must be at least 1");
    for (int i = 0; i < (count == 0 ? 1 : count); ++i)
      out.push_back("volcomp." + std::to_string(i));
  }
  if (out.size() > kMaxInstances) {
    return Fail(Error::kInvalidArgument,
                "at most " + std::to_string(kMaxInstances) + " instances (count=/names=)");
  }
  for (size_t i = 0; i < out.size(); ++i) {
    const std::string& n = out[i];
    bool printable = !n.empty();
    for (char c : n) printable = printable && std::isgraph(static_cast<unsigned char>(c)) != 0;
    if (!printable || n.size() > kMaxNameLength) {
      return Fail(Error::kInvalidArgument, "names=: \"" + n + "\" is not a HAL name (1.." +
                                               std::to_string(kMaxNameLength) +
                                               " printable characters, no spaces)");
    }
    for (size_t j = 0; j < i; ++j) {
      if (out[j] == n) return Fail(Error::kInvalidArgument, "names=: \"" + n + "\" given twice");
    }
  }
  return out;
}

Expected<double> ParseLinearUnits(const std::string& text) {
  if (text.empty()) return 1.0;
  if (const std::optional<double> mm = hosted::LinuxcncMmPerLinearUnit(text)) return *mm;
  return Fail(
      Error::kInvalidArgument,
      "units=" + text + ": not a linear unit LinuxCNC uses (mm or inch, as [TRAJ]LINEAR_UNITS)");
}

Expected<ChannelMap> MapChannels(const std::string& axes, const NativeTable& table) {
  ChannelMap m;
  if (axes.empty()) {
    m.count = table.axis_count();
    for (uint8_t a = 0; a < m.count; ++a) {
      m.axis_of[a] = a;
      m.position_channel[a] = a;
    }
    return m;
  }
  if (axes.size() > kMaxChannels) {
    return Fail(Error::kInvalidArgument,
                "axes=" + axes + ": at most " + std::to_string(kMaxChannels) + " joints");
  }
  bool named[table::kMaxAxes] = {};
  for (size_t j = 0; j < axes.size(); ++j) {
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(axes[j])));
    const int a = table.FindAxis(letter);
    if (a < 0) {
      return Fail(Error::kInvalidArgument,
                  "axes=" + axes + ": joint " + std::to_string(j) + " is '" + axes[j] +
                      "', which is not an axis of the table (" + table.AxisNames() + ")");
    }
    m.axis_of[j] = static_cast<uint8_t>(a);
    if (!named[a]) m.position_channel[a] = static_cast<uint8_t>(j);
    named[a] = true;
  }
  for (uint8_t a = 0; a < table.axis_count(); ++a) {
    if (!named[a]) {
      return Fail(Error::kInvalidArgument, "axes=" + axes + ": the table's axis " +
                                               std::string(1, table.axis(a).name) +
                                               " has no joint (the table needs its position)");
    }
  }
  m.count = static_cast<uint8_t>(axes.size());
  return m;
}

}  // namespace volcomp::linuxcnc
