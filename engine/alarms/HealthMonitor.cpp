#include "alarms/HealthMonitor.h"

#include <QMutexLocker>

namespace neptus::alarms {

namespace {

// Heard for less than this and never named: short-lived (see the header).
constexpr qint64 establishMs = 5000;
// A short-lived system silent this long is forgotten.
constexpr qint64 forgetShortLivedMs = 10 * 60 * 1000;
// Systems a summary names before "and N more".
constexpr int namedInSummary = 5;

} // namespace

HealthMonitor::HealthMonitor(AlarmGraph &graph, const tree::VariableTree &tree, const Clock *clock)
    : m_graph(graph)
    , m_tree(tree)
    , m_clock(clock)
{
}

void HealthMonitor::setCommsTimeout(double seconds)
{
    QMutexLocker lock(&m_mutex);
    m_timeoutMs = seconds * 1000;
}

void HealthMonitor::setForgetAfter(double seconds)
{
    QMutexLocker lock(&m_mutex);
    m_forgetAfterMs = std::max<qint64>(0, static_cast<qint64>(seconds * 1000));
}

void HealthMonitor::forget(quint16 id)
{
    QMutexLocker lock(&m_mutex);
    const auto it = m_systems.constFind(id);
    if (it == m_systems.cend())
        return;
    m_graph.forget(it->node);
    m_systems.erase(it);
}

Level HealthMonitor::levelOfEntityState(qint64 state)
{
    switch (state) {
    case 0: return Info;    // BOOT
    case 1: return Normal;  // NORMAL
    case 2: return Warning; // FAULT
    case 3: return Error;   // ERROR
    case 4: return Failure; // FAILURE
    default: return Unknown;
    }
}

HealthMonitor::System &HealthMonitor::systemLocked(quint16 id)
{
    System &system = m_systems[id];
    const QString name = m_tree.systemName(id);
    if (system.node == AlarmGraph::noNode) {
        system.name = name;
        system.node = m_graph.ensure(QStringLiteral("systems/") + name);
    } else if (system.name != name) {
        system.name = name;
        m_graph.rename(system.node, name);
    }
    return system;
}

double HealthMonitor::limitLocked(const System &system) const
{
    if (!system.streaming) // IMC's Announce period is 10 s
        return 1.5 * (system.announceIntervalMs < 0 ? 10000.0 : system.announceIntervalMs) + m_timeoutMs;
    // A system heard once has no interval yet: assume IMC's 1 s heartbeat.
    return (system.intervalMs < 0 ? 1000.0 : system.intervalMs) + m_timeoutMs;
}

void HealthMonitor::observe(const msg::Message &message)
{
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    QMutexLocker lock(&m_mutex);
    System &system = systemLocked(message.header.src);
    const bool announce = message.def() && message.def()->abbrev == u"Announce";
    if (announce) {
        // Its stream stopped long ago (it restarted, or forgot this console): awaited anew.
        if (system.streaming && now - system.streamMs > limitLocked(system)) {
            system.streaming = false;
            system.intervalMs = -1;
        }
        if (!system.streaming && (system.waitingSinceMs == 0 || now - system.lastMs > limitLocked(system)))
            system.waitingSinceMs = now;
        if (system.announceMs > 0)
            system.announceIntervalMs = static_cast<double>(now - system.announceMs);
        system.announceMs = now;
        system.console = message.integer(u"sys_type") == 0; // CCU
    } else {
        if (system.streaming) {
            const double gap = static_cast<double>(now - system.streamMs);
            system.intervalMs = system.intervalMs < 0 ? gap : 0.9 * system.intervalMs + 0.1 * gap;
        }
        system.streaming = true;
        system.streamMs = now;
        system.waitingSinceMs = 0;
    }
    if (system.firstMs == 0)
        system.firstMs = now;
    system.lastMs = now;
    // Traffic clears a silence; only a stream clears "heard only its Announce".
    if (system.lost != Normal && !(announce && system.unstreamed)) {
        system.lost = Normal;
        system.unstreamed = false;
        m_graph.clear(system.node);
    }
    if (message.def() && message.def()->abbrev == u"EntityState") {
        Entity &entity = entityLocked(system, message.header.src, message.header.srcEnt);
        m_graph.raise(entity.node, levelOfEntityState(message.integer(u"state")), message.text(u"description"));
    }
}

HealthMonitor::Entity &HealthMonitor::entityLocked(System &system, quint16 id, quint8 number)
{
    Entity &entity = system.entities[number];
    const QString label = m_tree.entityLabel(id, number);
    if (entity.node == AlarmGraph::noNode) {
        entity.node = m_graph.ensure(QStringLiteral("systems/%1/%2").arg(system.name, label));
        entity.label = label;
    } else if (entity.label != label) {
        // Named by a late EntityList or EntityInfo: the alarm keeps its place and level.
        entity.label = label;
        m_graph.rename(entity.node, label);
    }
    return entity;
}

QString HealthMonitor::silenceText(double ms)
{
    const qint64 seconds = static_cast<qint64>(ms / 1000.0);
    if (seconds < 60)
        return QStringLiteral("%1 s").arg(seconds);
    if (seconds < 3600)
        return QStringLiteral("%1 min %2 s").arg(seconds / 60).arg(seconds % 60, 2, 10, QLatin1Char('0'));
    return QStringLiteral("%1 h %2 min").arg(seconds / 3600).arg((seconds % 3600) / 60, 2, 10, QLatin1Char('0'));
}

bool HealthMonitor::establishedLocked(quint16 id, const System &system) const
{
    return system.lastMs - system.firstMs >= establishMs || m_tree.isNamed(id);
}

void HealthMonitor::updateShortLivedLocked(const QList<quint16> &silent)
{
    QString text;
    if (!silent.isEmpty()) {
        QStringList names;
        for (qsizetype i = 0; i < std::min<qsizetype>(silent.size(), namedInSummary); ++i)
            names << msg::systemLabel(silent[i]);
        if (silent.size() > namedInSummary)
            names << QStringLiteral("%1 more").arg(silent.size() - namedInSummary);
        text = QStringLiteral("%1 unnamed system(s) heard for under %2 s went silent: %3 (forged ids, or a vehicle "
                              "lost at once)")
                   .arg(silent.size())
                   .arg(establishMs / 1000)
                   .arg(names.join(QStringLiteral(", ")));
    }
    if (text == m_shortLivedText)
        return;
    m_shortLivedText = text;
    if (m_shortLived == AlarmGraph::noNode)
        m_shortLived = m_graph.ensure(QStringLiteral("links/short-lived systems"));
    m_graph.raise(m_shortLived, text.isEmpty() ? Normal : Warning, text);
}

QList<quint16> HealthMonitor::check()
{
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    QMutexLocker lock(&m_mutex);
    QList<quint16> shortLived;
    QList<quint16> forgotten;
    const qint64 shortLivedLimit = m_forgetAfterMs > 0 ? std::min(m_forgetAfterMs, forgetShortLivedMs) : forgetShortLivedMs;
    for (auto it = m_systems.begin(); it != m_systems.end();) {
        System &system = *it;
        if (system.lastMs == 0) {
            ++it;
            continue;
        }
        systemLocked(it.key()); // follows a rename
        for (auto entity = system.entities.begin(); entity != system.entities.end(); ++entity)
            entityLocked(system, it.key(), entity.key());
        const double silent = static_cast<double>(now - system.lastMs);
        const double limit = limitLocked(system);
        const Level level = silent > 3 * limit ? Error : silent > limit ? Warning : Normal;
        if (level == Normal) {
            // Announcing, and nothing else, for long: DUNE would have streamed by now.
            const bool unstreamed = !system.streaming && !system.console && system.waitingSinceMs > 0
                                    && now - system.waitingSinceMs > waitForStreamMs;
            const QString text = unstreamed ? QStringLiteral("heard only its Announce for %1: it sends this console nothing "
                                                             "(does it reach this console's address?)")
                                                  .arg(silenceText(static_cast<double>(now - system.waitingSinceMs)))
                                            : QString();
            if (unstreamed) {
                system.lost = Warning;
                system.unstreamed = true;
                m_graph.raise(system.node, Warning, text);
            } else if (system.lost != Normal) {
                m_graph.clear(system.node);
                system.lost = Normal;
                system.unstreamed = false;
            }
            ++it;
            continue;
        }
        const bool established = establishedLocked(it.key(), system);
        const qint64 forgetMs = established ? m_forgetAfterMs : shortLivedLimit; // 0: never
        if (forgetMs > 0 && silent > static_cast<double>(forgetMs)) {
            m_graph.forget(system.node); // its alarms and its entities', to Unknown
            forgotten.append(it.key());
            it = m_systems.erase(it);
            continue;
        }
        if (!established) {
            // What its entities said is as doubtful as the system itself: no
            // forged id's entity failure stays behind (the summary names it).
            for (const Entity &entity : std::as_const(system.entities))
                if (m_graph.ownLevel(entity.node) != Unknown)
                    m_graph.raise(entity.node, Unknown);
            shortLived.append(it.key());
            ++it;
            continue;
        }
        // The text follows the silence as it grows (once a second at most).
        system.lost = level;
        system.unstreamed = false;
        m_graph.raise(system.node, level, QStringLiteral("communications lost: nothing heard for ") + silenceText(silent));
        ++it;
    }
    std::sort(shortLived.begin(), shortLived.end());
    updateShortLivedLocked(shortLived);
    return forgotten;
}

} // namespace neptus::alarms
