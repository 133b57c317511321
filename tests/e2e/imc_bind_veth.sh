#!/usr/bin/env bash
# A console on a field network: two network namespaces joined by a veth pair
# that this test makes (console 10.77.0.1 on nq-console, a simulated vehicle
# 10.77.0.2 in a namespace of its own), the console bound with
# --imc-bind nq-console. The vehicle streams only after the console's
# heartbeats reach it over the pair, so its state in the console's tree shows
# both directions work. Runs only in an isolated network namespace holding
# nothing but loopback (the sandbox's): no other interface is touched.
# Usage: imc_bind_veth.sh NEPTUS NEPTUS_SIM CONSOLE_QML
set -uo pipefail
neptus=$1 sim=$2 layout=$3
skip() { echo "SKIPPED: $*"; exit 77; }
command -v ip >/dev/null || skip "no 'ip' (iproute2) here"
command -v unshare >/dev/null && command -v nsenter >/dev/null || skip "no unshare/nsenter here"
links=$(ip -o link show | awk -F': ' '{print $2}' | tr '\n' ' ')
[ "$links" = "lo " ] || skip "not in an isolated network namespace (links here: $links); run it in the sandbox (tools/test)"

work=$(mktemp -d)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  wait 2>/dev/null
  ip link del nq-console 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; for f in "$work"/*.log; do echo "--- $f"; cat "$f"; done; exit 1; }

ip link add nq-console type veth peer name nq-vehicle || skip "cannot make a veth pair here (needs CAP_NET_ADMIN)"
unshare -n sleep 600 &
vehicle_ns=$!
pids+=("$vehicle_ns")
sleep 0.2
ip link set nq-vehicle netns "$vehicle_ns" || fail "cannot move nq-vehicle into the vehicle's namespace"
ip addr add 10.77.0.1/24 dev nq-console && ip link set nq-console up || fail "cannot configure nq-console"
in_vehicle() { nsenter -t "$vehicle_ns" -n "$@"; }
in_vehicle ip link set lo up
in_vehicle ip addr add 10.77.0.2/24 dev nq-vehicle && in_vehicle ip link set nq-vehicle up || fail "cannot configure nq-vehicle"

in_vehicle "$sim" --id 0x1f --name lauv-veth --host 10.77.0.2 --port 6002 --console 10.77.0.1:6001 >"$work/sim.log" 2>&1 &
pids+=($!)
"$neptus" --console "$layout" --imc-bind nq-console --imc-peer 10.77.0.2:6002 --dds-domain -1 --no-record \
  --quit-after 6000 --dump-tree "$work/tree.txt" >"$work/console.log" 2>&1
status=$?
[ "$status" = 0 ] || fail "the console exited with $status"
grep -q "IMC/UDP on 10.77.0.1:6001" "$work/console.log" || fail "the console did not listen on nq-console's address"
grep -q "^lauv-veth/EstimatedState/lat" "$work/tree.txt" || fail "no EstimatedState from the vehicle over the veth pair"
count=$(grep -c "^lauv-veth/" "$work/tree.txt")
echo "ok: lauv-veth streams to the console over the veth pair ($count variables in the tree)"
grep "lauv-veth/EstimatedState/depth" "$work/tree.txt"
