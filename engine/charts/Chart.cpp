#include "charts/Chart.h"

#include "geo/Polygon.h"

#include <QtEndian>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <numeric>

namespace neptus::charts {

using namespace Qt::StringLiterals;

namespace {

constexpr char magic[] = "NQCHART2\n";
constexpr qsizetype magicSize = sizeof magic - 1;

bool isArea(const Feature &f) { return f.geometry == Feature::Geometry::Area; }

bool inside(const Feature &area, double lon, double lat)
{
    if (area.west <= area.east && (lon < area.west || lon > area.east || lat < area.south || lat > area.north))
        return false;
    if (area.edges) { // only the edges at this latitude
        const auto &e = *area.edges;
        const auto band = std::floor((lat - e.south) / e.step);
        if (band < 0 || band >= double(e.bands.size()))
            return false;
        bool in = false;
        for (const Feature::Edges::Edge &a : e.bands[std::size_t(band)])
            if ((a.lat0 > lat) != (a.lat1 > lat)
                && (lon < std::min(a.lon0, a.lon1) // wholly east of the point: crossed; else where it crosses
                    || (lon < std::max(a.lon0, a.lon1) && lon < a.lon0 + (lat - a.lat0) * (a.lon1 - a.lon0) / (a.lat1 - a.lat0))))
                in = !in;
        return in;
    }
    bool in = false; // even-odd over all rings: holes and several outer rings alike
    for (const auto &ring : area.parts)
        in ^= geo::insideRing(ring, lon, lat, [](const Vertex &v) { return std::pair{v.lon, v.lat}; });
    return in;
}

// Metres of reach a feature is indexed with: what reportAt looks for around a point at most
// (a hazard within the radius asked; a sounding within 500 m). The smaller a feature's reach,
// the fewer places list it, and the fewer features a point is tested against.
constexpr double indexReach = 100, soundingReach = 500;

// Square degrees inside its outer rings less its holes (shoelace; only to compare sizes).
double areaOf(const Feature &area)
{
    double sum = 0;
    for (const auto &ring : area.parts)
        for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
            sum += ring[j].lon * ring[i].lat - ring[i].lon * ring[j].lat;
    return std::abs(sum) / 2;
}

// Metres between two nearby points (a local plane: well under 1 % off within a few km).
struct Plane
{
    double lon0, lat0, kx, ky;
    explicit Plane(double lon, double lat)
        : lon0(lon), lat0(lat), kx(111320.0 * std::cos(lat * std::numbers::pi / 180)), ky(110574.0)
    {
    }
    std::pair<double, double> xy(const Vertex &v) const { return {(v.lon - lon0) * kx, (v.lat - lat0) * ky}; }
};

double distanceTo(const Plane &plane, const Feature &f)
{
    double best = std::numeric_limits<double>::infinity();
    for (const auto &part : f.parts) {
        for (std::size_t i = 0; i < part.size(); ++i) {
            const auto [x, y] = plane.xy(part[i]);
            if (f.geometry == Feature::Geometry::Point || part.size() == 1) {
                best = std::min(best, x * x + y * y);
                continue;
            }
            if (i == 0)
                continue;
            const auto [ax, ay] = plane.xy(part[i - 1]);
            const double dx = x - ax, dy = y - ay, length2 = dx * dx + dy * dy;
            const double t = length2 > 0 ? std::clamp((-ax * dx - ay * dy) / length2, 0.0, 1.0) : 0;
            const double px = ax + t * dx, py = ay + t * dy;
            best = std::min(best, px * px + py * py);
        }
    }
    return std::sqrt(best); // squared until here: metres from a point, hypot's care for overflow is not needed
}

// Bytes with every count checked against what is left.
class Reader
{
public:
    explicit Reader(QByteArrayView bytes) : m_bytes(bytes) {}
    bool failed() const { return !m_error.isEmpty(); }
    const QString &error() const { return m_error; }
    qsizetype left() const { return m_bytes.size() - m_at; }

