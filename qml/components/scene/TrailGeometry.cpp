#include "TrailGeometry.h"

#include "geo/Geodesy.h"

#include <QVector3D>

#include <algorithm>

TrailGeometry::TrailGeometry(QQuick3DObject *parent)
    : QQuick3DGeometry(parent)
{
    m_uploadTimer.setSingleShot(true);
    m_uploadTimer.setInterval(2 * m_uploadInterval);
    connect(&m_uploadTimer, &QTimer::timeout, this, &TrailGeometry::upload);
}

void TrailGeometry::setUploadInterval(int ms)
{
    ms = std::max(ms, 100);
    if (ms == m_uploadInterval)
        return;
    m_uploadInterval = ms;
    m_uploadTimer.setInterval(2 * ms);
    emit uploadIntervalChanged();
}

void TrailGeometry::setTracks(neptus::geo::Tracks *tracks)
{
    if (m_tracks == tracks)
        return;
    if (m_tracks)
        disconnect(m_tracks, nullptr, this, nullptr);
    m_tracks = tracks;
    if (m_tracks) {
        connect(m_tracks, &neptus::geo::Tracks::updated, this, &TrailGeometry::rebuild);
        connect(m_tracks, &neptus::geo::Tracks::homeChanged, this, [this] { m_revision = ~0ull; rebuild(); });
    }
    m_revision = ~0ull;
    rebuild();
    emit tracksChanged();
}

void TrailGeometry::setSystem(const QString &system)
{
    if (m_system == system)
        return;
    m_system = system;
    m_revision = ~0ull;
    rebuild();
    emit systemChanged();
}

void TrailGeometry::rebuild()
{
    using namespace neptus::geo;
    const Tracks::Track *track = m_tracks ? m_tracks->track(m_system) : nullptr;
    const quint64 revision = track ? track->revision : 0;
    if (revision == m_revision)
        return;
    const bool restart = m_revision == ~0ull || !track || track->dropped != m_dropped;
    m_revision = revision;
    const int count = track ? int(track->fixes.size()) : 0;
    if (restart) {
        m_vertices.clear();
        m_dropped = track ? track->dropped : 0;
        m_min = QVector3D(1e30f, 1e30f, 1e30f);
        m_max = -m_min;
    }

    // Convert only the fixes added since the last time.
    const qsizetype have = m_vertices.size() / qsizetype(3 * sizeof(float));
    if (track && count > have) {
        const Geodetic home{m_tracks->homeLat(), m_tracks->homeLon(), m_tracks->homeHeight()};
        m_vertices.resize(qsizetype(count) * 3 * sizeof(float));
        auto *v = reinterpret_cast<float *>(m_vertices.data()) + have * 3;
        for (qsizetype i = have; i < count; ++i, v += 3) {
            const auto &fix = track->fixes[std::size_t(i)];
            const Eigen::Vector3d ned = toNed({fix.lat, fix.lon, fix.height}, home);
            const QVector3D p(float(ned.y()), float(-ned.z()), float(-ned.x()));
            v[0] = p.x();
            v[1] = p.y();
            v[2] = p.z();
            for (int d = 0; d < 3; ++d) {
                m_min[d] = std::min(m_min[d], p[d]);
                m_max[d] = std::max(m_max[d], p[d]);
            }
        }
    }

    if (count != m_pointCount) {
        m_pointCount = count;
        emit pointCountChanged();
    }
    // A new or restarted trail shows at once; growth at most every interval,
    // in a frame the tracks' update makes anyway (a timer of its own would
    // draw frames of their own). The timer only
    // catches the last fixes of a trail that stopped growing.
    if (restart || !m_sinceUpload.isValid() || m_sinceUpload.elapsed() >= m_uploadInterval)
        upload();
    else if (!m_uploadTimer.isActive())
        m_uploadTimer.start();
}

void TrailGeometry::upload()
{
    m_uploadTimer.stop();
    m_sinceUpload.start();
    clear();
    if (m_pointCount >= 2) {
        setVertexData(m_vertices);
        setStride(3 * sizeof(float));
        setPrimitiveType(PrimitiveType::LineStrip);
        addAttribute(Attribute::PositionSemantic, 0, Attribute::F32Type);
        setBounds(m_min, m_max);
    }
    update();
    m_uploadedCount = m_pointCount >= 2 ? m_pointCount : 0;
    emit uploaded();
}
