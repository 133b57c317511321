#include "qmlmodels/Tracks.h"

#include "geo/Geodesy.h"

#include <cmath>

namespace neptus::geo {

namespace {
// New systems that join per update (per frame): a thousand at once froze the console.
constexpr int newSystemsPerUpdate = 8;
} // namespace

Tracks::Tracks(tree::VariableTreeModel *model, QObject *parent)
    : QAbstractListModel(parent)
    , m_model(model)
    , m_consumer(model->tree()->addConsumer())
{
    connect(model, &tree::VariableTreeModel::synced, this, &Tracks::update);
    m_more.setSingleShot(true);
    m_more.setInterval(16);
    connect(&m_more, &QTimer::timeout, this, &Tracks::update);
    m_forget.setInterval(1000);
    connect(&m_forget, &QTimer::timeout, this, &Tracks::forgetSilent);
    m_forget.start();
}

QStringList Tracks::systems() const
{
    QStringList names;
    for (const auto &t : m_tracks)
        names << t->system;
    return names;
}

const Tracks::Track *Tracks::track(const QString &system) const
{
    return m_byName.value(system);
}

void Tracks::setMaxDrawn(int systems)
{
    setDrawLimit(m_maxDrawn, std::max(systems, 1));
}

void Tracks::setMaxUnnamedDrawn(int systems)
{
    setDrawLimit(m_maxUnnamedDrawn, std::max(systems, 0));
}

void Tracks::setDrawLimit(int &limit, int systems)
{
    if (systems == limit)
        return;
    limit = systems;
    m_rowsDirty = true;
    updateRows();
    emit systemsChanged();
}

QVariantMap Tracks::home() const
{
    return {{QStringLiteral("lat"), degrees(m_homeLat)},
            {QStringLiteral("lon"), degrees(m_homeLon)},
            {QStringLiteral("height"), m_homeHeight},
            {QStringLiteral("valid"), m_hasHome}};
}

void Tracks::setHome(const QVariantMap &home)
{
    bool latOk = false, lonOk = false;
    const double lat = home.value(QStringLiteral("lat")).toDouble(&latOk);
    const double lon = home.value(QStringLiteral("lon")).toDouble(&lonOk);
    if (!latOk || !lonOk || std::abs(lat) > 90 || std::abs(lon) > 180) {
        qWarning("Tracks: a home needs lat in [-90, 90] and lon in [-180, 180] degrees");
        return;
    }
    m_homeLat = radians(lat);
    m_homeLon = radians(lon);
    m_homeHeight = home.value(QStringLiteral("height")).toDouble();
    m_hasHome = true;
    emit homeChanged();
    if (!m_rows.empty()) // every row's position from home moved
        emit dataChanged(index(0), index(rowCount() - 1), {NorthRole, EastRole, DownRole});
}

QVariantMap Tracks::latest(const QString &system) const
{
    const Track *t = track(system);
    if (!t)
        return {};
    const Fix &f = t->latest;
    return {{QStringLiteral("lat"), degrees(f.lat)},   {QStringLiteral("lon"), degrees(f.lon)},
            {QStringLiteral("height"), f.height},      {QStringLiteral("depth"), f.depth},
            {QStringLiteral("roll"), degrees(f.roll)}, {QStringLiteral("pitch"), degrees(f.pitch)},
            {QStringLiteral("heading"), degrees(f.heading)}, {QStringLiteral("time"), f.time},
            {QStringLiteral("count"), qulonglong(t->fixes.size())}, {QStringLiteral("announced"), t->announcedOnly}};
}

QVariantMap Tracks::ned(const QString &system) const
{
    const Track *t = track(system);
    if (!t || !m_hasHome)
        return {};
    const auto &f = t->latest;
    const Eigen::Vector3d d = toNed({f.lat, f.lon, f.height}, {m_homeLat, m_homeLon, m_homeHeight});
    return {{QStringLiteral("north"), d.x()}, {QStringLiteral("east"), d.y()}, {QStringLiteral("down"), d.z()}};
}

QList<QPointF> Tracks::nedPath(const QString &system, int maxPoints) const
{
    QList<QPointF> points;
    const Track *t = track(system);
    if (!t || !m_hasHome || t->fixes.empty() || maxPoints < 2)
        return points;
    const Geodetic home{m_homeLat, m_homeLon, m_homeHeight};
    const auto add = [&](const Fix &f) {
        const Eigen::Vector3d d = toNed({f.lat, f.lon, f.height}, home);
        points.append(QPointF(d.y(), d.x()));
    };
    const std::size_t n = t->fixes.size();
    const std::size_t stride = std::max<std::size_t>(1, (n + std::size_t(maxPoints) - 2) / std::size_t(maxPoints - 1));
    for (std::size_t i = 0; i < n; i += stride)
        add(t->fixes[i]);
    add(t->latest);
    return points;
}

int Tracks::count(const QString &system) const
{
    const Track *t = track(system);
    return t ? int(t->fixes.size()) : 0;
}

void Tracks::clear(const QString &system)
{
    Track *t = m_byName.value(system);
    if (!t)
        return;
    t->dropped += t->fixes.size();
    t->fixes.clear();
    ++t->revision;
    ++m_revision;
    notifyChanged();
    emit updated();
}

Tracks::Track &Tracks::trackFor(quint16 id, const QString &system, bool named)
{
    if (Track *t = m_byId.value(id)) {
        if (t->system != system) { // named by its Announce
            m_byName.remove(t->system);
            t->system = system;
            m_byName.insert(system, t);
            const auto row = std::find(m_rows.begin(), m_rows.end(), t);
            if (row != m_rows.end()) {
                const int r = int(row - m_rows.begin());
                emit dataChanged(index(r), index(r), {SystemRole});
            }
            m_systemsChanged = true;
        }
        if (t->named != named) {
            t->named = named;
            m_rowsDirty = true;
        }
        return *t;
    }
    m_tracks.push_back(std::make_unique<Track>());
    Track *t = m_tracks.back().get();
    t->id = id;
    t->system = system;
    t->named = named;
    m_byId.insert(id, t);
    m_byName.insert(system, t);
    m_rowsDirty = true;
    m_systemsChanged = true;
    return *t;
}

void Tracks::updateRows()
{
    if (!m_rowsDirty)
        return;
    m_rowsDirty = false;
    // Named systems first, then a few others, each in the order first heard.
    std::vector<Track *> drawn;
    for (const bool named : {true, false}) {
        const int most = named ? m_maxDrawn : std::min<int>(m_maxDrawn, int(drawn.size()) + m_maxUnnamedDrawn);
        for (const auto &t : m_tracks) {
            if (t->named == named && int(drawn.size()) < most)
                drawn.push_back(t.get());
        }
    }
    const QSet<const Track *> wanted(drawn.begin(), drawn.end());
    const QSet<const Track *> had(m_rows.begin(), m_rows.end());
    if (wanted == had)
        return;
    removeRows([&](const Track &t) { return !wanted.contains(&t); });
    for (Track *t : drawn) {
        if (had.contains(t))
            continue;
        const int row = rowCount();
        beginInsertRows({}, row, row);
        m_rows.push_back(t);
        m_shownRevision.push_back(t->revision);
        endInsertRows();
    }
    m_systemsChanged = true; // `hidden` changed
}

void Tracks::removeRows(const std::function<bool(const Track &)> &unwanted)
{
    for (int row = int(m_rows.size()) - 1; row >= 0; --row) {
        if (!unwanted(*m_rows[size_t(row)]))
            continue;
        beginRemoveRows({}, row, row);
        m_rows.erase(m_rows.begin() + row);
        m_shownRevision.erase(m_shownRevision.begin() + row);
        endRemoveRows();
    }
}

void Tracks::forgetSilent()
{
    if (!m_model)
        return;
    const qint64 now = m_model->tree()->clock().now().toMSecsSinceEpoch();
    forget([&](const Track &t) { return !t.named && now - t.heardMs > m_forgetAfterMs; });
}

void Tracks::forget(const std::function<bool(const Track &)> &unwanted)
{
    if (std::none_of(m_tracks.begin(), m_tracks.end(), [&](const auto &t) { return unwanted(*t); }))
        return;
    removeRows(unwanted); // before the tracks they point to go
    for (const auto &t : m_tracks) {
        if (unwanted(*t)) {
            m_byId.remove(t->id);
            m_byName.remove(t->system);
        }
    }
    std::erase_if(m_tracks, [&](const auto &t) { return unwanted(*t); });
    m_rowsDirty = true;
    updateRows(); // others may take the rows given back
    m_systemsChanged = true;
    flushSystems();
    ++m_revision;
    emit updated();
}

void Tracks::flushSystems()
{
    // Once per batch: what binds to the list (a colour per system, found by
    // its index) reads it again once, not once per new system.
    if (!m_systemsChanged)
        return;
    m_systemsChanged = false;
    emit systemsChanged();
}

void Tracks::notifyChanged()
{
    // One dataChanged per run of neighbouring rows that moved.
    const int rows = rowCount();
    for (int row = 0; row < rows;) {
        if (m_rows[static_cast<size_t>(row)]->revision == m_shownRevision[static_cast<size_t>(row)]) {
            ++row;
            continue;
        }
        int last = row;
        while (last + 1 < rows
               && m_rows[static_cast<size_t>(last + 1)]->revision != m_shownRevision[static_cast<size_t>(last + 1)])
            ++last;
        for (int r = row; r <= last; ++r)
            m_shownRevision[static_cast<size_t>(r)] = m_rows[static_cast<size_t>(r)]->revision;
        emit dataChanged(index(row), index(last));
        row = last + 1;
    }
}

int Tracks::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

QVariant Tracks::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Track &t = *m_rows[static_cast<size_t>(index.row())];
    const Fix &f = t.latest;
    const bool valid = t.revision > 0;
    const auto fromHome = [&](int axis) {
        if (!valid || !m_hasHome)
            return 0.0;
        return toNed({f.lat, f.lon, f.height}, {m_homeLat, m_homeLon, m_homeHeight})[axis];
    };
    switch (role) {
    case Qt::DisplayRole:
    case SystemRole: return t.system;
    case ValidRole: return valid;
    case LatitudeRole: return degrees(f.lat);
    case LongitudeRole: return degrees(f.lon);
    case HeightRole: return f.height;
    case DepthRole: return f.depth;
    case RollRole: return degrees(f.roll);
    case PitchRole: return degrees(f.pitch);
    case HeadingRole: return degrees(f.heading);
    case NorthRole: return fromHome(0);
    case EastRole: return fromHome(1);
    case DownRole: return fromHome(2);
    case TimeRole: return f.time;
    case CountRole: return static_cast<int>(t.fixes.size());
    default: return {};
    }
}

