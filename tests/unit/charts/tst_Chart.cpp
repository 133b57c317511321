// Charts as the console keeps them: the cell format handed over by the helper
// and cached (every kind of damage refused), and what the charts say at a
// point, on cells made here.
#include "charts/Chart.h"

#include <gtest/gtest.h>

using namespace neptus::charts;
using namespace Qt::StringLiterals;

namespace {

Feature area(const QString &objectClass, std::vector<std::vector<Vertex>> rings, QMap<QString, QString> attributes = {})
{
    Feature f;
    f.objectClass = objectClass;
    f.geometry = Feature::Geometry::Area;
    f.parts = std::move(rings);
    f.attributes = std::move(attributes);
    return f;
}

std::vector<Vertex> box(double west, double south, double east, double north)
{
    return {{west, south, 0}, {east, south, 0}, {east, north, 0}, {west, north, 0}, {west, south, 0}};
}

Feature point(const QString &objectClass, double lon, double lat, QMap<QString, QString> attributes = {})
{
    Feature f;
    f.objectClass = objectClass;
    f.geometry = Feature::Geometry::Point;
    f.parts = {{{lon, lat, 0}}};
    f.attributes = std::move(attributes);
    return f;
}

// A 0.1° cell: land in the west, a 5-10 m depth area with a 2-5 m shoal (a hole in it, an area of its
// own), a wreck, a restricted area, soundings; coverage the whole cell.
Cell cell(const QString &name = u"XX4TEST.000"_s, int band = 4)
{
    Cell c;
    c.name = name;
    c.edition = 3;
    c.update = 2;
    c.issued = u"20260101"_s;
    c.usageBand = band;
    c.scale = 50000;
    c.features.push_back(area(u"M_COVR"_s, {box(-8.8, 41.1, -8.7, 41.2)}, {{u"CATCOV"_s, u"1"_s}}));
    c.features.push_back(area(u"LNDARE"_s, {box(-8.8, 41.1, -8.78, 41.2)}, {{u"OBJNAM"_s, u"West Shore"_s}}));
    c.features.push_back(area(u"DEPARE"_s, {box(-8.78, 41.1, -8.7, 41.2), box(-8.75, 41.14, -8.74, 41.15)},
                              {{u"DRVAL1"_s, u"5"_s}, {u"DRVAL2"_s, u"10"_s}}));
    c.features.push_back(area(u"DEPARE"_s, {box(-8.75, 41.14, -8.74, 41.15)}, {{u"DRVAL1"_s, u"2"_s}, {u"DRVAL2"_s, u"5"_s}}));
    c.features.push_back(area(u"SEAARE"_s, {box(-8.78, 41.1, -8.7, 41.2)}, {{u"OBJNAM"_s, u"The Bay"_s}}));
    c.features.push_back(area(u"SEAARE"_s, {box(-8.76, 41.13, -8.73, 41.16)}, {{u"OBJNAM"_s, u"The Cove"_s}}));
    c.features.push_back(point(u"WRECKS"_s, -8.72, 41.18, {{u"VALSOU"_s, u"3.5"_s}, {u"OBJNAM"_s, u"Old Hulk"_s}}));
    c.features.push_back(area(u"RESARE"_s, {box(-8.71, 41.1, -8.7, 41.11)}, {{u"OBJNAM"_s, u"Range"_s}}));
    Feature soundings;
    soundings.objectClass = u"SOUNDG"_s;
    soundings.parts = {{{-8.72, 41.17, 7.4}}, {{-8.755, 41.135, 6.1}}};
    c.features.push_back(soundings);
    return c;
}

} // namespace

TEST(Chart, ACellGoesOverAsBytesAndComesBackTheSame)
{
    const Cell before = cell();
    const QByteArray bytes = encodeCell(before);
    const auto after = decodeCell(bytes);
    ASSERT_TRUE(after) << after.error().toStdString();
    EXPECT_EQ(after->name, before.name);
    EXPECT_EQ(after->edition, 3);
    EXPECT_EQ(after->update, 2);
    EXPECT_EQ(after->usageBand, 4);
    EXPECT_EQ(after->scale, 50000);
    ASSERT_EQ(after->features.size(), before.features.size());
    for (std::size_t i = 0; i < before.features.size(); ++i) {
        EXPECT_EQ(after->features[i].objectClass, before.features[i].objectClass);
        EXPECT_EQ(after->features[i].attributes, before.features[i].attributes);
        ASSERT_EQ(after->features[i].parts.size(), before.features[i].parts.size());
        for (std::size_t p = 0; p < before.features[i].parts.size(); ++p)
            for (std::size_t v = 0; v < before.features[i].parts[p].size(); ++v) {
                const Vertex &a = after->features[i].parts[p][v], &b = before.features[i].parts[p][v];
                EXPECT_NEAR(a.lon, b.lon, 1e-7); // a centimetre
                EXPECT_NEAR(a.lat, b.lat, 1e-7);
                EXPECT_NEAR(a.z, b.z, 1e-3);
            }
    }
    EXPECT_EQ(after->counts().value(u"DEPARE"_s), 2);
    const auto bounds = after->bounds();
    ASSERT_TRUE(bounds.valid);
    EXPECT_NEAR(bounds.west, -8.8, 1e-7);
    EXPECT_NEAR(bounds.north, 41.2, 1e-7);
}

