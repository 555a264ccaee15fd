// HAL component `volcomp_board`: the volcomp board firmware between LinuxCNC's step generators and
// the drives, on HAL step/dir pins (docs/linuxcnc.md §2).
//
//   loadrt volcomp_board table=FILE.vct [resolution_nm=1000] [invert_dir=1] [dir_negative_high=1]
//                        [max_correction_steps=1000] [correction_rate=2000]
//                        [correction_accel=200000] [poll_periods=50] [home_steps=X,Y,Z]
//   addf volcomp-board.update base-thread     (after stepgen.make-pulses, before the drives)
//
// Per base period: sample the STEP/DIR inputs; every kPeriodsPerTick periods run the
// control tick (BoardConfig::tick_hz = base rate / 2, see hal_step_io.hpp; the firmware's tick
// timer accepts only that rate); every poll_periods periods run the main loop (home edges
// reference the board, enable, e-stop); set the STEP/DIR outputs to the output waveform's level
// at this instant. Drive timing in the board's configuration: pulse width, step space, direction
// setup and hold = one base period; maximum output rate = tick rate.
//
// Referencing: a rising edge on an axis's home pin (wired to joint.N.homed, which rises once
// LinuxCNC has homed the joint and made its final move to [JOINT_N]HOME) makes the board's input
// position of that axis its home position, home_steps (HOME x SCALE, 0 by default): from then on
// the board looks the table up at the joint position, whatever the step count was at power-on.
//
// The table image is read and validated at load (loadrt fails with the reason) and
// activated through the firmware (BoardApp::ActivateImage: image validation, board match) at the
// first period; the correction engages once every axis is referenced (a rising edge on its home
// pin) and enable is high. A configuration the pins or the thread cannot run (e.g. a base period
// whose tick rate is not a whole number of Hz) is refused at the first period: message, `fault`,
// no output pulses.
#include <cstring>
#include <utility>
#include <vector>

#include "board/board_glue.hpp"
#include "board/hal_step_io.hpp"
#include "board/thread_board_config.hpp"
#include "hal_module.hpp"
#include "table_file.hpp"
#include "volcomp/table/table_image.hpp"

namespace lc = volcomp::linuxcnc;

extern "C" {
MODULE_AUTHOR("volcomp");
MODULE_DESCRIPTION("volcomp board firmware on HAL step/dir pins");
MODULE_LICENSE("GPL");
char* table = nullptr;
RTAPI_MP_STRING(table, "table image file (volcomp build ...)");
int resolution_nm = 1000;
RTAPI_MP_INT(resolution_nm, "nm per step of X, Y and Z (must match the table)");
int invert_dir = 1;
RTAPI_MP_INT(invert_dir, "1: DIR input high means negative (LinuxCNC stepgen)");
int dir_negative_high = 1;
RTAPI_MP_INT(dir_negative_high, "1: DIR output high for negative moves (encoder counter mode)");
int max_correction_steps = 1000;
RTAPI_MP_INT(max_correction_steps, "largest |correction| per axis, steps");
int correction_rate = 2000;
RTAPI_MP_INT(correction_rate, "correction velocity limit, steps/s");
int correction_accel = 200000;
RTAPI_MP_INT(correction_accel, "correction acceleration limit, steps/s^2");
int poll_periods = 50;
RTAPI_MP_INT(poll_periods, "base periods per main-loop pass");
int home_steps[3] = {0, 0, 0};
RTAPI_MP_ARRAY_INT(home_steps,
                   3,
                   "machine position of X, Y, Z at the home edge, steps ([JOINT_N]HOME x SCALE)");
}

