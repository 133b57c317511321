<?xml version="1.0" encoding="UTF-8"?>
<!--
  A printable mission sheet (HTML) for the people on the boat: the plan's
  maneuvers with their parameters, where they go, how far and how long, the
  transitions, the vehicle's limits and the mission's checklists with boxes
  to tick. Prints on A4 in black and white; readable on a tablet in the sun.
-->
<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
  <xsl:output method="html" encoding="UTF-8" indent="yes" doctype-system="about:legacy-compat"/>

  <xsl:key name="maneuver" match="/translation/mission/plan/maneuvers/*" use="@id"/>
  <xsl:variable name="mission" select="/translation/mission"/>
  <xsl:variable name="plan" select="$mission/plan"/>
  <xsl:variable name="vehicle" select="/translation/vehicle"/>
  <xsl:variable name="geometry" select="/translation/geometry"/>

  <xsl:template name="duration">
    <xsl:param name="seconds"/>
    <xsl:choose>
      <xsl:when test="string($seconds) = ''">does not end by itself</xsl:when>
      <xsl:otherwise>
        <xsl:variable name="s" select="round($seconds)"/>
        <xsl:value-of select="concat(floor($s div 3600), ':', format-number(floor($s mod 3600 div 60), '00'), ':', format-number($s mod 60, '00'))"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:template>

  <xsl:template match="/">
    <html lang="en">
      <head>
        <meta charset="utf-8"/>
        <title><xsl:value-of select="concat('Plan ', $plan/@id, ' — ', $vehicle/@name)"/></title>
        <style>
          body { font: 11pt/1.35 "DejaVu Sans", sans-serif; color: #000; background: #fff; margin: 1.5em; }
          h1 { font-size: 16pt; margin: 0 0 .2em; } h2 { font-size: 13pt; margin: 1.2em 0 .4em; border-bottom: 2px solid #000; }
          table { border-collapse: collapse; width: 100%; } th, td { border: 1px solid #000; padding: .25em .4em; text-align: left; vertical-align: top; }
          th { background: #ddd; } td.n { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
          .box { display: inline-block; width: .9em; height: .9em; border: 2px solid #000; margin-right: .5em; vertical-align: -.1em; }
          .done { background: #000; } .facts td { border: none; padding: .1em 1em .1em 0; } .params { font-size: 9.5pt; }
          @media print { body { margin: 0; } h2 { break-after: avoid; } tr { break-inside: avoid; } }
        </style>
      </head>
      <body>
        <h1><xsl:value-of select="concat('Plan ', $plan/@id)"/></h1>
        <table class="facts">
          <tr><td>Mission</td><td><xsl:value-of select="$mission/@name"/> (<xsl:value-of select="$mission/@id"/>)</td></tr>
          <tr><td>Vehicle</td><td><xsl:value-of select="concat($vehicle/@name, ' (', $vehicle/@id, ', ', $vehicle/@kind)"/><xsl:if test="$vehicle/@imc-id">, IMC <xsl:value-of select="$vehicle/@imc-id"/></xsl:if>)</td></tr>
          <tr><td>Home</td><td><xsl:value-of select="concat(format-number($mission/home/@lat, '0.000000'), ', ', format-number($mission/home/@lon, '0.000000'))"/></td></tr>
          <xsl:if test="$plan/start-actions/*">
            <tr><td>Sends at the start</td><td><xsl:for-each select="$plan/start-actions/*"><xsl:value-of select="concat(name(), ' ', name)"/><xsl:if test="position() != last()">, </xsl:if></xsl:for-each></td></tr>
          </xsl:if>
          <xsl:if test="$plan/end-actions/*">
            <tr><td>Sends at the end</td><td><xsl:for-each select="$plan/end-actions/*"><xsl:value-of select="concat(name(), ' ', name)"/><xsl:if test="position() != last()">, </xsl:if></xsl:for-each></td></tr>
          </xsl:if>
          <tr><td>Starts with</td><td><xsl:value-of select="$plan/@start"/></td></tr>
          <tr><td>Length</td><td><xsl:value-of select="format-number($geometry/@length, '#,##0')"/> m</td></tr>
          <tr><td>Duration</td><td><xsl:call-template name="duration"><xsl:with-param name="seconds" select="$geometry/@duration"/></xsl:call-template></td></tr>
          <xsl:if test="$geometry/@max-depth"><tr><td>Deepest</td><td><xsl:value-of select="$geometry/@max-depth"/> m</td></tr></xsl:if>
          <xsl:if test="$geometry/@max-altitude"><tr><td>Lowest above the bottom</td><td><xsl:value-of select="$geometry/@max-altitude"/> m (largest altitude)</td></tr></xsl:if>
          <xsl:if test="$geometry/@max-height"><tr><td>Highest</td><td><xsl:value-of select="$geometry/@max-height"/> m</td></tr></xsl:if>
        </table>
        <xsl:if test="normalize-space($plan/description)"><p><xsl:value-of select="$plan/description"/></p></xsl:if>

        <h2>Maneuvers</h2>
        <table>
          <tr><th>#</th><th>Maneuver</th><th>Type</th><th>Position</th><th>z</th><th>Speed</th><th>Leg m</th><th>Time</th><th>Parameters</th></tr>
          <xsl:for-each select="$geometry/maneuver">
            <xsl:variable name="id" select="@id"/>
            <xsl:variable name="m" select="key('maneuver', $id)"/>
            <tr>
              <td class="n"><xsl:value-of select="position()"/></td>
              <td><xsl:value-of select="@id"/></td>
              <td><xsl:value-of select="@type"/></td>
              <td class="n"><xsl:value-of select="concat(format-number($m/@lat, '0.00000'), ', ', format-number($m/@lon, '0.00000'))"/></td>
              <td class="n">
                <xsl:if test="@min-z != @max-z"><xsl:value-of select="concat(@min-z, '–')"/></xsl:if>
                <xsl:value-of select="concat(@max-z, ' ', @z-units)"/>
              </td>
              <td class="n"><xsl:value-of select="format-number(@speed, '0.0#')"/> m/s</td>
              <td class="n"><xsl:value-of select="format-number(@transit + @length, '#,##0')"/></td>
              <td class="n"><xsl:call-template name="duration"><xsl:with-param name="seconds" select="@duration"/></xsl:call-template></td>
              <td class="params">
                <xsl:for-each select="$m/@*[name() != 'id' and name() != 'lat' and name() != 'lon' and name() != 'z' and name() != 'z_units' and name() != 'speed' and name() != 'speed_units']">
                  <xsl:value-of select="concat(name(), '=', .)"/><xsl:if test="position() != last()">, </xsl:if>
                </xsl:for-each>
                <xsl:if test="$m/start-actions/*"> · at start: <xsl:for-each select="$m/start-actions/*"><xsl:value-of select="concat(name(), ' ', name)"/><xsl:if test="position() != last()">, </xsl:if></xsl:for-each></xsl:if>
              </td>
            </tr>
          </xsl:for-each>
        </table>

        <xsl:if test="$plan/transition">
          <h2>Transitions</h2>
          <table>
            <tr><th>From</th><th>To</th><th>When</th></tr>
            <xsl:for-each select="$plan/transition">
              <tr><td><xsl:value-of select="@from"/></td><td><xsl:value-of select="@to"/></td><td><xsl:value-of select="@condition"/></td></tr>
            </xsl:for-each>
          </table>
        </xsl:if>

        <xsl:if test="$vehicle/limits">
          <h2>Vehicle limits</h2>
          <table class="facts">
            <xsl:for-each select="$vehicle/limits/@*">
              <tr>
                <td><xsl:value-of select="translate(name(), '-', ' ')"/></td>
                <td>
                  <xsl:choose>
                    <xsl:when test="name() = 'endurance'"><xsl:call-template name="duration"><xsl:with-param name="seconds" select="."/></xsl:call-template></xsl:when>
                    <xsl:when test="contains(name(), 'speed')"><xsl:value-of select="concat(., ' m/s')"/></xsl:when>
                    <xsl:when test="name() = 'z-units' or name() = 'rpm-per-mps'"><xsl:value-of select="."/></xsl:when>
                    <xsl:otherwise><xsl:value-of select="concat(., ' m')"/></xsl:otherwise>
                  </xsl:choose>
                </td>
              </tr>
            </xsl:for-each>
          </table>
        </xsl:if>

        <xsl:for-each select="$mission/checklist">
          <h2><xsl:value-of select="concat('Checklist: ', @name)"/><xsl:if test="not(@name)"><xsl:value-of select="@id"/></xsl:if></h2>
          <xsl:for-each select="group">
            <h3><xsl:value-of select="@name"/></h3>
            <xsl:for-each select="item">
              <div>
                <span class="box"><xsl:if test="@checked = 'true'"><xsl:attribute name="class">box done</xsl:attribute></xsl:if></span>
                <xsl:value-of select="@text"/>
                <xsl:if test="@variable"> <small> (<xsl:value-of select="concat(@variable, ' in [', @min, ', ', @max, ']')"/>)</small></xsl:if>
                <xsl:if test="@note"> <em> — <xsl:value-of select="@note"/></em></xsl:if>
              </div>
            </xsl:for-each>
          </xsl:for-each>
        </xsl:for-each>
      </body>
    </html>
  </xsl:template>
</xsl:stylesheet>
