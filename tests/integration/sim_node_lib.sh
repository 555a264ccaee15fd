# Shared by the tool-session scripts (sourced): a `volcomp-sim node` on SLCAN-TCP with its flash in
# $work/flash, and a 24x24x24 sample grid large enough for an upload to take a few seconds.
# Needs: $sim (volcomp-sim), $work (scratch directory), fail().

# start_node [PORT]: starts the node on PORT (default: any free port); sets $node_pid and $can
# (the --can spec).
start_node() {
  rm -f "$work/ready"
  "$sim" node --slcan-tcp "${1:-0}" --flash-dir "$work/flash" --ready-file "$work/ready" --duration 300 \
    >>"$work/node.log" 2>&1 &
  node_pid=$!
  for _ in $(seq 100); do [[ -s $work/ready ]] && break; sleep 0.05; done
  [[ -s $work/ready ]] || fail "node did not start"
  can=$(cat "$work/ready")
}

# write_big_grid FILE: corrections at 24 x 24 x 24 nodes (x_mm,y_mm,z_mm,dx_um,dy_um,dz_um).
write_big_grid() {
  python3 - "$1" <<'PY'
import math, sys
with open(sys.argv[1], "w") as f:
    f.write("x_mm,y_mm,z_mm,dx_um,dy_um,dz_um\n")
    for k in range(24):
        for j in range(24):
            for i in range(24):
                f.write("%d,%d,%d,%.3f,%.3f,%.3f\n" % (i * 20, j * 20, k * 10, 8 * math.sin(i / 4),
                        0.3 * j, 4 * math.cos(k / 3)))
PY
}
