#pragma once

// Sample missions and helpers the mission tests share.

#include "mission/MissionXml.h"

#include <QStringList>

namespace neptus::test {

// Errors one to a line, for test messages.
inline QString errorsText(const mission::Errors &errors)
{
    QStringList lines;
    for (const auto &e : errors)
        lines << e.toString();
    return lines.join(u'\n');
}

// Every maneuver type, a map with every feature kind and a checklist.
inline const char *const everything = R"X(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="harbour" name="Harbour survey">
  <description>Every element once.</description>
  <home lat="41.185" lon="-8.706" height="0"/>
  <vehicle id="lauv-xplore-1"/>
  <vehicle id="x8-02"/>
  <map id="harbour-map" name="Harbour">
    <mark id="buoy" name="Buoy" color="#ff8000" layer="marks" lat="41.186" lon="-8.705"/>
    <transponder id="t1" north="100" east="-50" depth="10" config="lsts3.conf"/>
    <path id="channel"><point lat="41.18" lon="-8.70"/><point north="10" east="20"/></path>
    <polygon id="ops" role="operating-area" z-min="0" z-max="50" z-units="DEPTH">
      <point lat="41.18" lon="-8.71"/><point lat="41.19" lon="-8.71"/><point lat="41.19" lon="-8.70"/>
    </polygon>
    <circle id="nogo" role="no-go" lat="41.187" lon="-8.707" radius="30"/>
    <box id="pier" lat="41.187" lon="-8.707" width="10" length="80" bearing="45" z-min="0" z-max="5" z-units="HEIGHT"/>
    <cylinder id="c" north="0" east="0" width="10" length="10"/>
    <ellipsoid id="e" north="0" east="0" width="10" length="20"/>
    <image id="chart" file="chart.png"><corner lat="41.19" lon="-8.71"/><corner lat="41.18" lon="-8.70"/></image>
    <image id="photo" file="photo.jpg" lat="41.185" lon="-8.706" scale="0.5" rotation="10"/>
    <model id="ship" file="ship.obj" lat="41.185" lon="-8.706" yaw="90" scale="1"/>
  </map>
  <plan id="survey" vehicle="lauv-xplore-1" start="go">
    <description>Out, survey, back.</description>
    <variable name="target_depth" value="5"/>
    <start-actions>
      <SetEntityParameters><name>Sidescan</name><params><EntityParameter><name>Active</name><value>true</value></EntityParameter></params></SetEntityParameters>
    </start-actions>
    <maneuvers>
      <Goto id="go" lat="41.185" lon="-8.706" z="2" z_units="DEPTH" speed="1.5" speed_units="METERS_PS" timeout="600"/>
      <PopUp id="up" lat="41.186" lon="-8.706" z="0" z_units="DEPTH" speed="1.5" duration="30" radius="5" flags="WAIT_AT_SURFACE|CURR_POS"/>
      <Loiter id="wait" lat="41.186" lon="-8.706" z="3" z_units="DEPTH" speed="1" duration="300" type="CIRCULAR" radius="20" direction="CLOCKW"/>
      <StationKeeping id="sk" lat="41.186" lon="-8.705" radius="10" duration="60" speed="1"/>
      <YoYo id="yoyo" lat="41.187" lon="-8.705" z="10" z_units="DEPTH" amplitude="4" pitch="15" speed="1.2"/>
      <Rows id="rows" lat="41.187" lon="-8.705" z="3" z_units="ALTITUDE" speed="1.2" bearing="90" width="50" length="100" hstep="10" coff="5" alternation="100" flags="SQUARE_CURVE"/>
      <FollowPath id="path" lat="41.186" lon="-8.704" z="2" z_units="DEPTH" speed="1"><point x="0" y="0" z="0"/><point x="50" y="0" z="1"/></FollowPath>
      <FollowTrajectory id="traj" lat="41.186" lon="-8.704" speed="1"><point x="0" y="0" t="0"/><point x="0" y="30" t="30"/></FollowTrajectory>
      <Elevator id="elev" lat="41.186" lon="-8.704" start_z="0" start_z_units="DEPTH" end_z="20" end_z_units="DEPTH" radius="15" speed="1"/>
      <ExpandingSquare id="square" lat="41.186" lon="-8.704" z="2" z_units="DEPTH" speed="1" width="30" hstep="10" bearing="0"/>
      <CompassCalibration id="compass" lat="41.186" lon="-8.704" z="1" z_units="DEPTH" pitch="10" amplitude="1" duration="600" speed="1" radius="15" direction="CCLOCKW"/>
      <ScheduledGoto id="sched" arrival_time="1800000000" lat="41.186" lon="-8.704" z="1" z_units="DEPTH" travel_z="2" travel_z_units="DEPTH" delayed="SKIP"/>
      <Launch id="launch" lat="41.186" lon="-8.704" z="0" z_units="DEPTH" speed="1"/>
      <Takeoff id="takeoff" lat="41.186" lon="-8.704" z="100" z_units="HEIGHT" speed="17" takeoff_pitch="15"/>
      <Land id="land" lat="41.186" lon="-8.704" z="0" z_units="HEIGHT" speed="15" abort_z="30" bearing="270" glide_slope="8" glide_slope_alt="20"/>
    </maneuvers>
    <transition from="go" to="up" condition="ManeuverIsDone"/>
    <transition from="up" to="rows"><actions><PlanControl><type>REQUEST</type></PlanControl></actions></transition>
  </plan>
  <checklist id="before-launch" name="Before launch">
    <group name="Power">
      <item text="Battery above 80 %" variable="lauv-xplore-1/FuelLevel/value" min="80" max="100"/>
      <item text="Hull closed" checked="true" note="Two people check"/>
    </group>
  </checklist>
</mission>
)X";

} // namespace neptus::test
