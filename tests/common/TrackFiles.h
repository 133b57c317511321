#pragma once

// What a KML or GPX track file holds, read as a map program reads it: the
// root element's namespace and the track points (KML: coordinate tuples of
// its LineStrings; GPX: trkpt elements). `error` is set when it is not
// well-formed XML.

#include <QFile>
#include <QString>
#include <QXmlStreamReader>

namespace neptus::test {

struct TrackFileContents
{
    QString rootNamespace;
    qsizetype points = 0;
    QString error;
};

inline TrackFileContents readTrackFile(const QString &path)
{
    TrackFileContents contents;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        contents.error = file.errorString();
        return contents;
    }
    const bool kml = path.endsWith(QStringLiteral(".kml"));
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        if (contents.rootNamespace.isEmpty())
            contents.rootNamespace = xml.namespaceUri().toString();
        if (kml && xml.name() == u"coordinates")
            contents.points += xml.readElementText().split(u' ', Qt::SkipEmptyParts).size();
        else if (!kml && xml.name() == u"trkpt")
            ++contents.points;
    }
    if (xml.hasError())
        contents.error = xml.errorString();
    return contents;
}

} // namespace neptus::test
