<?xml version="1.0" encoding="UTF-8"?>
<!--
  Shared by qgc-plan.xsl and qgc-wpl.xsl: a plan as MAVLink mission items,
  in execution order, as <item command frame p1 p2 p3 p4 lat lon alt/>
  (p4 "nan" where MAVLink wants NaN). Surveys, paths and squares are expanded
  to waypoints through the points the engine worked out (<geometry>); a speed
  change (MAV_CMD_DO_CHANGE_SPEED) comes before a maneuver that changes speed.
  Altitudes: HEIGHT relative to home (frame 3), ALTITUDE above terrain
  (frame 10), DEPTH as negative altitude (ArduSub), NONE at home height.
-->
<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
  <xsl:key name="maneuver" match="/translation/mission/plan/maneuvers/*" use="@id"/>

  <xsl:template name="mavlink-items">
    <xsl:for-each select="/translation/geometry/maneuver">
      <xsl:variable name="id" select="@id"/>
      <xsl:variable name="m" select="key('maneuver', $id)"/>
      <xsl:variable name="previous" select="preceding-sibling::maneuver[1]"/>
      <xsl:if test="not($previous) or $previous/@speed != @speed">
        <item command="178" frame="2" p1="{number(/translation/vehicle/@kind != 'UAV')}" p2="{@speed}" p3="-1" p4="0" lat="0" lon="0" alt="0"/>
      </xsl:if>
      <xsl:variable name="frame">
        <xsl:choose>
          <xsl:when test="@z-units = 'ALTITUDE'">10</xsl:when>
          <xsl:otherwise>3</xsl:otherwise>
        </xsl:choose>
      </xsl:variable>
      <xsl:variable name="last" select="point[last()]"/>
      <xsl:choose>
        <xsl:when test="@type = 'Takeoff'">
          <item command="22" frame="{$frame}" p1="{sum($m/@takeoff_pitch)}" p2="0" p3="0" p4="nan" lat="{$last/@lat}" lon="{$last/@lon}">
            <xsl:attribute name="alt"><xsl:apply-templates select="$last" mode="altitude"/></xsl:attribute>
          </item>
        </xsl:when>
        <xsl:when test="@type = 'Land'">
          <item command="21" frame="{$frame}" p1="0" p2="0" p3="0" p4="nan" lat="{$last/@lat}" lon="{$last/@lon}" alt="0"/>
        </xsl:when>
        <xsl:when test="@type = 'Loiter' or @type = 'StationKeeping'">
          <xsl:variable name="radius">
            <xsl:choose>
              <xsl:when test="$m/@radius and $m/@direction = 'CCLOCKW'"><xsl:value-of select="-$m/@radius"/></xsl:when>
              <xsl:when test="$m/@radius"><xsl:value-of select="$m/@radius"/></xsl:when>
              <xsl:otherwise>0</xsl:otherwise>
            </xsl:choose>
          </xsl:variable>
          <xsl:variable name="lat" select="$m/@lat"/>
          <xsl:variable name="lon" select="$m/@lon"/>
          <xsl:variable name="alt"><xsl:apply-templates select="$last" mode="altitude"/></xsl:variable>
          <xsl:choose>
            <xsl:when test="number($m/@duration) &gt; 0">
              <item command="19" frame="{$frame}" p1="{$m/@duration}" p2="0" p3="{$radius}" p4="1" lat="{$lat}" lon="{$lon}" alt="{$alt}"/>
            </xsl:when>
            <xsl:otherwise>
              <item command="17" frame="{$frame}" p1="0" p2="0" p3="{$radius}" p4="nan" lat="{$lat}" lon="{$lon}" alt="{$alt}"/>
            </xsl:otherwise>
          </xsl:choose>
        </xsl:when>
        <xsl:otherwise>
          <xsl:for-each select="point">
            <xsl:variable name="hold">
              <xsl:choose>
                <xsl:when test="position() = last() and ($m/self::PopUp or $m/self::CompassCalibration) and $m/@duration"><xsl:value-of select="$m/@duration"/></xsl:when>
                <xsl:otherwise>0</xsl:otherwise>
              </xsl:choose>
            </xsl:variable>
            <item command="16" frame="{$frame}" p1="{$hold}" p2="0" p3="0" p4="nan" lat="{@lat}" lon="{@lon}">
              <xsl:attribute name="alt"><xsl:apply-templates select="." mode="altitude"/></xsl:attribute>
            </item>
          </xsl:for-each>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each>
  </xsl:template>

  <xsl:template match="point" mode="altitude">
    <xsl:choose>
      <xsl:when test="@z-units = 'DEPTH'"><xsl:value-of select="-@z"/></xsl:when>
      <xsl:when test="@z-units = 'NONE'">0</xsl:when>
      <xsl:otherwise><xsl:value-of select="@z"/></xsl:otherwise>
    </xsl:choose>
  </xsl:template>
</xsl:stylesheet>