QHash<int, QByteArray> Tracks::roleNames() const
{
    return {{SystemRole, "system"},   {ValidRole, "valid"},     {LatitudeRole, "lat"},     {LongitudeRole, "lon"},
            {HeightRole, "height"},   {DepthRole, "depth"},     {RollRole, "roll"},        {PitchRole, "pitch"},
            {HeadingRole, "heading"}, {NorthRole, "north"},     {EastRole, "east"},        {DownRole, "down"},
            {TimeRole, "time"},       {CountRole, "count"}};
}

void Tracks::homeOnce(double lat, double lon, double height)
{
    if (m_hasHome)
        return;
    m_homeLat = lat;
    m_homeLon = lon;
    m_homeHeight = height;
    m_hasHome = true;
    emit homeChanged();
    if (!m_rows.empty())
        emit dataChanged(index(0), index(rowCount() - 1), {NorthRole, EastRole, DownRole});
}

void Tracks::append(const QString &system, const Fix &fix)
{
    const Track *known = track(system);
    // Not from the tree: a private id, past any IMC system's.
    Track &t = trackFor(known ? known->id : m_nextPrivateId++, system, true);
    homeOnce(fix.lat, fix.lon, 0);
    add(t, fix);
    updateRows();
    flushSystems();
    notifyChanged();
}