namespace {

constexpr const char* kName = "volcomp_board";
constexpr int kAxes = lc::HalStepIo::kAxes;

struct AxisPins {
  hal_bit_t *step_in, *dir_in, *home, *step_out, *dir_out;
  hal_s32_t *commanded, *correction, *output, *backlog, *pulses_out;
};

struct Pins {
  AxisPins axis[kAxes];
  hal_bit_t *enable, *estop, *ready, *compensating, *fault, *referenced;
  hal_s32_t *overruns, *max_backlog, *queue_overflows, *decode_errors, *tick_hz, *late_periods;
  hal_u32_t* table_crc;
};

int g_comp_id = -1;
Pins* g_pins = nullptr;
std::vector<uint8_t> g_image;
lc::BoardGlue g_board;
bool g_started = false, g_failed = false;
int64_t g_now_ns = 0;
uint64_t g_period_index = 0;
long g_period_ns = 0;

void StartBoard(long period) {
  g_period_ns = period;
  lc::ThreadBoardParams params;
  params.resolution_nm = static_cast<uint32_t>(resolution_nm);
  params.invert_input_dir = invert_dir != 0;
  params.max_correction_steps = max_correction_steps;
  params.correction_rate_steps_s = static_cast<uint32_t>(correction_rate);
  params.correction_accel_steps_s2 = static_cast<uint32_t>(correction_accel);
  for (int a = 0; a < kAxes; ++a) params.home_position_steps[a] = home_steps[a];
  const volcomp::BoardConfig config = lc::ThreadBoardConfig(params, static_cast<uint32_t>(period));
  volcomp::Status s = g_board.Start(config, static_cast<uint32_t>(period), dir_negative_high != 0);
  if (!s.ok()) {
    rtapi_print_msg(RTAPI_MSG_ERR,
                    "%s: the %s refused the configuration for a base period of %ld ns, tick %u Hz "
                    "(%s: %s); the board does not run\n",
                    kName, volcomp::canopen::ConfigPartName(g_board.refused_by()), period,
                    config.tick_hz, volcomp::ErrorText(s.error()), s.name());
    g_failed = true;
  } else {
    s = g_board.ActivateImage(g_image.data(), static_cast<uint32_t>(g_image.size()));
    if (!s.ok()) {
      rtapi_print_msg(RTAPI_MSG_ERR,
                      "%s: table activation failed (%s: %s); the board stays in pass-through\n",
                      kName, volcomp::ErrorText(s.error()), s.name());
      g_failed = true;
    }
  }
  *g_pins->tick_hz = static_cast<int32_t>(config.tick_hz);
  g_started = true;
}

void Update(void*, long period) {
  Pins& p = *g_pins;
  if (!g_started) StartBoard(period);
  if (period != g_period_ns) ++*p.late_periods;  // the thread's period must not change
  bool step[kAxes], dir[kAxes];
  for (int a = 0; a < kAxes; ++a) {
    step[a] = *p.axis[a].step_in;
    dir[a] = *p.axis[a].dir_in;
  }
  lc::HalStepIo& io = g_board.io();
  io.SampleInputs(step, dir);
  if (g_period_index % lc::kPeriodsPerTick == 0 && g_board.ticking()) {
    io.BeginTick(g_now_ns);
    g_board.Tick();
  }
  if (g_period_index % static_cast<uint64_t>(poll_periods) == 0) {
    lc::BoardLines lines;
    for (int a = 0; a < kAxes; ++a) lines.home[a] = *p.axis[a].home;
    lines.enable = *p.enable;
    lines.estop = *p.estop || g_failed;
    g_board.Poll(lines);
    lc::BoardState st;
    g_board.ReadState(&st);
    *p.ready = st.ready && !g_failed;
    *p.compensating = st.compensating;
    *p.fault = st.fault || g_failed;
    *p.referenced = st.referenced;
    *p.overruns = static_cast<int32_t>(st.overruns);
    *p.max_backlog = static_cast<int32_t>(st.max_backlog);
    *p.table_crc = st.table_crc32;
  }
  // Positions every period: a sampler reading them together with the drives' counts must see
  // one consistent instant.
  lc::BoardState st;
  g_board.ReadState(&st);
  io.Render(g_now_ns, step, dir);
  for (int a = 0; a < kAxes; ++a) {
    *p.axis[a].step_out = step[a];
    *p.axis[a].dir_out = dir[a];
    *p.axis[a].commanded = st.commanded[a];
    *p.axis[a].correction = st.correction[a];
    *p.axis[a].output = st.output[a];
    *p.axis[a].backlog = st.backlog[a];
    *p.axis[a].pulses_out = static_cast<int32_t>(io.rendered_pulses(static_cast<uint8_t>(a)));
  }
  *p.queue_overflows = static_cast<int32_t>(io.queue_overflows());
  *p.decode_errors = static_cast<int32_t>(io.decode_errors());
  g_now_ns += period;
  ++g_period_index;
}

int MakePins() {
  g_pins = static_cast<Pins*>(hal_malloc(sizeof(Pins)));
  if (g_pins == nullptr) return -1;
  std::memset(g_pins, 0, sizeof(Pins));
  int r = 0;
  const char* c = "volcomp-board";
  for (int a = 0; a < kAxes && r == 0; ++a) {
    AxisPins& x = g_pins->axis[a];
    r |= hal_pin_bit_newf(HAL_IN, &x.step_in, g_comp_id, "%s.%d.step-in", c, a);
    r |= hal_pin_bit_newf(HAL_IN, &x.dir_in, g_comp_id, "%s.%d.dir-in", c, a);
    r |= hal_pin_bit_newf(HAL_IN, &x.home, g_comp_id, "%s.%d.home", c, a);
    r |= hal_pin_bit_newf(HAL_OUT, &x.step_out, g_comp_id, "%s.%d.step-out", c, a);
    r |= hal_pin_bit_newf(HAL_OUT, &x.dir_out, g_comp_id, "%s.%d.dir-out", c, a);
    r |= hal_pin_s32_newf(HAL_OUT, &x.commanded, g_comp_id, "%s.%d.commanded", c, a);
    r |= hal_pin_s32_newf(HAL_OUT, &x.correction, g_comp_id, "%s.%d.correction", c, a);
    r |= hal_pin_s32_newf(HAL_OUT, &x.output, g_comp_id, "%s.%d.output", c, a);
    r |= hal_pin_s32_newf(HAL_OUT, &x.backlog, g_comp_id, "%s.%d.backlog", c, a);
    r |= hal_pin_s32_newf(HAL_OUT, &x.pulses_out, g_comp_id, "%s.%d.pulses-out", c, a);
  }
  Pins& p = *g_pins;
  r |= hal_pin_bit_newf(HAL_IN, &p.enable, g_comp_id, "%s.enable", c);
  r |= hal_pin_bit_newf(HAL_IN, &p.estop, g_comp_id, "%s.estop", c);
  r |= hal_pin_bit_newf(HAL_OUT, &p.ready, g_comp_id, "%s.ready", c);
  r |= hal_pin_bit_newf(HAL_OUT, &p.compensating, g_comp_id, "%s.compensating", c);
  r |= hal_pin_bit_newf(HAL_OUT, &p.fault, g_comp_id, "%s.fault", c);
  r |= hal_pin_bit_newf(HAL_OUT, &p.referenced, g_comp_id, "%s.referenced", c);
  r |= hal_pin_s32_newf(HAL_OUT, &p.overruns, g_comp_id, "%s.overruns", c);
  r |= hal_pin_s32_newf(HAL_OUT, &p.max_backlog, g_comp_id, "%s.max-backlog", c);
  r |= hal_pin_s32_newf(HAL_OUT, &p.queue_overflows, g_comp_id, "%s.queue-overflows", c);
  r |= hal_pin_s32_newf(HAL_OUT, &p.decode_errors, g_comp_id, "%s.decode-errors", c);
  r |= hal_pin_s32_newf(HAL_OUT, &p.tick_hz, g_comp_id, "%s.tick-hz", c);
  r |= hal_pin_s32_newf(HAL_OUT, &p.late_periods, g_comp_id, "%s.period-changes", c);
  r |= hal_pin_u32_newf(HAL_OUT, &p.table_crc, g_comp_id, "%s.table-crc", c);
  return r;
}

}  // namespace

