// HAL component `volcomp`: native volumetric compensation for LinuxCNC (docs/linuxcnc.md §3).
//
//   loadrt volcomp table=FILE.vct [max_correction_steps=1000] [correction_rate=2000]
//                  [correction_accel=200000]
//   addf volcomp.update servo-thread        (after motion-controller, before the stepgen/PID)
//
// Per joint j (joint j = table axis j, e.g. X Y Z for trivkins):
//   volcomp.j.pos-cmd-in  <- joint.j.motor-pos-cmd       volcomp.j.pos-cmd-out -> stepgen/PID
//   volcomp.j.pos-fb-in   <- stepgen/encoder feedback    volcomp.j.pos-fb-out  -> motor-pos-fb
//   volcomp.j.correction  the correction added to the command and subtracted from the
//                         feedback (mm)
// Global: enable, referenced (in; e.g. motion.is-all-homed), reload (in, rising edge: read the
// table file again; refused tables leave the active one and set table-error), active, clamped,
// table-crc, table-error (out).
//
// The correction is the firmware's: trilinear GRID3 + AXIS1D lookup of the commanded position,
// clamped to max_correction_steps, moved toward with the rate and acceleration limits at the servo
// rate; it ramps in when enable and referenced are both high and ramps out when either drops.
#include <cstring>
#include <vector>

#include "hal_module.hpp"
#include "native/native_compensator.hpp"

namespace lc = volcomp::linuxcnc;

extern "C" {
MODULE_AUTHOR("volcomp");
MODULE_DESCRIPTION("volcomp native volumetric compensation");
MODULE_LICENSE("GPL");
char* table = nullptr;
RTAPI_MP_STRING(table, "table image file (volcomp build ...)");
int max_correction_steps = 1000;
RTAPI_MP_INT(max_correction_steps, "largest |correction| per axis, table steps");
int correction_rate = 2000;
RTAPI_MP_INT(correction_rate, "correction velocity limit, table steps/s");
int correction_accel = 200000;
RTAPI_MP_INT(correction_accel, "correction acceleration limit, table steps/s^2");
}

namespace {

constexpr const char* kName = "volcomp";
constexpr int kJoints = lc::NativeCompensator::kMaxJoints;

struct Pins {
  hal_float_t *cmd_in[kJoints], *cmd_out[kJoints], *fb_in[kJoints], *fb_out[kJoints],
      *correction[kJoints];
  hal_bit_t *enable, *referenced, *reload, *active, *clamped;
  hal_u32_t* table_crc;
  hal_s32_t* table_error;
};

int g_comp_id = -1;
Pins* g_pins = nullptr;
lc::NativeCompensator g_comp;
std::vector<uint8_t> g_first_image;
long g_period_ns = 0;
bool g_last_reload = false;

lc::NativeLimits Limits() {
  lc::NativeLimits l;
  l.max_correction_steps = max_correction_steps;
  l.rate_steps_s = static_cast<uint32_t>(correction_rate);
  l.accel_steps_s2 = static_cast<uint32_t>(correction_accel);
  return l;
}

void Load(std::vector<uint8_t> image, long period) {
  const uint32_t tick_hz = static_cast<uint32_t>(1000000000L / period);
  const volcomp::Status s = g_comp.Load(std::move(image), tick_hz, Limits());
  *g_pins->table_error = static_cast<int32_t>(s.error());
  if (!s.ok()) {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: table \"%s\" refused (%s)%s\n", kName, table, s.name(),
                    g_comp.loaded() ? "; the active table stays" : "");
  }
  *g_pins->table_crc = g_comp.table_crc32();
}

