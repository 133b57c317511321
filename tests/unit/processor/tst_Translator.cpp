// Translation in neptus-xslt, a process of its own kept for the program's
// life: the same output as in process, errors with file and line, and a
// stylesheet that would run for ever or fill memory is stopped at its limit
// while the caller goes on.
#include "processor/Stylesheet.h"
#include "processor/Translator.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include <signal.h>

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

// What the helper's protocol cannot carry (a parameter over 1 MB, a thousand
// parameters) is said as such, before the helper is given it: not "used more
// than its memory", as when the helper ended on it.
TEST(Translator, WhatTheProtocolCannotCarryIsSaidNotTakenForMemory)
{
    QTemporaryDir dir;
    const QString path = writeStylesheet(dir, QStringLiteral("v.xsl"), R"X(<xsl:output method="text"/><xsl:param name="v"/>
<xsl:template match="/"><xsl:value-of select="string-length($v)"/></xsl:template>)X");
    const auto big = translate(path, plan, QStringLiteral("plan.xml"), {{"v", QString(2 << 20, u'x')}});
    ASSERT_FALSE(big);
    EXPECT_EQ(big.error().message, QStringLiteral("parameter v is 2097154 bytes: a parameter takes at most 1048576"));
    QList<std::pair<QByteArray, QString>> many;
    for (int i = 0; i < 1000; ++i)
        many.append({"p" + QByteArray::number(i), QStringLiteral("1")});
    const auto tooMany = translate(path, plan, QStringLiteral("plan.xml"), many);
    ASSERT_FALSE(tooMany);
    EXPECT_EQ(tooMany.error().message, QStringLiteral("1000 parameters: a translation takes at most 996"));
    // Just under the limits, and the helper serves as before.
    const auto fits = translate(path, plan, QStringLiteral("plan.xml"), {{"v", QString((1 << 20) - 2, u'x')}});
    ASSERT_TRUE(fits) << fits.error().toString().toStdString();
    EXPECT_EQ(*fits, QByteArray("1048574"));
}

// 2^40 elements would take hours and terabytes: the helper is stopped at
// whichever limit it meets first, and the error says which. (The memory case
// has time enough to meet its memory limit on a busy machine: with 4 s, a
// fresh clone's CI beside two other builds met the time limit first.)
TEST(Translator, AStylesheetThatRunsOnIsStoppedAtItsLimit)
{
    QTemporaryDir dir;
    const QString path = writeStylesheet(dir, QStringLiteral("bomb.xsl"), doubling(40));
    for (const auto &[limits, expected] : {std::pair{TranslateLimits{60, 128}, QStringLiteral("128 MB of memory")},
                                           std::pair{TranslateLimits{1, 4096}, QStringLiteral("1 s limit")}}) {
        QElapsedTimer clock;
        clock.start();
        const auto out = translate(path, plan, QStringLiteral("plan.xml"), {}, limits);
        const qint64 elapsed = clock.elapsed();
        ASSERT_FALSE(out);
        EXPECT_TRUE(out.error().message.startsWith(QStringLiteral("stopped:"))) << out.error().toString().toStdString();
        EXPECT_TRUE(out.error().message.contains(expected)) << out.error().toString().toStdString();
        EXPECT_LT(elapsed, limits.seconds * 1000 + 2000) << "stopped at its limit, not after";
        std::printf("doubling(40), limits %d s / %d MB: stopped after %lld ms: %s\n", limits.seconds, limits.megabytes,
                    static_cast<long long>(elapsed), qPrintable(out.error().message));
    }
}

