#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <QMap>
#include <QString>
#include <QStringList>

#include <cmath>
#include <expected>
#include <memory>
#include <optional>
#include <vector>

// Nautical charts (IHO S-57 ENC cells) as the console keeps them: the
// features that matter for drawing a chart under the vehicles and checking a
// plan against it, read from a cell by the neptus-chart-import helper (GDAL's
// S-57 driver, updates applied) and handed over, and cached, as bytes.
// Coordinates are WGS84 degrees; depths metres (positive down, as S-57).
namespace neptus::charts {

struct Vertex
{
    double lon = 0, lat = 0;
    double z = 0; // a sounding's depth; 0 elsewhere
};

struct Feature
{
    enum class Geometry : quint8 { Point = 1, Line = 2, Area = 3 };
    // What reportAt() asks of it, worked out from its class by Cell::index()
    // (a plan check asks every feature near each of ten thousand points:
    // comparing class names there was most of its time).
    enum class Role : quint8 { Other, Coverage, Land, Depth, Hazard, Restriction, SeaArea, Sounding };

    QString objectClass; // S-57 acronym: DEPARE, LNDARE, WRECKS, ...
    Geometry geometry = Geometry::Point;
    // Points: one each (many for a sounding group); lines: polylines; areas:
    // rings (outer and holes alike: inside is decided by the even-odd rule).
    std::vector<std::vector<Vertex>> parts;
    // Its S-57 attributes by acronym, as text (DRVAL1 "1.8", OBJNAM "Eastern Bay").
    QMap<QString, QString> attributes;

    std::optional<double> number(const QString &attribute) const;
    QString name() const { return attributes.value(QStringLiteral("OBJNAM")); }

    // Its bounds, once Cell::index() has run (west > east until then: every point is tested).
    double west = 1, south = 0, east = 0, north = 0;
    Role role = Role::Other; // Cell::index()
    double size = 0;          // a named sea area's, in square degrees (Cell::index())
    // Depth areas' DRVAL1 and DRVAL2, hazards' VALSOU as `shallowest` (Cell::index()).
    std::optional<double> shallowest, deepest;
    // An area's edges by band of latitude (Cell::index()), so that a point is
    // tested against the few edges at its latitude, not all of a coastline's.
    struct Edges
    {
        double south = 0, step = 1;
        // Each edge's ends (longitude, latitude), copied: the few a point is
        // tested against lie together in memory.
        struct Edge
        {
            double lon0, lat0, lon1, lat1;
        };
        std::vector<std::vector<Edge>> bands;
    };
    std::shared_ptr<const Edges> edges;
};

struct Cell
{
    QString name;         // DSNM: US4MD81M.000
    int edition = 0;      // EDTN
    int update = 0;       // UPDN: the last update applied
    QString issued;       // ISDT of the last update (YYYYMMDD)
    // `issued` as YYYY-MM-DD (as it is when it is not eight digits).
    QString issuedDate() const
    {
        return issued.size() == 8 ? issued.left(4) + u'-' + issued.mid(4, 2) + u'-' + issued.mid(6, 2) : issued;
    }
    int usageBand = 0;    // INTU: 1 overview … 6 berthing
    int scale = 0;        // DSPM CSCL: compilation scale, 1:scale
    QString comment;      // DSID COMT
    std::vector<Feature> features;

