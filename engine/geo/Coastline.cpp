#include "Coastline.h"
#include "Polygon.h"

#include <QDir>
#include <QFileInfo>
#include <QMutex>
#include <QMutexLocker>

#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace neptus::geo {

namespace {

// libnetcdf (and the HDF5 under it) is not thread-safe: one call at a time.
QMutex netcdfLock;

constexpr int maxDelta = 65535; // bin-relative coordinates run 0..65535 across a bin

struct Failure
{
    QString what;
};

} // namespace

struct Coastline::File
{
    QString path;
    QString error; // why it cannot be read ("" when it can)
    int id = -1;
    int binMinutes = 0, columns = 0, rows = 0, bins = 0, segments = 0, points = 0;
    int segInfoVar = -1, segStartVar = -1, antVar = -1, dxVar = -1, dyVar = -1;
    std::vector<int> binFirstSegment;
    std::vector<short> binNodes, binSegments;

    ~File()
    {
        if (id >= 0)
            nc_close(id);
    }

    void check(int status, const char *what) const
    {
        if (status != NC_NOERR)
            throw Failure{QStringLiteral("%1: %2: %3").arg(path, QLatin1String(what), QString::fromUtf8(nc_strerror(status)))};
    }
    [[noreturn]] void damaged(const QString &what) const
    {
        throw Failure{QStringLiteral("%1: not a GSHHG binned shoreline file: %2").arg(path, what)};
    }
    int variable(const char *name) const
    {
        int var = -1;
        check(nc_inq_varid(id, name, &var), name);
        return var;
    }
    size_t length(int var, const char *name) const
    {
        int dims = 0;
        check(nc_inq_varndims(id, var, &dims), name);
        if (dims != 1)
            damaged(QStringLiteral("%1 has %2 dimensions, not 1").arg(QLatin1String(name)).arg(dims));
        int dim = -1;
        size_t n = 0;
        check(nc_inq_vardimid(id, var, &dim), name);
        check(nc_inq_dimlen(id, dim, &n), name);
        return n;
    }
    int scalar(const char *name) const
    {
        int value = 0;
        const size_t at = 0;
        check(nc_get_var1_int(id, variable(name), &at, &value), name);
        return value;
    }
    template <typename T>
    std::vector<T> range(int var, size_t first, size_t count, const char *name) const
    {
        std::vector<T> values(count);
        if (count == 0)
            return values;
        int status = NC_NOERR;
        if constexpr (std::is_same_v<T, int>)
            status = nc_get_vara_int(id, var, &first, &count, values.data());
        else if constexpr (std::is_same_v<T, short>)
            status = nc_get_vara_short(id, var, &first, &count, values.data());
        else
            status = nc_get_vara_schar(id, var, &first, &count, values.data());
        check(status, name);
        return values;
    }

    void open()
    {
        check(nc_open(QFile::encodeName(path).constData(), NC_NOWRITE, &id), "cannot open");
        binMinutes = scalar("Bin_size_in_minutes");
        columns = scalar("N_bins_in_360_longitude_range");
        rows = scalar("N_bins_in_180_degree_latitude_range");
        bins = scalar("N_bins_in_file");
        segments = scalar("N_segments_in_file");
        points = scalar("N_points_in_file");
        if (binMinutes <= 0 || columns * binMinutes != 360 * 60 || rows * binMinutes != 180 * 60 || bins != columns * rows
            || segments < 0 || points < 0)
            damaged(QStringLiteral("bins of %1′ do not make %2 × %3 = %4").arg(binMinutes).arg(columns).arg(rows).arg(bins));
        const int firstVar = variable("Id_of_first_segment_in_a_bin"), nodesVar = variable("Embedded_node_levels_in_a_bin"),
                  countVar = variable("N_segments_in_a_bin");
        segInfoVar = variable("Embedded_npts_levels_exit_entry_for_a_segment");
        segStartVar = variable("Id_of_first_point_in_a_segment");
        dxVar = variable("Relative_longitude_from_SW_corner_of_bin");
        dyVar = variable("Relative_latitude_from_SW_corner_of_bin");
        // GSHHG 2.3 has two Antarcticas (ice front, grounding line): the flag
        // marks the ice front's pieces, drawn as land; older files lack it.
        if (nc_inq_varid(id, "Embedded_ANT_flag", &antVar) != NC_NOERR)
            antVar = -1;
        const auto need = [this](int var, size_t n, const char *name) {
            if (length(var, name) < n)
                damaged(QStringLiteral("%1 holds %2 values, fewer than %3").arg(QLatin1String(name)).arg(length(var, name)).arg(n));
        };
        need(firstVar, size_t(bins), "Id_of_first_segment_in_a_bin");
        need(nodesVar, size_t(bins), "Embedded_node_levels_in_a_bin");
        need(countVar, size_t(bins), "N_segments_in_a_bin");
        need(segInfoVar, size_t(segments), "Embedded_npts_levels_exit_entry_for_a_segment");
        need(segStartVar, size_t(segments), "Id_of_first_point_in_a_segment");
        if (antVar >= 0)
            need(antVar, size_t(segments), "Embedded_ANT_flag");
        need(dxVar, size_t(points), "Relative_longitude_from_SW_corner_of_bin");
        need(dyVar, size_t(points), "Relative_latitude_from_SW_corner_of_bin");
        binFirstSegment = range<int>(firstVar, 0, size_t(bins), "Id_of_first_segment_in_a_bin");
        binNodes = range<short>(nodesVar, 0, size_t(bins), "Embedded_node_levels_in_a_bin");
        binSegments = range<short>(countVar, 0, size_t(bins), "N_segments_in_a_bin");
        for (int b = 0; b < bins; ++b) {
            if (binSegments[b] < 0 || binFirstSegment[b] < 0 || int64_t(binFirstSegment[b]) + binSegments[b] > segments)
                damaged(QStringLiteral("bin %1 names segments %2 to %3 of %4")
                            .arg(b).arg(binFirstSegment[b]).arg(int64_t(binFirstSegment[b]) + binSegments[b]).arg(segments));
        }
    }
};

