#pragma once

#include <QString>

#include <array>
#include <memory>
#include <vector>

// The world's shorelines, offline: GSHHG (Wessel & Smith's Global
// Self-consistent, Hierarchical, High-resolution Geography) in the binned
// netCDF files GMT reads, as Debian's gmt-gshhg-{low,high,full} install them
// (binned_GSHHS_{c,l,i,h,f}.nc), read with libnetcdf.
//
// The files cut every shoreline into pieces per bin (a square of a few
// minutes to a degree): a piece either closes inside its bin (an island, a
// lake) or enters through one side of the bin and leaves through another.
// Levels nest: 1 land, 2 lake, 3 island in a lake, 4 pond on such an island;
// the sea is 0. An area gives, per bin, the shore pieces (to draw as lines)
// and closed rings (each piece closed along the bin's sides) whose even-odd
// fill is exactly the land: inside an odd number of rings is land.
namespace neptus::geo {

struct LonLat
{
    double lon = 0, lat = 0; // degrees
};

struct CoastArea
{
    // Pieces of shoreline, as drawn (not closed along bin sides).
    std::vector<std::vector<LonLat>> shores;
    // Closed rings, first point repeated at the end: land by the even-odd rule.
    std::vector<std::vector<LonLat>> rings;
    char resolution = 0; // 'c', 'l', 'i', 'h' or 'f'
    int binCount = 0;    // bins read (with or without shore)
    size_t pointCount() const;
    // Land by the even-odd rule over the rings (longitude in the area's frame).
    bool isLand(double lat, double lon) const;
};

class Coastline
{
public:
    // The resolutions GSHHG comes in, coarsest first, and what each keeps:
    // about 25 km, 5 km, 1 km, 200 m and 40 m between points.
    static constexpr std::array<char, 5> resolutions{'c', 'l', 'i', 'h', 'f'};
    // Where Debian installs the files, unless NEPTUS_GSHHG_DIR says otherwise.
    static QString defaultDirectory();

    explicit Coastline(QString directory = defaultDirectory());
    ~Coastline();
    Coastline(const Coastline &) = delete;
    Coastline &operator=(const Coastline &) = delete;

    // The resolutions whose file was there when made, coarsest first.
    QString available() const { return m_available; }
    // The resolution for a map showing `metresPerPixel` (the coarsest with
    // points at most three pixels apart), among those available; 0 when none is.
    char resolutionFor(double metresPerPixel) const;

    // Every bin overlapping the box (degrees; west may be below -180 and east
    // above 180: longitudes come back in the box's frame). Thread-safe (one
    // read at a time: libnetcdf is not). Empty area and `error` set (naming
    // the file) when the file is missing or damaged.
    CoastArea read(char resolution, double west, double south, double east, double north, QString *error) const;

private:
    struct File;
    QString filePath(char resolution) const;
    QString m_directory;
    QString m_available;
    mutable std::array<std::unique_ptr<File>, 5> m_files;
};

} // namespace neptus::geo
