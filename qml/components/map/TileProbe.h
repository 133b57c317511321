#pragma once

#include <QNetworkAccessManager>
#include <QObject>
#include <QPoint>
#include <QPointer>
#include <QTimer>
#include <QUrl>
#include <QtQml/qqmlregistration.h>

class QNetworkReply;

// Whether a map's tile source has the tile under the view's centre: a file
// in a z/x/y.png folder, or an answer from a tile server on the local
// network. A source that gives nothing must say so rather than leave a blank
// map (Qt Location draws nothing and reports nothing). Looks again, at most
// every 300 ms, when the centre tile changes.
class TileProbe : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QString directory MEMBER m_directory WRITE setDirectory NOTIFY sourceChanged)
    Q_PROPERTY(QString server MEMBER m_server WRITE setServer NOTIFY sourceChanged)
    Q_PROPERTY(double latitude MEMBER m_lat WRITE setLatitude NOTIFY sourceChanged)
    Q_PROPERTY(double longitude MEMBER m_lon WRITE setLongitude NOTIFY sourceChanged)
    Q_PROPERTY(double zoomLevel MEMBER m_zoom WRITE setZoomLevel NOTIFY sourceChanged)
    Q_PROPERTY(Status status READ status NOTIFY checked)
    // Why there is no tile ("" while there is one or nothing is known yet).
    Q_PROPERTY(QString message READ message NOTIFY checked)

public:
    enum Status { Unknown, Found, Missing };
    Q_ENUM(Status)

    explicit TileProbe(QObject *parent = nullptr);

    void setDirectory(const QString &v) { set(m_directory, v); }
    void setServer(const QString &v) { set(m_server, v); }
    void setLatitude(double v) { set(m_lat, v); }
    void setLongitude(double v) { set(m_lon, v); }
    void setZoomLevel(double v) { set(m_zoom, v); }
    Status status() const { return m_status; }
    QString message() const { return m_message; }

    // The tile (x, y) at `zoom` holding a point (Web Mercator, as OSM numbers them).
    static QPoint tileAt(double latDeg, double lonDeg, int zoom);
    // Where a tile is in a z/x/y.png folder ("15/15591/12262.png"), and on a server ("http://…/15/15591/12262.png").
    static QString tilePath(int z, int x, int y);
    static QUrl tileUrl(const QString &server, int z, int x, int y);

signals:
    void sourceChanged();
    void checked();

private:
    template <typename T> void set(T &member, const T &value)
    {
        if (member == value)
            return;
        member = value;
        emit sourceChanged();
        m_timer.start();
    }
    void check();
    void report(Status status, const QString &message);

    QString m_directory, m_server;
    double m_lat = 0, m_lon = 0, m_zoom = 15;
    Status m_status = Unknown;
    QString m_message;
    QString m_lastTile; // what was checked last, so an unchanged tile is not asked again
    QTimer m_timer;
    QNetworkAccessManager m_network;
    QPointer<QNetworkReply> m_reply;
};
