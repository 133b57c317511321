#include "qmlmodels/ReplayModel.h"

#include <QFileInfo>

using namespace neptus;

ReplayModel::ReplayModel(std::shared_ptr<const log::LogSet> logs, log::ReplayTarget *target, QObject *parent)
    : QObject(parent)
    , m_player(logs, target)
{
    QStringList names;
    for (const auto &file : logs->logs()) {
        names.append(QFileInfo(file->folder()).fileName());
        if (!file->damage().isEmpty())
            m_problems.append(file->damage());
    }
    m_name = names.join(QStringLiteral(" + "));
    static const char *const kinds[] = {"note", "alarm", "planStart", "planEnd"};
    for (const log::LogMarker &marker : log::markersOf(*logs))
        m_markers.append(QVariantMap{{QStringLiteral("time"), marker.time},
                                     {QStringLiteral("kind"), QString::fromLatin1(kinds[marker.kind])},
                                     {QStringLiteral("text"), marker.text}});
    connect(&m_player, &log::Player::positionChanged, this, &ReplayModel::positionChanged);
    connect(&m_player, &log::Player::playingChanged, this, &ReplayModel::playingChanged);
    connect(&m_player, &log::Player::speedChanged, this, &ReplayModel::speedChanged);
    connect(&m_player, &log::Player::decodeFailed, this, [this](const QString &why) {
        m_problems.append(why);
        emit problemsChanged();
    });
}

double ReplayModel::nextMarker(int direction) const
{
    const double now = m_player.position();
    double best = -1;
    for (const QVariant &entry : m_markers) {
        const double t = entry.toMap().value(QStringLiteral("time")).toDouble();
        if (direction >= 0 && t > now + 0.001 && (best < 0 || t < best))
            best = t;
        if (direction < 0 && t < now - 0.5 && t > best)
            best = t;
    }
    return best;
}
