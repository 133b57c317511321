// Translation in neptus-xslt, a process of its own: the same output as in
// process, errors with file and line, and a stylesheet that would run for
// ever or fill memory is stopped at its limit while the caller goes on.
#include "processor/Stylesheet.h"
#include "processor/Translator.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace neptus::processor;

namespace {

QString writeStylesheet(const QTemporaryDir &dir, const QString &name, const QByteArray &body)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write("<?xml version=\"1.0\"?>\n<xsl:stylesheet version=\"1.0\" xmlns:xsl=\"http://www.w3.org/1999/XSL/Transform\">\n"
               + body + "\n</xsl:stylesheet>\n");
    return path;
}

// A template that calls itself twice, `depth` deep: 2^depth elements.
QByteArray doubling(int depth)
{
    return R"X(<xsl:template match="/"><r><xsl:call-template name="t"><xsl:with-param name="n" select=")X"
           + QByteArray::number(depth) + R"X("/></xsl:call-template></r></xsl:template>
<xsl:template name="t"><xsl:param name="n"/><xsl:if test="$n &gt; 0"><a><xsl:call-template name="t"><xsl:with-param name="n" select="$n - 1"/></xsl:call-template><xsl:call-template name="t"><xsl:with-param name="n" select="$n - 1"/></xsl:call-template></a></xsl:if></xsl:template>)X";
}

const QByteArray plan = "<plan id=\"survey\"><goto lat=\"41.18\" lon=\"-8.70\"/></plan>";

} // namespace

TEST(Translator, GivesWhatTheStylesheetGivesInProcess)
{
    QTemporaryDir dir;
    const QString path = writeStylesheet(dir, QStringLiteral("wp.xsl"), R"X(<xsl:output method="text"/><xsl:param name="v"/>
<xsl:template match="/plan"><xsl:value-of select="concat($v, ':', @id, ' ', goto/@lat)"/></xsl:template>)X");
    const auto out = translate(path, plan, QStringLiteral("plan.xml"), {{"v", QStringLiteral("lauv")}});
    ASSERT_TRUE(out) << out.error().toString().toStdString();
    EXPECT_EQ(*out, QByteArray("lauv:survey 41.18"));
    const auto local = Stylesheet::load(path);
    ASSERT_TRUE(local);
    EXPECT_EQ(*out, *local->apply(plan, QStringLiteral("plan.xml"), {{"v", QStringLiteral("lauv")}}));
}

TEST(Translator, ErrorsKeepTheirFileAndLine)
{
    QTemporaryDir dir;
    const QString path = writeStylesheet(dir, QStringLiteral("peek.xsl"),
                                         R"X(<xsl:template match="/"><xsl:copy-of select="document('/etc/passwd')"/></xsl:template>)X");
    const auto out = translate(path, plan, QStringLiteral("plan.xml"));
    ASSERT_FALSE(out);
    EXPECT_EQ(out.error().file, path);
    EXPECT_EQ(out.error().line, 3);
    EXPECT_TRUE(out.error().message.contains(QStringLiteral("/etc/passwd"))) << out.error().toString().toStdString();
}

// 2^40 elements would take hours and terabytes: the helper is stopped at
// whichever limit it meets first, and the error says which.
TEST(Translator, AStylesheetThatRunsOnIsStoppedAtItsLimit)
{
    QTemporaryDir dir;
    const QString path = writeStylesheet(dir, QStringLiteral("bomb.xsl"), doubling(40));
    for (const auto &[limits, expected] : {std::pair{TranslateLimits{4, 128}, QStringLiteral("128 MB of memory")},
                                           std::pair{TranslateLimits{1, 4096}, QStringLiteral("1 s limit")}}) {
        QElapsedTimer clock;
        clock.start();
        const auto out = translate(path, plan, QStringLiteral("plan.xml"), {}, limits);
        const qint64 elapsed = clock.elapsed();
        ASSERT_FALSE(out);
        EXPECT_TRUE(out.error().message.startsWith(QStringLiteral("stopped:"))) << out.error().toString().toStdString();
#if !defined(__SANITIZE_ADDRESS__)
        // (AddressSanitizer reserves its heap at start: the address-space cap
        // does not see it grow, and the helper meets its time limit instead.)
        EXPECT_TRUE(out.error().message.contains(expected)) << out.error().toString().toStdString();
#endif
        EXPECT_LT(elapsed, limits.seconds * 1000 + 2000) << "stopped at its limit, not after";
        std::printf("doubling(40), limits %d s / %d MB: stopped after %lld ms: %s\n", limits.seconds, limits.megabytes,
                    static_cast<long long>(elapsed), qPrintable(out.error().message));
    }
}
