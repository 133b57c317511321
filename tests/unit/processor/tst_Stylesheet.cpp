// The mission processor's stylesheets: they transform, take parameters as
// plain strings, and a hostile one (reading files, writing files, the
// network, endless recursion) gets a clear error and does nothing.
#include "processor/Stylesheet.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using neptus::processor::Stylesheet;

namespace {

QByteArray xslt(const QByteArray &body, const QByteArray &extraNamespaces = {})
{
    return "<?xml version=\"1.0\"?>\n"
           "<xsl:stylesheet version=\"1.0\" xmlns:xsl=\"http://www.w3.org/1999/XSL/Transform\" "
           + extraNamespaces + ">\n" + body + "\n</xsl:stylesheet>\n";
}

const QByteArray plan = "<plan id=\"survey\"><goto lat=\"41.18\" lon=\"-8.70\"/><goto lat=\"41.19\" lon=\"-8.71\"/></plan>";

bool write(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

} // namespace

TEST(Stylesheet, TransformsWithParametersPassedAsStrings)
{
    const auto style = Stylesheet::parse(xslt(R"X(
<xsl:output method="text"/>
<xsl:param name="vehicle"/>
<xsl:template match="/plan">
  <xsl:value-of select="concat($vehicle, ' ', @id, ':')"/>
  <xsl:for-each select="goto"><xsl:value-of select="concat(' ', @lat, ',', @lon)"/></xsl:for-each>
</xsl:template>)X"), QStringLiteral("waypoints.xsl"));
    ASSERT_TRUE(style) << style.error().toString().toStdString();
    // A value that would be XPath if it were not quoted.
    const auto out = style->apply(plan, QStringLiteral("plan.xml"), {{"vehicle", QStringLiteral("lauv's 'xplore' ) or (1")}});
    ASSERT_TRUE(out) << out.error().toString().toStdString();
    EXPECT_EQ(*out, QByteArray("lauv's 'xplore' ) or (1 survey: 41.18,-8.70 41.19,-8.71"));
}

TEST(Stylesheet, ErrorsNameTheStylesheetAndLine)
{
    const auto broken = Stylesheet::parse(xslt("<xsl:template match=\"/\">\n<xsl:value-of select=\"((\"/>\n</xsl:template>"),
                                          QStringLiteral("broken.xsl"));
    ASSERT_FALSE(broken);
    EXPECT_EQ(broken.error().file, QStringLiteral("broken.xsl"));
    EXPECT_EQ(broken.error().line, 4) << broken.error().toString().toStdString();
    const auto notXml = Stylesheet::parse("<xsl:stylesheet", QStringLiteral("cut.xsl"));
    ASSERT_FALSE(notXml);
    EXPECT_EQ(notXml.error().file, QStringLiteral("cut.xsl"));
}

TEST(Stylesheet, ReadingAFileIsRefused)
{
    const auto style = Stylesheet::parse(xslt(R"X(<xsl:output method="text"/>
<xsl:template match="/"><xsl:copy-of select="document('/etc/passwd')"/></xsl:template>)X"), QStringLiteral("peek.xsl"));
    ASSERT_TRUE(style) << style.error().toString().toStdString();
    const auto out = style->apply(plan, QStringLiteral("plan.xml"));
    ASSERT_FALSE(out) << "read: " << out->left(80).toStdString();
    EXPECT_EQ(out.error().file, QStringLiteral("peek.xsl"));
    EXPECT_TRUE(out.error().message.contains(QStringLiteral("/etc/passwd"))) << out.error().message.toStdString();
}

TEST(Stylesheet, TheNetworkIsRefused)
{
    const auto style = Stylesheet::parse(xslt(R"X(<xsl:output method="text"/>
<xsl:template match="/"><xsl:copy-of select="document('http://127.0.0.1:9/mission.xml')"/></xsl:template>)X"),
                                         QStringLiteral("fetch.xsl"));
    ASSERT_TRUE(style);
    const auto out = style->apply(plan, QStringLiteral("plan.xml"));
    ASSERT_FALSE(out);
    EXPECT_TRUE(out.error().message.contains(QStringLiteral("127.0.0.1"))) << out.error().message.toStdString();
    // Nor may a stylesheet import one from the network, or from another folder.
    for (const char *href : {"http://127.0.0.1:9/evil.xsl", "/etc/evil.xsl"}) {
        const auto imports = Stylesheet::parse(xslt(QByteArray("<xsl:import href=\"") + href + "\"/>"), QStringLiteral("imports.xsl"));
        ASSERT_FALSE(imports) << href;
        EXPECT_TRUE(imports.error().message.contains(QStringLiteral("refused"))) << imports.error().message.toStdString();
    }
}

TEST(Stylesheet, WritingFilesIsRefused)
{
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("sub/written.txt"));
    const auto style = Stylesheet::parse(xslt(QByteArray(R"X(<xsl:template match="/">
<exsl:document href=")X") + target.toUtf8() + R"X(" method="text">owned</exsl:document><done/></xsl:template>)X",
                                              "xmlns:exsl=\"http://exslt.org/common\" extension-element-prefixes=\"exsl\""),
                                         QStringLiteral("write.xsl"));
    ASSERT_TRUE(style) << style.error().toString().toStdString();
    const auto out = style->apply(plan, QStringLiteral("plan.xml"));
    EXPECT_FALSE(out);
    EXPECT_FALSE(QFile::exists(target));
    EXPECT_FALSE(QFile::exists(dir.filePath(QStringLiteral("sub"))));
}

TEST(Stylesheet, EndlessRecursionIsAnError)
{
    const auto style = Stylesheet::parse(xslt(R"X(<xsl:template match="/"><xsl:call-template name="again"/></xsl:template>
<xsl:template name="again"><x><xsl:call-template name="again"/></x></xsl:template>)X"), QStringLiteral("loop.xsl"));
    ASSERT_TRUE(style);
    const auto out = style->apply(plan, QStringLiteral("plan.xml"));
    ASSERT_FALSE(out);
    EXPECT_TRUE(out.error().message.contains(QStringLiteral("recursion"), Qt::CaseInsensitive)
                || out.error().message.contains(QStringLiteral("depth"), Qt::CaseInsensitive))
        << out.error().message.toStdString();
}

TEST(Stylesheet, ImportsBesideTheStylesheetWork)
{
    QTemporaryDir dir;
    ASSERT_TRUE(write(dir.filePath(QStringLiteral("common.xsl")),
                      xslt(R"X(<xsl:template name="where"><xsl:value-of select="concat(@lat, '/', @lon)"/></xsl:template>)X")));
    ASSERT_TRUE(write(dir.filePath(QStringLiteral("main.xsl")), xslt(R"X(<xsl:import href="common.xsl"/>
<xsl:output method="text"/>
<xsl:template match="/plan"><xsl:for-each select="goto"><xsl:call-template name="where"/>;</xsl:for-each></xsl:template>)X")));
    const auto style = Stylesheet::load(dir.filePath(QStringLiteral("main.xsl")));
    ASSERT_TRUE(style) << style.error().toString().toStdString();
    const auto out = style->apply(plan, QStringLiteral("plan.xml"));
    ASSERT_TRUE(out) << out.error().toString().toStdString();
    EXPECT_EQ(*out, QByteArray("41.18/-8.70;41.19/-8.71;"));
}
