// Console layout files as the designer reads, edits and writes them.
#include "Paths.h"
#include "SmallDisk.h"
#include "LayoutDocument.h"
#include "QtPrinters.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <csignal>

using namespace neptus::layout;
using namespace Qt::StringLiterals;

namespace {

// What a person might write by hand: comments everywhere, bindings,
// functions, a declared property, a handler, a trailing comment, members
// separated by `;`, a multi-line expression, single quotes.
const QString handWritten = uR"(import QtQuick
import Neptus.Components

// Operations room, AUV team.
Console {
    title: "AUV ops"   // shown in the title bar
    formatVersion: 1
    id: layout
    property real scale: 1.5

    function depthColour(d) {
        return d > 50 ? "red" : "green"
    }

    // Depth of the main vehicle.
    Gauge {
        id: depth
        path: 'lauv-1/EstimatedState/depth'
        y: 20; x: 10
        width: 200 * layout.scale
        height: 120
        color: layout.depthColour(value)
        label: value > 10
               ? "deep"
               : "shallow"
        onClicked: {
            console.log("tapped")
        }
    }

    Rectangle { id: frame; x: 0; y: 0; width: 10; height: 10 }
    // end of the components
}
)"_s;

LayoutDocument parsed(const QString &text)
{
    auto document = LayoutDocument::parse(text);
    EXPECT_TRUE(document) << document.error().toString().toStdString();
    return std::move(*document);
}

QString readFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

void writeFile(const QString &path, const QString &text)
{
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(text.toUtf8());
}

} // namespace

TEST(LayoutDocument, ShippedConsolesAreInTheDesignersDialect)
{
    const QDir consoles(neptus::test::sourcePath(QStringLiteral("qml/consoles")));
    const QStringList files = consoles.entryList({u"*.qml"_s}, QDir::Files);
    ASSERT_FALSE(files.isEmpty());
    for (const QString &name : files) {
        const QString original = readFile(consoles.filePath(name));
        auto document = LayoutDocument::load(consoles.filePath(name));
        ASSERT_TRUE(document) << document.error().toStdString();
        if (document->text() != original) {
            // Left beside the build for a look: what the designer would write.
            writeFile(QDir::current().filePath(name + u".designer"_s), document->text());
        }
        EXPECT_EQ(document->text(), original)
            << name.toStdString() << ": saving it unedited would change it (see " << qPrintable(name) << ".designer)";
    }
}

TEST(LayoutDocument, SavingWhatItWroteGivesTheSameBytes)
{
    const QString once = parsed(handWritten).text();
    EXPECT_EQ(parsed(once).text(), once);
    // The dialect: id first, geometry next, other properties by name.
    EXPECT_TRUE(once.contains(u"    Gauge {\n        id: depth\n        x: 10\n        y: 20\n"
                              "        width: 200 * layout.scale\n        height: 120\n        color:"_s))
        << once.toStdString();
}

TEST(LayoutDocument, HandWrittenContentSurvivesAnEdit)
{
    LayoutDocument document = parsed(handWritten);
    ASSERT_TRUE(document.setProperties(u"depth"_s, {{u"x"_s, 42}, {u"height"_s, 130.5}}));
    const QString text = document.text();
    for (const QString &kept : {u"// Operations room, AUV team."_s, u"title: \"AUV ops\" // shown in the title bar"_s,
                                u"property real scale: 1.5"_s, u"function depthColour(d) {"_s,
                                u"        return d > 50 ? \"red\" : \"green\""_s, u"// Depth of the main vehicle."_s,
                                u"width: 200 * layout.scale"_s, u"color: layout.depthColour(value)"_s,
                                u"        label: value > 10\n               ? \"deep\"\n               : \"shallow\""_s,
                                u"            console.log(\"tapped\")"_s, u"// end of the components"_s,
                                u"path: 'lauv-1/EstimatedState/depth'"_s})
        EXPECT_TRUE(text.contains(kept)) << "lost: " << kept.toStdString() << "\n" << text.toStdString();
    EXPECT_TRUE(text.contains(u"        x: 42\n"_s));
    EXPECT_TRUE(text.contains(u"        height: 130.5\n"_s));
    EXPECT_EQ(document.value(u"frame"_s, u"width"_s), QVariant(10));
}

