#pragma once

#include "MapOverlayItem.h"

#include <QColor>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

#include <vector>

// A plan on the map, drawn by the scene graph: its legs as one line strip
// and a dot per maneuver (filled by its worst problem), worked out in
// screen coordinates each frame the view moves (a few thousand projections,
// well under a millisecond) instead of one QML binding per marker. The plan
// editor draws its numbered, draggable markers over this for small plans
// and for the selected maneuver.
class PlanOverlayItem : public MapOverlayItem
{
    Q_OBJECT
    QML_ELEMENT
    // [{lat, lon}] in order (PlanEditorModel.path).
    Q_PROPERTY(QVariantList path READ path WRITE setPath NOTIFY changed)
    // [{lat, lon, severity: "error" | "warning" | ""}] (PlanEditorModel.maneuvers).
    Q_PROPERTY(QVariantList maneuvers READ maneuvers WRITE setManeuvers NOTIFY changed)
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
    QVariantList maneuvers() const { return m_maneuverList; }
    void setManeuvers(const QVariantList &maneuvers);

signals:
    void changed();

protected:
    QSGNode *updatePaintNode(QSGNode *old, UpdatePaintNodeData *) override;

private:
    struct Dot
    {
        double lat, lon; // radians
        int severity;    // 0 none, 1 warning, 2 error
    };
    QVariantList m_pathList, m_maneuverList;
    std::vector<std::pair<double, double>> m_path; // radians
    std::vector<Dot> m_dots;
    QColor m_lineColor = Qt::blue, m_dotColor = Qt::white, m_outlineColor = Qt::black, m_warningColor = Qt::yellow,
           m_errorColor = Qt::red;
    double m_lineWidth = 2, m_dotRadius = 6;
};