    quint32 u32(const char *what)
    {
        if (!take(4, what))
            return 0;
        const quint32 v = qFromLittleEndian<quint32>(m_bytes.data() + m_at - 4);
        return v;
    }
    qint32 i32(const char *what) { return static_cast<qint32>(u32(what)); }
    quint8 u8(const char *what)
    {
        if (!take(1, what))
            return 0;
        return static_cast<quint8>(m_bytes[m_at - 1]);
    }
    QString string(const char *what)
    {
        const quint32 size = u32(what);
        if (failed() || !take(size, what))
            return {};
        return QString::fromUtf8(m_bytes.data() + m_at - size, size);
    }
    // A count of items each at least `minimum` bytes long.
    quint32 count(const char *what, qsizetype minimum)
    {
        const quint32 n = u32(what);
        if (!failed() && qsizetype(n) > left() / minimum)
            fail(u"%1: %2 claimed, more than the %3 bytes left hold"_s.arg(QLatin1StringView(what)).arg(n).arg(left()));
        return failed() ? 0 : n;
    }
    void fail(const QString &why)
    {
        if (m_error.isEmpty())
            m_error = why;
    }

private:
    bool take(qsizetype n, const char *what)
    {
        if (failed())
            return false;
        if (n > left()) {
            fail(u"cut short in %1 (at byte %2)"_s.arg(QLatin1StringView(what)).arg(m_at));
            return false;
        }
        m_at += n;
        return true;
    }
    QByteArrayView m_bytes;
    qsizetype m_at = 0;
    QString m_error;
};

void putU32(QByteArray &out, quint32 v)
{
    char b[4];
    qToLittleEndian(v, b);
    out.append(b, 4);
}
void putString(QByteArray &out, const QString &s)
{
    const QByteArray utf8 = s.toUtf8();
    putU32(out, quint32(utf8.size()));
    out.append(utf8);
}

} // namespace

std::optional<double> Feature::number(const QString &attribute) const
{
    bool ok = false;
    const double v = attributes.value(attribute).toDouble(&ok);
    return ok && std::isfinite(v) ? std::optional(v) : std::nullopt;
}

QMap<QString, int> Cell::counts() const
{
    QMap<QString, int> out;
    for (const Feature &f : features)
        ++out[f.objectClass];
    return out;
}

Cell::Bounds Cell::bounds() const
{
    Bounds b;
    for (const Feature &f : features) {
        if (!isCoverage(f))
            continue;
        for (const auto &ring : f.parts)
            for (const Vertex &v : ring) {
                if (!b.valid) {
                    b = {v.lon, v.lat, v.lon, v.lat, true};
                    continue;
                }
                b.west = std::min(b.west, v.lon);
                b.east = std::max(b.east, v.lon);
                b.south = std::min(b.south, v.lat);
                b.north = std::max(b.north, v.lat);
            }
    }
    return b;
}

void Cell::index()
{
    double west = std::numeric_limits<double>::infinity(), south = west, east = -west, north = -west;
    for (Feature &f : features) {
        f.west = f.south = std::numeric_limits<double>::infinity();
        f.east = f.north = -std::numeric_limits<double>::infinity();
        std::size_t vertices = 0;
        for (const auto &part : f.parts) {
            vertices += part.size();
            for (const Vertex &v : part) {
                f.west = std::min(f.west, v.lon);
                f.east = std::max(f.east, v.lon);
                f.south = std::min(f.south, v.lat);
                f.north = std::max(f.north, v.lat);
            }
        }
        f.role = roleOf(f);
        f.size = f.role == Feature::Role::SeaArea ? areaOf(f) : 0;
        f.shallowest = f.role == Feature::Role::Depth ? f.number(u"DRVAL1"_s)
                     : f.role == Feature::Role::Hazard ? f.number(u"VALSOU"_s) : std::nullopt;
        f.deepest = f.role == Feature::Role::Depth ? f.number(u"DRVAL2"_s) : std::nullopt;
        f.edges.reset();
        if (isArea(f) && vertices > 32 && f.north > f.south) {
            // About 8 edges a band; each edge in every band its latitudes span.
            auto edges = std::make_shared<Feature::Edges>();
            const std::size_t bands = std::clamp<std::size_t>(vertices / 8, 1, 16384);
            edges->south = f.south;
            edges->step = (f.north - f.south) / double(bands) * (1 + 1e-12);
            edges->bands.resize(bands);
            for (std::size_t r = 0; r < f.parts.size(); ++r) {
                const auto &ring = f.parts[r];
                for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
                    const Vertex &a = ring[i], &b = ring[j];
                    const auto first = std::size_t(std::max(0.0, std::floor((std::min(a.lat, b.lat) - edges->south) / edges->step)));
                    const auto last = std::min(bands - 1, std::size_t(std::floor((std::max(a.lat, b.lat) - edges->south) / edges->step)));
                    for (std::size_t band = first; band <= last; ++band)
                        edges->bands[band].push_back({a.lon, a.lat, b.lon, b.lat});
                }
            }
            f.edges = std::move(edges);
        }
        if (f.west <= f.east) {
            west = std::min(west, f.west);
            east = std::max(east, f.east);
            south = std::min(south, f.south);
            north = std::max(north, f.north);
        }
    }
    grid.reset();
    if (!(west < east && south < north))
        return;
    // A grid of about 64 × 64 places over the cell; a feature is listed in every place within reach of its bounds.
    auto g = std::make_shared<Grid>();
    // (Longitude's reach at the cell's latitude furthest from the equator: the widest in degrees.)
    const double poleward = std::max(std::abs(south), std::abs(north));
    const double reachLat = soundingReach / 110574.0,
                 reachLon = soundingReach / (111320.0 * std::max(0.01, std::cos(poleward * std::numbers::pi / 180)));
    g->west = west - reachLon;
    g->south = south - reachLat;
    g->nx = g->ny = 64;
    g->dx = (east + reachLon - g->west) / g->nx;
    g->dy = (north + reachLat - g->south) / g->ny;
    g->buckets.resize(std::size_t(g->nx * g->ny));
    for (std::size_t i = 0; i < features.size(); ++i) {
        const Feature &f = features[i];
        if (f.west > f.east || f.role == Feature::Role::Other)
            continue;
        const double k = f.role == Feature::Role::Sounding ? 1 : indexReach / soundingReach;
        const int x0 = std::clamp(int((f.west - k * reachLon - g->west) / g->dx), 0, g->nx - 1);
        const int x1 = std::clamp(int((f.east + k * reachLon - g->west) / g->dx), 0, g->nx - 1);
        const int y0 = std::clamp(int((f.south - k * reachLat - g->south) / g->dy), 0, g->ny - 1);
        const int y1 = std::clamp(int((f.north + k * reachLat - g->south) / g->dy), 0, g->ny - 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                g->buckets[std::size_t(y * g->nx + x)].push_back({f.west, f.south, f.east, f.north, quint32(i), f.role});
    }
    grid = std::move(g);
}

const QStringList &keptClasses()
{
    static const QStringList classes{
        u"M_COVR"_s, u"LNDARE"_s, u"COALNE"_s, u"SLCONS"_s, u"DEPARE"_s, u"DRGARE"_s, u"DEPCNT"_s, u"SOUNDG"_s,
        u"OBSTRN"_s, u"WRECKS"_s, u"UWTROC"_s, u"RESARE"_s, u"CTNARE"_s, u"MIPARE"_s, u"FAIRWY"_s,
        u"BOYLAT"_s, u"BOYSPP"_s, u"BOYSAW"_s, u"BOYCAR"_s, u"BOYISD"_s, u"BCNLAT"_s, u"BCNSPP"_s, u"BCNCAR"_s,
        u"BCNISD"_s, u"LIGHTS"_s, u"SEAARE"_s};
    return classes;
}

bool isHazard(const QString &c)
{
    return c == u"OBSTRN" || c == u"WRECKS" || c == u"UWTROC";
}

bool isRestriction(const QString &c)
{
    return c == u"RESARE" || c == u"CTNARE" || c == u"MIPARE";
}

bool isCoverage(const Feature &f)
{
    return f.objectClass == u"M_COVR" && isArea(f) && f.attributes.value(u"CATCOV"_s, u"1"_s) == u"1";
}

Feature::Role roleOf(const Feature &f)
{
    using Role = Feature::Role;
    const QString &c = f.objectClass;
    if (isCoverage(f))
        return Role::Coverage;
    if (c == u"LNDARE")
        return isArea(f) ? Role::Land : Role::Other;
    if (c == u"DEPARE" || c == u"DRGARE")
        return isArea(f) ? Role::Depth : Role::Other;
    if (isHazard(c))
        return Role::Hazard;
    if (isRestriction(c))
        return Role::Restriction;
    if (c == u"SEAARE")
        return isArea(f) && !f.name().isEmpty() ? Role::SeaArea : Role::Other;
    if (c == u"SOUNDG")
        return Role::Sounding;
    return Role::Other;
}

QString className(const QString &objectClass)
{
    static const QMap<QString, QString> names{
        {u"M_COVR"_s, u"data coverage"_s}, {u"LNDARE"_s, u"land"_s}, {u"COALNE"_s, u"coastline"_s},
        {u"SLCONS"_s, u"shoreline construction"_s}, {u"DEPARE"_s, u"depth area"_s}, {u"DRGARE"_s, u"dredged area"_s},
        {u"DEPCNT"_s, u"depth contour"_s}, {u"SOUNDG"_s, u"sounding"_s}, {u"OBSTRN"_s, u"obstruction"_s},
        {u"WRECKS"_s, u"wreck"_s}, {u"UWTROC"_s, u"underwater rock"_s}, {u"RESARE"_s, u"restricted area"_s},
        {u"CTNARE"_s, u"caution area"_s}, {u"MIPARE"_s, u"military practice area"_s}, {u"FAIRWY"_s, u"fairway"_s},
        {u"BOYLAT"_s, u"lateral buoy"_s}, {u"BOYSPP"_s, u"special purpose buoy"_s}, {u"BOYSAW"_s, u"safe water buoy"_s},
        {u"BOYCAR"_s, u"cardinal buoy"_s}, {u"BOYISD"_s, u"isolated danger buoy"_s}, {u"BCNLAT"_s, u"lateral beacon"_s},
        {u"BCNSPP"_s, u"special purpose beacon"_s}, {u"BCNCAR"_s, u"cardinal beacon"_s},
        {u"BCNISD"_s, u"isolated danger beacon"_s}, {u"LIGHTS"_s, u"light"_s}, {u"SEAARE"_s, u"sea area"_s}};
    return names.value(objectClass, objectClass);
}

Drawn drawnAs(const Feature &f)
{
    using Role = Feature::Role;
    const QString &k = f.objectClass;
    const bool area = isArea(f);
    if (f.role == Role::Land)
        return Drawn::Land;
    if (f.role == Role::Depth)
        return Drawn::Depth;
    if (f.role == Role::Hazard)
        return Drawn::Hazard;
    if (k == u"DEPCNT")
        return Drawn::Contour;
    if (k == u"COALNE" || k == u"SLCONS")
        return Drawn::Coast;
    if (f.role == Role::Restriction && area)
        return Drawn::Restricted;
    if (k == u"FAIRWY" && area)
        return Drawn::Fairway;
    if (f.geometry == Feature::Geometry::Point) {
        if (k.startsWith(u"BOY"_s))
            return Drawn::Buoy;
        if (k.startsWith(u"BCN"_s))
            return Drawn::Beacon;
        if (k == u"LIGHTS")
            return Drawn::Light;
    }
    return Drawn::Nothing;
}

namespace {

// A list attribute's S-57 codes (COLOUR, COLPAT), up to the first that is no
// number: GDAL writes a list as "(count:a,b,...)"; a plain "3" is taken too.
// `whole` says whether all of them were numbers.
std::vector<int> listCodes(const Feature &f, const QString &attribute, bool *whole = nullptr)
{
    QString text = f.attributes.value(attribute).trimmed();
    if (text.startsWith(u'(') && text.endsWith(u')'))
        text = text.mid(1, text.size() - 2).section(u':', -1);
    std::vector<int> codes;
    bool ok = true;
    for (const QString &part : text.split(u',', Qt::SkipEmptyParts)) {
        const int code = part.trimmed().toInt(&ok);
        if (!ok)
            break;
        codes.push_back(code);
    }
    if (whole)
        *whole = ok;
    return codes;
}

AidColour colourOf(int code, bool light)
{
    switch (code) {
    case 3: return AidColour::Red;
    case 4: return AidColour::Green;
    case 6: case 9: case 11: return AidColour::Yellow; // yellow, amber, orange
    case 1: return light ? AidColour::Yellow : AidColour::Other;
    default: return AidColour::Other;
    }
}

} // namespace

AidColour aidColour(const Feature &f)
{
    const std::vector<int> codes = listCodes(f, u"COLOUR"_s);
    return codes.empty() ? AidColour::Other : colourOf(codes.front(), f.objectClass == u"LIGHTS");
}

std::optional<AidBands> aidBands(const Feature &f)
{
    if (!f.objectClass.startsWith(u"BOY"_s) && !f.objectClass.startsWith(u"BCN"_s)) // buoys and beacons only
        return std::nullopt;
    // COLPAT (a list too; the first is taken): 1 horizontal stripes, 2 vertical, 3 diagonal, 4 squared,
    // 5 stripes of unknown direction, 6 border stripe (S-57's attribute catalogue).
    static constexpr std::optional<ColourPattern> patterns[] = {std::nullopt, ColourPattern::Horizontal, ColourPattern::Vertical,
                                                                ColourPattern::Diagonal, ColourPattern::Squared,
                                                                ColourPattern::Horizontal, std::nullopt};
    const std::vector<int> pattern = listCodes(f, u"COLPAT"_s);
    const int code = pattern.empty() ? 0 : pattern.front();
    bool whole = false;
    const std::vector<int> codes = listCodes(f, u"COLOUR"_s, &whole);
    if (code <= 0 || code >= int(std::size(patterns)) || !patterns[code] || codes.size() < 2 || !whole)
        return std::nullopt;
    AidBands bands{*patterns[code], {}};
    for (const int c : codes)
        bands.colours.push_back(colourOf(c, false));
    return bands;
}

QString patternName(ColourPattern pattern)
{
    static const QString names[] = {u"horizontal"_s, u"vertical"_s, u"diagonal"_s, u"squared"_s};
    return names[int(pattern)];
}

QString colourName(AidColour colour)
{
    static const QString names[] = {u"aid"_s, u"red"_s, u"green"_s, u"yellow"_s};
    return names[int(colour)];
}

std::optional<LightSector> lightSector(const Feature &f)
{
    if (f.objectClass != u"LIGHTS")
        return std::nullopt;
    const auto s1 = f.number(u"SECTR1"_s), s2 = f.number(u"SECTR2"_s);
    if (!s1 || !s2 || !std::isfinite(*s1) || !std::isfinite(*s2))
        return std::nullopt;
    const auto fromLight = [](double bearing) {
        const double d = std::fmod(bearing + 180, 360);
        return d < 0 ? d + 360 : d;
    };
    return LightSector{fromLight(*s1), fromLight(*s2)};
}

Shape shapeOf(const Feature &f)
{
    switch (drawnAs(f)) {
    case Drawn::Hazard:
        return Shape::Cross;
    case Drawn::Light:
        return Shape::Flare;
    case Drawn::Buoy: {
        // BOYSHP: 1 conical, 2 can, 3 spherical, 4 pillar, 5 spar, 6 barrel, 7 super-buoy, 8 ice buoy.
        static constexpr Shape buoys[] = {Shape::Ring, Shape::Conical, Shape::Can, Shape::Spherical, Shape::Pillar,
                                          Shape::Spar, Shape::Barrel, Shape::SuperBuoy};
        const int shape = f.attributes.value(u"BOYSHP"_s).toInt();
        return shape > 0 && shape < int(std::size(buoys)) ? buoys[shape] : Shape::Ring;
    }
    case Drawn::Beacon: {
        // BCNSHP: 1 stake, pole, perch or post, 2 withy, 3 tower, 4 lattice, 5 pile, 6 cairn, 7 buoyant beacon.
        static constexpr Shape beacons[] = {Shape::Triangle, Shape::Stake, Shape::Stake, Shape::Tower, Shape::Lattice, Shape::Pile,
                                            Shape::Cairn};
        const int shape = f.attributes.value(u"BCNSHP"_s).toInt();
        return shape > 0 && shape < int(std::size(beacons)) ? beacons[shape] : Shape::Triangle;
    }
    default:
        return Shape::Nothing;
    }
}

QString shapeName(Shape shape)
{
    static const QString names[] = {QString(), u"cross"_s, u"flare"_s, u"ring"_s, u"conical"_s, u"can"_s, u"spherical"_s,
                                    u"pillar"_s, u"spar"_s, u"barrel"_s, u"super-buoy"_s, u"triangle"_s, u"stake"_s,
                                    u"tower"_s, u"lattice"_s, u"pile"_s, u"cairn"_s};
    return names[std::size_t(shape)];
}

double safetyContour(const std::vector<Cell> &cells, double safetyDepth)
{
    double safety = std::numeric_limits<double>::infinity();
    for (const Cell &c : cells)
        for (const Feature &f : c.features)
            if (f.objectClass == u"DEPCNT")
                if (const auto value = f.number(u"VALDCO"_s); value && *value >= safetyDepth)
                    safety = std::min(safety, *value);
    return std::isfinite(safety) ? safety : safetyDepth;
}

int depthShade(double shallowest, double safetyContour)
{
    return shallowest < 0 ? 0 : shallowest < safetyContour ? 1 : shallowest < 2 * safetyContour ? 2 : 3;
}

QByteArray encodeCell(const Cell &cell)
{
    QByteArray out(magic, magicSize);
    putString(out, cell.name);
    putU32(out, quint32(cell.edition));
    putU32(out, quint32(cell.update));
    putString(out, cell.issued);
    putU32(out, quint32(cell.usageBand));
    putU32(out, quint32(cell.scale));
    putString(out, cell.comment);
    putU32(out, quint32(cell.features.size()));
    for (const Feature &f : cell.features) {
        putString(out, f.objectClass);
        out.append(char(f.geometry));
        putU32(out, quint32(f.attributes.size()));
        for (auto it = f.attributes.cbegin(); it != f.attributes.cend(); ++it) {
            putString(out, it.key());
            putString(out, it.value());
        }
        putU32(out, quint32(f.parts.size()));
        for (const auto &part : f.parts) {
            putU32(out, quint32(part.size()));
            const bool depths = std::any_of(part.begin(), part.end(), [](const Vertex &v) { return v.z != 0; });
            out.append(char(depths));
            for (const Vertex &v : part) {
                putU32(out, quint32(qint32(std::lround(v.lon * 1e7))));
                putU32(out, quint32(qint32(std::lround(v.lat * 1e7))));
                if (depths)
                    putU32(out, quint32(qint32(std::lround(v.z * 1000))));
            }
        }
    }
    return out;
}

std::expected<Cell, QString> decodeCell(QByteArrayView bytes)
{
    if (bytes.size() < magicSize || std::memcmp(bytes.data(), magic, magicSize) != 0)
        return std::unexpected(u"not a chart cell (it does not start with NQCHART2)"_s);
    Reader r(bytes.sliced(magicSize));
    Cell cell;
    cell.name = r.string("the cell's name");
    cell.edition = r.i32("the edition");
    cell.update = r.i32("the update");
    cell.issued = r.string("the issue date");
    cell.usageBand = r.i32("the usage band");
    cell.scale = r.i32("the scale");
    cell.comment = r.string("the comment");
    // Each feature at least: a class (4), a geometry (1), two counts (8).
    const quint32 features = r.count("features", 13);
    cell.features.reserve(std::min<quint32>(features, quint32(r.left() / 64))); // (a Feature is ~110 bytes in memory)
    for (quint32 i = 0; i < features && !r.failed(); ++i) {
        Feature f;
        f.objectClass = r.string("an object class");
        const quint8 geometry = r.u8("a geometry");
        if (geometry < 1 || geometry > 3)
            r.fail(u"feature %1 (%2): geometry %3 is none of point, line, area"_s.arg(i).arg(f.objectClass).arg(geometry));
        f.geometry = Feature::Geometry(geometry);
        const quint32 attributes = r.count("attributes", 8);
        for (quint32 a = 0; a < attributes && !r.failed(); ++a) {
            const QString key = r.string("an attribute's name");
            f.attributes.insert(key, r.string("an attribute's value"));
        }
        const quint32 parts = r.count("parts", 5);
        f.parts.reserve(std::min<quint32>(parts, quint32(r.left() / 64)));
        for (quint32 p = 0; p < parts && !r.failed(); ++p) {
            const quint32 vertices = r.u32("a part's size");
            const bool depths = r.u8("a part's kind") != 0;
            if (!r.failed() && qsizetype(vertices) > r.left() / (depths ? 12 : 8))
                r.fail(u"feature %1 (%2): %3 vertices claimed, more than the bytes left hold"_s.arg(i).arg(f.objectClass).arg(vertices));
            std::vector<Vertex> part;
            part.reserve(r.failed() ? 0 : vertices);
            for (quint32 v = 0; v < vertices && !r.failed(); ++v) {
                Vertex x{r.i32("a longitude") / 1e7, r.i32("a latitude") / 1e7, depths ? r.i32("a depth") / 1000.0 : 0};
                if (!r.failed() && (std::abs(x.lon) > 180 || std::abs(x.lat) > 90))
                    r.fail(u"feature %1 (%2): a vertex is not a position (%3, %4)"_s.arg(i).arg(f.objectClass).arg(x.lon).arg(x.lat));
                part.push_back(x);
            }
            f.parts.push_back(std::move(part));
        }
        cell.features.push_back(std::move(f));
    }
    if (r.failed())
        return std::unexpected(r.error());
    if (r.left() != 0)
        return std::unexpected(u"%1 bytes after the last feature"_s.arg(r.left()));
    cell.index();
    return cell;
}

bool Cell::covers(double lon, double lat) const
{
    if (!grid) {
        for (const Feature &f : features)
            if ((f.west > f.east ? roleOf(f) : f.role) == Feature::Role::Coverage && inside(f, lon, lat))
                return true;
        return false;
    }
    for (const Grid::Candidate &k : grid->at(lon, lat))
        if (k.role == Feature::Role::Coverage && lon >= k.west && lon <= k.east && lat >= k.south && lat <= k.north
            && inside(features[k.feature], lon, lat))
            return true;
    return false;
}

const Cell *bestCellAt(const std::vector<Cell> &cells, double lon, double lat)
{
    const Cell *best = nullptr;
    for (const Cell &c : cells)
        if ((!best || c.usageBand > best->usageBand) && c.covers(lon, lat))
            best = &c;
    return best;
}

std::vector<std::size_t> drawingOrder(const std::vector<Cell> &cells)
{
    std::vector<std::size_t> order(cells.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cells[a].usageBand < cells[b].usageBand; });
    return order;
}

