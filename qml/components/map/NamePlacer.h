#pragma once

#include <QList>
#include <QObject>
#include <QPointF>
#include <QRectF>
#include <QtQml/qqmlregistration.h>

// Where the map's feature names go (MapFeatureLayer): each name at the first
// of eight places round its glyph (right, left, above, below, then the upper
// right, lower right, upper left and lower left corners) clear of `avoid`
// (the systems' marks and labels), of every glyph and of the names placed
// before it; -1 where none is clear (the name is left out). Worked out in
// C++ over a grid of the rectangles, because it runs at every move of a
// vehicle: in JavaScript, testing every rectangle against every other, 300
// features took 73 ms a move (BENCHMARKS.md).
class NamePlacer : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_SINGLETON

public:
    using QObject::QObject;
    // `glyphs` the glyphs' centres, `widths` their names' widths (`height`
    // each); a glyph covers `glyphHalf` round its centre; a name lies `gap`
    // from its glyph beside it, `side` from it above, below and at a corner.
    // Glyphs outside `within`, or not at a number, are not worked out (0).
    Q_INVOKABLE QList<int> place(const QList<QPointF> &glyphs, const QList<qreal> &widths, qreal height, const QList<QRectF> &avoid,
                                 qreal glyphHalf, qreal gap, qreal side, const QRectF &within) const;
    // The rectangle of a name `width` by `height` at a place round a glyph at `at`.
    Q_INVOKABLE QRectF nameRect(QPointF at, int place, qreal width, qreal height, qreal gap, qreal side) const
    {
        return rectOf(at, place, width, height, gap, side);
    }
    static QRectF rectOf(QPointF at, int place, qreal width, qreal height, qreal gap, qreal side);
    static constexpr int placeCount = 8;
};
