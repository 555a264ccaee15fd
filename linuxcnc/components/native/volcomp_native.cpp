// HAL component `volcomp`: native volumetric compensation for LinuxCNC (docs/linuxcnc.md §3,
// `man 9 volcomp`).
//
//   loadrt volcomp table=FILE[,FILE...] [count=N | names=A[,B...]] [units=mm|inch[,...]]
//                  [axes=XYZ[,...]]
//   addf <name>.feedback servo-thread POSITION   (after the drives' feedback is read, before
//                                                 motion-command-handler)
//   addf <name>.update servo-thread POSITION     (right after motion-controller)
//
// Two functions, as LinuxCNC's moveoff has: `feedback` gives motion this period's feedback minus
// the correction the drive was last commanded with (so motion sees its feedback as fresh as
// without the component), `update` computes the correction from the positions motion has just
// written and corrects the command.
//
// Per instance (default name volcomp.0) and joint channel J (joint J by default; axes= names the
// table axis of each channel, e.g. axes=XYYZ for a gantry):
//   <name>.joint.J.joint-pos-cmd  <- joint.J.pos-cmd: the machine position the table is read at
//   <name>.joint.J.pos-cmd-in     <- joint.J.motor-pos-cmd     pos-cmd-out -> stepgen / pid command
//   <name>.joint.J.pos-fb-in      <- stepgen / encoder         pos-fb-out  -> joint.J.motor-pos-fb
//   <name>.joint.J.vel-cmd-in     <- joint.J.vel-cmd           vel-cmd-out -> pid command-deriv
//   <name>.joint.J.correction     the correction (machine units) added to the command and taken
//                                 out of the feedback
//   <name>.enable, .referenced (in), .reload (in, rising edge), .active, .clamped (out),
//   .table-crc (u32), .table-error (s32: 0 or the error code of the last load), .reload-count (u32)
//   parameters <name>.axis.L.max-correction, .max-correction-vel, .max-correction-accel,
//   .direction-hysteresis, .switch-vel, .switch-accel (per table axis L, machine units: mm or
//   inch, degrees for rotary axes; read every period)
//
// The servo-thread function reads no file and allocates nothing: tables are read, validated and
// prepared at loadrt and by the loader thread on a reload (native/table_loader.hpp), then switched
// in by pointer (native/table_exchange.hpp).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "hal_module.hpp"
#include "native/instance_config.hpp"
#include "native/native_compensator.hpp"
#include "native/native_table.hpp"
#include "native/table_exchange.hpp"
#include "native/table_loader.hpp"

namespace lc = volcomp::linuxcnc;

extern "C" {
MODULE_AUTHOR("volcomp");
MODULE_DESCRIPTION("volcomp native volumetric compensation");
MODULE_LICENSE("GPL");
int count = 0;
RTAPI_MP_INT(count, "number of instances volcomp.0 ... (default 1)");
char* names[lc::kMaxInstances] = {};
RTAPI_MP_ARRAY_STRING(names, 8, "instance names (instead of count)");
char* table[lc::kMaxInstances] = {};
RTAPI_MP_ARRAY_STRING(table, 8, "table image file of each instance (volcomp build ...)");
char* units[lc::kMaxInstances] = {};
RTAPI_MP_ARRAY_STRING(units, 8, "linear units of each instance: mm (default) or inch");
char* axes[lc::kMaxInstances] = {};
RTAPI_MP_ARRAY_STRING(axes,
                      8,
                      "table axis of each joint channel, e.g. XYYZ (default: the table's axes)");
}

