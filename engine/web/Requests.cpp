#include "web/Requests.h"

#include <QRegularExpression>
#include <QUrlQuery>

using namespace Qt::StringLiterals;

namespace neptus::web {

namespace {

std::expected<qint64, RequestError> timeParameter(const QUrlQuery &query, const QString &name, qint64 fallback)
{
    if (!query.hasQueryItem(name))
        return fallback;
    bool ok = false;
    const qint64 value = query.queryItemValue(name).toLongLong(&ok);
    if (!ok || value < 0 || value > 32'503'680'000'000) // year 3000
        return std::unexpected(RequestError{400, u"'%1' must be milliseconds since 1970"_s.arg(name)});
    return value;
}

std::expected<void, RequestError> onlyParameters(const QUrlQuery &query, const QStringList &allowed)
{
    QStringList seen;
    for (const auto &[key, value] : query.queryItems(QUrl::FullyDecoded)) {
        if (key == u"token"_s)
            continue;
        if (!allowed.contains(key))
            return std::unexpected(RequestError{400, u"unknown parameter '%1'"_s.arg(key.left(40))});
        if (seen.contains(key))
            return std::unexpected(RequestError{400, u"parameter '%1' given twice"_s.arg(key)});
        seen.append(key);
    }
    return {};
}

} // namespace

std::expected<ApiRequest, RequestError> parseApi(const QUrl &url, qint64 nowMs)
{
    if (url.toEncoded().size() > maxUrlLength)
        return std::unexpected(RequestError{414, u"URL longer than %1 characters"_s.arg(maxUrlLength)});
    const QString path = url.path();
    const QUrlQuery query(url);
    ApiRequest request;
    if (path == u"/api/state"_s) {
        if (auto ok = onlyParameters(query, {}); !ok)
            return std::unexpected(ok.error());
        return request;
    }
    if (path == u"/api/track"_s || path == u"/api/alarms"_s || path == u"/api/plans"_s) {
        request.kind = path == u"/api/track"_s ? ApiRequest::Track : path == u"/api/alarms"_s ? ApiRequest::Alarms : ApiRequest::Plans;
        QStringList allowed{u"from"_s, u"to"_s};
        if (request.kind == ApiRequest::Track)
            allowed.append(u"system"_s);
        if (auto ok = onlyParameters(query, allowed); !ok)
            return std::unexpected(ok.error());
        const auto to = timeParameter(query, u"to"_s, nowMs);
        if (!to)
            return std::unexpected(to.error());
        const auto from = timeParameter(query, u"from"_s, *to - 3'600'000);
        if (!from)
            return std::unexpected(from.error());
        if (*from > *to)
            return std::unexpected(RequestError{400, u"'from' is after 'to'"_s});
        if (*to - *from > maxSpanMs)
            return std::unexpected(RequestError{400, u"at most a week at a time"_s});
        request.fromMs = *from;
        request.toMs = *to;
        if (request.kind == ApiRequest::Track) {
            static const QRegularExpression name(uR"(^[A-Za-z0-9_.:-]{1,64}$)"_s);
            request.system = query.queryItemValue(u"system"_s, QUrl::FullyDecoded);
            if (!name.match(request.system).hasMatch())
                return std::unexpected(RequestError{400, u"'system' must be a system's name (letters, digits, - _ . :)"_s});
        }
        return request;
    }
    if (path == u"/api/coastline"_s || path == u"/api/chart"_s) {
        request.kind = path == u"/api/chart"_s ? ApiRequest::Chart : ApiRequest::Coastline;
        if (auto ok = onlyParameters(query, request.kind == ApiRequest::Chart ? QStringList{u"bbox"_s, u"safety"_s} : QStringList{u"bbox"_s}); !ok)
            return std::unexpected(ok.error());
        if (query.hasQueryItem(u"safety"_s)) {
            bool ok = false;
            request.safety = query.queryItemValue(u"safety"_s).toDouble(&ok);
            if (!ok || !(request.safety >= 0) || request.safety > 1000)
                return std::unexpected(RequestError{400, u"'safety' must be a depth in metres, 0 to 1000"_s});
        }
        const QStringList parts = query.queryItemValue(u"bbox"_s).split(u',');
        double v[4] = {};
        bool ok = parts.size() == 4;
        for (int i = 0; ok && i < 4; ++i)
            v[i] = parts[i].toDouble(&ok);
        if (!ok || !(v[0] < v[2]) || !(v[1] < v[3]) || v[1] < -90 || v[3] > 90 || v[0] < -360 || v[2] > 360)
            return std::unexpected(RequestError{400, u"'bbox' must be west,south,east,north in degrees"_s});
        if (v[2] - v[0] > 10 || v[3] - v[1] > 10)
            return std::unexpected(RequestError{400, u"'bbox' at most 10 degrees a side"_s});
        request.west = v[0];
        request.south = v[1];
        request.east = v[2];
        request.north = v[3];
        return request;
    }
    return std::unexpected(RequestError{404, u"no such page"_s});
}

std::expected<StaticFile, RequestError> staticFile(const QString &urlPath, const QString &pageDir, const QString &leafletDir)
{
    static const QHash<QString, std::pair<QString, QByteArray>> page{
        {u"/"_s, {u"index.html"_s, "text/html; charset=utf-8"}},
        {u"/index.html"_s, {u"index.html"_s, "text/html; charset=utf-8"}},
        {u"/app.js"_s, {u"app.js"_s, "text/javascript; charset=utf-8"}},
        {u"/style.css"_s, {u"style.css"_s, "text/css; charset=utf-8"}},
    };
    static const QHash<QString, std::pair<QString, QByteArray>> leaflet{
        {u"/leaflet/leaflet.js"_s, {u"leaflet.js"_s, "text/javascript; charset=utf-8"}},
        {u"/leaflet/leaflet.css"_s, {u"leaflet.css"_s, "text/css; charset=utf-8"}},
        {u"/leaflet/images/marker-icon.png"_s, {u"images/marker-icon.png"_s, "image/png"}},
        {u"/leaflet/images/marker-shadow.png"_s, {u"images/marker-shadow.png"_s, "image/png"}},
        {u"/leaflet/images/layers.png"_s, {u"images/layers.png"_s, "image/png"}},
    };
    if (const auto it = page.constFind(urlPath); it != page.cend())
        return StaticFile{pageDir + u'/' + it->first, it->second};
    if (const auto it = leaflet.constFind(urlPath); it != leaflet.cend())
        return StaticFile{leafletDir + u'/' + it->first, it->second};
    return std::unexpected(RequestError{404, u"no such page"_s});
}

bool authorized(const QUrl &url, const QByteArray &authorization, const QString &token)
{
    if (token.isEmpty())
        return true;
    QByteArray given = QUrlQuery(url).queryItemValue(u"token"_s, QUrl::FullyDecoded).toUtf8();
    if (authorization.startsWith("Bearer "))
        given = authorization.mid(7).trimmed();
    const QByteArray expected = token.toUtf8();
    if (given.size() != expected.size())
        return false;
    unsigned char diff = 0;
    for (qsizetype i = 0; i < given.size(); ++i)
        diff |= static_cast<unsigned char>(given[i] ^ expected[i]);
    return diff == 0;
}

} // namespace neptus::web