TEST(Chart, DamagedBytesAreRefusedSayingWhatIsWrong)
{
    const QByteArray good = encodeCell(cell());
    EXPECT_EQ(decodeCell("NQMESH1\n").error(), u"not a chart cell (it does not start with NQCHART2)"_s);
    // Cut anywhere: an error, never a crash.
    for (qsizetype size = 9; size < good.size(); size += 37)
        EXPECT_FALSE(decodeCell(QByteArrayView(good).first(size))) << size;
    EXPECT_TRUE(decodeCell(good + "x").error().contains(u"1 bytes after the last feature"_s));
    // A count claiming more than there is is refused before anything is made of it.
    QByteArray huge = good;
    const qsizetype featuresAt = 9 + 4 + cell().name.size() + 4 + 4 + 4 + 8 + 4 + 4 + 4;
    huge[featuresAt] = char(0xff);
    huge[featuresAt + 1] = char(0xff);
    huge[featuresAt + 2] = char(0xff);
    huge[featuresAt + 3] = char(0x7f);
    const auto refused = decodeCell(huge);
    ASSERT_FALSE(refused);
    EXPECT_TRUE(refused.error().contains(u"features: 2147483647 claimed"_s)) << refused.error().toStdString();
}

TEST(Chart, WhatTheChartSaysAtAPoint)
{
    const std::vector<Cell> cells{cell()};
    const auto land = reportAt(cells, -8.79, 41.15);
    EXPECT_TRUE(land.covered);
    EXPECT_EQ(land.cell, u"XX4TEST.000"_s);
    EXPECT_TRUE(land.land);

    const auto deep = reportAt(cells, -8.755, 41.135);
    EXPECT_FALSE(deep.land);
    EXPECT_EQ(deep.depthMin, 5);
    EXPECT_EQ(deep.depthMax, 10);
    EXPECT_EQ(deep.place, u"The Cove"_s) << "the smallest named sea area holding it";
    ASSERT_TRUE(deep.sounding);
    EXPECT_NEAR(*deep.sounding, 6.1, 1e-9);
    EXPECT_NEAR(deep.soundingDistance, 0, 1e-6);

    // Inside the shoal: the depth area around it has a hole there.
    const auto shoal = reportAt(cells, -8.745, 41.145);
    EXPECT_EQ(shoal.depthMin, 2);
    EXPECT_EQ(shoal.depthMax, 5);

    // Within 25 m of the wreck (about 17 m east of it), and not at 100 m.
    const auto nearWreck = reportAt(cells, -8.7198, 41.18);
    ASSERT_EQ(nearWreck.hazards.size(), 1u);
    EXPECT_EQ(nearWreck.hazards[0].objectClass, u"WRECKS"_s);
    EXPECT_EQ(nearWreck.hazards[0].name, u"Old Hulk"_s);
    EXPECT_EQ(nearWreck.hazards[0].depth, 3.5);
    EXPECT_NEAR(nearWreck.hazards[0].distance, 16.8, 0.5);
    EXPECT_TRUE(reportAt(cells, -8.7188, 41.18).hazards.empty());
    EXPECT_EQ(reportAt(cells, -8.7188, 41.18, 200).hazards.size(), 1u);

    const auto range = reportAt(cells, -8.705, 41.105);
    ASSERT_EQ(range.restrictions.size(), 1u);
    EXPECT_EQ(range.restrictions[0].name, u"Range"_s);
    EXPECT_TRUE(reportAt(cells, -8.705, 41.115).restrictions.empty());

    EXPECT_FALSE(reportAt(cells, -8.5, 41.15).covered);
}

