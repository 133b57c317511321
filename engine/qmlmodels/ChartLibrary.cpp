#include "qmlmodels/ChartLibrary.h"

#include "charts/ChartFiles.h"

#include <QDir>
#include <QtConcurrent/QtConcurrentRun>

#include <memory>

using namespace Qt::StringLiterals;

ChartLibrary::ChartLibrary(QObject *parent)
    : QObject(parent)
    , m_folder(neptus::charts::defaultLibraryDir())
    , m_cells(neptus::charts::libraryCells(m_folder))
{
}

void ChartLibrary::setFolder(const QString &folder)
{
    const QString absolute = QDir(folder).absolutePath();
    if (absolute == m_folder)
        return;
    m_folder = absolute;
    m_cells = neptus::charts::libraryCells(m_folder);
    emit changed();
}

void ChartLibrary::add(const QString &source)
{
    if (busy())
        return;
    auto result = std::make_shared<std::expected<QStringList, QString>>();
    m_adding.disconnect(this);
    connect(&m_adding, &QFutureWatcherBase::finished, this, [this, source, result] {
        m_cells = neptus::charts::libraryCells(m_folder);
        if (*result)
            finish(false, tr("added %1 from %2").arg((*result)->join(u", "_s), QDir::toNativeSeparators(source)));
        else
            finish(true, result->error());
        emit changed();
    });
    m_busy = true;
    m_adding.setFuture(QtConcurrent::run([source, folder = m_folder, result] { *result = neptus::charts::addToLibrary(source, folder); }));
    emit busyChanged();
}

void ChartLibrary::remove(const QString &cell)
{
    if (busy())
        return;
    const auto removed = neptus::charts::removeFromLibrary(cell, m_folder);
    m_cells = neptus::charts::libraryCells(m_folder);
    finish(!removed, removed ? tr("removed %1").arg(cell) : removed.error());
    emit changed();
}

void ChartLibrary::finish(bool failed, const QString &message)
{
    m_busy = false;
    m_failed = failed;
    m_message = message;
    emit busyChanged();
}
