#pragma once

#include <QByteArray>
#include <QString>
#include <QUrl>

#include <expected>

namespace neptus::web {

// What the live web page may ask, read from a request's URL before anything
// is done with it: every part checked, anything else refused with the HTTP
// status and the reason. Nothing here changes anything: the page is read-only.
struct ApiRequest
{
    enum Kind { State, Track, Alarms, Plans, Coastline, Chart };
    Kind kind = State;
    QString system;            // Track
    qint64 fromMs = 0, toMs = 0; // Track, Alarms, Plans
    double west = 0, south = 0, east = 0, north = 0; // Coastline, Chart (degrees)
    double safety = 5;         // Chart: the safety depth, metres
};

struct RequestError
{
    int status = 400;
    QString message;
};

constexpr qsizetype maxUrlLength = 2048;
constexpr qint64 maxSpanMs = 7 * 24 * 3600 * 1000ll; // a week of history at most per request

// /api/state, /api/track?system=NAME[&from=MS][&to=MS], /api/alarms, /api/plans
// ([from], [to]: milliseconds since 1970 UTC; default the last hour before
// `nowMs`), /api/coastline?bbox=W,S,E,N (at most 10° a side),
// /api/chart?bbox=W,S,E,N[&safety=METRES] (the same box; safety depth 0–1000 m, default 5).
std::expected<ApiRequest, RequestError> parseApi(const QUrl &url, qint64 nowMs);

// The static files the page is made of, by URL path: the file to send (in the
// page's folder or Leaflet's) and its type, or 404.
struct StaticFile
{
    QString path;
    QByteArray mimeType;
};
std::expected<StaticFile, RequestError> staticFile(const QString &urlPath, const QString &pageDir, const QString &leafletDir);

// The access token, from `?token=` or an `Authorization: Bearer` header,
// compared in constant time. An empty `token` lets every request in.
bool authorized(const QUrl &url, const QByteArray &authorization, const QString &token);

} // namespace neptus::web
