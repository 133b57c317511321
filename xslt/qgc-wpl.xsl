<?xml version="1.0" encoding="UTF-8"?>
<!--
  MAVLink waypoint list (QGC WPL 110, text; Mission Planner and QGroundControl
  read it): line 0 the home, then the plan's items (mavlink-items.xsl), tab
  separated: index, current, frame, command, p1..p4, lat, lon, alt, autocontinue.
-->
<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
                xmlns:exsl="http://exslt.org/common" exclude-result-prefixes="exsl">
  <xsl:import href="mavlink-items.xsl"/>
  <xsl:output method="text" encoding="UTF-8"/>

  <xsl:param name="home_lat" select="/translation/mission/home/@lat"/>
  <xsl:param name="home_lon" select="/translation/mission/home/@lon"/>
  <xsl:param name="home_height" select="/translation/mission/home/@height"/>

  <xsl:template match="/">
    <xsl:variable name="items"><xsl:call-template name="mavlink-items"/></xsl:variable>
    <xsl:text>QGC WPL 110&#10;</xsl:text>
    <xsl:value-of select="concat('0&#9;1&#9;0&#9;16&#9;0&#9;0&#9;0&#9;0&#9;', $home_lat, '&#9;', $home_lon, '&#9;', $home_height, '&#9;1&#10;')"/>
    <xsl:for-each select="exsl:node-set($items)/item">
      <xsl:value-of select="concat(position(), '&#9;0&#9;', @frame, '&#9;', @command, '&#9;', @p1, '&#9;', @p2, '&#9;', @p3, '&#9;',
                                   substring(@p4, 1, 99 * (@p4 != 'nan')), substring('0', 1, @p4 = 'nan'), '&#9;', @lat, '&#9;', @lon, '&#9;', @alt, '&#9;1&#10;')"/>
    </xsl:for-each>
  </xsl:template>
</xsl:stylesheet>