void Tracks::append(quint16 id, const QString &system, const std::vector<Fix> &fixes)
{
    if (fixes.empty())
        return;
    Track &t = trackFor(id, system, true);
    homeOnce(fixes.front().lat, fixes.front().lon, 0);
    for (const Fix &fix : fixes)
        add(t, fix);
    updateRows();
    flushSystems();
    notifyChanged();
}

void Tracks::add(Track &t, const Fix &fix)
{
    bool keep = t.fixes.empty();
    if (!keep) {
        const Fix &last = t.fixes.back();
        const auto offset = [&](const Fix &f) {
            const Eigen::Vector3d d = toNed({f.lat, f.lon, f.height}, {last.lat, last.lon, last.height});
            return Eigen::Vector3d(d.x(), d.y(), double(f.depth - last.depth));
        };
        const Eigen::Vector3d to = offset(fix);
        const double moved = to.norm();
        keep = moved >= m_maximumSpacing || fix.time - last.time >= 10;
        // Left out so far, but not if the straight line to this fix would pass
        // further than `tolerance` from any of them: the one before is kept.
        const bool bends = moved >= m_minimumSpacing && std::any_of(t.pending.begin(), t.pending.end(), [&](const Fix &f) {
            const Eigen::Vector3d between = offset(f);
            const double along = std::clamp(between.dot(to) / std::max(1e-9, to.squaredNorm()), 0.0, 1.0);
            return (between - along * to).norm() > m_tolerance;
        });
        if (bends) {
            t.fixes.push_back(t.pending.back());
            t.pending.clear();
        }
    }
    t.latest = fix;
    if (!keep) {
        t.pending.push_back(fix);
    } else {
        t.pending.clear();
        if (t.fixes.size() >= m_capacity) {
            // The older half thinned to every other fix (views draw it anew: `dropped` changes).
            const std::size_t half = t.fixes.size() / 2;
            std::size_t kept = 0;
            for (std::size_t i = 0; i < half; i += 2)
                t.fixes[kept++] = t.fixes[i];
            const std::size_t removed = half - kept;
            t.fixes.erase(t.fixes.begin() + std::ptrdiff_t(kept), t.fixes.begin() + std::ptrdiff_t(half));
            t.dropped += removed;
        }
        t.fixes.push_back(fix);
    }
    ++t.revision;
    ++m_revision;
}

