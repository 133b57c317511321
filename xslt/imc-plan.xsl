<?xml version="1.0" encoding="UTF-8"?>
<!--
  IMC PlanSpecification, the plan an IMC vehicle (DUNE) loads through PlanDB.
  Output: the message in IMC's XML form (msg::fromXml reads it and the codec
  encodes it). Each maneuver becomes the IMC message of its type with its
  attributes as fields; angles are copied in degrees and marked unit="deg"
  (the encoder turns them into radians, the one conversion the direct C++
  encoder uses too, so both give the same bytes); ExpandingSquare, which IMC
  lacks, becomes a FollowPath through the corners the engine worked out.
  Empty lists are left out (an absent field is empty).
-->
<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
  <!-- For the encoder, not for reading: no indentation (neptus-msg shows a message readably). -->
  <xsl:output method="xml" indent="no" encoding="UTF-8"/>

  <xsl:key name="geometry" match="/translation/geometry/maneuver" use="@id"/>
  <xsl:variable name="plan" select="/translation/mission/plan"/>

  <xsl:template match="/">
    <PlanSpecification>
      <plan_id><xsl:value-of select="$plan/@id"/></plan_id>
      <description><xsl:value-of select="$plan/description"/></description>
      <variables>
        <xsl:for-each select="$plan/variable">
          <PlanVariable>
            <name><xsl:value-of select="@name"/></name>
            <value><xsl:value-of select="@value"/></value>
            <type>
              <xsl:choose>
                <xsl:when test="@type"><xsl:value-of select="@type"/></xsl:when>
                <xsl:when test="translate(@value, '0123456789', '') = '' and @value != ''">NUMBER</xsl:when>
                <xsl:when test="translate(@value, '0123456789', '') = '-' and starts-with(@value, '-') and string-length(@value) &gt; 1">NUMBER</xsl:when>
                <xsl:when test="translate(@value, '0123456789', '') = '.' and not(starts-with(@value, '.')) and substring(@value, string-length(@value)) != '.'">NUMBER</xsl:when>
                <xsl:when test="translate(@value, '0123456789', '') = '-.' and starts-with(@value, '-') and not(starts-with(@value, '-.')) and substring(@value, string-length(@value)) != '.'">NUMBER</xsl:when>
                <xsl:otherwise>TEXT</xsl:otherwise>
              </xsl:choose>
            </type>
            <access>
              <xsl:choose>
                <xsl:when test="@access"><xsl:value-of select="@access"/></xsl:when>
                <xsl:otherwise>INPUT</xsl:otherwise>
              </xsl:choose>
            </access>
          </PlanVariable>
        </xsl:for-each>
      </variables>
      <start_man_id><xsl:value-of select="$plan/@start"/></start_man_id>
      <maneuvers>
        <xsl:for-each select="$plan/maneuvers/*">
          <PlanManeuver>
            <maneuver_id><xsl:value-of select="@id"/></maneuver_id>
            <data><xsl:apply-templates select="." mode="maneuver"/></data>
            <xsl:if test="start-actions/*"><start_actions><xsl:copy-of select="start-actions/*"/></start_actions></xsl:if>
            <xsl:if test="end-actions/*"><end_actions><xsl:copy-of select="end-actions/*"/></end_actions></xsl:if>
          </PlanManeuver>
        </xsl:for-each>
      </maneuvers>
      <transitions>
        <xsl:for-each select="$plan/transition">
          <PlanTransition>
            <source_man><xsl:value-of select="@from"/></source_man>
            <dest_man><xsl:value-of select="@to"/></dest_man>
            <conditions><xsl:value-of select="@condition"/></conditions>
            <xsl:if test="actions/*"><actions><xsl:copy-of select="actions/*"/></actions></xsl:if>
          </PlanTransition>
        </xsl:for-each>
      </transitions>
      <start_actions><xsl:copy-of select="$plan/start-actions/*"/></start_actions>
      <end_actions><xsl:copy-of select="$plan/end-actions/*"/></end_actions>
    </PlanSpecification>
  </xsl:template>

  <!-- A field per attribute, angles marked as degrees (templates by name: matched through a hash). -->
  <xsl:template match="@lat | @lon | @roll | @pitch | @yaw | @bearing | @cross_angle | @takeoff_pitch" mode="field">
    <xsl:element name="{name()}"><xsl:attribute name="unit">deg</xsl:attribute><xsl:value-of select="."/></xsl:element>
  </xsl:template>
  <xsl:template match="@*" mode="field">
    <xsl:element name="{name()}"><xsl:value-of select="."/></xsl:element>
  </xsl:template>
  <xsl:template match="@id" mode="field"/>

  <xsl:template match="*" mode="maneuver">
    <xsl:element name="{local-name()}">
      <xsl:apply-templates select="@*" mode="field"/>
      <xsl:if test="point">
        <points>
          <xsl:for-each select="point">
            <xsl:choose>
              <xsl:when test="../self::FollowTrajectory">
                <TrajectoryPoint><x><xsl:value-of select="@x"/></x><y><xsl:value-of select="@y"/></y><z><xsl:value-of select="@z"/></z><t><xsl:value-of select="@t"/></t></TrajectoryPoint>
              </xsl:when>
              <xsl:otherwise>
                <PathPoint><x><xsl:value-of select="@x"/></x><y><xsl:value-of select="@y"/></y><z><xsl:value-of select="@z"/></z></PathPoint>
              </xsl:otherwise>
            </xsl:choose>
          </xsl:for-each>
        </points>
      </xsl:if>
    </xsl:element>
  </xsl:template>

  <xsl:template match="ExpandingSquare" mode="maneuver">
    <xsl:variable name="id" select="@id"/>
    <FollowPath>
      <xsl:apply-templates select="@*[name() != 'id' and name() != 'width' and name() != 'hstep' and name() != 'bearing']" mode="field"/>
      <points>
        <xsl:for-each select="key('geometry', $id)/offset">
          <PathPoint><x><xsl:value-of select="@x"/></x><y><xsl:value-of select="@y"/></y><z>0</z></PathPoint>
        </xsl:for-each>
      </points>
    </FollowPath>
  </xsl:template>
</xsl:stylesheet>
