<?xml version="1.0" encoding="UTF-8"?>
<!--
  Shared by qgc-plan.xsl and qgc-wpl.xsl: a plan as MAVLink mission items,
  in execution order, as <item maneuver command frame p1 p2 p3 p4 lat lon alt/>
  (p4 "nan" where MAVLink wants NaN). Surveys, paths and squares are expanded
  to waypoints through the points the engine worked out (<geometry>); a speed
  change (MAV_CMD_DO_CHANGE_SPEED) comes before a maneuver that changes speed.
  Altitudes: HEIGHT relative to home (frame 3), ALTITUDE above terrain
  (frame 10), DEPTH as negative altitude (ArduSub), NONE at home height.
-->
<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
  <xsl:key name="maneuver" match="/translation/mission/plan/maneuvers/*" use="@id"/>
  <xsl:key name="step" match="/translation/geometry/maneuver" use="@step"/>

  <!-- (Computed with expressions, not xsl:choose into variables: a variable with content is a
       result tree fragment, a document of its own per maneuver, and costs ten times more.) -->
  <xsl:template name="mavlink-items">
    <!-- A maneuver whose meaning mission items cannot carry is refused, naming it, before anything is made:
         never turned into waypoints that do something else. -->
    <xsl:variable name="refused" select="/translation/geometry/maneuver[not(contains(
        ' Goto Rows FollowPath ExpandingSquare CrossHatch Loiter StationKeeping PopUp Elevator Takeoff Land ', concat(' ', @type, ' ')))]"/>
    <xsl:if test="$refused">
      <xsl:message terminate="yes">
        <xsl:text>not expressible as MAVLink mission items: </xsl:text>
        <xsl:for-each select="$refused">
          <xsl:if test="position() &gt; 1">; </xsl:if>
          <xsl:value-of select="concat('maneuver ', @id, ' (', @type, ')')"/>
          <xsl:choose>
            <xsl:when test="@type = 'YoYo'">, its rise and fall in depth</xsl:when>
            <xsl:when test="@type = 'ScheduledGoto'">, its arrival time</xsl:when>
            <xsl:when test="@type = 'FollowTrajectory'">, the times of its points</xsl:when>
            <xsl:when test="@type = 'CompassCalibration'">, a calibration (ArduPilot calibrates outside missions)</xsl:when>
            <xsl:when test="@type = 'Launch'">, a launch from a launcher</xsl:when>
          </xsl:choose>
        </xsl:for-each>
      </xsl:message>
    </xsl:if>
    <xsl:for-each select="/translation/geometry/maneuver">
      <xsl:variable name="m" select="key('maneuver', @id)"/>
      <xsl:variable name="frame" select="3 + 7 * (@z-units = 'ALTITUDE')"/>
      <xsl:variable name="id" select="@id"/>
      <xsl:if test="@step = 1 or key('step', @step - 1)/@speed != @speed">
        <item maneuver="{$id}" command="178" frame="2" p1="{number(/translation/vehicle/@kind != 'UAV')}" p2="{@speed}" p3="-1" p4="0" lat="0" lon="0" alt="0"/>
      </xsl:if>
      <xsl:choose>
        <xsl:when test="@type = 'Takeoff'">
          <xsl:for-each select="point[last()]">
            <item maneuver="{$id}" command="22" frame="{$frame}" p1="{sum($m/@takeoff_pitch)}" p2="0" p3="0" p4="nan" lat="{@lat}" lon="{@lon}"
                  alt="{@z * (1 - 2 * (@z-units = 'DEPTH')) * (@z-units != 'NONE')}"/>
          </xsl:for-each>
        </xsl:when>
        <xsl:when test="@type = 'Land'">
          <item maneuver="{$id}" command="21" frame="{$frame}" p1="0" p2="0" p3="0" p4="nan" lat="{point[last()]/@lat}" lon="{point[last()]/@lon}" alt="0"/>
        </xsl:when>
        <xsl:when test="@type = 'Loiter' or @type = 'StationKeeping'">
          <xsl:for-each select="point[last()]">
            <xsl:choose>
              <xsl:when test="number($m/@duration) &gt; 0">
                <item maneuver="{$id}" command="19" frame="{$frame}" p1="{$m/@duration}" p2="0" p3="{sum($m/@radius) * (1 - 2 * ($m/@direction = 'CCLOCKW'))}"
                      p4="1" lat="{@lat}" lon="{@lon}" alt="{@z * (1 - 2 * (@z-units = 'DEPTH')) * (@z-units != 'NONE')}"/>
              </xsl:when>
              <xsl:otherwise>
                <item maneuver="{$id}" command="17" frame="{$frame}" p1="0" p2="0" p3="{sum($m/@radius) * (1 - 2 * ($m/@direction = 'CCLOCKW'))}"
                      p4="nan" lat="{@lat}" lon="{@lon}" alt="{@z * (1 - 2 * (@z-units = 'DEPTH')) * (@z-units != 'NONE')}"/>
              </xsl:otherwise>
            </xsl:choose>
          </xsl:for-each>
        </xsl:when>
        <xsl:otherwise>
          <!-- Waypoints; a pop-up holds its duration at the last one. -->
          <xsl:for-each select="point">
            <item maneuver="{$id}" command="16" frame="{$frame}" p1="{sum($m/@duration) * (position() = last() and boolean($m/self::PopUp))}"
                  p2="0" p3="0" p4="nan" lat="{@lat}" lon="{@lon}" alt="{@z * (1 - 2 * (@z-units = 'DEPTH')) * (@z-units != 'NONE')}"/>
          </xsl:for-each>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each>
  </xsl:template>
</xsl:stylesheet>
