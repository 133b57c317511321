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
}

QStringList Tracks::systems() const
{
    QStringList names;
    for (const auto &t : m_tracks)
        names << t->system;
    return names;
}

// By name: called by QML and tests, not per fix.
const Tracks::Track *Tracks::track(const QString &system) const
{
    for (const auto &t : m_tracks)
        if (t->system == system)
            return t.get();
    return nullptr;
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
    if (!m_tracks.empty()) // every row's position from home moved
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
            {QStringLiteral("count"), qulonglong(t->fixes.size())}};
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

int Tracks::count(const QString &system) const
{
    const Track *t = track(system);
    return t ? int(t->fixes.size()) : 0;
}

void Tracks::clear(const QString &system)
{
    for (auto &t : m_tracks)
        if (t->system == system) {
            t->dropped += t->fixes.size();
            t->fixes.clear();
            ++t->revision;
            ++m_revision;
            notifyChanged();
            emit updated();
        }
}

int Tracks::rowOf(const Track &track) const
{
    return m_rowById.value(track.id, -1);
}

Tracks::Track &Tracks::trackFor(quint16 id, const QString &system)
{
    if (const auto row = m_rowById.constFind(id); row != m_rowById.cend()) {
        Track &t = *m_tracks[static_cast<size_t>(*row)];
        if (t.system != system) {
            t.system = system; // named by its Announce
            emit dataChanged(index(*row), index(*row), {SystemRole});
            m_systemsChanged = true;
        }
        return t;
    }
    const int row = rowCount();
    beginInsertRows({}, row, row);
    m_tracks.push_back(std::make_unique<Track>());
    m_tracks.back()->id = id;
    m_tracks.back()->system = system;
    m_rowById.insert(id, row);
    m_shownRevision.push_back(0);
    endInsertRows();
    m_systemsChanged = true;
    return *m_tracks.back();
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
        if (m_tracks[static_cast<size_t>(row)]->revision == m_shownRevision[static_cast<size_t>(row)]) {
            ++row;
            continue;
        }
        int last = row;
        while (last + 1 < rows
               && m_tracks[static_cast<size_t>(last + 1)]->revision != m_shownRevision[static_cast<size_t>(last + 1)])
            ++last;
        for (int r = row; r <= last; ++r)
            m_shownRevision[static_cast<size_t>(r)] = m_tracks[static_cast<size_t>(r)]->revision;
        emit dataChanged(index(row), index(last));
        row = last + 1;
    }
}

int Tracks::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_tracks.size());
}

QVariant Tracks::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Track &t = *m_tracks[static_cast<size_t>(index.row())];
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
    if (!m_tracks.empty())
        emit dataChanged(index(0), index(rowCount() - 1), {NorthRole, EastRole, DownRole});
}

void Tracks::append(const QString &system, const Fix &fix)
{
    const Track *known = track(system);
    // Not from the tree: a private id, past any IMC system's.
    Track &t = trackFor(known ? known->id : quint16(0xF000 + m_tracks.size()), system);
    homeOnce(fix.lat, fix.lon, 0);
    add(t, fix);
    flushSystems();
    notifyChanged();
}

void Tracks::add(Track &t, const Fix &fix)
{
    t.latest = fix;
    bool keep = t.fixes.empty();
    if (!keep) {
        const Fix &last = t.fixes.back();
        const Eigen::Vector3d d = toNed({fix.lat, fix.lon, fix.height}, {last.lat, last.lon, last.height});
        keep = std::hypot(d.x(), d.y(), fix.depth - last.depth) >= m_minimumSpacing || fix.time - last.time >= 10;
    }
    if (keep) {
        if (t.fixes.size() >= m_capacity) {
            const std::size_t forget = m_capacity / 10;
            t.fixes.erase(t.fixes.begin(), t.fixes.begin() + std::ptrdiff_t(forget));
            t.dropped += forget;
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
    add(trackFor(id, tree.systemName(id)), fix);
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
    std::vector<tree::NodeId> nodes;
    nodes.swap(m_waiting);
    m_waitingSet.clear();
    for (const tree::NodeId node : changes.changedNodes)
        if (tree.kind(node) == tree::VariableTree::Kind::Message && tree.name(node) == QLatin1String("EstimatedState"))
            nodes.push_back(node);
    int joined = 0;
    for (const tree::NodeId node : nodes) {
        if (!m_rowById.contains(tree.systemOf(node)) && joined++ >= newSystemsPerUpdate) {
            if (!m_waitingSet.contains(node)) {
                m_waitingSet.insert(node);
                m_waiting.push_back(node);
            }
            continue;
        }
        read(node);
    }
    if (!m_waiting.empty() && !m_more.isActive())
        m_more.start(); // the model syncs only when the tree changes
    flushSystems();
    if (m_revision == before)
        return;
    notifyChanged();
    emit updated();
}

} // namespace neptus::geo