TEST(LayoutDocument, TellsLiteralsFromBindings)
{
    const LayoutDocument document = parsed(handWritten);
    EXPECT_TRUE(document.isBinding(u"depth"_s, u"width"_s));
    EXPECT_TRUE(document.isBinding(u"depth"_s, u"label"_s));
    EXPECT_FALSE(document.isBinding(u"depth"_s, u"height"_s));
    EXPECT_FALSE(document.isBinding(u"depth"_s, u"missing"_s));
    EXPECT_EQ(document.value(u"depth"_s, u"path"_s), QVariant(u"lauv-1/EstimatedState/depth"_s));
    EXPECT_EQ(document.value(u"layout"_s, u"title"_s), QVariant(u"AUV ops"_s));
    EXPECT_FALSE(document.value(u"depth"_s, u"width"_s).isValid());
}

TEST(LayoutDocument, AddsAComponentWithItsImportAndAFreshId)
{
    LayoutDocument document = parsed(u"import QtQuick\n\nConsole {\n    id: layout\n}\n"_s);
    const QString first = document.addComponent(u"Gauge"_s, u"Neptus.Components"_s,
                                                {{u"x"_s, 8}, {u"y"_s, 16}, {u"path"_s, u"auv/Rpm/value"_s}});
    const QString second = document.addComponent(u"Gauge"_s, u"Neptus.Components"_s, {});
    EXPECT_EQ(first, u"gauge1"_s);
    EXPECT_EQ(second, u"gauge2"_s);
    EXPECT_EQ(document.text(), u"import QtQuick\nimport Neptus.Components\n\nConsole {\n    id: layout\n\n"
                               "    Gauge {\n        id: gauge1\n        x: 8\n        y: 16\n        path: \"auv/Rpm/value\"\n    }\n\n"
                               "    Gauge {\n        id: gauge2\n    }\n}\n"_s);
    document.addComponent(u"Readout"_s, u"Neptus.Components"_s, {});
    EXPECT_EQ(document.text().count(u"import Neptus.Components"_s), 1);
}

TEST(LayoutDocument, EveryEditUndoesAndRedoes)
{
    LayoutDocument document = parsed(handWritten);
    std::vector<QString> states{document.text()};
    const QString gauge = document.addComponent(u"Gauge"_s, u"Neptus.Components"_s, {{u"x"_s, 1}});
    states.push_back(document.text());
    ASSERT_TRUE(document.setProperties(gauge, {{u"x"_s, 100}, {u"y"_s, 50}}));
    states.push_back(document.text());
    const QString copy = document.duplicate(gauge, 20, 20);
    states.push_back(document.text());
    ASSERT_TRUE(document.moveInZOrder(copy, 0));
    states.push_back(document.text());
    ASSERT_TRUE(document.setBinding(u"depth"_s, u"height"_s, u"parent.height / 2"_s));
    states.push_back(document.text());
    ASSERT_TRUE(document.resetProperty(u"depth"_s, u"label"_s));
    states.push_back(document.text());
    ASSERT_TRUE(document.remove(u"frame"_s));
    states.push_back(document.text());

    for (auto it = states.rbegin() + 1; it != states.rend(); ++it) {
        ASSERT_TRUE(document.undo());
        EXPECT_EQ(document.text(), *it);
    }
    EXPECT_FALSE(document.canUndo());
    for (auto it = states.begin() + 1; it != states.end(); ++it) {
        ASSERT_TRUE(document.redo());
        EXPECT_EQ(document.text(), *it);
    }
    EXPECT_FALSE(document.canRedo());
    // A new edit after an undo drops what could have been redone.
    document.undo();
    document.setProperties(gauge, {{u"x"_s, 7}});
    EXPECT_FALSE(document.canRedo());
}

TEST(LayoutDocument, AnEditThatChangesNothingIsNoUndoStep)
{
    LayoutDocument document = parsed(handWritten);
    ASSERT_TRUE(document.setProperties(u"frame"_s, {{u"x"_s, 0}}));
    EXPECT_FALSE(document.canUndo());
}