TEST(Chart, TheBestUsageBandCoveringThePointAnswers)
{
    Cell harbour;
    harbour.name = u"XX5HARB.000"_s;
    harbour.usageBand = 5;
    harbour.features.push_back(area(u"M_COVR"_s, {box(-8.75, 41.14, -8.74, 41.15)}, {{u"CATCOV"_s, u"1"_s}}));
    harbour.features.push_back(area(u"DEPARE"_s, {box(-8.75, 41.14, -8.74, 41.15)}, {{u"DRVAL1"_s, u"3"_s}, {u"DRVAL2"_s, u"4"_s}}));
    const std::vector<Cell> cells{cell(), harbour};
    EXPECT_EQ(reportAt(cells, -8.745, 41.145).cell, u"XX5HARB.000"_s);
    EXPECT_EQ(reportAt(cells, -8.745, 41.145).depthMin, 3);
    EXPECT_EQ(reportAt(cells, -8.76, 41.12).cell, u"XX4TEST.000"_s) << "outside the harbour cell";
    EXPECT_EQ(reportAt(cells, -8.76, 41.12).place, u"The Bay"_s);
}

// Where cells overlap, the best usage band is drawn over the rest: cells in
// band order, overview first, and a lesser cell's point there covered.
TEST(Chart, WhereCellsOverlapTheBestUsageBandIsDrawnOverTheRest)
{
    Cell harbour;
    harbour.name = u"XX5HARB.000"_s;
    harbour.usageBand = 5;
    harbour.features.push_back(area(u"M_COVR"_s, {box(-8.75, 41.14, -8.74, 41.15)}, {{u"CATCOV"_s, u"1"_s}}));
    Cell overview = cell(u"XX1OVER.000"_s, 1);
    harbour.index();
    overview.index();
    const std::vector<Cell> cells{harbour, cell(), overview};
    EXPECT_EQ(drawingOrder(cells), (std::vector<std::size_t>{2, 1, 0}));
    EXPECT_TRUE(coveredByBetter(cells, cells[1], -8.745, 41.145)) << "inside the harbour cell";
    EXPECT_TRUE(coveredByBetter(cells, cells[2], -8.745, 41.145));
    EXPECT_TRUE(coveredByBetter(cells, cells[2], -8.72, 41.18)) << "the overview under the band-4 cell";
    EXPECT_FALSE(coveredByBetter(cells, cells[1], -8.72, 41.18)) << "outside the harbour cell";
    EXPECT_FALSE(coveredByBetter(cells, cells[0], -8.745, 41.145)) << "nothing better than the harbour";
    EXPECT_EQ(bestCellAt(cells, -8.745, 41.145), &cells[0]);
    EXPECT_EQ(bestCellAt(cells, -8.5, 41.145), nullptr);
}

// An aid's colour as drawn, from its COLOUR list as GDAL writes it: the first
// colour (a green-red-green preferred channel buoy is green), red, green and
// yellow apart, the rest (white, black, none said, nonsense) as other aids.
TEST(Chart, AnAidIsDrawnInItsFirstChartedColour)
{
    const auto colour = [](const QString &value) {
        return aidColour(point(u"BOYLAT"_s, 0, 0, value.isNull() ? QMap<QString, QString>{} : QMap<QString, QString>{{u"COLOUR"_s, value}}));
    };
    EXPECT_EQ(colour(u"(1:3)"_s), AidColour::Red);
    EXPECT_EQ(colour(u"(1:4)"_s), AidColour::Green);
    EXPECT_EQ(colour(u"(3:4,3,4)"_s), AidColour::Green);
    EXPECT_EQ(colour(u"(2:6,2)"_s), AidColour::Yellow);
    EXPECT_EQ(colour(u"3"_s), AidColour::Red);
    EXPECT_EQ(colour(u"(1:1)"_s), AidColour::Other);
    EXPECT_EQ(colour(u"(1:2)"_s), AidColour::Other);
    EXPECT_EQ(colour(QString()), AidColour::Other);
    EXPECT_EQ(colour(u"(red)"_s), AidColour::Other);
    EXPECT_EQ(colour(u"(2:3,x)"_s), AidColour::Red) << "the first colour, whatever follows";
    EXPECT_EQ(drawnAs([] { Feature f = point(u"BOYLAT"_s, 0, 0); f.role = roleOf(f); return f; }()), Drawn::Buoy);
    EXPECT_EQ(aidColour(point(u"LIGHTS"_s, 0, 0, {{u"COLOUR"_s, u"(1:1)"_s}})), AidColour::Yellow) << "a white light: yellow, as S-52";
    EXPECT_EQ(colour(u"(2:11,1)"_s), AidColour::Yellow) << "orange (a special purpose buoy's) is drawn yellow";
    EXPECT_EQ(colourName(AidColour::Green), u"green"_s);
    EXPECT_EQ(colourName(AidColour::Other), u"aid"_s);
}

