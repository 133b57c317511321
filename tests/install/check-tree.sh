#!/usr/bin/env bash
# The install tree runs from anywhere: `cmake --install` into one folder, moved
# to another, and the programs there find their data beside them (not in the
# build or source tree): neptus-msg lists the installed definitions,
# neptus-sim starts, neptus --self-test passes.
# Usage: check-tree.sh BUILD_DIR
set -uo pipefail
build=$1
work=$(mktemp -d /tmp/neptus-tree-XXXXXX)
trap 'rm -rf "$work"' EXIT
failures=0
check() { if [ "$2" = 0 ]; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi; }

cmake --install "$build" --prefix "$work/first" >"$work/install.log" 2>&1; check "cmake --install" $?
mv "$work/first" "$work/moved"
prefix=$work/moved
for f in bin/neptus bin/neptus-msg bin/neptus-sim bin/neptus-model-import bin/neptus-script-host bin/neptus-xslt bin/neptus-mission \
         share/neptus-qt/msgdefs/imc.xml share/neptus-qt/schemas/mission.xsd share/neptus-qt/xslt/imc-plan.xsl \
         share/neptus-qt/vehicles/lauv-sim-1.xml \
         share/neptus-qt/consoles/Default.qml share/neptus-qt/dds/loopback.xml share/applications/neptus-qt.desktop; do
  [ -e "$prefix/$f" ]; check "installed $f" $?
done
# No path into the source tree's data is compiled into the programs (debug
# information naming source files does not count: nothing reads it).
source=$(cd "$(dirname "$0")/../.." && pwd)
! grep -qaE "$source/(msgdefs|qml/consoles|dds|schemas|xslt|vehicles)" "$prefix"/bin/*; check "no path to the source tree's data in the programs" $?
"$prefix/bin/neptus-msg" list >"$work/list.txt" 2>&1
grep -q "^ *350  EstimatedState" "$work/list.txt"; check "neptus-msg list from the moved tree" $?
: >"$work/sim.txt"
timeout 10 "$prefix/bin/neptus-sim" --port 16190 >"$work/sim.txt" 2>&1 &
sim=$!
for _ in $(seq 50); do grep -q "on 127.0.0.1" "$work/sim.txt" && break; sleep 0.1; done
grep -q "on 127.0.0.1:16190" "$work/sim.txt"; check "neptus-sim starts with the installed definitions" $?
kill "$sim" 2>/dev/null; wait "$sim" 2>/dev/null
# A mission through the installed schemas, vehicles and stylesheets.
cat >"$work/m.xml" <<'EOF'
<mission format="1" id="m"><home lat="41.18" lon="-8.70"/><vehicle id="lauv-sim-1"/>
<plan id="p" vehicle="lauv-sim-1" start="a"><maneuvers><Goto id="a" lat="41.18" lon="-8.70" z="2" z_units="DEPTH" speed="1.5"/></maneuvers></plan></mission>
EOF
"$prefix/bin/neptus-mission" validate "$work/m.xml" >/dev/null 2>&1; check "neptus-mission validate with the installed schema and vehicles" $?
"$prefix/bin/neptus-mission" translate "$work/m.xml" --plan p --to imc -o "$work/p.imc.xml" >/dev/null 2>&1 \
  && grep -q "<PlanSpecification>" "$work/p.imc.xml"; check "neptus-mission translate with the installed stylesheet and helper" $?
"$prefix/bin/neptus" --self-test >"$work/selftest.log" 2>&1; status=$?
check "neptus --self-test from the moved tree ($(grep -c ' ok$' "$work/selftest.log") types and consoles)" $status
[ $status = 0 ] || grep FAILED "$work/selftest.log" | head | sed 's/^/  /'
grep -q "$prefix/share/neptus-qt/consoles" "$work/selftest.log"; check "the consoles came from the moved tree" $?
[ "$failures" = 0 ] || exit 1