TEST(LayoutDocument, DuplicatesWithFreshIdsBesideTheOriginal)
{
    LayoutDocument document = parsed(u"Console {\n    id: layout\n\n    Panel {\n        id: panel1\n        x: 10\n        y: 10\n\n"
                                      "        Label {\n            id: label1\n        }\n\n        Label {\n            id: label2\n        }\n    }\n\n"
                                      "    Panel {\n        id: top\n    }\n}\n"_s);
    const QString copy = document.duplicate(u"panel1"_s, 5, 5);
    EXPECT_EQ(copy, u"panel2"_s);
    EXPECT_EQ(document.value(copy, u"x"_s), QVariant(15));
    const QStringList ids = document.ids();
    EXPECT_EQ(ids, (QStringList{u"layout"_s, u"panel1"_s, u"label1"_s, u"label2"_s, u"panel2"_s, u"label3"_s, u"label4"_s,
                                u"top"_s}));
    // Just above the original, below what was above it.
    ASSERT_EQ(document.root().children.size(), 3u);
    EXPECT_EQ(document.root().children[1]->id(), u"panel2"_s);
    ASSERT_TRUE(document.moveInZOrder(u"top"_s, 0));
    EXPECT_EQ(document.root().children[0]->id(), u"top"_s);
}

TEST(LayoutDocument, RefusesBindingsThatWouldBreakTheFile)
{
    LayoutDocument document = parsed(handWritten);
    EXPECT_FALSE(document.setBinding(u"depth"_s, u"height"_s, u"1\n    foo: 2"_s));
    EXPECT_FALSE(document.setBinding(u"depth"_s, u"height"_s, u"(1"_s));
    EXPECT_FALSE(document.setBinding(u"depth"_s, u"height"_s, u"1 }"_s));
    EXPECT_FALSE(document.setBinding(u"depth"_s, u"height"_s, u"1 // comment"_s));
    EXPECT_FALSE(document.setBinding(u"depth"_s, u"id"_s, u"other"_s));
    EXPECT_FALSE(document.setProperties(u"depth"_s, {{u"id"_s, u"other"_s}}));
    EXPECT_FALSE(document.setProperties(u"depth"_s, {{u"x"_s, QVariant::fromValue(std::nan(""))}}));
    EXPECT_FALSE(document.canUndo());
    EXPECT_TRUE(document.setBinding(u"depth"_s, u"height"_s, u"Math.max(1,\n    parent.height)"_s));
    EXPECT_EQ(parsed(document.text()).text(), document.text());
}

TEST(LayoutDocument, LiteralsReadBackAsWritten)
{
    const QVariantList values{true, false, 0, -12, 2.5, 1e-9, u"plain"_s, u"quote \" backslash \\ newline \n tab \t"_s,
                              QVariantList{1, u"two"_s, QVariantList{3.5}}, QStringList{u"a"_s, u"b"_s}};
    for (const QVariant &v : values) {
        const QString text = LayoutDocument::literal(v);
        ASSERT_FALSE(text.isEmpty()) << v.toString().toStdString();
        const auto back = LayoutDocument::fromLiteral(text);
        ASSERT_TRUE(back) << text.toStdString();
        if (v.typeId() == QMetaType::QStringList)
            EXPECT_EQ(back->toStringList(), v.toStringList());
        else
            EXPECT_EQ(back->toString(), v.toString()) << text.toStdString();
    }
    EXPECT_FALSE(LayoutDocument::fromLiteral(u"parent.width"_s));
    EXPECT_FALSE(LayoutDocument::fromLiteral(u"1 + 1"_s));
    EXPECT_FALSE(LayoutDocument::fromLiteral(u"[1, x]"_s));
    EXPECT_EQ(LayoutDocument::fromLiteral(u"'single'"_s), QVariant(u"single"_s));
}

