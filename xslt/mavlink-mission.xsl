<?xml version="1.0" encoding="UTF-8"?>
<!--
  The mission a MAVLink vehicle is sent over its link (target "mavlink"): the
  plan's items (mavlink-items.xsl), each naming the maneuver it was made
  from, as <mission-items><item maneuver command frame p1 p2 p3 p4 lat lon alt/>…
  The console puts the home before them (item 0, as ArduPilot counts) and
  uploads them with the MAVLink mission protocol (docs/mavlink.md).
-->
<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
  <xsl:import href="mavlink-items.xsl"/>
  <xsl:output method="xml" encoding="UTF-8" indent="yes"/>

  <xsl:template match="/">
    <mission-items plan="{/translation/@plan}" vehicle="{/translation/@vehicle}">
      <xsl:call-template name="mavlink-items"/>
    </mission-items>
  </xsl:template>
</xsl:stylesheet>
