#pragma once

#include "qmlmodels/Tracks.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>
#include <QQuick3DGeometry>
#include <QVector3D>
#include <QtQml/qqmlregistration.h>

// One system's trail as a 3D line strip, in metres from the tracks' home:
// x east, y up, z south (Qt Quick 3D's axes). New fixes are converted as
// they come, but the whole strip goes to the GPU at most every
// `uploadInterval` (a second by default; a long trail is megabytes, and each
// upload costs Qt Quick 3D a frame of its own right after the one it is in:
// 4 a second per trail were a fifth of the console's CPU; the vehicle itself
// moves every frame), with an update of the tracks; the last growth of a
// trail that stopped within two intervals.
class TrailGeometry : public QQuick3DGeometry
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(neptus::geo::Tracks *tracks READ tracks WRITE setTracks NOTIFY tracksChanged)
    Q_PROPERTY(QString system READ system WRITE setSystem NOTIFY systemChanged)
    Q_PROPERTY(int pointCount READ pointCount NOTIFY pointCountChanged)
    // Points in the geometry handed to the GPU (catches up within 2 s).
    Q_PROPERTY(int uploadedCount READ uploadedCount NOTIFY uploaded)
    // Milliseconds between uploads of a growing trail (100 at least).
    Q_PROPERTY(int uploadInterval READ uploadInterval WRITE setUploadInterval NOTIFY uploadIntervalChanged)

public:
    explicit TrailGeometry(QQuick3DObject *parent = nullptr);

    neptus::geo::Tracks *tracks() const { return m_tracks; }
    void setTracks(neptus::geo::Tracks *tracks);
    QString system() const { return m_system; }
    void setSystem(const QString &system);
    int pointCount() const { return m_pointCount; }
    int uploadedCount() const { return m_uploadedCount; }
    int uploadInterval() const { return m_uploadInterval; }
    void setUploadInterval(int ms);

signals:
    void tracksChanged();
    void systemChanged();
    void pointCountChanged();
    void uploaded();
    void uploadIntervalChanged();

private:
    void rebuild();
    void upload();

    int m_uploadInterval = 1000;
    QTimer m_uploadTimer;
    QElapsedTimer m_sinceUpload;
    QPointer<neptus::geo::Tracks> m_tracks;
    QString m_system;
    int m_pointCount = 0;
    int m_uploadedCount = 0;
    quint64 m_revision = ~0ull;
    // Points converted so far (x, y, z floats), kept while the track only grows.
    QByteArray m_vertices;
    quint64 m_dropped = 0;
    QVector3D m_min, m_max;
};
