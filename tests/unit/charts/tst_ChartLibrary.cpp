// The console's own charts (the chart manager, neptus-chart add/remove/list):
// cells copied with their updates into a folder of their own, from a cell, a
// folder or a zip, replaced whole, removed; bad zips refused by name.
#include "charts/ChartFiles.h"
#include "Fixtures.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <archive.h>
#include <archive_entry.h>

#include <gtest/gtest.h>

using namespace neptus::charts;
using namespace Qt::StringLiterals;

namespace {

void write(const QString &path, const QByteArray &bytes)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

QByteArray read(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// A zip of (name, bytes) entries, written with libarchive.
void zip(const QString &path, const QList<std::pair<QString, QByteArray>> &entries)
{
    archive *a = archive_write_new();
    archive_write_set_format_zip(a);
    ASSERT_EQ(archive_write_open_filename(a, QFile::encodeName(path).constData()), ARCHIVE_OK);
    for (const auto &[name, bytes] : entries) {
        archive_entry *e = archive_entry_new();
        archive_entry_set_pathname(e, name.toUtf8().constData());
        archive_entry_set_filetype(e, AE_IFREG);
        archive_entry_set_perm(e, 0644);
        archive_entry_set_size(e, bytes.size());
        archive_write_header(a, e);
        archive_write_data(a, bytes.constData(), size_t(bytes.size()));
        archive_entry_free(e);
    }
    archive_write_close(a);
    archive_write_free(a);
}

} // namespace

TEST(ChartLibrary, ACellComesWithItsUpdatesAndIsReplacedWhole)
{
    QTemporaryDir dir;
    const QString library = dir.filePath(u"library"_s);
    EXPECT_TRUE(libraryCells(library).isEmpty());
    write(dir.filePath(u"stick/XX4TEST.000"_s), "base");
    write(dir.filePath(u"stick/XX4TEST.001"_s), "update 1");
    write(dir.filePath(u"stick/XX4TEST.002"_s), "update 2");
    write(dir.filePath(u"stick/XX4OTHER.000"_s), "another");
    const auto added = addToLibrary(dir.filePath(u"stick/XX4TEST.000"_s), library);
    ASSERT_TRUE(added) << added.error().toStdString();
    EXPECT_EQ(*added, QStringList{u"XX4TEST"_s}) << "the cell asked for, not its neighbours";
    EXPECT_EQ(libraryCells(library), QStringList{u"XX4TEST"_s});
    EXPECT_EQ(read(library + u"/XX4TEST/XX4TEST.002"_s), "update 2") << "its updates came with it";

    // A new edition: the old cell and its updates go, the new one is all there is.
    QDir(dir.filePath(u"stick"_s)).removeRecursively();
    write(dir.filePath(u"stick/XX4TEST.000"_s), "edition 2");
    ASSERT_TRUE(addToLibrary(dir.filePath(u"stick"_s), library));
    EXPECT_EQ(read(library + u"/XX4TEST/XX4TEST.000"_s), "edition 2");
    EXPECT_FALSE(QFile::exists(library + u"/XX4TEST/XX4TEST.001"_s)) << "an update of the old edition is not kept";
    EXPECT_EQ(QDir(library).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden), QStringList{u"XX4TEST"_s})
        << "nothing left over from the copying";

    ASSERT_TRUE(removeFromLibrary(u"XX4TEST"_s, library));
    EXPECT_TRUE(libraryCells(library).isEmpty());
    const auto unknown = removeFromLibrary(u"XX4TEST"_s, library);
    ASSERT_FALSE(unknown);
    EXPECT_TRUE(unknown.error().contains(u"no cell 'XX4TEST'"_s)) << unknown.error().toStdString();
    EXPECT_FALSE(removeFromLibrary(u"../library"_s, library)) << "a name, never a path";
}

