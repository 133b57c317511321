#!/usr/bin/env bash
# neptus-mission as a mission planner uses it: import each LSTS Neptus fixture,
# validate it against the shipped vehicles, translate every plan to every
# target its vehicle offers, and add a vehicle and a target with files only.
# Usage: mission_cli.sh NEPTUS_MISSION FIXTURES_DIR
set -uo pipefail
tool=$1
fixtures=$2/neptus
if [ ! -d "$fixtures/missions" ]; then
  echo "SKIPPED: $fixtures/missions is absent (../shared beside the checkout)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() { # description, then the command's success as $?
  if [ "$2" = 0 ]; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi
}

declare -A plans=([phase3]=5 [missao-cavado]=12 [Split]=14 [Horta]=3)
translated=0
for name in phase3 missao-cavado Split Horta; do
  out=$("$tool" import "$fixtures/missions/$name.nmisz" -o "$work/$name.xml" 2>"$work/$name.warnings")
  grep -q ": ${plans[$name]} plans," <<<"$out"; check "import $name.nmisz: ${plans[$name]} plans ($out)" $?
  grep -q "^left out, each said above: 0$" <<<"$out"; check "import $name.nmisz: nothing left out" $?
  printf '%s\n' "$out" >"$work/$name.report"
  "$tool" validate "$work/$name.xml" >/dev/null 2>"$work/$name.validate"
  status=$? # before the description's $(…) runs, which sets $? again
  check "validate $name.xml against the shipped vehicles$(sed 's/^/\n    /' "$work/$name.validate")" $status
  # Every plan, to every target its vehicle offers.
  for plan in $(grep -o '<plan id="[^"]*" vehicle="[^"]*"' "$work/$name.xml" | sed 's/<plan id="\([^"]*\)" vehicle="\([^"]*\)"/\1:\2/'); do
    id=${plan%%:*} vehicle=${plan##*:}
    for target in $("$tool" targets --vehicle "$vehicle" | awk '{print $1}'); do
      if "$tool" translate "$work/$name.xml" --plan "$id" --to "$target" -o "$work/$name.$id.$target" >/dev/null 2>"$work/err" \
         && [ -s "$work/$name.$id.$target" ]; then
        translated=$((translated + 1))
      else
        echo "  $name $id for $vehicle to $target: $(cat "$work/err")"
        failures=$((failures + 1))
      fi
    done
  done
done
[ "$translated" -ge $(((5 + 12 + 14 + 3) * 2)) ]; check "$translated translations of the 34 plans (IMC and mission sheet each; QGC plan and waypoints for the UAVs)" $?
grep -q "<PlanSpecification>" "$work/phase3.ctd1.imc"; check "phase3 ctd1 → IMC PlanSpecification" $?
head -1 "$work/Horta.rectangle.qgc-wpl" | grep -q "^QGC WPL 110$"; check "Horta rectangle → QGC WPL 110" $?
grep -q '"fileType": "Plan"' "$work/Horta.rectangle.qgc-plan"; check "Horta rectangle → QGroundControl .plan" $?
grep -q "<h1>Plan ctd1</h1>" "$work/phase3.ctd1.sheet"; check "phase3 ctd1 → mission sheet" $?

# Translating again keeps the previous file.
"$tool" translate "$work/phase3.xml" --plan ctd1 --to imc -o "$work/phase3.ctd1.imc" >/dev/null 2>&1
[ -s "$work/phase3.ctd1.imc.bak" ]; check "writing over a translation keeps the previous one as .bak" $?

out=$("$tool" stats "$work/Split.xml")
[ "$(grep -c "lauv-xplore-1" <<<"$out")" = 14 ]; check "stats lists the 14 plans of Split" $?

# Clear errors and exit codes for bad input.
"$tool" translate "$work/phase3.xml" --plan nope --to imc -o "$work/x" 2>"$work/err"
[ $? = 1 ] && grep -q "has no plan 'nope' (it has: ctd1, vents1" "$work/err"; check "an unknown plan is named, with the plans there are" $?
"$tool" translate "$work/phase3.xml" --plan ctd1 --to iver -o "$work/x" 2>"$work/err"
[ $? = 1 ] && grep -q "offers no translation to 'iver'" "$work/err"; check "a target the vehicle does not offer is refused" $?
printf '<mission format="1" id="m">\n<home lat="91" lon="0"/></mission>\n' >"$work/bad.xml"
"$tool" validate "$work/bad.xml" 2>"$work/err"
[ $? = 1 ] && grep -q "bad.xml:2: Element 'home', attribute 'lat'" "$work/err"; check "a bad file is reported with file, line and element" $?
# The report counts per kind, what was kept as it was, and what was left out.
grep -qE "^  maneuver Rows +7$" "$work/phase3.report"; check "the import report counts phase3's 7 Rows" $?
cat >"$work/odd.nmis" <<'NMIS'
<mission-def><header><id>odd</id><name>odd</name></header><definitions>
<home-reference><origin><latitude>41.5</latitude><longitude>-8.7</longitude><depth>0</depth></origin></home-reference>
</definitions><body><plan id="p" vehicle="lauv-xplore-1"><graph>
<node start="true"><id>ri</id><maneuver><RIPattern kind="automatic"><width>100</width></RIPattern></maneuver></node>
<node><id>go</id><maneuver><Goto kind="automatic"><finalPoint type="pointType"><point><coordinate><latitude>41.5</latitude>
<longitude>-8.7</longitude></coordinate><z>0</z><zunits>DEPTH</zunits></point></finalPoint><speed unit="m/s">1</speed>
<wobble>3</wobble></Goto></maneuver></node>
<edge><id>e</id><source>ri</source><target>go</target><guard>ManeuverIsDone</guard></edge>
</graph></plan></body></mission-def>
NMIS
out=$("$tool" import "$work/odd.nmis" -o "$work/odd.xml" 2>"$work/odd.warnings")
grep -q "^kept as it was (written back on export; its plan cannot be sent): 1$" <<<"$out" \
  && grep -q "^left out, each said above: 1$" <<<"$out" && grep -q "wobble" "$work/odd.warnings"
check "the import report counts a kept RIPattern and a left-out <wobble> ($out)" $?

"$tool" import "$work/bad.xml.nmisz" -o "$work/x" 2>"$work/err"
[ $? = 1 ]; check "importing a file that is not there fails" $?
"$tool" frobnicate 2>/dev/null
[ $? = 2 ]; check "an unknown command is a usage error (2)" $?

# The files a map names: a 3D model that reads (through the model import helper) passes, a missing one does not.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$work/ship.obj"
cat >"$work/models.xml" <<'EOF'
<mission format="1" id="m"><home lat="41" lon="-8"/>
<map id="harbour">
<model id="ship" file="ship.obj" lat="41" lon="-8" yaw="90"/>
<image id="chart" file="chart.png" lat="41" lon="-8" scale="0.5"/>
</map></mission>
EOF
"$tool" validate "$work/models.xml" 2>"$work/err"
[ $? = 1 ] && grep -q "models.xml:4: map 'harbour', image 'chart': no file" "$work/err" && ! grep -q "'ship'" "$work/err"
check "validate reads the map's 3D model and names the missing image" $?
printf 'this is not a model\n' >"$work/ship.obj"
"$tool" validate "$work/models.xml" 2>"$work/err"
[ $? = 1 ] && grep -q "models.xml:3: map 'harbour', model 'ship': .*could not be read" "$work/err"
check "a model the helper cannot read is named with its line" $?

# The plan editor's checks: a leg between two clear waypoints crosses a
# no-go area (an error, with its line); a maneuver nothing leads to (a warning).
cat >"$work/legs.xml" <<'EOF'
<mission format="1" id="m"><home lat="41" lon="-8"/><vehicle id="lauv-xplore-1"/>
<map id="harbour"><circle id="wreck" role="no-go" north="200" east="0" radius="30"/></map>
<plan id="survey" vehicle="lauv-xplore-1" start="a">
<maneuvers>
<Goto id="a" lat="41" lon="-8" z="2" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
<Goto id="b" lat="41.0036" lon="-8" z="2" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
<Goto id="spare" lat="41.001" lon="-8.001" z="2" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
</maneuvers>
<transition from="a" to="b"/>
</plan></mission>
EOF
"$tool" validate "$work/legs.xml" 2>"$work/err"
[ $? = 1 ] && grep -q "legs.xml:6: plan 'survey', 'b' (Goto): a leg crosses the no-go area 'wreck' (unsafe)" "$work/err" \
  && grep -q "warning: .*legs.xml:7: plan 'survey', 'spare' (Goto) cannot be reached from the start 'a'" "$work/err"
status=$?
check "a leg through a no-go area fails validation with its line; an unreachable maneuver is a warning$(sed 's/^/\n    /' "$work/err")" $status

# A duration past the vehicle's endurance is an estimate past a soft limit: a
# warning, and the file is valid (x8-02 can fly an hour; this is 100 km at 18 m/s).
cat >"$work/long.xml" <<'EOF'
<mission format="1" id="m"><home lat="41" lon="-8"/><vehicle id="x8-02"/>
<plan id="far" vehicle="x8-02" start="a">
<maneuvers>
<Goto id="a" lat="41" lon="-8" z="100" z_units="HEIGHT" speed="18" speed_units="METERS_PS"/>
<Goto id="b" lat="41.9" lon="-8" z="100" z_units="HEIGHT" speed="18" speed_units="METERS_PS"/>
</maneuvers>
<transition from="a" to="b"/>
</plan></mission>
EOF
"$tool" validate "$work/long.xml" >/dev/null 2>"$work/err"
[ $? = 0 ] && grep -q "warning: .*long.xml.*plan 'far' lasts 93 min, past x8-02's endurance of 60 min" "$work/err"
check "a plan past its vehicle's endurance is a warning, not an error$(sed 's/^/\n    /' "$work/err")" $?

# A vehicle and a target of one's own: files only.
mkdir -p "$work/mine"
cat >"$work/mine/glider.xml" <<'EOF'
<vehicle format="1" id="lauv-xplore-1" name="Xplore as a glider" kind="UUV">
  <maneuver type="Goto"/><maneuver type="YoYo"/><maneuver type="StationKeeping"/><maneuver type="PopUp"/><maneuver type="Rows"/>
  <translation target="count" name="Maneuver count" stylesheet="count.xsl" extension="txt"/>
</vehicle>
EOF
cat >"$work/mine/count.xsl" <<'EOF'
<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
  <xsl:output method="text"/>
  <xsl:template match="/"><xsl:value-of select="concat(count(/translation/mission/plan/maneuvers/*), ' maneuvers&#10;')"/></xsl:template>
</xsl:stylesheet>
EOF
"$tool" --vehicles "$work/mine" targets --vehicle lauv-xplore-1 | grep -q "^count"; check "a user's definition overrides the shipped one (targets lists 'count')" $?
"$tool" --vehicles "$work/mine" translate "$work/phase3.xml" --plan ctd1 --to count -o "$work/ctd1.txt" >/dev/null
[ "$(cat "$work/ctd1.txt")" = "9 maneuvers" ]; check "its own stylesheet translates (ctd1 has 9 maneuvers)" $?

echo "$failures failure(s)"
[ "$failures" = 0 ]
