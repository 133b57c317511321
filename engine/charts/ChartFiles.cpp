#include "charts/ChartFiles.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QMutex>
#include <QProcess>
#include <QSaveFile>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <archive.h>
#include <archive_entry.h>

#include <algorithm>
#include <memory>

namespace neptus::charts {

using namespace Qt::StringLiterals;

namespace {

// A cell's base file and its updates (.001 …), in order.
QFileInfoList cellFiles(const QString &cellPath)
{
    const QFileInfo base(cellPath);
    QFileInfoList files{base};
    for (int n = 1; n < 1000; ++n) {
        const QFileInfo update(base.dir().filePath(base.completeBaseName() + u".%1"_s.arg(n, 3, 10, QChar(u'0'))));
        if (!update.exists())
            break;
        files << update;
    }
    return files;
}

// What names this cell as read: its files' names, sizes and times, the format's version and the classes kept.
QString cacheKey(const QString &cellPath)
{
    QCryptographicHash hash(QCryptographicHash::Sha256);
    hash.addData("NQCHART2"); // the format, and what is kept of a cell: a new console reads cells again
    hash.addData(keptClasses().join(u' ').toUtf8());
    for (const QFileInfo &f : cellFiles(cellPath))
        hash.addData(u"%1 %2 %3\n"_s.arg(f.fileName()).arg(f.size()).arg(f.lastModified().toMSecsSinceEpoch()).toUtf8());
    return QFileInfo(cellPath).completeBaseName() + u'-' + QString::fromLatin1(hash.result().toHex().left(16)) + u".nqchart"_s;
}

} // namespace

std::expected<QStringList, QString> findCells(const QString &path)
{
    const QFileInfo info(path);
    if (!info.exists())
        return std::unexpected(u"%1: no such file or folder"_s.arg(path));
    if (info.isFile()) {
        if (info.suffix() != u"000")
            return std::unexpected(u"%1: not an S-57 base cell (a .000 file)"_s.arg(path));
        return QStringList{info.absoluteFilePath()};
    }
    QStringList cells;
    const int depth = QDir(path).absolutePath().count(u'/');
    QDirIterator it(path, {u"*.000"_s}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        if (QFileInfo(file).absoluteFilePath().count(u'/') - depth <= 4)
            cells << QFileInfo(file).absoluteFilePath();
    }
    std::sort(cells.begin(), cells.end());
    if (cells.isEmpty())
        return std::unexpected(u"%1: holds no S-57 cell (*.000)"_s.arg(path));
    return cells;
}

QString defaultCacheDir()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::GenericCacheLocation)).filePath(u"neptus-qt/charts"_s);
}

QString defaultHelper()
{
    return QDir(QCoreApplication::applicationDirPath()).filePath(u"neptus-chart-import"_s);
}

