#pragma once

#include "MapOverlayItem.h"

#include <QAbstractItemModel>
#include <QColor>
#include <QPointer>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

#include <vector>

// A plan on the map, drawn by the scene graph: its legs as one line strip,
// arrowheads along them, and a dot per maneuver (filled by its worst
// problem). The geometry is made in the map's own units (pixels at the zoom
// it was made for, around the plan's first point) and placed by a transform:
// panning or turning the map changes one matrix, and the vertices are made
// again only when the zoom or the plan changes. The plan editor draws its
// numbered, draggable markers over this for small plans and for the
// selected maneuver.
class PlanOverlayItem : public MapOverlayItem
{
    Q_OBJECT
    QML_ELEMENT
    // [{lat, lon}] in order (PlanEditorModel.path).
    Q_PROPERTY(QVariantList path READ path WRITE setPath NOTIFY pathChanged)
    // A dot per row, from its roles lat, lon and severity ("error" |
    // "warning" | ""): PlanEditorModel.maneuverRows (null: no dots).
    Q_PROPERTY(QAbstractItemModel *maneuvers READ maneuvers WRITE setManeuvers NOTIFY maneuversChanged)
    Q_PROPERTY(QColor lineColor MEMBER m_lineColor NOTIFY changed)
    Q_PROPERTY(double lineWidth MEMBER m_lineWidth NOTIFY changed)
    Q_PROPERTY(QColor dotColor MEMBER m_dotColor NOTIFY changed)
    Q_PROPERTY(QColor outlineColor MEMBER m_outlineColor NOTIFY changed)
    Q_PROPERTY(QColor warningColor MEMBER m_warningColor NOTIFY changed)
    Q_PROPERTY(QColor errorColor MEMBER m_errorColor NOTIFY changed)
    Q_PROPERTY(double dotRadius MEMBER m_dotRadius NOTIFY changed) // pixels

public:
    explicit PlanOverlayItem(QQuickItem *parent = nullptr);

    QVariantList path() const { return m_pathList; }
    void setPath(const QVariantList &path);
    QAbstractItemModel *maneuvers() const { return m_maneuvers; }
    void setManeuvers(QAbstractItemModel *maneuvers);
    // How many times the vertices were made (tests: panning makes none).
    Q_INVOKABLE int geometryBuilds() const { return m_builds; }

signals:
    void pathChanged();
    void maneuversChanged();
    void changed(); // the style

protected:
    QSGNode *updatePaintNode(QSGNode *old, UpdatePaintNodeData *) override;
    void updatePolish() override; // the dots read again from the model

private:
    struct Dot
    {
        Eigen::Vector2d at; // Mercator
        int severity;       // 0 none, 1 warning, 2 error
    };
    void dotsChanged(); // read again before the next frame
    bool m_dotsStale = false;
    QVariantList m_pathList;
    QPointer<QAbstractItemModel> m_maneuvers;
    std::vector<Eigen::Vector2d> m_path; // Mercator
    std::vector<Dot> m_dots;
    QColor m_lineColor = Qt::blue, m_dotColor = Qt::white, m_outlineColor = Qt::black, m_warningColor = Qt::yellow,
           m_errorColor = Qt::red;
    double m_lineWidth = 2, m_dotRadius = 6;
    bool m_stale = true;               // the plan or its style changed since the vertices were made
    bool m_styleStale = true;          // the style changed since the dot images were made
    double m_madeAtZoom = -1;          // the zoom they were made for
    Eigen::Vector2d m_origin{0, 0};    // Mercator of local (0, 0)
    int m_builds = 0;
};