// An aid of several colours in a pattern (S-57's COLPAT) is filled with its
// bands, in COLOUR's order: a preferred channel buoy green-red-green in
// horizontal bands, a safe water buoy red and white in vertical ones.
TEST(Chart, AnAidOfSeveralColoursIsFilledWithItsBands)
{
    const auto bands = [](const QString &colours, const QString &pattern, const QString &objectClass = u"BOYLAT"_s) {
        QMap<QString, QString> attributes{{u"COLOUR"_s, colours}};
        if (!pattern.isNull())
            attributes.insert(u"COLPAT"_s, pattern);
        return aidBands(point(objectClass, 0, 0, attributes));
    };
    EXPECT_EQ(bands(u"(3:4,3,4)"_s, u"(1:1)"_s), (AidBands{ColourPattern::Horizontal, {AidColour::Green, AidColour::Red, AidColour::Green}}));
    EXPECT_EQ(bands(u"(2:3,1)"_s, u"(1:2)"_s, u"BOYSAW"_s), (AidBands{ColourPattern::Vertical, {AidColour::Red, AidColour::Other}}));
    EXPECT_EQ(bands(u"(2:2,6)"_s, u"3"_s)->pattern, ColourPattern::Diagonal);
    EXPECT_EQ(bands(u"(2:1,3)"_s, u"(1:4)"_s)->pattern, ColourPattern::Squared);
    EXPECT_EQ(bands(u"(2:1,11)"_s, u"(1:5)"_s), (AidBands{ColourPattern::Horizontal, {AidColour::Other, AidColour::Yellow}}))
        << "stripes of unknown direction: drawn horizontal; orange: yellow";
    EXPECT_FALSE(bands(u"(2:1,3)"_s, u"(1:6)"_s)) << "a border stripe: the outline alone";
    EXPECT_FALSE(bands(u"(1:3)"_s, u"(1:1)"_s)) << "one colour: no bands";
    EXPECT_FALSE(bands(u"(2:3,4)"_s, QString())) << "no pattern said";
    EXPECT_FALSE(bands(u"(2:3,x)"_s, u"(1:1)"_s)) << "a colour that is no number";
    EXPECT_FALSE(bands(u"(2:3,4)"_s, u"(1:9)"_s)) << "no such pattern";
    EXPECT_FALSE(bands(u"(2:1,3)"_s, u"(1:1)"_s, u"LIGHTS"_s)) << "a light's colours are its sectors', not bands";
    EXPECT_FALSE(bands(u"(2:2,3)"_s, u"(1:1)"_s, u"WRECKS"_s)) << "buoys and beacons only";
    EXPECT_TRUE(bands(u"(3:2,6,2)"_s, u"(1:1)"_s, u"BCNCAR"_s));
    EXPECT_EQ(patternName(ColourPattern::Vertical), u"vertical"_s);
}

// A sector light's sector is drawn from the light: S-57's SECTR1 and SECTR2
// are bearings from seaward towards it, so each is turned half a circle.
TEST(Chart, ASectorLightsSectorIsTurnedToDirectionsFromTheLight)
{
    const auto sector = [](const QString &objectClass, QMap<QString, QString> attributes) {
        return lightSector(point(objectClass, 0, 0, std::move(attributes)));
    };
    const auto across = sector(u"LIGHTS"_s, {{u"SECTR1"_s, u"350"_s}, {u"SECTR2"_s, u"20"_s}});
    ASSERT_TRUE(across);
    EXPECT_DOUBLE_EQ(across->from, 170);
    EXPECT_DOUBLE_EQ(across->to, 200);
    const auto round = sector(u"LIGHTS"_s, {{u"SECTR1"_s, u"200"_s}, {u"SECTR2"_s, u"10"_s}});
    ASSERT_TRUE(round);
    EXPECT_DOUBLE_EQ(round->from, 20);
    EXPECT_DOUBLE_EQ(round->to, 190);
    // Its span clockwise, across north too; the same two limits are a light all round.
    EXPECT_DOUBLE_EQ(across->span(), 30);
    EXPECT_DOUBLE_EQ(round->span(), 170);
    EXPECT_DOUBLE_EQ((LightSector{276.5, 22}.span()), 105.5);
    EXPECT_DOUBLE_EQ((LightSector{40, 40}.span()), 360);
    EXPECT_FALSE(sector(u"LIGHTS"_s, {{u"SECTR1"_s, u"200"_s}})) << "one limit is no sector";
    EXPECT_FALSE(sector(u"LIGHTS"_s, {})) << "an all-round light";
    EXPECT_FALSE(sector(u"LIGHTS"_s, {{u"SECTR1"_s, u"x"_s}, {u"SECTR2"_s, u"10"_s}}));
    EXPECT_FALSE(sector(u"BOYLAT"_s, {{u"SECTR1"_s, u"200"_s}, {u"SECTR2"_s, u"10"_s}})) << "lights only";
}