    // How many features of each object class.
    QMap<QString, int> counts() const;
    // The bounds of its data coverage (M_COVR with CATCOV 1).
    struct Bounds
    {
        double west = 0, south = 0, east = 0, north = 0;
        bool valid = false;
    };
    Bounds bounds() const;
    // Works out each feature's bounds and a grid of which features are near
    // each place (hazards and areas within 100 m, soundings 500 m), so that reportAt() tests a point only against
    // those (decodeCell does it; a cell changed after must be indexed again).
    void index();
    // Whether its data coverage (M_COVR with CATCOV 1) holds the point.
    bool covers(double lon, double lat) const;
    struct Grid
    {
        double west = 0, south = 0, dx = 1, dy = 1;
        int nx = 0, ny = 0;
        // A feature near a place, with what reportAt() filters on first (its
        // role and bounds), so that the many it skips are never read whole.
        struct Candidate
        {
            double west, south, east, north;
            quint32 feature; // index in features
            Feature::Role role;
        };
        std::vector<std::vector<Candidate>> buckets; // nx × ny; features of role Other left out
        // The candidates near a point (empty outside the grid).
        const std::vector<Candidate> &at(double lon, double lat) const
        {
            static const std::vector<Candidate> none;
            const int x = int(std::floor((lon - west) / dx)), y = int(std::floor((lat - south) / dy));
            return x < 0 || y < 0 || x >= nx || y >= ny ? none : buckets[std::size_t(y * nx + x)];
        }
    };
    std::shared_ptr<const Grid> grid;
};

// The object classes the helper keeps (everything else in a cell is left there).
const QStringList &keptClasses();
// Obstructions, wrecks and underwater rocks; restricted, caution and military
// practice areas; data coverage (M_COVR with CATCOV 1).
bool isHazard(const QString &objectClass);
bool isRestriction(const QString &objectClass);
bool isCoverage(const Feature &feature);
Feature::Role roleOf(const Feature &feature);
// An object class in words ("depth area", "wreck"); the acronym when unknown.
QString className(const QString &objectClass);

// How a chart is drawn, the same on the console's map and the live web page:
// land and depth areas filled, depth contours, the coastline, restricted
// areas' and fairways' edges, and hazards, buoys, beacons and lights as
// symbols (an area or line hazard at its first point). Needs the role
// Cell::index() works out.
enum class Drawn : quint8 { Nothing, Land, Depth, Contour, Coast, Restricted, Fairway, Hazard, Buoy, Beacon, Light };
Drawn drawnAs(const Feature &feature);
// An aid's colour as it is drawn: the first of its COLOUR attribute's S-57
// colours ("(1:3)" red, "(3:4,3,4)" green with bands), what matters at a
// glance (port and starboard, a yellow special mark; a white light yellow,
// as S-52 draws it); Other for the rest (white, black, none said), drawn in
// the chart's aid colour.
enum class AidColour : quint8 { Other, Red, Green, Yellow };
AidColour aidColour(const Feature &feature);
// Its name in the page's JSON ("red", "green", "yellow"; "aid" for Other).
QString colourName(AidColour colour);
// A buoy or beacon of several colours in a pattern (COLPAT, with two or more
// COLOUR values), as S-52 fills its symbol: the colours in COLOUR's order, top
// to bottom (horizontal bands), left to right (vertical), from the upper left
// (diagonal), or in quarters (squared, two colours alternating). S-57's
// "stripes, direction unknown" are drawn horizontal; a border stripe is not
// banded (its outline alone). Orange and amber are drawn yellow, white and
// black in the aid colour, as aidColour()'s.
enum class ColourPattern : quint8 { Horizontal, Vertical, Diagonal, Squared };
struct AidBands
{
    ColourPattern pattern;
    std::vector<AidColour> colours;
    bool operator==(const AidBands &) const = default;
};
std::optional<AidBands> aidBands(const Feature &feature);
// Its name in the page's JSON ("horizontal", "vertical", "diagonal", "squared").
QString patternName(ColourPattern pattern);
// A sector light's sector, as directions from the light (degrees true): it
// shows from `from` clockwise to `to`. S-57 gives SECTR1 and SECTR2 as
// bearings from seaward towards the light, so each is turned half a circle.
struct LightSector
{
    double from = 0, to = 0;
    // Degrees clockwise from `from` to `to`: 360 for a light all round (the two limits the same).
    double span() const { return to > from ? to - from : to + 360 - from; }
};
std::optional<LightSector> lightSector(const Feature &feature);
// A symbol's shape, as paper charts draw it (INT 1's simplified symbols):
// buoys by BOYSHP (conical, can, spherical, pillar, spar, barrel, super-buoy;
// a ring when not said), beacons by BCNSHP (stake or withy, tower, lattice,
// pile, cairn; a triangle when not said), hazards a cross, lights a flare (a
// teardrop from the light, away to the lower right, beside a buoy's shape).
// Nothing for a feature drawnAs() draws no symbol for.
enum class Shape : quint8 { Nothing, Cross, Flare, Ring, Conical, Can, Spherical, Pillar, Spar, Barrel, SuperBuoy,
                            Triangle, Stake, Tower, Lattice, Pile, Cairn };
Shape shapeOf(const Feature &feature);
// Its name in the page's JSON ("cross", "flare", "conical", "can", …; "" for Nothing).
QString shapeName(Shape shape);
// The safety contour (S-52's idea): the first charted depth contour (DEPCNT's
// VALDCO) at or past the safety depth; the safety depth when there is none.
double safetyContour(const std::vector<Cell> &cells, double safetyDepth);
// A depth area's shade by its shallowest depth: 0 drying, 1 shallower than the
// safety contour (it stands out), 2 up to twice it (our choice), 3 deeper.
int depthShade(double shallowest, double safetyContour);

// A cell as bytes, as the helper writes it and the cache keeps it:
//   "NQCHART2\n", then counted strings and numbers (little-endian; positions
//   in 1e-7 degrees, about a centimetre; depths in millimetres, only for parts
//   that have them); reading checks every count against the bytes left, so
//   damaged bytes are an error naming what was wrong, never a crash or an
//   allocation of what they claim.
QByteArray encodeCell(const Cell &cell);
std::expected<Cell, QString> decodeCell(QByteArrayView bytes);

// What the charts say at a point.
struct PointReport
{
    bool covered = false;   // some cell's data coverage holds it
    QString cell;           // the cell answering (the best usage band covering it)
    bool land = false;      // inside a land area
    // Depth area (DEPARE, DRGARE) there: its range, shallowest first.
    std::optional<double> depthMin, depthMax;
    QString depthArea;      // its name, if it has one
    QString place;          // the named sea area (SEAARE) there, the smallest holding it
    // Hazards (obstructions, wrecks, rocks) and restricted areas (restricted,
    // caution, military practice) at the point: within `radius` of a point
    // hazard, inside an area one.
    struct Found
    {
        QString objectClass;
        QString name;
        std::optional<double> depth; // VALSOU, where charted
        double distance = 0;         // metres from the point (0 inside an area)
        std::size_t feature = 0;     // its index in the cell's features (which one, when several say the same)
    };
    std::vector<Found> hazards, restrictions;
    // The nearest sounding within 500 m.
    std::optional<double> sounding;
    double soundingDistance = 0;
};

// The cell with the best usage band (the largest scale) whose data coverage
// holds the point; null when none does.
const Cell *bestCellAt(const std::vector<Cell> &cells, double lon, double lat);
// Where cells overlap, the best usage band is what is drawn (S-52's idea, as
// chart plotters quilt): the cells' indices by usage band, overview first, so
// that drawn in this order the best band covers the others; and whether a
// cell of a better band than `cell` covers a point (a symbol or sounding of
// `cell` there is left out: the better cell's own are drawn).
std::vector<std::size_t> drawingOrder(const std::vector<Cell> &cells);
bool coveredByBetter(const std::vector<Cell> &cells, const Cell &cell, double lon, double lat);

// `soundings`: look for the nearest sounding (a plan check does not).
PointReport reportAt(const std::vector<Cell> &cells, double lon, double lat, double radius = 25, bool soundings = true);

} // namespace neptus::charts
