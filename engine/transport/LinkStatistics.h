#pragma once

#include "core/Clock.h"

#include <QHash>
#include <QMutex>
#include <QString>
#include <QStringList>

#include <vector>

namespace neptus::transport {

// What each system's link carries, for the operator and for alarms:
// messages and bytes (totals and per second), each message type with its
// count and rate, types our definitions lack, and packets that could not be
// decoded with the last reason. Transports report every packet (any
// thread); tick() turns counts into rates once a second.
class LinkStatistics
{
public:
    static constexpr quint16 unknownSystem = 0xFFFF;

    struct Type
    {
        quint16 id = 0;
        QString abbrev;          // "Unknown(281)" for a type the definitions lack
        bool known = true;
        quint64 count = 0;
        double rate = 0;         // per second, over the last tick
    };
    struct System
    {
        quint16 id = unknownSystem;
        QString link;            // "IMC/UDP", "DDS"
        QString peer;            // where its last undecodable packet came from
        quint64 messages = 0;
        quint64 bytes = 0;
        double messageRate = 0;
        double byteRate = 0;
        quint64 decodeErrors = 0;
        QString lastError;
        qint64 lastErrorMs = 0;  // the clock's time of the last decode error
        std::vector<Type> types; // by id
        // The hosts that sent as this system lately (more than one: an
        // impostor, or a vehicle on two networks) and where commands go ("" while held).
        QStringList sources;
        QString destination;
        int unknownTypes() const;
    };

    explicit LinkStatistics(const Clock *clock = &Clock::system());

    // A decoded packet of `bytes` bytes from `system` over `link`.
    // `mavlink`: a MAVLink message id (kept apart from IMC's).
    void received(quint16 system, const QString &link, quint16 messageId, const QString &abbrev, bool known,
                  qsizetype bytes, bool mavlink = false);
    // A packet that could not be decoded; `system` is unknownSystem when not
    // even its header said who sent it.
    void decodeFailed(quint16 system, const QString &link, const QString &peer, const QString &reason);
    // Who sends as `system`, and where commands to it go (from the link).
    void setSources(quint16 system, const QStringList &sources, const QString &destination);
    // A system forgotten (silent too long): its counts go with it.
    void forget(quint16 system);
    // Computes rates over the time since the last tick.
    void tick();

    // Every system, by id; undecodable packets of unknown senders under unknownSystem.
    std::vector<System> systems() const;
    System system(quint16 id) const;
    // Bumps with every tick and every new system or type: views compare it.
    quint64 version() const;

private:
    struct TypeCounter
    {
        Type type;
        quint64 countAtTick = 0;
    };
    struct Counter
    {
        System system;
        quint64 messagesAtTick = 0;
        quint64 bytesAtTick = 0;
        QHash<quint32, TypeCounter> types; // by id, MAVLink's with bit 16 set
    };
    Counter &counterLocked(quint16 system);
    System snapshotLocked(const Counter &counter) const;

    const Clock *m_clock;
    mutable QMutex m_mutex;
    QHash<quint16, Counter> m_counters;
    qint64 m_lastTickMs = 0;
    quint64 m_version = 0;
};

} // namespace neptus::transport
