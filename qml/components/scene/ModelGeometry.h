#pragma once

#include "models/ModelImport.h"

#include <QQuick3DGeometry>
#include <QUrl>
#include <QVector3D>
#include <QtQml/qqmlregistration.h>

// A model or terrain file (any format OpenSceneGraph reads, see
// engine/models/ModelLoader.h) as Qt Quick 3D geometry: positions, normals
// and vertex colours. Read in a separate process (ModelImport), so a damaged
// file is an error message and a large one does not freeze the screen. Files are in metres with Z up and, for vehicles, Y
// forward (OpenSceneGraph's east-north-up); the scene's axes are Qt Quick
// 3D's (x east, y up, z south), so a model's +Y points north.
class ModelGeometry : public QQuick3DGeometry
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QUrl source READ source WRITE setSource NOTIFY sourceChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY loaded)
    Q_PROPERTY(bool loading READ loading NOTIFY loadingChanged)
    Q_PROPERTY(int triangleCount READ triangleCount NOTIFY loaded)
    Q_PROPERTY(QVector3D boundsMin READ boundsMin NOTIFY loaded)
    Q_PROPERTY(QVector3D boundsMax READ boundsMax NOTIFY loaded)

public:
    explicit ModelGeometry(QQuick3DObject *parent = nullptr);

    QUrl source() const { return m_source; }
    void setSource(const QUrl &source);
    QString errorString() const { return m_error; }
    bool loading() const { return m_import.running(); }
    int triangleCount() const { return m_triangles; }
    QVector3D boundsMin() const { return m_min; }
    QVector3D boundsMax() const { return m_max; }

signals:
    void sourceChanged();
    void loaded();
    void loadingChanged();

private:
    void imported();

    neptus::models::ModelImport m_import;
    QUrl m_source;
    QString m_error;
    int m_triangles = 0;
    QVector3D m_min, m_max;
};
