<?xml version="1.0" encoding="UTF-8"?>
<!--
  QGroundControl mission (.plan, JSON) for ArduPilot and PX4 vehicles: the
  plan's items (mavlink-items.xsl), the planned home, an empty geofence and
  rally points. Parameters: firmware (MAV_AUTOPILOT, 3 ArduPilot, 12 PX4;
  default 3), vehicle_type (MAV_TYPE; default from the vehicle's kind).
-->
<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
                xmlns:exsl="http://exslt.org/common" exclude-result-prefixes="exsl">
  <xsl:import href="mavlink-items.xsl"/>
  <xsl:output method="text" encoding="UTF-8"/>

  <xsl:param name="firmware" select="3"/>
  <xsl:param name="vehicle_type" select="''"/>
  <xsl:param name="home_lat" select="/translation/mission/home/@lat"/>
  <xsl:param name="home_lon" select="/translation/mission/home/@lon"/>
  <xsl:param name="home_height" select="/translation/mission/home/@height"/>

  <xsl:template match="/">
    <xsl:variable name="items"><xsl:call-template name="mavlink-items"/></xsl:variable>
    <xsl:variable name="kind" select="/translation/vehicle/@kind"/>
    <xsl:variable name="type">
      <xsl:choose>
        <xsl:when test="$vehicle_type != ''"><xsl:value-of select="$vehicle_type"/></xsl:when>
        <xsl:when test="$kind = 'UAV'">1</xsl:when>
        <xsl:when test="$kind = 'USV'">11</xsl:when>
        <xsl:when test="$kind = 'UUV'">12</xsl:when>
        <xsl:when test="$kind = 'UGV'">10</xsl:when>
        <xsl:otherwise>0</xsl:otherwise>
      </xsl:choose>
    </xsl:variable>
    <xsl:variable name="speed" select="/translation/geometry/maneuver[1]/@speed"/>
    <xsl:text>{&#10;  "fileType": "Plan",&#10;  "version": 1,&#10;  "groundStation": "Neptus-Qt",&#10;</xsl:text>
    <xsl:text>  "geoFence": { "version": 2, "circles": [], "polygons": [] },&#10;</xsl:text>
    <xsl:text>  "rallyPoints": { "version": 2, "points": [] },&#10;</xsl:text>
    <xsl:text>  "mission": {&#10;    "version": 2,&#10;</xsl:text>
    <xsl:text>    "firmwareType": </xsl:text><xsl:value-of select="$firmware"/><xsl:text>,&#10;</xsl:text>
    <xsl:text>    "vehicleType": </xsl:text><xsl:value-of select="$type"/><xsl:text>,&#10;</xsl:text>
    <xsl:text>    "cruiseSpeed": </xsl:text><xsl:value-of select="$speed"/><xsl:text>,&#10;</xsl:text>
    <xsl:text>    "hoverSpeed": </xsl:text><xsl:value-of select="$speed"/><xsl:text>,&#10;</xsl:text>
    <xsl:text>    "plannedHomePosition": [</xsl:text>
    <xsl:value-of select="concat($home_lat, ', ', $home_lon, ', ', $home_height)"/>
    <xsl:text>],&#10;    "items": [</xsl:text>
    <xsl:for-each select="exsl:node-set($items)/item">
      <xsl:if test="position() &gt; 1">,</xsl:if>
      <xsl:text>&#10;      { "type": "SimpleItem", "autoContinue": true, "doJumpId": </xsl:text>
      <xsl:value-of select="position()"/>
      <xsl:text>, "command": </xsl:text><xsl:value-of select="@command"/>
      <xsl:text>, "frame": </xsl:text><xsl:value-of select="@frame"/>
      <xsl:text>, "AltitudeMode": 1, "Altitude": </xsl:text><xsl:value-of select="@alt"/>
      <xsl:text>, "AMSLAltAboveTerrain": null, "params": [</xsl:text>
      <xsl:value-of select="concat(@p1, ', ', @p2, ', ', @p3, ', ')"/>
      <xsl:choose>
        <xsl:when test="@p4 = 'nan'">null</xsl:when>
        <xsl:otherwise><xsl:value-of select="@p4"/></xsl:otherwise>
      </xsl:choose>
      <xsl:value-of select="concat(', ', @lat, ', ', @lon, ', ', @alt, '] }')"/>
    </xsl:for-each>
    <xsl:text>&#10;    ]&#10;  }&#10;}&#10;</xsl:text>
  </xsl:template>
</xsl:stylesheet>
