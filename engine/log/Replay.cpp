#include "log/Replay.h"

#include <QHash>

#include <algorithm>
#include <numeric>

namespace neptus::log {

LogSet::LogSet(std::vector<std::shared_ptr<const LogFile>> logs, double checkpointSeconds)
    : m_logs(std::move(logs))
{
    qsizetype total = 0;
    for (const auto &log : m_logs)
        total += log->count();
    m_entries.reserve(size_t(total));
    m_times.reserve(size_t(total));
    for (quint32 l = 0; l < m_logs.size(); ++l) {
        for (qsizetype i = 0; i < m_logs[l]->count(); ++i)
            m_entries.push_back({l, quint32(i)});
    }
    if (m_logs.size() > 1) {
        std::stable_sort(m_entries.begin(), m_entries.end(), [this](const Entry &a, const Entry &b) {
            return m_logs[a.log]->logTime(a.index) < m_logs[b.log]->logTime(b.index);
        });
    }
    for (qsizetype k = 0; k < count(); ++k) {
        const Entry &e = m_entries[size_t(k)];
        const LogFile &log = *m_logs[e.log];
        m_times.push_back(log.logTime(e.index));
        // Only Announce (151, in every IMC revision) is decoded here.
        if (log.messageId(e.index) == 151 && !m_names.contains(log.source(e.index))) {
            if (const auto m = log.decode(e.index); m && m->def() && m->def()->abbrev == u"Announce")
                m_names.insert(m->header.src, m->text(u"sys_name"));
        }
    }

    // Checkpoints: the last packet of each kind before each interval's start.
    if (m_entries.empty() || checkpointSeconds <= 0)
        return;
    QHash<quint64, qsizetype> last;
    double next = begin() + checkpointSeconds;
    for (qsizetype k = 0; k < count(); ++k) {
        while (m_times[size_t(k)] > next) {
            Checkpoint checkpoint{k, {}};
            checkpoint.last.reserve(size_t(last.size()));
            for (auto it = last.cbegin(); it != last.cend(); ++it)
                checkpoint.last.emplace_back(it.key(), it.value());
            m_checkpoints.push_back(std::move(checkpoint));
            next += checkpointSeconds;
            if (m_times[size_t(k)] > next + checkpointSeconds * 100) // a jump in time: skip the empty stretch
                next = m_times[size_t(k)] - checkpointSeconds / 2;
        }
        const Entry &e = m_entries[size_t(k)];
        last.insert(keyOf(*m_logs[e.log], e.index), k);
    }
}

quint64 LogSet::keyOf(const LogFile &log, qsizetype index)
{
    return (quint64(log.source(index)) << 40) | (quint64(log.sourceEntity(index)) << 32)
           | (quint64(log.destination(index)) << 16) | log.messageId(index);
}

QString LogSet::systemName(quint16 id) const
{
    return m_names.value(id, msg::systemLabel(id));
}

bool LogSet::sentByRecorder(qsizetype k) const
{
    const LogFile &log = logOf(k);
    return log.recorder() != 0xFFFF && log.source(indexInLog(k)) == log.recorder();
}

qsizetype LogSet::upperBound(double t) const
{
    return std::upper_bound(m_times.begin(), m_times.end(), t) - m_times.begin();
}

std::vector<qsizetype> LogSet::stateAt(double t) const
{
    const qsizetype end = upperBound(t);
    // The latest checkpoint at or before `end`.
    auto checkpoint = std::upper_bound(m_checkpoints.begin(), m_checkpoints.end(), end,
                                       [](qsizetype position, const Checkpoint &c) { return position < c.position; });
    QHash<quint64, qsizetype> last;
    qsizetype from = 0;
    if (checkpoint != m_checkpoints.begin()) {
        --checkpoint;
        last.reserve(qsizetype(checkpoint->last.size()));
        for (const auto &[key, k] : checkpoint->last)
            last.insert(key, k);
        from = checkpoint->position;
    }
    for (qsizetype k = from; k < end; ++k) {
        const Entry &e = m_entries[size_t(k)];
        last.insert(keyOf(*m_logs[e.log], e.index), k);
    }
    std::vector<qsizetype> packets;
    packets.reserve(size_t(last.size()));
    for (auto it = last.cbegin(); it != last.cend(); ++it)
        packets.push_back(it.value());
    std::sort(packets.begin(), packets.end());
    return packets;
}

Player::Player(std::shared_ptr<const LogSet> logs, ReplayTarget *target, QObject *parent)
    : QObject(parent)
    , m_logs(std::move(logs))
    , m_target(target)
{
    m_position = m_logs->begin();
    m_timer.setInterval(20);
    connect(&m_timer, &QTimer::timeout, this, &Player::tick);
}

void Player::play()
{
    if (playing())
        return;
    if (m_next >= m_logs->count())
        seek(m_logs->begin());
    m_wall.start();
    m_wallStartPosition = m_position;
    m_timer.start();
    emit playingChanged(true);
}

void Player::pause()
{
    if (!playing())
        return;
    m_timer.stop();
    emit playingChanged(false);
}

void Player::setSpeed(double speed)
{
    speed = speed <= asFastAsPossible ? asFastAsPossible : std::clamp(speed, 0.1, 100.0);
    if (speed == m_speed)
        return;
    m_speed = speed;
    m_wall.start();
    m_wallStartPosition = m_position;
    emit speedChanged(m_speed);
}

void Player::seek(double t)
{
    t = std::clamp(t, m_logs->begin(), m_logs->end());
    if (t >= m_position && t - m_position <= 10.0) {
        advanceTo(t);
    } else {
        m_target->clear();
        for (const qsizetype k : m_logs->stateAt(t))
            deliver(k);
        m_next = m_logs->upperBound(t);
        m_position = t;
        m_target->setTime(t);
        emit jumped(t);
        emit positionChanged(m_position);
    }
    m_wall.start();
    m_wallStartPosition = m_position;
}

void Player::step(double seconds)
{
    pause();
    advanceTo(std::min(m_position + seconds, m_logs->end()));
}

void Player::advanceTo(double t)
{
    t = std::min(t, m_logs->end());
    while (m_next < m_logs->count() && m_logs->time(m_next) <= t)
        deliver(m_next++);
    m_position = std::max(m_position, t);
    m_target->setTime(m_position);
    emit positionChanged(m_position);
}

void Player::deliver(qsizetype k)
{
    m_target->setTime(m_logs->time(k));
    auto message = m_logs->decode(k);
    if (!message) {
        if (m_decodeErrors++ < 20)
            emit decodeFailed(QStringLiteral("%1, packet at byte %2: %3")
                                  .arg(m_logs->logOf(k).dataFile())
                                  .arg(m_logs->logOf(k).offset(m_logs->indexInLog(k)))
                                  .arg(message.error().toString()));
        return;
    }
    m_target->deliver(*message, m_logs->sentByRecorder(k));
}

void Player::tick()
{
    if (m_speed == asFastAsPossible) {
        // As many as fit in most of a frame, then let the screen draw.
        QElapsedTimer budget;
        budget.start();
        while (m_next < m_logs->count() && budget.elapsed() < 15) {
            const qsizetype until = std::min(m_logs->count(), m_next + 512);
            while (m_next < until)
                deliver(m_next++);
        }
        m_position = m_next > 0 ? m_logs->time(m_next - 1) : m_logs->begin();
        m_target->setTime(m_position);
        emit positionChanged(m_position);
    } else {
        advanceTo(std::min(m_logs->end(), m_wallStartPosition + m_wall.elapsed() / 1000.0 * m_speed));
    }
    if (m_next >= m_logs->count()) {
        pause();
        emit finished();
    }
}

} // namespace neptus::log
