#!/usr/bin/env bash
# Fails unless the tests run where tools/test puts them: a network namespace
# with loopback alone (nothing a test sends can leave this machine) and a PID
# namespace of their own (nothing a test starts outlives the run).
set -euo pipefail
interfaces=$(awk -F: 'NR > 2 { gsub(/ /, "", $1); print $1 }' /proc/net/dev | sort | tr '\n' ' ')
if [ "$interfaces" != "lo " ]; then
  echo "FAIL: tests can see network interfaces other than loopback: $interfaces"
  echo "      run them with tools/test (or tools/dev ctest), which isolates the network."
  exit 1
fi
init=$(tr '\0' ' ' </proc/1/cmdline)
case "$init" in
  *bwrap*) ;;
  *) echo "FAIL: PID 1 is '$init', not bubblewrap's: tests share the host's PID namespace"; exit 1 ;;
esac
echo "ok: network interfaces: $interfaces; PID 1: $init"
