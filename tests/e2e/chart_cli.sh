#!/usr/bin/env bash
# neptus-chart as a script or a laptop without a screen uses it, on the NOAA
# cell of ../shared/fixtures/charts (its README's figures): info, depth in
# words and in JSON, and clear errors for what is not a chart or a position.
# Usage: chart_cli.sh NEPTUS_CHART FIXTURES_DIR
set -uo pipefail
tool=$1
cell=$2/charts/US4MD81M
if [ ! -d "$cell" ]; then
  echo "SKIPPED: $cell is absent (../shared beside the checkout)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() { # description, then the command's success as $?
  if [ "$2" = 0 ]; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi
}
chart() { "$tool" "$@" --cache "$work/cache"; }

out=$(chart info "$cell" 2>"$work/err")
grep -q "^US4MD81M.000: edition 31, update 3 (2025-09-23), usage band 4 (approach), 1:80,000$" <<<"$out"
check "info names the cell, its edition and last update ($out)" $?
grep -qE "^  DEPARE +depth area +525$" <<<"$out" && grep -qE "^  WRECKS +wreck +111$" <<<"$out"
check "info counts the features as the README does" $?
grep -q "coverage: longitude -76.58278 … -76.02961, latitude 38.36667 … 39.03333" <<<"$out"; check "info gives the coverage" $?
grep -q "reading .*US4MD81M.000 (1 of 1)" "$work/err"; check "progress on standard error" $?

out=$(chart depth "$cell" -76.544591 38.381221 2>/dev/null)
grep -q "(US4MD81M.000): land$" <<<"$out"; check "depth on land: land ($out)" $?
out=$(chart depth "$cell" -76.312942 38.850300 2>/dev/null)
grep -q "charted depth 10.9–18.2 m, in Eastern Bay" <<<"$out" && grep -q "nearest sounding: 12.4 m, 177 m away" <<<"$out"
check "depth in Eastern Bay: 10.9–18.2 m, a 12.4 m sounding 177 m away ($out)" $?
json=$(chart depth "$cell" -76.114104 38.679014 --json 2>/dev/null)
python3 -c 'import json, sys; d = json.load(sys.stdin); assert d["depth"] == {"min": 0, "max": 1.8} and d["place"] == "Island Creek" and d["hazards"] == [] and not d["land"], d' <<<"$json"
check "depth --json in Island Creek: 0–1.8 m, no hazard" $?
out=$(chart depth "$cell" -75 38.5 2>/dev/null); grep -q "no chart covers this point" <<<"$out"; check "outside the cell: said so" $?

chart depth "$cell" -76.3 north >/dev/null 2>"$work/err"; [ $? = 1 ] && grep -q "'-76.3 north' is not a longitude and latitude" "$work/err"
check "a position that is not one is refused, naming it" $?
chart depth "$cell" -76.3 38.85 --radius -5 >/dev/null 2>"$work/err"; [ $? = 1 ] && grep -q "^neptus-chart: --radius '-5' is not a distance in metres$" "$work/err"
check "a negative radius is refused as it was written ($(cat "$work/err"))" $?
chart info "$work/nowhere" >/dev/null 2>"$work/err"; [ $? = 1 ] && grep -q "nowhere: no such file or folder" "$work/err"
check "a path that is not there is refused, naming it" $?
head -c 2000 /dev/urandom >"$work/XX4BAD.000"
chart info "$work/XX4BAD.000" >/dev/null 2>"$work/err"; [ $? = 1 ] && grep -q "XX4BAD.000: not an S-57 cell" "$work/err"
check "a damaged cell is refused, naming it ($(cat "$work/err"))" $?

# neptus-mission validate --charts: a boat's plan across Eastern Bay onto Kent Island fails, saying where.
mission_tool=$(dirname "$tool")/neptus-mission
cat >"$work/bay.xml" <<'XML'
<mission format="1" id="bay" name="Eastern Bay">
  <home lat="38.8503" lon="-76.312942" height="0"/>
  <vehicle id="caravela-sim"/>
  <plan id="ashore" vehicle="caravela-sim" start="a">
    <maneuvers>
      <Goto id="a" lat="38.8503" lon="-76.33" z="0" z_units="DEPTH" speed="2"/>
      <Goto id="b" lat="38.8503" lon="-76.39" z="0" z_units="DEPTH" speed="2"/>
    </maneuvers>
    <transition from="a" to="b"/>
  </plan>
</mission>
XML
"$mission_tool" validate "$work/bay.xml" >"$work/out" 2>"$work/err"; status=$?
[ $status = 0 ]; check "without charts the plan passes" $?
HOME=$work "$mission_tool" validate "$work/bay.xml" --charts "$cell" >"$work/out" 2>"$work/err"; status=$?
[ $status = 1 ] && grep -q "plan 'ashore', 'b' (Goto): a leg crosses land (chart US4MD81M.000) (unsafe)" "$work/err"
check "validate --charts refuses a leg across land, naming the maneuver ($(cat "$work/err"))" $?

[ "$failures" = 0 ] || { echo "$failures failed"; exit 1; }
echo "all passed"