void Update(void*, long period) {
  Pins& p = *g_pins;
  if (g_period_ns == 0) {
    g_period_ns = period;
    Load(std::move(g_first_image), period);
  }
  // A reload reads the file in this thread: uspace threads are ordinary threads, and the table
  // switches only here, between two periods (the correction then moves within its limits).
  const bool reload = *p.reload;
  if (reload && !g_last_reload) {
    std::vector<uint8_t> image;
    const volcomp::Status read = lc::ReadFile(kName, table, &image);
    if (read.ok()) {
      Load(std::move(image), g_period_ns);
    } else {
      *p.table_error = static_cast<int32_t>(read.error());
    }
  }
  g_last_reload = reload;
  double pos[kJoints] = {}, corr[kJoints] = {};
  const int n = g_comp.loaded() ? g_comp.axis_count() : 0;
  for (int j = 0; j < n; ++j) pos[j] = *p.cmd_in[j];
  if (n > 0) g_comp.Tick(pos, *p.enable, *p.referenced, corr);
  for (int j = 0; j < kJoints; ++j) {
    *p.correction[j] = corr[j];
    *p.cmd_out[j] = *p.cmd_in[j] + corr[j];
    *p.fb_out[j] = *p.fb_in[j] - corr[j];
  }
  *p.active = g_comp.loaded() && g_comp.engaged();
  *p.clamped = g_comp.loaded() && g_comp.clamped();
}

int MakePins() {
  g_pins = static_cast<Pins*>(hal_malloc(sizeof(Pins)));
  if (g_pins == nullptr) return -1;
  std::memset(g_pins, 0, sizeof(Pins));
  Pins& p = *g_pins;
  int r = 0;
  for (int j = 0; j < kJoints; ++j) {
    r |= hal_pin_float_newf(HAL_IN, &p.cmd_in[j], g_comp_id, "volcomp.%d.pos-cmd-in", j);
    r |= hal_pin_float_newf(HAL_OUT, &p.cmd_out[j], g_comp_id, "volcomp.%d.pos-cmd-out", j);
    r |= hal_pin_float_newf(HAL_IN, &p.fb_in[j], g_comp_id, "volcomp.%d.pos-fb-in", j);
    r |= hal_pin_float_newf(HAL_OUT, &p.fb_out[j], g_comp_id, "volcomp.%d.pos-fb-out", j);
    r |= hal_pin_float_newf(HAL_OUT, &p.correction[j], g_comp_id, "volcomp.%d.correction", j);
  }
  r |= hal_pin_bit_newf(HAL_IN, &p.enable, g_comp_id, "volcomp.enable");
  r |= hal_pin_bit_newf(HAL_IN, &p.referenced, g_comp_id, "volcomp.referenced");
  r |= hal_pin_bit_newf(HAL_IN, &p.reload, g_comp_id, "volcomp.reload");
  r |= hal_pin_bit_newf(HAL_OUT, &p.active, g_comp_id, "volcomp.active");
  r |= hal_pin_bit_newf(HAL_OUT, &p.clamped, g_comp_id, "volcomp.clamped");
  r |= hal_pin_u32_newf(HAL_OUT, &p.table_crc, g_comp_id, "volcomp.table-crc");
  r |= hal_pin_s32_newf(HAL_OUT, &p.table_error, g_comp_id, "volcomp.table-error");
  return r;
}

}  // namespace

extern "C" int rtapi_app_main(void) {
  if (table == nullptr || table[0] == '\0') {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: table=FILE is required\n", kName);
    return -EINVAL;
  }
  if (max_correction_steps < 0 || correction_rate <= 0 || correction_accel <= 0) {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: the correction limits must be positive\n", kName);
    return -EINVAL;
  }
  if (!lc::ReadFile(kName, table, &g_first_image).ok()) return -EINVAL;
  // Validate now so that a bad file fails loadrt; the configuration needs the servo period,
  // known at the first call of the function.
  {
    lc::NativeCompensator probe;
    const volcomp::Status s = probe.Load(g_first_image, 1000, Limits());
    if (!s.ok()) {
      rtapi_print_msg(RTAPI_MSG_ERR, "%s: table \"%s\" refused: %s\n", kName, table, s.name());
      return -EINVAL;
    }
  }
  g_comp_id = hal_init(kName);
  if (g_comp_id < 0) return g_comp_id;
  if (MakePins() != 0 ||
      hal_export_funct("volcomp.update", Update, nullptr, 1, 0, g_comp_id) != 0) {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: cannot create pins or function\n", kName);
    hal_exit(g_comp_id);
    return -EINVAL;
  }
  hal_ready(g_comp_id);
  return 0;
}

extern "C" void rtapi_app_exit(void) { hal_exit(g_comp_id); }
