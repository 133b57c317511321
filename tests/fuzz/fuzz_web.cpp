// libFuzzer target: the live web page's request handling (web/Requests.h),
// what every request goes through before the server does anything with it.
// The input is split at its first newline: a URL (path and query, as a
// browser or an attacker sends it) and an Authorization header. Beyond "no
// crash, no sanitizer report": what is accepted is within bounds (a known
// kind; times in order and at most a week apart; a system name of the allowed
// characters; a box of at most 10°), what is refused has a 4xx status and a
// reason, a static file never leaves its folder, and no token is accepted
// but the right one.
#include "FuzzApplication.h"
#include "web/Requests.h"

#include <QRegularExpression>

#include <cstdio>
#include <cstdlib>

using namespace neptus;

namespace {

void check(bool ok, const char *what)
{
    test::fuzzCheck(ok, "fuzz_web", what);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    const qsizetype newline = bytes.indexOf('\n');
    const QByteArray target = newline < 0 ? bytes : bytes.left(newline);
    const QByteArray authorization = newline < 0 ? QByteArray() : bytes.mid(newline + 1);
    const QUrl url = QUrl::fromEncoded(QByteArray("http://127.0.0.1:8080") + (target.startsWith('/') ? "" : "/") + target);
    constexpr qint64 now = 1'790'000'000'000;

    const auto api = web::parseApi(url, now);
    if (api) {
        check(url.toEncoded().size() <= web::maxUrlLength, "a URL past the limit was accepted");
        check(api->fromMs <= api->toMs, "from after to accepted");
        check(api->toMs - api->fromMs <= web::maxSpanMs, "more than a week accepted");
        if (api->kind == web::ApiRequest::Track) {
            static const QRegularExpression name(QStringLiteral("^[A-Za-z0-9_.:-]{1,64}$"));
            check(name.match(api->system).hasMatch(), "a system name with other characters accepted");
        }
        if (api->kind == web::ApiRequest::Coastline)
            check(api->east - api->west <= 10 && api->north - api->south <= 10 && api->west < api->east && api->south < api->north
                      && api->south >= -90 && api->north <= 90,
                  "a bad box accepted");
    } else {
        check(api.error().status >= 400 && api.error().status < 500, "a refusal without a 4xx status");
        check(!api.error().message.isEmpty(), "a refusal without a reason");
    }

    const auto file = web::staticFile(url.path(), QStringLiteral("/page"), QStringLiteral("/leaflet"));
    if (file) {
        check(!file->path.contains(QStringLiteral("..")), "a static file path with '..'");
        check(file->path.startsWith(QStringLiteral("/page/")) || file->path.startsWith(QStringLiteral("/leaflet/")),
              "a static file outside its folders");
    }

    const QString token = QStringLiteral("0123456789abcdef0123");
    const bool in = web::authorized(url, authorization, token);
    const bool right = authorization.startsWith("Bearer ") ? authorization.mid(7).trimmed() == token.toUtf8()
                                                           : url.query(QUrl::FullyDecoded).contains(token);
    check(!in || right, "a wrong token accepted");
    check(web::authorized(url, authorization, QString()), "no token set, yet refused");
    return 0;
}
