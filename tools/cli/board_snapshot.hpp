// What `status` and `monitor` read from a board and report about it: identity, state, tables,
// per-axis positions, corrections and limits (in steps and in machine units: mm and µm, degrees
// and arcsec on a rotary axis), and the counters of 0x2140. Failures are the reads'
// (sdo_failure.hpp: kCommunication when the board does not answer).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen_client/can_session.hpp"

namespace volcomp::cli {

/// The counters of 0x2140:1.. in order (CounterNames()).
inline constexpr int kCounterCount = static_cast<int>(canopen::ObjectId::kEmcySuppressed) -
                                     static_cast<int>(canopen::ObjectId::kCanRxFrames) + 1;
/// Their names in the JSON ("can_rx_frames", ...) and the text.
const char* const* CounterNames();
/// Indices of the counters `monitor` shows on every line.
inline constexpr int kCanRxCounter = 0, kCanTxCounter = 1, kSdoAbortCounter = 3,
                     kOutputOverrunCounter = 6, kRefusedActionCounter = 8;

/// One axis as the board describes it (its configuration objects, read once).
struct AxisInfo {
  char name = '?';
  bool rotary = false;
  uint32_t resolution_e9 = 0;        // units (mm or degrees) per step x 1e9, 0x2012
  int32_t max_correction_steps = 0;  // 0x2015
  double units_per_step() const { return resolution_e9 * 1e-9; }
  const char* position_unit() const { return rotary ? "deg" : "mm"; }
  // The correction's display unit: µm on a linear axis, arcsec on a rotary one.
  const char* correction_unit() const { return rotary ? "arcsec" : "um"; }
  double correction_per_step() const { return units_per_step() * (rotary ? 3600.0 : 1000.0); }
};

/// The thermal correction as the board shows it (0x2150-0x2155, docs/thermal.md).
struct ThermalSnapshot {
  uint32_t status = 0;  // 0x2153:1, canopen::ThermalStatusBit
  uint32_t fault_channels = 0, outside_channels = 0, saturated_axes = 0;  // 0x2153:2-4
  uint32_t state[8] = {};          // 0x2151, thermal::ChannelState
  int32_t temperature_cC[8] = {};  // 0x2150, read for channels that are not unused
  uint32_t faults[8] = {};         // 0x2152, likewise
  int32_t offset_nm[6] = {};       // 0x2154, read while a model is in force
  int32_t slope_nm_per_m[6] = {};  // 0x2155, likewise
};

/// What the board does now (read every time).
struct Snapshot {
  std::string device_name, software_version;
  uint32_t vendor = 0, product = 0, revision = 0, serial = 0;
  uint32_t state = 0, table_status = 0, active_id = 0, active_crc = 0, staged_crc = 0,
           staged_id = 0, staged_bytes = 0, writable = 0, axes = 0;
  int32_t commanded[6] = {}, machine[6] = {}, correction_q8[6] = {}, output[6] = {};
  uint32_t backlog[6] = {};
  uint32_t limit_flags[6] = {}, clamped[6] = {}, rate_limited[6] = {};  // 0x2134-0x2136
  uint32_t counters[kCounterCount] = {};
  std::optional<uint8_t> nmt;              // from the last heartbeat the session saw
  std::optional<ThermalSnapshot> thermal;  // none on firmware without the thermal objects
};

/// Reads the snapshot (the device name and version are left empty when they cannot be read).
Expected<Snapshot> TakeSnapshot(canopen_client::CanSession& s);

/// The first `axes` (at most 6) configured axes: names, kinds, units per step, max corrections.
/// These are the configuration objects: while settings are pending, the edited values.
Expected<std::vector<AxisInfo>> ReadAxes(canopen_client::CanSession& s, uint32_t axes);

/// Whether the applied correction of axis `a` stands at its max correction (0x2015).
bool AtMaxCorrection(const Snapshot& n, const AxisInfo& x, uint32_t a);

/// Axis `a` as `status --json` and `monitor --json` report it; the machine position (the table's
/// coordinate, after the home offset 0x2018) only when `referenced`.
JsonValue AxisData(const Snapshot& n, const AxisInfo& x, uint32_t a, bool referenced);
/// The counters as an object, by CounterNames().
JsonValue CountersData(const Snapshot& n);
/// The thermal correction as `status --json` reports it: flags, the channels that are not unused
/// (temperature in C, state, faults), and while a model is in force the applied offset (um) and
/// slope (um/m) of each linear axis.
JsonValue ThermalData(const ThermalSnapshot& t, const std::vector<AxisInfo>& axes);

/// The device state flags joined with ',' ("referenced,writable"), "-" for none.
std::string StateText(uint32_t state);
/// An EMCY for people: the code, the register, the data and what the board's codes mean.
std::string EmcyText(const canopen::Emcy& e);

}  // namespace volcomp::cli