// One helper serves the program's translations (issue #39: starting a process
// and compiling the stylesheet was 14-18 ms of every translation): the same
// process, the stylesheet compiled once, and again when its file changes.
TEST(Translator, OneHelperServesEveryTranslationAndKeepsItsStylesheetsCompiled)
{
    QTemporaryDir dir;
    const QString path = writeStylesheet(dir, QStringLiteral("id.xsl"), R"X(<xsl:output method="text"/><xsl:param name="n"/>
<xsl:template match="/plan"><xsl:value-of select="concat('v1 ', @id, ' ', $n)"/></xsl:template>)X");
    ASSERT_TRUE(translate(path, plan, QStringLiteral("plan.xml"), {{"n", QStringLiteral("0")}}));
    const TranslatorStatus first = translatorStatus();
    ASSERT_GT(first.pid, 0) << "the helper stays";
    for (int i = 1; i <= 5; ++i) {
        const auto out = translate(path, plan, QStringLiteral("plan.xml"), {{"n", QString::number(i)}});
        ASSERT_TRUE(out) << out.error().toString().toStdString();
        EXPECT_EQ(*out, QByteArray("v1 survey ") + QByteArray::number(i)) << "each with its own parameters";
    }
    const TranslatorStatus after = translatorStatus();
    EXPECT_EQ(after.pid, first.pid) << "the same process";
    EXPECT_EQ(after.started, first.started);
    EXPECT_EQ(after.compiled, first.compiled) << "found compiled five times";
    EXPECT_EQ(after.translations, first.translations + 5);

    // A stylesheet edited on disk is compiled again (and so is one whose import changed: same folder).
    ASSERT_TRUE(writeStylesheet(dir, QStringLiteral("id.xsl"), R"X(<xsl:output method="text"/>
<xsl:template match="/plan"><xsl:value-of select="concat('version two of ', @id)"/></xsl:template>)X") == path);
    const auto edited = translate(path, plan, QStringLiteral("plan.xml"));
    ASSERT_TRUE(edited) << edited.error().toString().toStdString();
    EXPECT_EQ(*edited, QByteArray("version two of survey"));
    EXPECT_EQ(translatorStatus().compiled, first.compiled + 1);
    EXPECT_EQ(translatorStatus().pid, first.pid);
}

// A helper that died (killed, crashed, or stopped at a limit) is replaced at
// the next translation, which is not lost.
TEST(Translator, AHelperThatDiedIsReplacedAtTheNextTranslation)
{
    QTemporaryDir dir;
    const QString path = writeStylesheet(dir, QStringLiteral("wp.xsl"), R"X(<xsl:output method="text"/>
<xsl:template match="/plan"><xsl:value-of select="@id"/></xsl:template>)X");
    ASSERT_TRUE(translate(path, plan, QStringLiteral("plan.xml")));
    const TranslatorStatus before = translatorStatus();
    ASSERT_GT(before.pid, 0);
    ASSERT_EQ(::kill(pid_t(before.pid), SIGKILL), 0);
    QTest::qWait(50);
    const auto out = translate(path, plan, QStringLiteral("plan.xml"));
    ASSERT_TRUE(out) << out.error().toString().toStdString();
    EXPECT_EQ(*out, QByteArray("survey"));
    EXPECT_NE(translatorStatus().pid, before.pid);
    EXPECT_EQ(translatorStatus().started, before.started + 1);

    // Stopped at its time limit mid-translation: the next one works.
    const QString bomb = writeStylesheet(dir, QStringLiteral("bomb.xsl"), doubling(40));
    ASSERT_FALSE(translate(bomb, plan, QStringLiteral("plan.xml"), {}, TranslateLimits{1, 1024}));
    const auto again = translate(path, plan, QStringLiteral("plan.xml"));
    ASSERT_TRUE(again) << again.error().toString().toStdString();
    EXPECT_EQ(*again, QByteArray("survey"));
}

// The CPU limit is each translation's own, not the long-lived helper's whole
// life: translations that together take many times the limit all succeed.
TEST(Translator, TheTimeLimitIsEachTranslationsOwn)
{
    QTemporaryDir dir;
    // Each translation well within the limit in this build too (2^16 elements
    // take a few ms in the plain build and can take a second under the
    // sanitizers on a busy machine): the most work that takes under 100 ms here.
    int depth = 16;
    QString path;
    ASSERT_TRUE(translate(writeStylesheet(dir, QStringLiteral("warm.xsl"), doubling(1)), plan, QStringLiteral("plan.xml")))
        << "the helper started before anything is timed";
    for (;; --depth) {
        path = writeStylesheet(dir, QStringLiteral("work%1.xsl").arg(depth), doubling(depth));
        QElapsedTimer one;
        one.start();
        ASSERT_TRUE(translate(path, plan, QStringLiteral("plan.xml")));
        if (one.elapsed() < 100 || depth == 8)
            break;
    }
    QElapsedTimer clock;
    clock.start();
    int done = 0;
    while (clock.elapsed() < 2500 && done < 5000) {
        const auto out = translate(path, plan, QStringLiteral("plan.xml"), {}, TranslateLimits{1, 1024});
        ASSERT_TRUE(out) << "translation " << done << " after " << clock.elapsed() << " ms: " << out.error().toString().toStdString();
        ++done;
    }
    EXPECT_GE(clock.elapsed(), 2500) << "more than twice the 1 s limit in all";
    std::printf("%d translations of 2^%d elements in %lld ms, each within its 1 s\n", done, depth, static_cast<long long>(clock.elapsed()));
}

// Translations come from the GUI thread, the plan editor's workers and the
// command line: any number of threads at once, each gets its own answer.
TEST(Translator, ManyThreadsAtOnceEachGetTheirOwnAnswer)
{
    QTemporaryDir dir;
    const QString path = writeStylesheet(dir, QStringLiteral("echo.xsl"), R"X(<xsl:output method="text"/><xsl:param name="who"/>
<xsl:template match="/plan"><xsl:value-of select="concat($who, ' ', @id)"/></xsl:template>)X");
    std::vector<std::thread> threads;
    std::atomic<int> right = 0;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            for (int i = 0; i < 10; ++i) {
                const QString who = QStringLiteral("t%1-%2").arg(t).arg(i);
                const auto out = translate(path, plan, QStringLiteral("plan.xml"), {{"who", who}});
                if (out && *out == who.toUtf8() + " survey")
                    ++right;
                else
                    std::printf("%s: %s\n", qPrintable(who), out ? out->constData() : qPrintable(out.error().toString()));
            }
        });
    }
    for (auto &thread : threads)
        thread.join();
    EXPECT_EQ(right.load(), 40);
}