namespace {

struct Piece
{
    std::vector<LonLat> points;
    int level = 0;
    int entry = 4, exit = 4; // side 0 south, 1 east, 2 north, 3 west; 4 none (closed inside the bin)
    double in = 0, out = 0;  // where it enters and leaves, counter-clockwise round the bin's sides, in sides (0..4)
};

// Where a point on `side` lies round the bin, counter-clockwise from the
// south-west corner, in sides.
double around(int side, int x, int y)
{
    switch (side) {
    case 0: return x / double(maxDelta);
    case 1: return 1 + y / double(maxDelta);
    case 2: return 2 + (maxDelta - x) / double(maxDelta);
    default: return 3 + (maxDelta - y) / double(maxDelta);
    }
}

// One bin's rings: each level's pieces that cross the bin joined along its
// sides, the closed ones as they are, and the whole bin when what lies
// outside every piece is land. GSHHG keeps land on the left of every piece,
// so a ring of land (odd level) goes on counter-clockwise round the bin from
// where one piece leaves to where the next of its level enters, and a ring
// of water in land (even level) clockwise: either way a level's ring holds
// that level, and the levels nest.
void closeRings(std::vector<Piece> &pieces, const std::array<LonLat, 4> &corners, int outside, CoastArea &area)
{
    const auto closed = [](std::vector<LonLat> ring) {
        if (ring.size() > 1 && (ring.front().lon != ring.back().lon || ring.front().lat != ring.back().lat))
            ring.push_back(ring.front());
        return ring;
    };
    std::map<int, std::vector<size_t>> crossing; // level -> pieces
    for (size_t i = 0; i < pieces.size(); ++i) {
        if (pieces[i].entry == 4 || pieces[i].exit == 4)
            area.rings.push_back(closed(pieces[i].points));
        else
            crossing[pieces[i].level].push_back(i);
    }
    for (auto &[level, ids] : crossing) {
        std::vector<bool> used(ids.size(), false);
        const bool ccw = level % 2 == 1;
        for (size_t start = 0; start < ids.size(); ++start) {
            if (used[start])
                continue;
            std::vector<LonLat> ring;
            size_t at = start;
            for (size_t step = 0; step <= ids.size(); ++step) {
                const Piece &p = pieces[ids[at]];
                ring.insert(ring.end(), p.points.begin(), p.points.end());
                used[at] = true;
                // The next piece of this level entering after this one leaves.
                size_t next = start;
                double best = std::numeric_limits<double>::max();
                for (size_t j = 0; j < ids.size(); ++j) {
                    if (used[j] && j != start)
                        continue;
                    const double d = std::fmod(ccw ? pieces[ids[j]].in - p.out + 8 : p.out - pieces[ids[j]].in + 8, 4.0);
                    if (d < best) {
                        best = d;
                        next = j;
                    }
                }
                if (ccw) {
                    for (double corner = std::floor(p.out) + 1; corner < p.out + best; corner += 1)
                        ring.push_back(corners[size_t(int(corner) % 4)]);
                } else {
                    for (double corner = std::ceil(p.out) - 1; corner > p.out - best; corner -= 1)
                        ring.push_back(corners[size_t((int(corner) + 8) % 4)]);
                }
                if (next == start)
                    break;
                at = next;
            }
            area.rings.push_back(closed(std::move(ring)));
        }
    }
    if (outside % 2 == 1)
        area.rings.push_back({corners[0], corners[1], corners[2], corners[3], corners[0]});
}

} // namespace

