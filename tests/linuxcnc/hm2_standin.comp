component hm2_standin """A stand-in for a Mesa card (hostmot2) in tests: the pins, parameters and functions
of hm2_BOARD.0 that LinuxCNC's sample configurations by_interface/mesa/hm2-stepper and hm2-servo
use, and a machine behind them, so that those configurations run without the card.
Load with names=hm2_5i20.0 (the instance name is the board's).
Stepgens (position mode): the step count follows position-cmd at most maxvel fast, one period
late (as the card's read returns what its write ordered); position-fb = steps / position-scale.
Pwmgens and encoders: a servo amplifier and motor; the encoder counts
counts-per-s x (value / scale, limited to +-1) per second (the sample's INPUT_SCALE x
OUTPUT_SCALE makes that 1 machine unit/s per unit of pid output); an index every
index-counts counts resets the count while index-enable is set and clears it.
gpio.025.in_not: a home switch in series for every channel, pressed where the channel's
position (its count over its scale) is at or below home-switch-at.""";
pin in float stepgen.##.position-cmd [3];
pin out float stepgen.##.position-fb [3];
pin in bit stepgen.##.enable [3];
param rw float stepgen.##.position-scale [3] = 1.0;
param rw float stepgen.##.maxvel [3] = 0.0;
param rw float stepgen.##.maxaccel [3] = 0.0;
param rw u32 stepgen.##.dirsetup [3];
param rw u32 stepgen.##.dirhold [3];
param rw u32 stepgen.##.steplen [3];
param rw u32 stepgen.##.stepspace [3];

pin in float pwmgen.##.value [3];
pin in bit pwmgen.##.enable [3];
param rw float pwmgen.##.scale [3] = 1.0;
param rw u32 pwmgen.##.output-type [3];
param rw float pwmgen.##.counts-per-s [3] = -81920.0 "stand-in: encoder counts per second at duty 1";

pin out float encoder.##.position [3];
pin io bit encoder.##.index-enable [3];
param rw float encoder.##.scale [3] = 1.0;
param rw bit encoder.##.counter-mode [3];
param rw bit encoder.##.filter [3];
param rw bit encoder.##.index-invert [3];
param rw bit encoder.##.index-mask [3];
param rw bit encoder.##.index-mask-invert [3];
param rw s32 encoder.##.index-counts [3] = 16384 "stand-in: counts between index pulses";

param rw float home.#.switch-at [3] = -1.0 "stand-in: the switch position, machine units";

variable double motor_counts[3];
variable double duty[3];
variable rtapi_s64 steps[3];
variable double step_cmd[3];
variable rtapi_s64 index_zero[3];
// The card's names with underscores (halcompile would write hyphens): made in EXTRA_SETUP.
variable hal_bit_t *in_not_pin;
variable hal_bit_t *has_bit_pin;
variable hal_u32_t pwm_frequency;
variable hal_u32_t step_type[3];

function read;
function write;
option extra_setup;
license "GPL";
author "volcomp tests";
;;
#include <rtapi_math.h>

static double scaled(double v, double scale) { return scale != 0.0 ? v / scale : 0.0; }

EXTRA_SETUP() {
  int i, r;
  r = hal_pin_bit_newf(HAL_OUT, &in_not_pin, comp_id, "%s.gpio.025.in_not", prefix);
  if (r) return r;
  r = hal_pin_bit_newf(HAL_IO, &has_bit_pin, comp_id, "%s.watchdog.has_bit", prefix);
  if (r) return r;
  r = hal_param_u32_newf(HAL_RW, &pwm_frequency, comp_id, "%s.pwmgen.pwm_frequency", prefix);
  if (r) return r;
  for (i = 0; i < 3; i++) {
    r = hal_param_u32_newf(HAL_RW, &step_type[i], comp_id, "%s.stepgen.%02d.step_type", prefix, i);
    if (r) return r;
  }
  return 0;
}

FUNCTION(read) {
  int i;
  int pressed = 0;
  for (i = 0; i < 3; i++) {
    /* servo: the motor turned at the duty the last write ordered */
    double before = motor_counts[i];
    double after = before + pwmgen_counts_per_s(i) * duty[i] * fperiod;
    long long n = encoder_index_counts(i) > 0 ? encoder_index_counts(i) : 1;
    long long b = (long long)floor(before), a = (long long)floor(after);
    motor_counts[i] = after;
    if (encoder_index_enable(i) && floor((double)b / n) != floor((double)a / n)) {
      long long mark = (a > b ? (long long)floor((double)a / n) : (long long)floor((double)b / n)) * n;
      index_zero[i] = mark;
      encoder_index_enable(i) = 0;
    }
    encoder_position(i) = scaled((double)(a - index_zero[i]), encoder_scale(i));
    if (scaled((double)a, encoder_scale(i)) <= home_switch_at(i)) pressed = 1;

    /* stepgen: the steps the last write ordered */
    {
      double scale = stepgen_position_scale(i);
      double want = step_cmd[i] * scale - (double)steps[i];
      double most = stepgen_maxvel(i) > 0.0 ? stepgen_maxvel(i) * fabs(scale) * fperiod : 1e300;
      if (want > most) want = most;
      if (want < -most) want = -most;
      steps[i] += (long long)(want >= 0 ? floor(want + 0.5) : -floor(-want + 0.5));
      stepgen_position_fb(i) = scaled((double)steps[i], scale);
      if (scaled((double)steps[i], scale) <= home_switch_at(i)) pressed = 1;
    }
  }
  *in_not_pin = pressed;
}

FUNCTION(write) {
  int i;
  for (i = 0; i < 3; i++) {
    double d = pwmgen_enable(i) ? scaled(pwmgen_value(i), pwmgen_scale(i)) : 0.0;
    duty[i] = d > 1.0 ? 1.0 : (d < -1.0 ? -1.0 : d);
    if (stepgen_enable(i)) step_cmd[i] = stepgen_position_cmd(i);
    else step_cmd[i] = scaled((double)steps[i], stepgen_position_scale(i));
  }
}