TEST(ChartLibrary, AZippedExchangeSetIsUnpackedCellsOnly)
{
    QTemporaryDir dir;
    const QString library = dir.filePath(u"library"_s);
    const QString file = dir.filePath(u"ENC.zip"_s);
    zip(file, {{u"ENC_ROOT/CATALOG.031"_s, "catalogue"},
               {u"ENC_ROOT/XX4A/XX4A.000"_s, "a"},
               {u"ENC_ROOT/XX4A/XX4A.001"_s, "a1"},
               {u"ENC_ROOT/XX5B/XX5B.000"_s, "b"},
               {u"ENC_ROOT/README.TXT"_s, "read me"}});
    const auto added = addToLibrary(file, library);
    ASSERT_TRUE(added) << added.error().toStdString();
    EXPECT_EQ(*added, (QStringList{u"XX4A"_s, u"XX5B"_s}));
    EXPECT_EQ(read(library + u"/XX4A/XX4A.001"_s), "a1");
    EXPECT_EQ(QDir(library).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden), (QStringList{u"XX4A"_s, u"XX5B"_s}))
        << "the unpacked zip is gone, the catalogue and read-me were not taken";
}

TEST(ChartLibrary, ABadZipIsRefusedByNameAndTheLibraryStaysAsItWas)
{
    QTemporaryDir dir;
    const QString library = dir.filePath(u"library"_s);
    write(dir.filePath(u"XX4KEEP.000"_s), "kept");
    ASSERT_TRUE(addToLibrary(dir.filePath(u"XX4KEEP.000"_s), library));

    const QString escaping = dir.filePath(u"escaping.zip"_s);
    zip(escaping, {{u"../../outside.000"_s, "x"}});
    auto added = addToLibrary(escaping, library);
    ASSERT_FALSE(added);
    EXPECT_TRUE(added.error().contains(u"would unpack outside its folder"_s)) << added.error().toStdString();
    EXPECT_FALSE(QFile::exists(dir.filePath(u"outside.000"_s)));

    const QString garbage = dir.filePath(u"garbage.zip"_s);
    write(garbage, "this is not a zip");
    added = addToLibrary(garbage, library);
    ASSERT_FALSE(added);
    EXPECT_TRUE(added.error().startsWith(garbage)) << added.error().toStdString();

    const QString empty = dir.filePath(u"pictures.zip"_s);
    zip(empty, {{u"photo.jpg"_s, "jpeg"}});
    added = addToLibrary(empty, library);
    ASSERT_FALSE(added);
    EXPECT_TRUE(added.error().contains(u"holds no S-57 cell"_s)) << added.error().toStdString();

    EXPECT_EQ(QDir(library).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden), QStringList{u"XX4KEEP"_s});
}

// The maps, the depth watch and the plan editor share the cells of a folder
// (sharedCells): read once, with progress for the one who reads them, and
// read again when the folder's cells change (the chart manager added or
// replaced one), even while the old ones are still held.
TEST(ChartLibrary, SharedCellsAreReadAgainWhenTheFolderChanges)
{
    NEPTUS_REQUIRE_FIXTURE(fixture, "charts/US4MD81M/US4MD81M.000");
    QTemporaryDir dir;
    const QString library = dir.filePath(u"library"_s);
    ASSERT_TRUE(addToLibrary(fixture, library));
    QStringList said;
    const auto progress = [&](int done, int total, const QString &cell) { said << u"%1/%2 %3"_s.arg(done).arg(total).arg(QFileInfo(cell).fileName()); };
    const auto first = sharedCells(library, progress);
    ASSERT_TRUE(first) << first.error().toStdString();
    EXPECT_EQ(said, QStringList{u"0/1 US4MD81M.000"_s}) << "which cell is being read, and how far";
    said.clear();
    const auto same = sharedCells(library, progress);
    ASSERT_TRUE(same);
    EXPECT_EQ(same->get(), first->get()) << "read once, shared";
    EXPECT_TRUE(said.isEmpty());

    ASSERT_TRUE(addToLibrary(fixture, library)); // the cell again (as a new edition would be): new files
    const auto changed = sharedCells(library, progress);
    ASSERT_TRUE(changed);
    EXPECT_NE(changed->get(), first->get()) << "the folder's cells changed: read again";
    EXPECT_EQ(said.size(), 1);
}