size_t CoastArea::pointCount() const
{
    size_t n = 0;
    for (const auto &s : shores)
        n += s.size();
    return n;
}

bool CoastArea::isLand(double lat, double lon) const
{
    // Even-odd over all the rings together: a lake's ring inside land's undoes it.
    bool inside = false;
    for (const auto &ring : rings)
        inside ^= insideRing(ring, lon, lat, [](const LonLat &p) { return std::pair(p.lon, p.lat); });
    return inside;
}

QString Coastline::defaultDirectory()
{
    const QString set = qEnvironmentVariable("NEPTUS_GSHHG_DIR");
    return set.isEmpty() ? QStringLiteral("/usr/share/gmt-gshhg") : set;
}

Coastline::Coastline(QString directory) : m_directory(std::move(directory))
{
    // Looked for once: the map asks which resolution to use on every frame it moves.
    for (char r : resolutions) {
        if (QFileInfo::exists(filePath(r)))
            m_available += QLatin1Char(r);
    }
}

QString Coastline::filePath(char resolution) const
{
    return QDir(m_directory).filePath(QStringLiteral("binned_GSHHS_%1.nc").arg(QLatin1Char(resolution)));
}

Coastline::~Coastline()
{
    QMutexLocker lock(&netcdfLock);
    for (auto &f : m_files)
        f.reset();
}

char Coastline::resolutionFor(double metresPerPixel) const
{
    // The coarsest whose points are at most three pixels apart: finer only
    // adds points the same pixels draw.
    static constexpr std::array<double, 5> spacing{25000, 5000, 1000, 200, 40};
    const QString &have = m_available;
    char best = 0;
    for (size_t i = 0; i < resolutions.size(); ++i) {
        if (!have.contains(QLatin1Char(resolutions[i])))
            continue;
        best = resolutions[i];
        if (spacing[i] <= 3 * metresPerPixel)
            break;
    }
    return best;
}