TEST(LayoutDocument, BadFilesAreErrorsAtTheirLine)
{
    struct Case
    {
        QString text;
        int line;
        const char *says;
    };
    const std::vector<Case> cases{
        {u"import QtQuick\n\nConsole {\n    title: \"open\n}\n"_s, 4, "unterminated string"},
        {u"Console {\n    Gauge {\n        x: 1\n"_s, 2, "never closed"},
        {u"Console {\n    x: (1\n}\n"_s, 3, "'}' closes '(' opened at line 2"},
        {u"Console {\n    x: (1\n"_s, 2, "'(' is never closed"},
        {u"Console {\n    x: 1)\n}\n"_s, 2, "unbalanced ')'"},
        {u"Console {\n    x: [1)\n}\n"_s, 2, "closes '['"},
        {u"import QtQuick\n"_s, 2, "no root object"},
        {u"Console {\n}\nConsole {\n}\n"_s, 3, "after the root object"},
        {u"Console {\n    /* never\n}\n"_s, 2, "unterminated comment"},
        {u"Console {\n    x:\n}\n"_s, 2, "has no value"},
        {u"42\n"_s, 1, "expected an import or the root object"},
    };
    for (const Case &c : cases) {
        const auto document = LayoutDocument::parse(c.text);
        ASSERT_FALSE(document) << c.text.toStdString();
        EXPECT_EQ(document.error().line, c.line) << c.text.toStdString() << " → " << document.error().toString().toStdString();
        EXPECT_TRUE(document.error().message.contains(QString::fromUtf8(c.says)))
            << document.error().toString().toStdString();
    }
    const auto missing = LayoutDocument::load(u"/nonexistent/Console.qml"_s);
    ASSERT_FALSE(missing);
    EXPECT_TRUE(missing.error().startsWith(u"/nonexistent/Console.qml: "_s)) << missing.error().toStdString();
}

TEST(LayoutDocument, LoadErrorsNameTheFile)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"Broken.qml"_s);
    writeFile(path, u"Console {\n    title: \"x\n}\n"_s);
    const auto document = LayoutDocument::load(path);
    ASSERT_FALSE(document);
    EXPECT_EQ(document.error(), path + u":2:12: unterminated string"_s);
}

TEST(LayoutDocument, SavesAtomicallyAndKeepsTheOldVersion)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"Ops.qml"_s);
    LayoutDocument document = parsed(handWritten);
    ASSERT_TRUE(document.save(path));
    const QString first = readFile(path);
    EXPECT_EQ(first, document.text());
    EXPECT_FALSE(QFile::exists(path + u".bak"_s));

    document.setProperties(u"frame"_s, {{u"x"_s, 5}});
    ASSERT_TRUE(document.save(path));
    EXPECT_EQ(readFile(path), document.text());
    EXPECT_EQ(readFile(path + u".bak"_s), first);
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files), (QStringList{u"Ops.qml"_s, u"Ops.qml.bak"_s}));

    const auto denied = document.save(dir.filePath(u"no/such/dir/Ops.qml"_s));
    ASSERT_FALSE(denied);
    EXPECT_TRUE(denied.error().contains(u"no/such/dir/Ops.qml"_s)) << denied.error().toStdString();
}

TEST(LayoutDocumentDeathTest, ACrashMidSaveLeavesTheOldFileIntact)
{
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    QTemporaryDir dir;
    const QString path = dir.filePath(u"Ops.qml"_s);
    LayoutDocument document = parsed(handWritten);
    ASSERT_TRUE(document.save(path));
    const QString saved = readFile(path);
    document.setProperties(u"frame"_s, {{u"x"_s, 99}});
    // The process dies after the new text is written, before it replaces the file.
    EXPECT_EXIT(document.save(path, [] { std::raise(SIGKILL); }), testing::KilledBySignal(SIGKILL), "");
    EXPECT_EQ(readFile(path), saved);
    EXPECT_TRUE(LayoutDocument::load(path));
}

// A layout saved on a full filesystem (ENOSPC, the sandbox's small disk for
// saves): an error that says so, the layout on disk as it was; saved once
// there is room.
TEST(LayoutDocument, ASaveOnAFullDiskFailsSayingSoAndLeavesTheLayoutAsItWas)
{
    const QString disk = neptus::test::smallDisk(u"layout-saves"_s);
    if (disk.isEmpty())
        GTEST_SKIP() << neptus::test::noSmallDisk;
    QTemporaryDir dir(disk + u"/layout-XXXXXX"_s);
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(u"Ops.qml"_s);
    LayoutDocument document = parsed(handWritten);
    ASSERT_TRUE(document.save(path));
    const QString first = readFile(path);
    document.setProperties(u"frame"_s, {{u"x"_s, 5}});
    neptus::test::DiskFiller filler(disk);
    filler.fill(0);
    const auto full = document.save(path);
    ASSERT_FALSE(full);
    EXPECT_TRUE(full.error().contains(u"No space left on device"_s)) << full.error().toStdString();
    EXPECT_EQ(readFile(path), first);
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files), QStringList{u"Ops.qml"_s}) << "no temporary left behind";
    filler.free();
    ASSERT_TRUE(document.save(path));
    EXPECT_EQ(readFile(path), document.text());
}
