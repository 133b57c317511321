<?xml version="1.0" encoding="UTF-8"?>
<!--
  IMC PlanSpecification, the plan an IMC vehicle (DUNE) loads through PlanDB.
  Output: the message in IMC's XML form (msg::fromXml reads it and the codec
  encodes it). Each maneuver becomes the IMC message of its type with its
  attributes as fields; angles are copied in degrees and marked unit="deg"
  (the encoder turns them into radians, the one conversion the direct C++
  encoder uses too, so both give the same bytes); ExpandingSquare and
  CrossHatch, which IMC lacks, become a FollowPath through the points the
  engine worked out, with the custom settings it gives.
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

  <!-- A field per attribute, angles marked as degrees. Every field of IMC's maneuvers by name: a
       literal element is made at compile time, while xsl:element name="{name()}" has libxslt compile
       the name's expression again for every field (a third of the time of a large plan); an attribute
       no IMC maneuver has (a maneuver of a newer IMC) still becomes its field through the last two. -->
  <xsl:template match="@angAperture" mode="field"><angAperture unit="deg"><xsl:value-of select="."/></angAperture></xsl:template>
  <xsl:template match="@bearing" mode="field"><bearing unit="deg"><xsl:value-of select="."/></bearing></xsl:template>
  <xsl:template match="@cross_angle" mode="field"><cross_angle unit="deg"><xsl:value-of select="."/></cross_angle></xsl:template>
  <xsl:template match="@lat" mode="field"><lat unit="deg"><xsl:value-of select="."/></lat></xsl:template>
  <xsl:template match="@lon" mode="field"><lon unit="deg"><xsl:value-of select="."/></lon></xsl:template>
  <xsl:template match="@pitch" mode="field"><pitch unit="deg"><xsl:value-of select="."/></pitch></xsl:template>
  <xsl:template match="@roll" mode="field"><roll unit="deg"><xsl:value-of select="."/></roll></xsl:template>
  <xsl:template match="@takeoff_pitch" mode="field"><takeoff_pitch unit="deg"><xsl:value-of select="."/></takeoff_pitch></xsl:template>
  <xsl:template match="@yaw" mode="field"><yaw unit="deg"><xsl:value-of select="."/></yaw></xsl:template>
  <xsl:template match="@abort_z" mode="field"><abort_z><xsl:value-of select="."/></abort_z></xsl:template>
  <xsl:template match="@alternation" mode="field"><alternation><xsl:value-of select="."/></alternation></xsl:template>
  <xsl:template match="@altitude_interval" mode="field"><altitude_interval><xsl:value-of select="."/></altitude_interval></xsl:template>
  <xsl:template match="@amplitude" mode="field"><amplitude><xsl:value-of select="."/></amplitude></xsl:template>
  <xsl:template match="@arrival_time" mode="field"><arrival_time><xsl:value-of select="."/></arrival_time></xsl:template>
  <xsl:template match="@coff" mode="field"><coff><xsl:value-of select="."/></coff></xsl:template>
  <xsl:template match="@comms_timeout" mode="field"><comms_timeout><xsl:value-of select="."/></comms_timeout></xsl:template>
  <xsl:template match="@control_ent" mode="field"><control_ent><xsl:value-of select="."/></control_ent></xsl:template>
  <xsl:template match="@control_src" mode="field"><control_src><xsl:value-of select="."/></control_src></xsl:template>
  <xsl:template match="@controller" mode="field"><controller><xsl:value-of select="."/></controller></xsl:template>
  <xsl:template match="@converg_max" mode="field"><converg_max><xsl:value-of select="."/></converg_max></xsl:template>
  <xsl:template match="@converg_timeout" mode="field"><converg_timeout><xsl:value-of select="."/></converg_timeout></xsl:template>
  <xsl:template match="@custom" mode="field"><custom><xsl:value-of select="."/></custom></xsl:template>
  <xsl:template match="@delayed" mode="field"><delayed><xsl:value-of select="."/></delayed></xsl:template>
  <xsl:template match="@description" mode="field"><description><xsl:value-of select="."/></description></xsl:template>
  <xsl:template match="@direction" mode="field"><direction><xsl:value-of select="."/></direction></xsl:template>
  <xsl:template match="@duration" mode="field"><duration><xsl:value-of select="."/></duration></xsl:template>
  <xsl:template match="@end_z" mode="field"><end_z><xsl:value-of select="."/></end_z></xsl:template>
  <xsl:template match="@end_z_units" mode="field"><end_z_units><xsl:value-of select="."/></end_z_units></xsl:template>
  <xsl:template match="@flags" mode="field"><flags><xsl:value-of select="."/></flags></xsl:template>
  <xsl:template match="@formation_name" mode="field"><formation_name><xsl:value-of select="."/></formation_name></xsl:template>
  <xsl:template match="@glide_slope" mode="field"><glide_slope><xsl:value-of select="."/></glide_slope></xsl:template>
  <xsl:template match="@glide_slope_alt" mode="field"><glide_slope_alt><xsl:value-of select="."/></glide_slope_alt></xsl:template>
  <xsl:template match="@group_name" mode="field"><group_name><xsl:value-of select="."/></group_name></xsl:template>
  <xsl:template match="@hstep" mode="field"><hstep><xsl:value-of select="."/></hstep></xsl:template>
  <xsl:template match="@leader_bank_lim" mode="field"><leader_bank_lim><xsl:value-of select="."/></leader_bank_lim></xsl:template>
  <xsl:template match="@leader_speed" mode="field"><leader_speed><xsl:value-of select="."/></leader_speed></xsl:template>
  <xsl:template match="@length" mode="field"><length><xsl:value-of select="."/></length></xsl:template>
  <xsl:template match="@limits" mode="field"><limits><xsl:value-of select="."/></limits></xsl:template>
  <xsl:template match="@loiter_radius" mode="field"><loiter_radius><xsl:value-of select="."/></loiter_radius></xsl:template>
  <xsl:template match="@max_depth" mode="field"><max_depth><xsl:value-of select="."/></max_depth></xsl:template>
  <xsl:template match="@max_speed" mode="field"><max_speed><xsl:value-of select="."/></max_speed></xsl:template>
  <xsl:template match="@min_alt" mode="field"><min_alt><xsl:value-of select="."/></min_alt></xsl:template>
  <xsl:template match="@move_threshold" mode="field"><move_threshold><xsl:value-of select="."/></move_threshold></xsl:template>
  <xsl:template match="@name" mode="field"><name><xsl:value-of select="."/></name></xsl:template>
  <xsl:template match="@overlap" mode="field"><overlap><xsl:value-of select="."/></overlap></xsl:template>
  <xsl:template match="@plan_id" mode="field"><plan_id><xsl:value-of select="."/></plan_id></xsl:template>
  <xsl:template match="@popup_duration" mode="field"><popup_duration><xsl:value-of select="."/></popup_duration></xsl:template>
  <xsl:template match="@popup_period" mode="field"><popup_period><xsl:value-of select="."/></popup_period></xsl:template>
  <xsl:template match="@pos_sim_err_lim" mode="field"><pos_sim_err_lim><xsl:value-of select="."/></pos_sim_err_lim></xsl:template>
  <xsl:template match="@pos_sim_err_timeout" mode="field"><pos_sim_err_timeout><xsl:value-of select="."/></pos_sim_err_timeout></xsl:template>
  <xsl:template match="@pos_sim_err_wrn" mode="field"><pos_sim_err_wrn><xsl:value-of select="."/></pos_sim_err_wrn></xsl:template>
  <xsl:template match="@radius" mode="field"><radius><xsl:value-of select="."/></radius></xsl:template>
  <xsl:template match="@range" mode="field"><range><xsl:value-of select="."/></range></xsl:template>
  <xsl:template match="@rpm" mode="field"><rpm><xsl:value-of select="."/></rpm></xsl:template>
  <xsl:template match="@speed" mode="field"><speed><xsl:value-of select="."/></speed></xsl:template>
  <xsl:template match="@speed_units" mode="field"><speed_units><xsl:value-of select="."/></speed_units></xsl:template>
  <xsl:template match="@start_time" mode="field"><start_time><xsl:value-of select="."/></start_time></xsl:template>
  <xsl:template match="@start_z" mode="field"><start_z><xsl:value-of select="."/></start_z></xsl:template>
  <xsl:template match="@start_z_units" mode="field"><start_z_units><xsl:value-of select="."/></start_z_units></xsl:template>
  <xsl:template match="@syringe0" mode="field"><syringe0><xsl:value-of select="."/></syringe0></xsl:template>
  <xsl:template match="@syringe1" mode="field"><syringe1><xsl:value-of select="."/></syringe1></xsl:template>
  <xsl:template match="@syringe2" mode="field"><syringe2><xsl:value-of select="."/></syringe2></xsl:template>
  <xsl:template match="@sys_a" mode="field"><sys_a><xsl:value-of select="."/></sys_a></xsl:template>
  <xsl:template match="@sys_b" mode="field"><sys_b><xsl:value-of select="."/></sys_b></xsl:template>
  <xsl:template match="@target" mode="field"><target><xsl:value-of select="."/></target></xsl:template>
  <xsl:template match="@time_limit" mode="field"><time_limit><xsl:value-of select="."/></time_limit></xsl:template>
  <xsl:template match="@timeout" mode="field"><timeout><xsl:value-of select="."/></timeout></xsl:template>
  <xsl:template match="@travel_z" mode="field"><travel_z><xsl:value-of select="."/></travel_z></xsl:template>
  <xsl:template match="@travel_z_units" mode="field"><travel_z_units><xsl:value-of select="."/></travel_z_units></xsl:template>
  <xsl:template match="@turb_lim" mode="field"><turb_lim><xsl:value-of select="."/></turb_lim></xsl:template>
  <xsl:template match="@type" mode="field"><type><xsl:value-of select="."/></type></xsl:template>
  <xsl:template match="@width" mode="field"><width><xsl:value-of select="."/></width></xsl:template>
  <xsl:template match="@z" mode="field"><z><xsl:value-of select="."/></z></xsl:template>
  <xsl:template match="@z_units" mode="field"><z_units><xsl:value-of select="."/></z_units></xsl:template>
  <xsl:template match="@*" mode="field">
    <xsl:element name="{name()}"><xsl:value-of select="."/></xsl:element>
  </xsl:template>
  <xsl:template match="@id" mode="field"/>

  <xsl:template match="*" mode="maneuver">
    <xsl:copy>
      <xsl:apply-templates select="@*" mode="field"/>
      <!-- A Rows with no alternation means even rows: IMC's zero would have DUNE drive each row twice
           (engine/mission/PlanGeometry.h, rowsAlternation). -->
      <xsl:if test="self::Rows and not(@alternation)"><alternation>100</alternation></xsl:if>
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
    </xsl:copy>
  </xsl:template>

  <xsl:template match="ExpandingSquare | CrossHatch" mode="maneuver">
    <xsl:variable name="id" select="@id"/>
    <FollowPath>
      <!-- The pattern's own parameters make its points (engine/mission/PlanGeometry.h, patternShapeParameters). -->
      <xsl:apply-templates select="@*[not(contains(' id width hstep bearing coff flags custom ', concat(' ', name(), ' ')))]" mode="field"/>
      <xsl:if test="key('geometry', $id)/@custom">
        <custom><xsl:value-of select="key('geometry', $id)/@custom"/></custom>
      </xsl:if>
      <points>
        <xsl:for-each select="key('geometry', $id)/offset">
          <PathPoint><x><xsl:value-of select="@x"/></x><y><xsl:value-of select="@y"/></y><z>0</z></PathPoint>
        </xsl:for-each>
      </points>
    </FollowPath>
  </xsl:template>
</xsl:stylesheet>
