# Shared steps of the user-mode-linux tests (sourced by run_uml_*.sh): find the UML kernel and its
# modules, write the common start of the guest's init script, boot the guest, report its result.
# The guest runs with the host filesystem as root, so the scripts' paths work inside it.

# The PC tool's SDO timeout inside the guest. A user-mode-linux guest is one ordinary host process:
# on a loaded machine it stalls as a whole, once for 2 s in CI (uml_can_gateway, 2026-11-28: the
# upload's first SDO read timed out at the default 1000 ms while the session's own cycle loop saw a
# 2006 ms gap). Those stalls are the emulator's, not the board's, so the sessions give every tool
# command this much; the board's real timing is measured on the host (gateway latency, cycle rows).
uml_sdo_timeout_ms=10000

# Sets $uml (the kernel) and $mods (its module tree) or stops with what to install.
uml_require() {
  uml=$(command -v linux.uml || true)
  if [[ -z $uml ]]; then
    echo "user-mode-linux is not installed (scripts/setup-deps.sh can)" >&2
    exit 1
  fi
  mods=$(ls -d /usr/lib/uml/modules/*/kernel | head -n1)
}

# Prints the start of an init script: mounts, the CAN modules, and the vcan interfaces given.
uml_init_prologue() {
  cat <<INIT
#!/bin/sh
export PATH=/usr/sbin:/usr/bin:/sbin:/bin
mount -t proc proc /proc; mount -t sysfs sys /sys
for m in net/can/can.ko net/can/can-raw.ko drivers/net/can/dev/can-dev.ko drivers/net/can/vcan.ko; do
  insmod $mods/\$m || echo "insmod \$m failed"
done
for i in $*; do
  ip link add dev \$i type vcan && ip link set \$i txqueuelen 1000 && ip link set up \$i
done
INIT
}

# Prints the end of an init script: the session's exit code into WORK/rc, then power off.
uml_init_epilogue() {
  cat <<INIT
echo \$rc > $1/rc
/sbin/poweroff -f
INIT
}

# Boots WORK/init.sh with a TIMEOUT (seconds); the console goes to WORK/uml.log, the wall time in
# milliseconds to $uml_ms.
uml_boot() {
  local timeout_s=$1 work=$2 start end
  chmod +x "$work/init.sh"
  start=$(date +%s%N)
  timeout "$timeout_s" "$uml" mem=384M root=/dev/root rootfstype=hostfs rootflags=/ rw \
    init="$work/init.sh" con=null con0=null,fd:2 </dev/null >"$work/uml.log" 2>&1 || true
  end=$(date +%s%N)
  uml_ms=$(( (end - start) / 1000000 ))
}

# True when the guest's session succeeded; otherwise shows the end of the console on stderr.
uml_session_ok() {
  [[ "$(cat "$1/rc" 2>/dev/null)" == 0 ]] && return 0
  echo "--- uml console" >&2; tail -30 "$1/uml.log" >&2
  return 1
}