bool coveredByBetter(const std::vector<Cell> &cells, const Cell &cell, double lon, double lat)
{
    for (const Cell &c : cells)
        if (c.usageBand > cell.usageBand && c.covers(lon, lat))
            return true;
    return false;
}

PointReport reportAt(const std::vector<Cell> &cells, double lon, double lat, double radius, bool soundings)
{
    // Features whose bounds, grown by the radius (or the 500 m a sounding is looked for), miss the point are skipped.
    const double reach = std::max(radius, soundings ? 500.0 : 0.0);
    const double dLat = reach / 110574.0, dLon = reach / (111320.0 * std::max(0.01, std::cos(lat * std::numbers::pi / 180)));
    using Role = Feature::Role;
    PointReport report;
    // visit(feature, its role, its index) for the features of a cell whose role `wanted` takes and
    // whose bounds, grown by `grow` (× dLon, dLat), hold the point: those the cell's grid lists at the
    // point, filtered on the grid's copy of their role and bounds; all, when the cell is not indexed.
    const auto forEach = [&](const Cell &c, const auto &wanted, double grow, const auto &visit) {
        const double gLon = grow * dLon, gLat = grow * dLat;
        if (!c.grid || radius > indexReach) {
            for (std::size_t i = 0; i < c.features.size(); ++i) {
                const Feature &f = c.features[i];
                const Role role = f.west > f.east ? roleOf(f) : f.role;
                if (wanted(role) && (f.west > f.east || (lon >= f.west - gLon && lon <= f.east + gLon && lat >= f.south - gLat
                                                         && lat <= f.north + gLat)))
                    visit(f, role, i);
            }
            return;
        }
        for (const Cell::Grid::Candidate &k : c.grid->at(lon, lat))
            if (wanted(k.role) && lon >= k.west - gLon && lon <= k.east + gLon && lat >= k.south - gLat && lat <= k.north + gLat)
                visit(c.features[k.feature], k.role, std::size_t(k.feature));
    };
    const Cell *best = bestCellAt(cells, lon, lat);
    if (!best)
        return report;
    report.covered = true;
    report.cell = best->name;
    const Plane plane(lon, lat);
    double placeSize = 0;
    const auto wanted = [soundings](Role role) {
        return role != Role::Other && role != Role::Coverage && (role != Role::Sounding || soundings);
    };
    forEach(*best, wanted, 1, [&](const Feature &f, Role role, std::size_t index) {
        switch (role) {
        case Role::Land:
            report.land = report.land || inside(f, lon, lat);
            break;
        case Role::Depth: {
            const bool indexed = f.west <= f.east;
            const auto lo = indexed ? f.shallowest : f.number(u"DRVAL1"_s);
            // (One no shallower than the one found already would change nothing: not tested.)
            if (lo && (!report.depthMin || *lo < *report.depthMin) && inside(f, lon, lat)) {
                report.depthMin = lo;
                report.depthMax = indexed ? f.deepest : f.number(u"DRVAL2"_s);
                report.depthArea = f.name();
            }
            break;
        }
        case Role::Hazard:
        case Role::Restriction: {
            // A restricted area counts only inside it (no distance to its edges worked out);
            // a hazard, area or not, within the radius.
            const bool area = isArea(f);
            if (area && role == Role::Restriction && !inside(f, lon, lat))
                break;
            const double d = area && inside(f, lon, lat) ? 0 : distanceTo(plane, f);
            if (d <= (area && role == Role::Restriction ? 0 : radius))
                (role == Role::Hazard ? report.hazards : report.restrictions)
                    .push_back({f.objectClass, f.name(), role == Role::Hazard ? (f.west <= f.east ? f.shallowest : f.number(u"VALSOU"_s)) : std::nullopt, d, index});
            break;
        }
        case Role::SeaArea:
            if (inside(f, lon, lat)) {
                const double size = f.west <= f.east ? f.size : areaOf(f);
                if (report.place.isEmpty() || size < placeSize) {
                    report.place = f.name();
                    placeSize = size;
                }
            }
            break;
        case Role::Sounding:
            for (const auto &part : f.parts)
                for (const Vertex &v : part) {
                    const auto [x, y] = plane.xy(v);
                    const double d = std::hypot(x, y);
                    if (d <= 500 && (!report.sounding || d < report.soundingDistance)) {
                        report.sounding = v.z;
                        report.soundingDistance = d;
                    }
                }
            break;
        case Role::Other:
        case Role::Coverage:
            break;
        }
    });
    return report;
}

} // namespace neptus::charts