void Tracks::read(tree::NodeId node)
{
    const tree::VariableTree &tree = *m_model->tree();
    auto field = [&](const char *name) {
        return tree.snapshot(tree.childByName(node, QString::fromLatin1(name))).value.toDouble();
    };
    const double lat = field("lat"), lon = field("lon");
    if (!std::isfinite(lat) || !std::isfinite(lon) || std::abs(lat) > M_PI / 2 || std::abs(lon) > M_PI)
        return; // an invalid position is not drawn at the wrong place
    const Geodetic p = imcPosition(lat, lon, field("height"), field("x"), field("y"), field("z"));
    Fix fix;
    fix.time = tree.snapshot(node).timestamp;
    fix.lat = p.lat;
    fix.lon = p.lon;
    fix.height = float(p.height);
    fix.depth = float(field("depth"));
    fix.roll = float(field("phi"));
    fix.pitch = float(field("theta"));
    fix.heading = float(field("psi"));
    const quint16 id = tree.systemOf(node);
    homeOnce(lat, lon, field("height")); // the vehicle's own reference, not its offset position
    const QString name = tree.systemName(id);
    Track &t = trackFor(id, name, tree.isNamed(id));
    t.heardMs = tree.clock().now().toMSecsSinceEpoch();
    if (t.announcedOnly) { // its own state from now on: the announced place is no part of its trail
        t.announcedOnly = false;
        t.fixes.clear();
    }
    add(t, fix);
}