// A translation on the GUI thread (a MAVLink plan sent) does not wait behind
// a long one on a worker (an export): the second goes to the second helper.
TEST(Translator, AShortTranslationDoesNotWaitBehindALongOne)
{
    QTemporaryDir dir;
    const QString spin = writeStylesheet(dir, QStringLiteral("spin.xsl"), R"X(<xsl:template match="/"><done><xsl:call-template name="t"><xsl:with-param name="n" select="40"/></xsl:call-template></done></xsl:template>
<xsl:template name="t"><xsl:param name="n"/><xsl:if test="$n &gt; 0"><xsl:call-template name="t"><xsl:with-param name="n" select="$n - 1"/></xsl:call-template><xsl:call-template name="t"><xsl:with-param name="n" select="$n - 1"/></xsl:call-template></xsl:if></xsl:template>)X");
    const QString quick = writeStylesheet(dir, QStringLiteral("quick.xsl"), R"X(<xsl:output method="text"/>
<xsl:template match="/plan"><xsl:value-of select="@id"/></xsl:template>)X");
    // The long one runs until its limit stops it (2^40 template calls), however fast the build.
    std::atomic<bool> longDone = false;
    std::thread worker([&] {
        const auto out = translate(spin, plan, QStringLiteral("plan.xml"), {}, TranslateLimits{4, 1024});
        ASSERT_FALSE(out);
        EXPECT_TRUE(out.error().message.contains(QStringLiteral("4 s limit"))) << out.error().toString().toStdString();
        longDone = true;
    });
    QTest::qWait(300); // the long one is under way
    ASSERT_FALSE(longDone.load());
    const auto out = translate(quick, plan, QStringLiteral("plan.xml"));
    const bool longWasStillRunning = !longDone.load();
    worker.join();
    ASSERT_TRUE(out) << out.error().toString().toStdString();
    EXPECT_EQ(*out, QByteArray("survey"));
    EXPECT_TRUE(longWasStillRunning) << "the short translation was answered while the long one ran";
}