namespace {

constexpr const char* kComponent = "volcomp";
constexpr uint8_t kMaxAxes = lc::NativeCompensator::kMaxAxes;

struct ChannelPins {
  hal_float_t *joint_pos, *cmd_in, *cmd_out, *fb_in, *fb_out, *vel_in, *vel_out, *correction;
};

// One per AxisLimits field, in its order (the parameter names: kParamNames).
constexpr int kLimitCount = 6;
constexpr const char* kParamNames[kLimitCount] = {"max-correction",       "max-correction-vel",
                                                  "max-correction-accel", "direction-hysteresis",
                                                  "switch-vel",           "switch-accel"};
constexpr const char* kParamUnits[kLimitCount] = {"", "/s", "/s^2", "", "/s", "/s^2"};

struct AxisParams {
  hal_float_t value[kLimitCount];
};

constexpr double lc::AxisLimits::*kFields[kLimitCount] = {
    &lc::AxisLimits::max_correction, &lc::AxisLimits::max_vel,
    &lc::AxisLimits::max_accel,      &lc::AxisLimits::direction_hysteresis,
    &lc::AxisLimits::switch_vel,     &lc::AxisLimits::switch_accel};

// In HAL's shared memory (hal_malloc): pins point here, parameters live here.
struct InstanceHal {
  ChannelPins channel[lc::kMaxChannels];
  AxisParams axis[kMaxAxes];
  hal_bit_t *enable, *referenced, *reload, *active, *clamped;
  hal_u32_t *table_crc, *reload_count;
  hal_s32_t* table_error;
};

struct Instance {
  std::string name;
  std::string path;
  lc::ChannelMap map;
  double scale[kMaxAxes] = {};  // table units per machine unit, per table axis
  InstanceHal* hal = nullptr;
  lc::NativeCompensator comp;
  const lc::NativeTable* active = nullptr;     // owned; the loader frees it once replaced
  std::unique_ptr<lc::NativeTable> reference;  // the first table's copy: reloads must match it
  lc::TableExchange exchange;
  double applied[kMaxAxes][kLimitCount] = {};  // the limits taken, machine units (as the params)
  long period_ns = 0;
  bool last_reload = false;
  uint32_t reloads = 0;
  double last_correction[lc::kMaxChannels] = {};  // per channel, machine units
  uint32_t feedback_calls = 0;  // the feedback function runs (it must be in a thread)
  uint32_t updates = 0;
};

int g_comp_id = -1;
std::vector<Instance*> g_instances;
lc::TableLoader* g_loader = nullptr;

void Print(lc::TableLoader::Level level, const std::string& message) {
  rtapi_print_msg(level == lc::TableLoader::Level::kError ? RTAPI_MSG_ERR : RTAPI_MSG_INFO, "%s\n",
                  message.c_str());
}

const char* UnitName(const Instance& in, uint8_t a) {
  if (in.active->axis(a).kind == volcomp::table::AxisKind::kRotary) return "deg";
  return in.scale[a] == 1.0 ? "mm" : "inch";
}

// Says, once per change of the limits, a limit that takes effect other than as set: the maximum
// correction rounded down to whole table steps, a direction switch slower than switch-accel (the
// servo period or switch-vel bounds it). So the value in force is never a silent one.
void SayLimitsInForce(Instance& in, uint8_t a) {
  const char* u = UnitName(in, a);
  const char name = in.active->axis(a).name;
  const double k = in.scale[a];
  const double max = in.comp.MaxCorrectionInForce(a) / k;
  if (max != in.applied[a][0]) {
    rtapi_print_msg(RTAPI_MSG_INFO,
                    "%s: axis %c: max-correction %g %s takes effect as %g %s (whole table steps "
                    "of %g %s, rounded down)\n",
                    in.name.c_str(), name, in.applied[a][0], u, max, u,
                    in.active->axis(a).units_per_step / k, u);
  }
  double accel = 0;
  const volcomp::SwitchAccelBound b = in.comp.SwitchAccel(a, &accel);
  if (b == volcomp::SwitchAccelBound::kNone) return;
  rtapi_print_msg(RTAPI_MSG_INFO,
                  "%s: axis %c: switch-accel %g %s/s^2 takes effect as %g %s/s^2, the most %s\n",
                  in.name.c_str(), name, in.applied[a][5], u, accel / k, u,
                  b == volcomp::SwitchAccelBound::kPeriod
                      ? "a servo period represents (below one table step per period^2)"
                      : "that reaches switch-vel within one servo period");
}

// The limit parameters, checked every period (a `setp` takes effect here); values the limiter
// cannot take are refused with a message and the parameters set back.
void ApplyParams(Instance& in, bool force) {
  for (uint8_t a = 0; a < in.active->axis_count(); ++a) {
    AxisParams& p = in.hal->axis[a];
    double* cur = in.applied[a];
    bool same = true;
    for (int i = 0; i < kLimitCount; ++i) same = same && p.value[i] == cur[i];
    if (!force && same) continue;
    const double k = in.scale[a];
    lc::AxisLimits l;
    for (int i = 0; i < kLimitCount; ++i) l.*kFields[i] = p.value[i] * k;
    const volcomp::Status s = in.comp.SetLimits(a, l);
    if (s.ok()) {
      for (int i = 0; i < kLimitCount; ++i) cur[i] = p.value[i];
      SayLimitsInForce(in, a);
      continue;
    }
    const char* u = UnitName(in, a);
    std::string given, kept;
    for (int i = 0; i < kLimitCount; ++i) {
      char b[96];
      std::snprintf(b, sizeof b, "%s%s %g %s%s", i > 0 ? ", " : "", kParamNames[i], p.value[i], u,
                    kParamUnits[i]);
      given += b;
      std::snprintf(b, sizeof b, "%s%g", i > 0 ? ", " : "", cur[i]);
      kept += b;
    }
    rtapi_print_msg(
        RTAPI_MSG_ERR,
        "%s: axis %c: limits refused (%s): the velocities and accelerations must be positive, "
        "max-correction at most %g %s, direction-hysteresis at most %g %s, max-correction-accel "
        "below %g %s/s^2 at a %ld ns servo period, max-correction-vel at least %g %s/s for it, "
        "switch-accel at least max-correction-accel (%s); they stay %s\n",
        in.name.c_str(), in.active->axis(a).name, given.c_str(),
        volcomp::table::kMaxCorrectionSteps * in.active->axis(a).units_per_step / k, u,
        65535 * in.active->axis(a).units_per_step / k, u, in.comp.MaxAccel(a) / k, u, in.period_ns,
        in.comp.MinVel(a, l.max_accel) / k, u, s.name(), kept.c_str());
    for (int i = 0; i < kLimitCount; ++i) p.value[i] = cur[i];
  }
}

// Before motion: the feedback motion reads, without the correction the drive was commanded with.
void Feedback(void* arg, long) {
  Instance& in = *static_cast<Instance*>(arg);
  InstanceHal& h = *in.hal;
  for (uint8_t j = 0; j < in.map.count; ++j) {
    *h.channel[j].fb_out = *h.channel[j].fb_in - in.last_correction[j];
  }
  ++in.feedback_calls;
}

void Update(void* arg, long period) {
  Instance& in = *static_cast<Instance*>(arg);
  InstanceHal& h = *in.hal;
  bool force = false;
  if (period != in.period_ns) {  // the first period: the limits are converted for this rate
    in.period_ns = period;
    (void)in.comp.SetPeriod(period);
    force = true;
  }
  ApplyParams(in, force);
  const bool reload = *h.reload;
  if (reload && !in.last_reload) in.exchange.RequestReload();
  in.last_reload = reload;
  if (in.exchange.SwapIn(&in.active)) {
    in.comp.UseTable(in.active);
    ++in.reloads;
  }
  const uint8_t n = in.active->axis_count();
  double pos[kMaxAxes] = {}, corr[kMaxAxes] = {}, vel[kMaxAxes] = {};
  for (uint8_t a = 0; a < n; ++a)
    pos[a] = *h.channel[in.map.position_channel[a]].joint_pos * in.scale[a];
  in.comp.Tick(pos, *h.enable, *h.referenced, corr, vel);
  for (uint8_t j = 0; j < in.map.count; ++j) {
    ChannelPins& c = h.channel[j];
    const uint8_t a = in.map.axis_of[j];
    const double k = in.scale[a];
    const double correction = corr[a] / k;
    *c.correction = correction;
    *c.cmd_out = *c.cmd_in + correction;
    *c.vel_out = *c.vel_in + vel[a] / k;
    in.last_correction[j] = correction;
    // Without the feedback function in a thread, motion still gets the feedback minus the
    // correction, one period late (said once, below).
    if (in.feedback_calls == 0) *c.fb_out = *c.fb_in - correction;
  }
  if (++in.updates == 1000 && in.feedback_calls == 0) {
    rtapi_print_msg(
        RTAPI_MSG_ERR,
        "%s: %s.feedback runs in no thread: motion gets its feedback one servo period "
        "late; addf %s.feedback servo-thread POSITION, after the function that reads the "
        "drives' feedback and before motion-command-handler\n",
        in.name.c_str(), in.name.c_str(), in.name.c_str());
  }
  *h.active = in.comp.engaged();
  *h.clamped = in.comp.clamped();
  *h.table_crc = in.active->crc32();
  *h.table_error = in.exchange.last_error();
  *h.reload_count = in.reloads;
}

int MakePins(Instance& in) {
  in.hal = static_cast<InstanceHal*>(hal_malloc(sizeof(InstanceHal)));
  if (in.hal == nullptr) return -ENOMEM;
  std::memset(static_cast<void*>(in.hal), 0, sizeof(InstanceHal));
  InstanceHal& h = *in.hal;
  const char* n = in.name.c_str();
  int r = 0;
  for (uint8_t j = 0; j < in.map.count && r == 0; ++j) {
    ChannelPins& c = h.channel[j];
    r |= hal_pin_float_newf(HAL_IN, &c.joint_pos, g_comp_id, "%s.joint.%u.joint-pos-cmd", n, j);
    r |= hal_pin_float_newf(HAL_IN, &c.cmd_in, g_comp_id, "%s.joint.%u.pos-cmd-in", n, j);
    r |= hal_pin_float_newf(HAL_OUT, &c.cmd_out, g_comp_id, "%s.joint.%u.pos-cmd-out", n, j);
    r |= hal_pin_float_newf(HAL_IN, &c.fb_in, g_comp_id, "%s.joint.%u.pos-fb-in", n, j);
    r |= hal_pin_float_newf(HAL_OUT, &c.fb_out, g_comp_id, "%s.joint.%u.pos-fb-out", n, j);
    r |= hal_pin_float_newf(HAL_IN, &c.vel_in, g_comp_id, "%s.joint.%u.vel-cmd-in", n, j);
    r |= hal_pin_float_newf(HAL_OUT, &c.vel_out, g_comp_id, "%s.joint.%u.vel-cmd-out", n, j);
    r |= hal_pin_float_newf(HAL_OUT, &c.correction, g_comp_id, "%s.joint.%u.correction", n, j);
  }
  for (uint8_t a = 0; a < in.active->axis_count() && r == 0; ++a) {
    AxisParams& p = h.axis[a];
    const char l = static_cast<char>(in.active->axis(a).name - 'A' + 'a');
    lc::AxisLimits d = lc::NativeCompensator::DefaultLimits(in.active->axis(a));
    for (int i = 0; i < kLimitCount && r == 0; ++i) {
      r |= hal_param_float_newf(HAL_RW, &p.value[i], g_comp_id, "%s.axis.%c.%s", n, l,
                                kParamNames[i]);
      p.value[i] = in.applied[a][i] = d.*kFields[i] / in.scale[a];
    }
  }
  r |= hal_pin_bit_newf(HAL_IN, &h.enable, g_comp_id, "%s.enable", n);
  r |= hal_pin_bit_newf(HAL_IN, &h.referenced, g_comp_id, "%s.referenced", n);
  r |= hal_pin_bit_newf(HAL_IN, &h.reload, g_comp_id, "%s.reload", n);
  r |= hal_pin_bit_newf(HAL_OUT, &h.active, g_comp_id, "%s.active", n);
  r |= hal_pin_bit_newf(HAL_OUT, &h.clamped, g_comp_id, "%s.clamped", n);
  r |= hal_pin_u32_newf(HAL_OUT, &h.table_crc, g_comp_id, "%s.table-crc", n);
  r |= hal_pin_s32_newf(HAL_OUT, &h.table_error, g_comp_id, "%s.table-error", n);
  r |= hal_pin_u32_newf(HAL_OUT, &h.reload_count, g_comp_id, "%s.reload-count", n);
  if (r != 0) return r;
  *h.table_crc = in.active->crc32();
  char fn[HAL_NAME_LEN + 1];
  std::snprintf(fn, sizeof fn, "%s.feedback", n);
  r = hal_export_funct(fn, Feedback, &in, /*uses_fp=*/1, /*reentrant=*/0, g_comp_id);
  if (r != 0) return r;
  std::snprintf(fn, sizeof fn, "%s.update", n);
  return hal_export_funct(fn, Update, &in, /*uses_fp=*/1, /*reentrant=*/0, g_comp_id);
}

// Entry `i` of a per-instance parameter: its own, or the single value given for all.
std::string PerInstance(char* const* values, size_t i) {
  if (values[i] != nullptr) return values[i];
  if (i > 0 && values[0] != nullptr && values[1] == nullptr) return values[0];
  return "";
}

// Builds instance `name` from its parameters; false (after a message) when it cannot.
bool MakeInstance(const std::string& name, size_t i, Instance* in) {
  in->name = name;
  in->path = table[i] != nullptr ? table[i] : "";
  if (in->path.empty()) {
    rtapi_print_msg(RTAPI_MSG_ERR,
                    "%s: %s: no table file: table=FILE is required, one file for each instance "
                    "(table=a.vct,b.vct for two)\n",
                    kComponent, name.c_str());
    return false;
  }
  auto fail = [&](const volcomp::Failure& f) {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: %s: %s\n", kComponent, name.c_str(), f.message.c_str());
    return false;
  };
  volcomp::Expected<std::unique_ptr<lc::NativeTable>> t = lc::NativeTable::ReadFile(in->path);
  if (!t.ok()) return fail(t.error());
  volcomp::Expected<double> mm_per_unit = lc::ParseLinearUnits(PerInstance(units, i));
  if (!mm_per_unit.ok()) return fail(mm_per_unit.error());
  volcomp::Expected<lc::ChannelMap> map = lc::MapChannels(PerInstance(axes, i), **t);
  if (!map.ok()) return fail(map.error());
  volcomp::Expected<std::unique_ptr<lc::NativeTable>> ref = (*t)->Copy(in->path);
  if (!ref.ok()) return fail(ref.error());
  in->map = *map;
  for (uint8_t a = 0; a < (*t)->axis_count(); ++a) {
    const bool rotary = (*t)->axis(a).kind == volcomp::table::AxisKind::kRotary;
    in->scale[a] = rotary ? 1.0 : *mm_per_unit;
  }
  in->reference = std::move(*ref);
  in->active = t->release();
  in->comp.UseTable(in->active);
  return true;
}

void FreeInstances() {
  for (Instance* in : g_instances) {
    delete in->active;
    delete in;
  }
  g_instances.clear();
}

}  // namespace

