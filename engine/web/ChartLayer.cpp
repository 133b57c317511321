#include "web/ChartLayer.h"

#include "geo/Polygon.h"

#include <QJsonArray>

#include <cmath>

using namespace Qt::StringLiterals;

namespace neptus::web {

namespace {

double rounded(double degrees) { return std::round(degrees * 1e6) / 1e6; }

QJsonArray path(const std::vector<charts::Vertex> &points, double tolerance, bool closed)
{
    QJsonArray out;
    for (const charts::Vertex &v : geo::thinned(points, tolerance, [](const charts::Vertex &p) { return std::pair{p.lon, p.lat}; }))
        out.append(QJsonArray{rounded(v.lat), rounded(v.lon)});
    // A ring too small to see is left out whole; a line keeps its two ends.
    if (closed && out.size() < 4)
        return {};
    return out;
}

} // namespace

QJsonObject chartLayer(const std::vector<charts::Cell> &cells, double west, double south, double east, double north,
                       double safetyDepth, double tolerance)
{
    using charts::Drawn;
    const double safety = charts::safetyContour(cells, safetyDepth);
    static const char *const shades[] = {"drying", "shallow", "medium", "deep"};
    QJsonArray layers, marks, names;
    QJsonArray shaded[4], land, contour, safetyLine, coast, restricted, fairway; // the layer being filled
    const auto meets = [&](const charts::Feature &f) {
        return f.west > f.east || (f.east >= west && f.west <= east && f.north >= south && f.south <= north);
    };
    const auto endLayer = [&](int band) {
        QJsonObject areas{{u"land"_s, land}};
        for (int i = 0; i < 4; ++i)
            areas.insert(QString::fromLatin1(shades[i]), shaded[i]);
        layers.append(QJsonObject{{u"band"_s, band},
                                  {u"areas"_s, areas},
                                  {u"lines"_s, QJsonObject{{u"contour"_s, contour}, {u"safety"_s, safetyLine}, {u"coast"_s, coast},
                                                           {u"restricted"_s, restricted}, {u"fairway"_s, fairway}}}});
        for (QJsonArray *a : {&shaded[0], &shaded[1], &shaded[2], &shaded[3], &land, &contour, &safetyLine, &coast, &restricted, &fairway})
            *a = QJsonArray();
    };
    const std::vector<std::size_t> order = charts::drawingOrder(cells);
    for (std::size_t n = 0; n < order.size(); ++n) {
        const charts::Cell &cell = cells[order[n]];
        bool used = false;
        for (const charts::Feature &f : cell.features) {
            const Drawn drawn = charts::drawnAs(f);
            if (drawn == Drawn::Nothing || !meets(f))
                continue;
            used = true;
            if (drawn == Drawn::Land || drawn == Drawn::Depth) {
                QJsonArray polygon;
                for (const auto &ring : f.parts)
                    if (QJsonArray r = path(ring, tolerance, true); !r.isEmpty())
                        polygon.append(r);
                if (polygon.isEmpty())
                    continue;
                (drawn == Drawn::Land ? land : shaded[charts::depthShade(f.shallowest.value_or(0), safety)]).append(polygon);
            } else if (drawn == Drawn::Contour || drawn == Drawn::Coast || drawn == Drawn::Restricted || drawn == Drawn::Fairway) {
                QJsonArray &lines = drawn == Drawn::Coast        ? coast
                                    : drawn == Drawn::Restricted ? restricted
                                    : drawn == Drawn::Fairway    ? fairway
                                    : f.number(u"VALDCO"_s) == safety ? safetyLine : contour;
                for (const auto &part : f.parts)
                    if (QJsonArray line = path(part, tolerance, false); line.size() >= 2)
                        lines.append(line);
            } else {
                static const QString kinds[] = {u"hazard"_s, u"buoy"_s, u"beacon"_s, u"light"_s};
                const QString &kind = kinds[int(drawn) - int(Drawn::Hazard)];
                for (const auto &part : f.parts) {
                    if (part.empty() || charts::coveredByBetter(cells, cell, part.front().lon, part.front().lat))
                        continue;
                    QJsonObject mark{{u"kind"_s, kind}, {u"shape"_s, charts::shapeName(charts::shapeOf(f))}, {u"lat"_s, rounded(part.front().lat)}, {u"lon"_s, rounded(part.front().lon)},
                                     {u"scamin"_s, f.number(u"SCAMIN"_s).value_or(0)}, {u"what"_s, charts::className(f.objectClass)}};
                    if (!f.name().isEmpty())
                        mark.insert(u"name"_s, f.name());
                    if (drawn != Drawn::Hazard)
                        if (const charts::AidColour c = charts::aidColour(f); c != charts::AidColour::Other)
                            mark.insert(u"colour"_s, charts::colourName(c));
                    if (const auto bands = charts::aidBands(f)) {
                        QJsonArray colours;
                        for (const charts::AidColour c : bands->colours)
                            colours.append(charts::colourName(c));
                        mark.insert(u"bands"_s, QJsonObject{{u"pattern"_s, charts::patternName(bands->pattern)}, {u"colours"_s, colours}});
                    }
                    if (drawn == Drawn::Hazard && f.shallowest)
                        mark.insert(u"depth"_s, *f.shallowest);
                    if (const auto sector = charts::lightSector(f))
                        mark.insert(u"sector"_s, QJsonArray{sector->from, sector->to});
                    marks.append(mark);
                    if (f.geometry != charts::Feature::Geometry::Point)
                        break; // an area or line hazard at its first point
                }
            }
        }
        if (used)
            names.append(cell.name);
        if (n + 1 == order.size() || cells[order[n + 1]].usageBand != cell.usageBand)
            endLayer(cell.usageBand);
    }
    return {{u"cells"_s, names}, {u"safetyContour"_s, safety}, {u"layers"_s, layers}, {u"marks"_s, marks}};
}

} // namespace neptus::web
