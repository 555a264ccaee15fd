// CiA 402 CSP gateway: frame forwarding with target / actual position correction.
#include "volcomp/gateway/csp_gateway.hpp"

#include "volcomp/base/byte_order.hpp"

namespace volcomp::gateway {
namespace {

constexpr uint32_t kNmtCobId = 0x000;
constexpr uint32_t kSdoRequestBase = 0x600;
constexpr uint32_t kSdoResponseBase = 0x580;
constexpr uint32_t kHeartbeatBase = 0x700;
constexpr uint32_t kEmcyBase = 0x080;

bool IsOwnCobId(uint32_t id, uint8_t node) {
  return node != 0 && (id == kSdoRequestBase + node || id == kSdoResponseBase + node ||
                       id == kHeartbeatBase + node || id == kEmcyBase + node);
}

// A standard data frame that may carry a mapped field.
bool IsPdoCandidate(const CanFrame& f) { return !f.extended && !f.rtr; }

uint32_t Wrap(int32_t v) { return static_cast<uint32_t>(v); }

}  // namespace

Status ValidateGatewayConfig(const GatewayConfig& config, uint8_t axis_count) {
  if (axis_count == 0 || axis_count > table::kMaxAxes) return Error::kConfigInvalid;
  if (config.map_count > kMaxPdoMaps || config.own_node_id > 127) return Error::kConfigInvalid;
  if (config.sync_cob_id == kNmtCobId || config.sync_cob_id > 0x7FF ||
      IsOwnCobId(config.sync_cob_id, config.own_node_id)) {
    return Error::kConfigInvalid;
  }
  if (config.feedback != FeedbackMode::kAtSync && config.feedback != FeedbackMode::kLatest) {
    return Error::kConfigInvalid;
  }
  for (uint8_t i = 0; i < config.map_count; ++i) {
    const PdoMap& m = config.map[i];
    if (m.cob_id == kNmtCobId || m.cob_id > 0x7FF || m.cob_id == config.sync_cob_id) {
      return Error::kConfigInvalid;
    }
    if (IsOwnCobId(m.cob_id, config.own_node_id)) return Error::kConfigInvalid;
    if (m.field != PdoField::kTargetPosition && m.field != PdoField::kActualPosition) {
      return Error::kConfigInvalid;
    }
    if (m.offset > 4 || m.axis >= axis_count) return Error::kConfigInvalid;
    for (uint8_t j = 0; j < i; ++j) {
      const PdoMap& o = config.map[j];
      if (o.field != m.field) continue;
      if (o.axis == m.axis) return Error::kConfigInvalid;  // one target / one actual per axis
      const bool overlap = o.offset < m.offset + 4 && m.offset < o.offset + 4;
      if (o.cob_id == m.cob_id && overlap) return Error::kConfigInvalid;
    }
  }
  return Status::Ok();
}

Status CspGateway::Configure(const GatewayConfig& config, uint8_t axis_count) {
  VOLCOMP_TRY(ValidateGatewayConfig(config, axis_count));
  config_ = config;
  axis_count_ = axis_count;
  counters_ = GatewayCounters();
  for (uint8_t a = 0; a < table::kMaxAxes; ++a) {
    correction_[a].store(0, std::memory_order_relaxed);
    sent_[a] = at_sync_[a] = last_target_[a] = 0;
    base_[a] = 0;
    counter_[a].store(0, std::memory_order_relaxed);
    has_target_[a] = false;
  }
  return Status::Ok();
}

bool CspGateway::IsOwnTxCobId(uint32_t id) const {
  const uint8_t n = config_.own_node_id;
  return n != 0 && (id == kSdoResponseBase + n || id == kHeartbeatBase + n || id == kEmcyBase + n);
}

Route CspGateway::FromController(const CanFrame& in, CanFrame* out) {
  ++counters_.from_controller;
  *out = in;
  if (!IsPdoCandidate(in)) return Route::kForward;
  if (config_.own_node_id != 0 && in.id == kSdoRequestBase + config_.own_node_id) {
    ++counters_.local;
    return Route::kLocal;
  }
  if (in.id == config_.sync_cob_id) {
    ++counters_.syncs;
    for (uint8_t a = 0; a < axis_count_; ++a) at_sync_[a] = sent_[a];
    return Route::kForward;
  }
  for (uint8_t i = 0; i < config_.map_count; ++i) {
    const PdoMap& m = config_.map[i];
    if (m.cob_id != in.id || m.field != PdoField::kTargetPosition) continue;
    if (in.dlc < m.offset + 4u) {
      ++counters_.short_pdos;
      continue;
    }
    const uint8_t a = m.axis;
    const int32_t target = LoadLeI32(in.data + m.offset);
    const uint32_t machine = config_.invert[a] ? 0u - Wrap(target) : Wrap(target);
    if (!has_target_[a]) {
      base_[a] = machine;
      has_target_[a] = true;
    }
    counter_[a].store(machine - base_[a], std::memory_order_relaxed);
    last_target_[a] = target;
    sent_[a] = correction_[a].load(std::memory_order_relaxed);
    StoreLe32(out->data + m.offset, Wrap(target) + Wrap(sent_[a]));
    ++counters_.targets_corrected;
  }
  return Route::kForward;
}

Route CspGateway::FromDrive(const CanFrame& in, CanFrame* out) {
  ++counters_.from_drives;
  *out = in;
  if (!IsPdoCandidate(in)) return Route::kForward;
  if (IsOwnTxCobId(in.id)) {
    ++counters_.conflicts;
    return Route::kDrop;
  }
  for (uint8_t i = 0; i < config_.map_count; ++i) {
    const PdoMap& m = config_.map[i];
    if (m.cob_id != in.id || m.field != PdoField::kActualPosition) continue;
    if (in.dlc < m.offset + 4u) {
      ++counters_.short_pdos;
      continue;
    }
    const uint32_t actual = LoadLe32(in.data + m.offset);
    StoreLe32(out->data + m.offset, actual - Wrap(feedback_correction(m.axis)));
    ++counters_.actuals_corrected;
  }
  return Route::kForward;
}

void CspGateway::SetCorrection(uint8_t axis, int32_t machine_steps) {
  if (axis >= axis_count_) return;
  correction_[axis].store(
      config_.invert[axis] ? static_cast<int32_t>(0u - Wrap(machine_steps)) : machine_steps,
      std::memory_order_relaxed);
}

}  // namespace volcomp::gateway