// Buoys and beacons in their charted shape (BOYSHP, BCNSHP), as paper charts
// draw them; a ring or a triangle when the cell does not say; hazards a cross,
// lights a flare, and no symbol for what is not one.
TEST(Chart, BuoysAndBeaconsAreDrawnInTheirChartedShape)
{
    const auto shape = [](const QString &objectClass, QMap<QString, QString> attributes = {}) {
        Feature f = point(objectClass, 0, 0, std::move(attributes));
        f.role = roleOf(f);
        return shapeOf(f);
    };
    EXPECT_EQ(shape(u"BOYLAT"_s, {{u"BOYSHP"_s, u"1"_s}}), Shape::Conical);
    EXPECT_EQ(shape(u"BOYLAT"_s, {{u"BOYSHP"_s, u"2"_s}}), Shape::Can);
    EXPECT_EQ(shape(u"BOYSPP"_s, {{u"BOYSHP"_s, u"3"_s}}), Shape::Spherical);
    EXPECT_EQ(shape(u"BOYSAW"_s, {{u"BOYSHP"_s, u"4"_s}}), Shape::Pillar);
    EXPECT_EQ(shape(u"BOYSPP"_s, {{u"BOYSHP"_s, u"5"_s}}), Shape::Spar);
    EXPECT_EQ(shape(u"BOYSPP"_s, {{u"BOYSHP"_s, u"6"_s}}), Shape::Barrel);
    EXPECT_EQ(shape(u"BOYSPP"_s, {{u"BOYSHP"_s, u"7"_s}}), Shape::SuperBuoy);
    EXPECT_EQ(shape(u"BOYLAT"_s), Shape::Ring);
    EXPECT_EQ(shape(u"BOYLAT"_s, {{u"BOYSHP"_s, u"8"_s}}), Shape::Ring) << "an ice buoy: no symbol of its own";
    EXPECT_EQ(shape(u"BOYLAT"_s, {{u"BOYSHP"_s, u"nonsense"_s}}), Shape::Ring);
    EXPECT_EQ(shape(u"BCNLAT"_s, {{u"BCNSHP"_s, u"1"_s}}), Shape::Stake);
    EXPECT_EQ(shape(u"BCNLAT"_s, {{u"BCNSHP"_s, u"2"_s}}), Shape::Stake) << "a withy";
    EXPECT_EQ(shape(u"BCNLAT"_s, {{u"BCNSHP"_s, u"3"_s}}), Shape::Tower);
    EXPECT_EQ(shape(u"BCNSPP"_s, {{u"BCNSHP"_s, u"4"_s}}), Shape::Lattice);
    EXPECT_EQ(shape(u"BCNSPP"_s, {{u"BCNSHP"_s, u"5"_s}}), Shape::Pile);
    EXPECT_EQ(shape(u"BCNSPP"_s, {{u"BCNSHP"_s, u"6"_s}}), Shape::Cairn);
    EXPECT_EQ(shape(u"BCNLAT"_s, {{u"BCNSHP"_s, u"7"_s}}), Shape::Triangle) << "a buoyant beacon: no symbol of its own";
    EXPECT_EQ(shape(u"BCNLAT"_s), Shape::Triangle);
    EXPECT_EQ(shape(u"WRECKS"_s), Shape::Cross);
    EXPECT_EQ(shape(u"LIGHTS"_s), Shape::Flare);
    EXPECT_EQ(shape(u"SEAARE"_s), Shape::Nothing);
    EXPECT_EQ(shapeName(Shape::Conical), u"conical"_s);
    EXPECT_EQ(shapeName(Shape::SuperBuoy), u"super-buoy"_s);
}