// A DUNE vehicle's Announce says where it is (from its EstimatedState), and
// comes seconds before it streams to a console it has just met: shown there
// at once, until its first EstimatedState.
void Tracks::readAnnounce(tree::NodeId node)
{
    const tree::VariableTree &tree = *m_model->tree();
    const quint16 id = tree.systemOf(node);
    if (const auto known = m_byId.constFind(id); known != m_byId.cend() && !(*known)->announcedOnly)
        return;
    auto field = [&](const char *name) {
        return tree.snapshot(tree.childByName(node, QString::fromLatin1(name))).value.toDouble();
    };
    const double lat = field("lat"), lon = field("lon");
    if (!std::isfinite(lat) || !std::isfinite(lon) || std::abs(lat) > M_PI / 2 || std::abs(lon) > M_PI || (lat == 0 && lon == 0))
        return; // none given (0, 0), or nonsense
    Fix fix;
    fix.time = tree.snapshot(node).timestamp;
    fix.lat = lat;
    fix.lon = lon;
    fix.height = float(field("height"));
    homeOnce(lat, lon, fix.height);
    Track &t = trackFor(id, tree.systemName(id), tree.isNamed(id));
    t.announcedOnly = true;
    t.heardMs = tree.clock().now().toMSecsSinceEpoch();
    t.fixes.clear();
    add(t, fix);
}

void Tracks::update()
{
    if (!m_model)
        return;
    const tree::VariableTree &tree = *m_model->tree();
    const auto changes = m_model->tree()->takeChanges(m_consumer);
    const quint64 before = m_revision;
    // New systems join a few per update: each brings a marker, a trail and
    // a 3D model, and a thousand at once froze the console for seconds.
    // The others wait for the next updates (one frame each), newest state first read then.
    // Systems the tree forgot leave the map (named ones too).
    if (!changes.removed.empty()) {
        QSet<quint16> gone;
        for (const auto &removed : changes.removed)
            gone.insert(removed.system);
        forget([&gone](const Track &t) { return gone.contains(t.id); });
    }
    std::vector<tree::NodeId> nodes;
    nodes.swap(m_waiting);
    m_waitingSet.clear();
    if (!changes.removed.empty()) // nodes of forgotten systems belong to no system now
        std::erase_if(nodes, [&tree](tree::NodeId node) { return tree.systemOf(node) == 0xFFFF; });
    std::vector<tree::NodeId> announces;
    for (const tree::NodeId node : changes.changedNodes) {
        if (tree.kind(node) != tree::VariableTree::Kind::Message)
            continue;
        if (tree.name(node) == QLatin1String("EstimatedState"))
            nodes.push_back(node);
        else if (tree.name(node) == QLatin1String("Announce"))
            announces.push_back(node);
    }
    int joined = 0;
    for (const tree::NodeId node : nodes) {
        if (!m_byId.contains(tree.systemOf(node)) && joined++ >= newSystemsPerUpdate) {
            if (!m_waitingSet.contains(node)) {
                m_waitingSet.insert(node);
                m_waiting.push_back(node);
            }
            continue;
        }
        read(node);
    }
    for (const tree::NodeId node : announces)
        if (m_byId.contains(tree.systemOf(node)) || joined++ < newSystemsPerUpdate)
            readAnnounce(node);
    if (!m_waiting.empty() && !m_more.isActive())
        m_more.start(); // the model syncs only when the tree changes
    updateRows();
    flushSystems();
    if (m_revision == before)
        return;
    notifyChanged();
    emit updated();
}

} // namespace neptus::geo