extern "C" int rtapi_app_main(void) {
  if (table == nullptr || table[0] == '\0') {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: table=FILE is required\n", kName);
    return -EINVAL;
  }
  if (resolution_nm <= 0 || poll_periods <= 0 || max_correction_steps < 0 || correction_rate <= 0 ||
      correction_accel <= 0) {
    rtapi_print_msg(RTAPI_MSG_ERR,
                    "%s: resolution_nm, poll_periods and the correction limits "
                    "must be positive\n",
                    kName);
    return -EINVAL;
  }
  volcomp::Expected<std::vector<uint8_t>> bytes = lc::ReadTableFile(table);
  if (!bytes.ok()) {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: %s\n", kName, bytes.error().message.c_str());
    return -EINVAL;
  }
  g_image = std::move(*bytes);
  const auto view = volcomp::table::ParseImage(g_image.data(), g_image.size());
  if (!view.ok()) {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: %s\n", kName,
                    lc::ImageRefusal(table, view.status()).c_str());
    return -EINVAL;
  }
  g_comp_id = hal_init(kName);
  if (g_comp_id < 0) return g_comp_id;
  if (MakePins() != 0 ||
      hal_export_funct("volcomp-board.update", Update, nullptr, 1, 0, g_comp_id) != 0) {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: cannot create pins or function\n", kName);
    hal_exit(g_comp_id);
    return -EINVAL;
  }
  rtapi_print_msg(RTAPI_MSG_INFO, "%s: table \"%s\", %zu bytes, CRC-32 %08X\n", kName, table,
                  g_image.size(), view->crc32);
  hal_ready(g_comp_id);
  return 0;
}

extern "C" void rtapi_app_exit(void) { hal_exit(g_comp_id); }