std::expected<Cell, QString> loadCell(const QString &cellPath, const LoadOptions &options, bool *fromCache)
{
    const QString cacheDir = options.cacheDir.isEmpty() ? defaultCacheDir() : options.cacheDir;
    const QString cached = QDir(cacheDir).filePath(cacheKey(cellPath));
    if (fromCache)
        *fromCache = false;
    if (QFile file(cached); file.open(QIODevice::ReadOnly)) {
        if (auto cell = decodeCell(file.readAll())) {
            if (fromCache)
                *fromCache = true;
            return cell;
        }
        // A damaged cache file is read again from the cell.
    }
    const QString helper = options.helper.isEmpty() ? defaultHelper() : options.helper;
    if (!QFileInfo(helper).isExecutable())
        return std::unexpected(u"%1: cannot read charts: the helper %2 is missing"_s.arg(cellPath, helper));
    QProcess process;
    process.start(helper, {cellPath});
    if (!process.waitForStarted(10'000))
        return std::unexpected(u"%1: cannot start the chart reader %2: %3"_s.arg(cellPath, helper, process.errorString()));
    QByteArray bytes;
    // Read as it comes: a big cell is more than a pipe holds.
    const auto deadline = std::chrono::steady_clock::now() + options.timeout;
    while (process.state() != QProcess::NotRunning) {
        if (std::chrono::steady_clock::now() > deadline) {
            process.kill();
            process.waitForFinished(2000);
            return std::unexpected(u"%1: reading took longer than %2 s, stopped"_s.arg(cellPath).arg(options.timeout.count() / 1000.0));
        }
        process.waitForReadyRead(200);
        bytes += process.readAllStandardOutput();
    }
    bytes += process.readAllStandardOutput();
    if (process.exitStatus() == QProcess::CrashExit)
        return std::unexpected(u"%1: the S-57 reader crashed on it (the cell is damaged)"_s.arg(cellPath));
    if (process.exitCode() != 0) {
        const QString why = QString::fromUtf8(process.readAllStandardError()).trimmed();
        return std::unexpected(why.isEmpty() ? u"%1: could not be read"_s.arg(cellPath) : why);
    }
    auto cell = decodeCell(bytes);
    if (!cell)
        return std::unexpected(u"%1: %2"_s.arg(cellPath, cell.error()));
    // Kept for the next start; a cache that cannot be written only costs reading it again.
    QDir().mkpath(cacheDir);
    QSaveFile save(cached);
    if (save.open(QIODevice::WriteOnly) && save.write(bytes) == bytes.size() && save.commit()) {
        // This cell as it was before (an older update, an older console) is read no more.
        const QString prefix = QFileInfo(cellPath).completeBaseName() + u'-';
        for (const QFileInfo &old : QDir(cacheDir).entryInfoList({prefix + u"*.nqchart"_s}, QDir::Files))
            if (old.absoluteFilePath() != QFileInfo(cached).absoluteFilePath())
                QFile::remove(old.absoluteFilePath());
    }
    return cell;
}

std::expected<std::vector<Cell>, QString> loadCells(const QString &path, const LoadOptions &options,
                                                    const std::function<void(int, int, const QString &)> &progress)
{
    const auto cells = findCells(path);
    if (!cells)
        return std::unexpected(cells.error());
    std::vector<Cell> out;
    for (int i = 0; i < cells->size(); ++i) {
        if (progress)
            progress(i, int(cells->size()), cells->at(i));
        auto cell = loadCell(cells->at(i), options);
        if (!cell)
            return std::unexpected(cell.error());
        out.push_back(std::move(*cell));
    }
    return out;
}

std::expected<std::shared_ptr<const std::vector<Cell>>, QString> sharedCells(
    const QString &path, const std::function<void(int, int, const QString &)> &progress)
{
    static QMutex mutex;
    static QHash<QString, std::weak_ptr<const std::vector<Cell>>> open;
    // One reader at a time: a second asker of the same path waits and gets the same cells.
    const QMutexLocker lock(&mutex);
    // Keyed by the cells' files as they are now: a folder whose cells were
    // added, updated or removed (the chart manager) is read again.
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QString key = absolute;
    if (const auto cells = findCells(absolute))
        for (const QString &cell : *cells)
            key += u'\n' + cacheKey(cell);
    if (auto cells = open.value(key).lock())
        return cells;
    auto loaded = loadCells(absolute, {}, progress);
    if (!loaded)
        return std::unexpected(loaded.error());
    auto cells = std::make_shared<const std::vector<Cell>>(std::move(*loaded));
    open.insert(key, cells);
    return cells;
}

QString defaultLibraryDir()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation)).filePath(u"neptus-qt/charts"_s);
}

namespace {

// A cell file's name: a base cell or an update (NAME.000 … NAME.999).
bool isCellFile(const QString &name)
{
    const QString suffix = QFileInfo(name).suffix();
    return suffix.size() == 3 && std::all_of(suffix.begin(), suffix.end(), [](QChar c) { return c.isDigit(); });
}

// Unpacks the cell files of a zip into `dir`, streamed (an exchange set may
// be gigabytes); names are kept inside `dir`.
std::expected<void, QString> unzipCells(const QString &zipPath, const QString &dir)
{
    constexpr qint64 maxBytes = 16ll * 1024 * 1024 * 1024;
    constexpr int maxEntries = 200'000;
    struct Free { void operator()(archive *a) const { archive_read_free(a); } };
    std::unique_ptr<archive, Free> zip(archive_read_new());
    archive_read_support_format_zip(zip.get());
    const auto failed = [&](const QString &what) {
        return std::unexpected(u"%1: %2: %3"_s.arg(zipPath, what, QString::fromUtf8(archive_error_string(zip.get()))));
    };
    if (archive_read_open_filename(zip.get(), QFile::encodeName(zipPath).constData(), 1 << 16) != ARCHIVE_OK)
        return failed(u"not a zip archive"_s);
    qint64 total = 0;
    for (int entries = 0;; ++entries) {
        archive_entry *entry = nullptr;
        const int status = archive_read_next_header(zip.get(), &entry);
        if (status == ARCHIVE_EOF)
            return {};
        if (status != ARCHIVE_OK && status != ARCHIVE_WARN)
            return failed(u"damaged zip archive"_s);
        if (entries >= maxEntries)
            return std::unexpected(u"%1: more than %2 files in the archive"_s.arg(zipPath).arg(maxEntries));
        const char *raw = archive_entry_pathname(entry);
        const QString name = QDir::cleanPath(QString::fromUtf8(raw ? raw : ""));
        if (archive_entry_filetype(entry) != AE_IFREG || !isCellFile(name))
            continue; // folders, catalogues, read-me files, pictures
        if (name.isEmpty() || QDir::isAbsolutePath(name) || name == u".."_s || name.startsWith(u"../"_s))
            return std::unexpected(u"%1: entry '%2' would unpack outside its folder"_s.arg(zipPath, name));
        const QString target = QDir(dir).filePath(name);
        if (!QDir().mkpath(QFileInfo(target).absolutePath()))
            return std::unexpected(u"%1: cannot make a folder for '%2'"_s.arg(dir, name));
        QFile out(target);
        if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return std::unexpected(u"%1: %2"_s.arg(target, out.errorString()));
        char buffer[1 << 16];
        for (;;) {
            const la_ssize_t n = archive_read_data(zip.get(), buffer, sizeof buffer);
            if (n < 0)
                return failed(u"damaged entry '%1'"_s.arg(name));
            if (n == 0)
                break;
            total += n;
            if (total > maxBytes)
                return std::unexpected(u"%1: unpacks to more than %2 GiB of cells"_s.arg(zipPath).arg(maxBytes >> 30));
            if (out.write(buffer, n) != n)
                return std::unexpected(u"%1: %2"_s.arg(target, out.errorString()));
        }
    }
}

} // namespace

