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

#include <algorithm>

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

std::expected<std::shared_ptr<const std::vector<Cell>>, QString> sharedCells(const QString &path)
{
    static QMutex mutex;
    static QHash<QString, std::weak_ptr<const std::vector<Cell>>> open;
    // One reader at a time: a second asker of the same path waits and gets the same cells.
    const QMutexLocker lock(&mutex);
    const QString key = QFileInfo(path).absoluteFilePath();
    if (auto cells = open.value(key).lock())
        return cells;
    auto loaded = loadCells(key);
    if (!loaded)
        return std::unexpected(loaded.error());
    auto cells = std::make_shared<const std::vector<Cell>>(std::move(*loaded));
    open.insert(key, cells);
    return cells;
}

} // namespace neptus::charts
