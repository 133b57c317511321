<?xml version="1.0" encoding="UTF-8"?>
<!--
  OceanServer Iver mission (.mis, VectorMap's text format): one line per
  waypoint between START and END,
    N; lat; lon; distance; heading; D|H|U… P… VC… S…; 0
  with the distance (feet) and heading (degrees) from the previous waypoint;
  D depth or H height above the bottom in feet, U for a yo-yo (shallow,
  deep in feet, dive angle in degrees); P the time parked at the waypoint
  (seconds: station keeping, loiter, pop-up); cameras off (VC); S speed in
  knots. Surveys, paths and squares are expanded through the points the
  engine worked out (<geometry>); a loiter is its centre, parked for its
  duration (an Iver cannot circle).
-->
<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
  <xsl:output method="text" encoding="UTF-8"/>

  <xsl:key name="maneuver" match="/translation/mission/plan/maneuvers/*" use="@id"/>
  <xsl:variable name="feet" select="3.280839895"/>
  <xsl:variable name="knots" select="1.943844492"/>

  <xsl:template match="/">
    <xsl:value-of select="concat('; Iver mission: plan ', /translation/@plan, ' of mission ', /translation/mission/@id,
                                 ' for ', /translation/@vehicle, ', made by Neptus-Qt&#10;')"/>
    <xsl:text>; depths and distances in feet, speeds in knots, park times in seconds&#10;START&#10;</xsl:text>
    <!-- (Expressions, not variables with content: those are result tree fragments, a document each.) -->
    <xsl:for-each select="/translation/geometry/maneuver/point">
      <xsl:variable name="g" select=".."/>
      <xsl:variable name="m" select="key('maneuver', $g/@id)"/>
      <xsl:value-of select="concat(position(), '; ', format-number(@lat, '0.000000'), '; ', format-number(@lon, '0.000000'), '; ',
                                   format-number(@leg * $feet, '0.00'), '; ', format-number(@heading, '0.00'), '; ')"/>
      <xsl:choose>
        <xsl:when test="$g/@type = 'YoYo'">
          <xsl:value-of select="concat('U', format-number($g/@min-z * $feet, '0.0'), ',', format-number($g/@max-z * $feet, '0.0'), ',',
                                       format-number(sum($m/@pitch), '0'))"/>
        </xsl:when>
        <xsl:when test="@z-units = 'ALTITUDE'"><xsl:value-of select="concat('H', format-number(@z * $feet, '0.0'))"/></xsl:when>
        <xsl:otherwise><xsl:value-of select="concat('D', format-number(@z * $feet, '0.0'))"/></xsl:otherwise>
      </xsl:choose>
      <!-- Parked at the last point of a station keeping, loiter or pop-up, for its duration. -->
      <xsl:value-of select="concat(' P', format-number(sum($m/@duration) * (not(following-sibling::point) and boolean($m/self::StationKeeping | $m/self::Loiter | $m/self::PopUp)), '0'),
                                   ' VC1,0,0,1000,0,VC2,0,0,1000,0 S', format-number($g/@speed * $knots, '0.0'), '; 0&#10;')"/>
    </xsl:for-each>
    <xsl:text>END&#10;</xsl:text>
  </xsl:template>
</xsl:stylesheet>