extern "C" int rtapi_app_main(void) {
  std::vector<std::string> given;
  for (char* n : names) {
    if (n != nullptr) given.push_back(n);
  }
  volcomp::Expected<std::vector<std::string>> inst = lc::InstanceNames(count, given);
  if (!inst.ok()) {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: %s\n", kComponent, inst.error().message.c_str());
    return -EINVAL;
  }
  size_t tables = 0;
  while (tables < lc::kMaxInstances && table[tables] != nullptr) ++tables;
  if (tables > inst->size()) {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: table= names %zu files for %zu instance(s)\n", kComponent,
                    tables, inst->size());
    return -EINVAL;
  }
  for (size_t i = 0; i < inst->size(); ++i) {
    Instance* in = new Instance();
    g_instances.push_back(in);
    if (!MakeInstance((*inst)[i], i, in)) {
      FreeInstances();
      return -EINVAL;
    }
  }
  g_comp_id = hal_init(kComponent);
  if (g_comp_id < 0) {
    FreeInstances();
    return g_comp_id;
  }
  for (Instance* in : g_instances) {
    const int r = MakePins(*in);
    if (r != 0) {
      rtapi_print_msg(RTAPI_MSG_ERR,
                      "%s: %s: cannot create its pins, parameters or function (%d)\n", kComponent,
                      in->name.c_str(), r);
      hal_exit(g_comp_id);
      FreeInstances();
      return r < 0 ? r : -EINVAL;
    }
  }
  std::vector<lc::TableLoader::Job> jobs;
  for (Instance* in : g_instances) {
    jobs.push_back({in->name, in->path, in->reference.get(), &in->exchange});
    rtapi_print_msg(RTAPI_MSG_INFO, "%s: table \"%s\" (axes %s, %zu bytes, CRC-32 %08X)\n",
                    in->name.c_str(), in->path.c_str(), in->active->AxisNames().c_str(),
                    in->active->size_bytes(), in->active->crc32());
  }
  g_loader = new lc::TableLoader(Print);
  g_loader->Start(std::move(jobs));
  hal_ready(g_comp_id);
  return 0;
}

extern "C" void rtapi_app_exit(void) {
  hal_exit(g_comp_id);  // no more servo-thread calls
  if (g_loader != nullptr) {
    g_loader->Stop();
    delete g_loader;
    g_loader = nullptr;
  }
  FreeInstances();
}