std::expected<QStringList, QString> addToLibrary(const QString &source, const QString &libraryDir)
{
    const QDir library(libraryDir.isEmpty() ? defaultLibraryDir() : libraryDir);
    if (!QDir().mkpath(library.absolutePath()))
        return std::unexpected(u"%1: cannot make the charts folder"_s.arg(library.absolutePath()));
    // A zip is unpacked beside the library first (the same disk: the moves below are renames).
    QTemporaryDir unpacked(library.filePath(u".unpacking-XXXXXX"_s));
    // An exchange set's catalogue stands for its folder (a file chooser picks files).
    QString from = QFileInfo(source).fileName().compare(u"CATALOG.031"_s, Qt::CaseInsensitive) == 0 ? QFileInfo(source).absolutePath() : source;
    if (QFileInfo(source).isFile() && QFileInfo(source).suffix().compare(u"zip"_s, Qt::CaseInsensitive) == 0) {
        if (!unpacked.isValid())
            return std::unexpected(u"%1: %2"_s.arg(library.absolutePath(), unpacked.errorString()));
        if (auto done = unzipCells(source, unpacked.path()); !done)
            return std::unexpected(done.error());
        from = unpacked.path();
    }
    const auto cells = findCells(from);
    if (!cells)
        return std::unexpected(from == source ? cells.error() : u"%1: holds no S-57 cell (*.000)"_s.arg(source));
    // Each cell is copied whole into a folder of its own beside the library's,
    // then put in place: a copy that fails leaves the cell held before.
    QStringList added;
    for (const QString &cell : *cells) {
        const QString name = QFileInfo(cell).completeBaseName();
        QTemporaryDir staging(library.filePath(u".adding-XXXXXX"_s));
        if (!staging.isValid())
            return std::unexpected(u"%1: %2"_s.arg(library.absolutePath(), staging.errorString()));
        for (const QFileInfo &file : cellFiles(cell)) {
            const QString target = QDir(staging.path()).filePath(file.fileName());
            if (!QFile::copy(file.absoluteFilePath(), target))
                return std::unexpected(u"%1: cannot copy it into %2"_s.arg(file.absoluteFilePath(), library.absolutePath()));
            // (A copy keeps a read-only source's permissions: the operator's own copy is theirs.)
            QFile::setPermissions(target, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup | QFile::ReadOther);
        }
        const QString place = library.filePath(name);
        if (QFileInfo::exists(place) && !QDir(place).removeRecursively())
            return std::unexpected(u"%1: cannot replace it"_s.arg(place));
        if (!QDir().rename(staging.path(), place))
            return std::unexpected(u"%1: cannot put the cell there"_s.arg(place));
        staging.setAutoRemove(false);
        added << name;
    }
    return added;
}

std::expected<void, QString> removeFromLibrary(const QString &cellName, const QString &libraryDir)
{
    const QDir library(libraryDir.isEmpty() ? defaultLibraryDir() : libraryDir);
    if (cellName.isEmpty() || cellName.contains(u'/') || cellName.startsWith(u'.') || !libraryCells(library.path()).contains(cellName))
        return std::unexpected(u"%1: the charts folder holds no cell '%2'"_s.arg(library.absolutePath(), cellName));
    if (!QDir(library.filePath(cellName)).removeRecursively())
        return std::unexpected(u"%1: cannot remove it"_s.arg(library.filePath(cellName)));
    return {};
}

QStringList libraryCells(const QString &libraryDir)
{
    const QDir library(libraryDir.isEmpty() ? defaultLibraryDir() : libraryDir);
    QStringList names;
    for (const QString &folder : library.entryList(QDir::Dirs | QDir::NoDotAndDotDot))
        if (!folder.startsWith(u'.') && QFileInfo::exists(library.filePath(folder + u'/' + folder + u".000"_s)))
            names << folder;
    return names;
}

} // namespace neptus::charts