CoastArea Coastline::read(char resolution, double west, double south, double east, double north, QString *error) const
{
    CoastArea area;
    area.resolution = resolution;
    const auto index = std::find(resolutions.begin(), resolutions.end(), resolution) - resolutions.begin();
    QMutexLocker lock(&netcdfLock);
    try {
        if (index >= int(resolutions.size()))
            throw Failure{QStringLiteral("no GSHHG resolution '%1' (c, l, i, h or f)").arg(QLatin1Char(resolution))};
        auto &file = m_files[size_t(index)];
        if (!file) {
            file = std::make_unique<File>();
            file->path = filePath(resolution);
            if (!QFileInfo::exists(file->path))
                file->error = QStringLiteral("%1: no such file (Debian's gmt-gshhg packages install it)").arg(file->path);
            else {
                try {
                    file->open();
                } catch (const Failure &f) {
                    file->error = f.what;
                }
            }
        }
        const File &f = *file;
        if (!f.error.isEmpty())
            throw Failure{f.error};
        if (!(std::isfinite(west) && std::isfinite(east) && std::isfinite(south) && std::isfinite(north)) || east < west || north < south)
            throw Failure{QStringLiteral("not an area: %1..%2 E, %3..%4 N").arg(west).arg(east).arg(south).arg(north)};

        const double size = f.binMinutes / 60.0, scale = size / maxDelta;
        const int firstColumn = int(std::floor(west / size));
        const int lastColumn = std::min(int(std::ceil(east / size)) - 1, firstColumn + f.columns - 1);
        const int topRow = std::max(0, int(std::floor((90 - std::min(north, 90.0)) / size)));
        const int bottomRow = std::min(f.rows - 1, int(std::ceil((90 - std::max(south, -90.0)) / size)) - 1);
        for (int row = topRow; row <= bottomRow; ++row) {
            // The segments and points of this row's bins, each read at once.
            std::vector<int> columnBins;
            int segLo = f.segments, segHi = 0;
            for (int c = firstColumn; c <= lastColumn; ++c) {
                const int b = row * f.columns + ((c % f.columns) + f.columns) % f.columns;
                columnBins.push_back(b);
                if (f.binSegments[b] > 0) {
                    segLo = std::min(segLo, f.binFirstSegment[b]);
                    segHi = std::max(segHi, f.binFirstSegment[b] + f.binSegments[b]);
                }
            }
            area.binCount += int(columnBins.size());
            if (segHi <= segLo) {
                // No shore in the row: land or water whole, as its corners say.
                for (size_t k = 0; k < columnBins.size(); ++k) {
                    const int b = columnBins[k];
                    if (((f.binNodes[b] >> 9) & 7) % 2 == 1) {
                        const double w = (firstColumn + int(k)) * size, s = 90 - (row + 1) * size;
                        area.rings.push_back({{w, s}, {w + size, s}, {w + size, s + size}, {w, s + size}, {w, s}});
                    }
                }
                continue;
            }
            const auto info = f.range<int>(f.segInfoVar, size_t(segLo), size_t(segHi - segLo), "segment information");
            const auto starts = f.range<int>(f.segStartVar, size_t(segLo), size_t(segHi - segLo), "segment starts");
            const auto ant = f.antVar >= 0 ? f.range<signed char>(f.antVar, size_t(segLo), size_t(segHi - segLo), "Antarctica flags")
                                           : std::vector<signed char>();
            int64_t ptLo = f.points, ptHi = 0;
            for (size_t s = 0; s < info.size(); ++s) {
                const int64_t n = int64_t(uint32_t(info[s]) >> 9);
                if (starts[s] < 0 || n < 2 || starts[s] + n > f.points)
                    f.damaged(QStringLiteral("segment %1 names points %2 to %3 of %4").arg(segLo + int(s)).arg(starts[s]).arg(starts[s] + n).arg(f.points));
                ptLo = std::min<int64_t>(ptLo, starts[s]);
                ptHi = std::max<int64_t>(ptHi, starts[s] + n);
            }
            const auto dx = f.range<short>(f.dxVar, size_t(ptLo), size_t(ptHi - ptLo), "longitudes");
            const auto dy = f.range<short>(f.dyVar, size_t(ptLo), size_t(ptHi - ptLo), "latitudes");

            for (size_t k = 0; k < columnBins.size(); ++k) {
                const int b = columnBins[k];
                const double w = (firstColumn + int(k)) * size, s = 90 - (row + 1) * size;
                std::vector<Piece> pieces;
                int lowest = 5;
                for (int seg = f.binFirstSegment[b]; seg < f.binFirstSegment[b] + f.binSegments[b]; ++seg) {
                    const size_t i = size_t(seg - segLo);
                    const uint32_t bits = uint32_t(info[i]);
                    int level = int((bits >> 6) & 7);
                    if (!ant.empty() && ant[i])
                        level = 1; // Antarctica's ice front: land
                    else if (level == 6)
                        continue; // Antarctica's grounding line, the other Antarctica
                    level = std::clamp(level, 1, 4);
                    Piece p;
                    p.level = level;
                    p.exit = int(bits & 7);
                    p.entry = int((bits >> 3) & 7);
                    if (p.exit > 4 || p.entry > 4)
                        f.damaged(QStringLiteral("segment %1 enters through side %2 and leaves through %3").arg(seg).arg(p.entry).arg(p.exit));
                    const int64_t first = starts[i] - ptLo, n = int64_t(bits >> 9);
                    p.points.reserve(size_t(n));
                    for (int64_t j = first; j < first + n; ++j)
                        p.points.push_back({w + uint16_t(dx[size_t(j)]) * scale, s + uint16_t(dy[size_t(j)]) * scale});
                    if (p.entry < 4 && p.exit < 4) {
                        p.in = around(p.entry, uint16_t(dx[size_t(first)]), uint16_t(dy[size_t(first)]));
                        p.out = around(p.exit, uint16_t(dx[size_t(first + n - 1)]), uint16_t(dy[size_t(first + n - 1)]));
                    }
                    lowest = std::min(lowest, level);
                    area.shores.push_back(p.points);
                    pieces.push_back(std::move(p));
                }
                // Outside every piece: one level below the lowest piece, or
                // (no piece kept) what the bin's south-west corner lies in.
                const int outside = pieces.empty() ? (f.binNodes[b] >> 9) & 7 : lowest - 1;
                const std::array<LonLat, 4> corners{LonLat{w, s}, LonLat{w + size, s}, LonLat{w + size, s + size}, LonLat{w, s + size}};
                closeRings(pieces, corners, outside, area);
            }
        }
    } catch (const Failure &failure) {
        if (error)
            *error = failure.what;
        return CoastArea{{}, {}, resolution, 0};
    }
    if (error)
        error->clear();
    return area;
}

} // namespace neptus::geo
