#include "charts/S57Reader.h"

#include <QFileInfo>

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <memory>

namespace neptus::charts {

using namespace Qt::StringLiterals;

namespace {

// GDAL's complaints, kept to say why a cell could not be read.
void CPL_STDCALL collectError(CPLErr level, CPLErrorNum, const char *message)
{
    if (level >= CE_Failure) {
        auto *last = static_cast<QString *>(CPLGetErrorHandlerUserData());
        if (last)
            *last = QString::fromUtf8(message);
    }
}

// Collects GDAL's last failure into `into` for as long as it lives, whichever way the read ends.
struct ErrorsInto
{
    explicit ErrorsInto(QString *into) { CPLPushErrorHandlerEx(collectError, into); }
    ~ErrorsInto() { CPLPopErrorHandler(); }
    ErrorsInto(const ErrorsInto &) = delete;
    ErrorsInto &operator=(const ErrorsInto &) = delete;
};

std::vector<Vertex> points(const OGRSimpleCurve &curve)
{
    std::vector<Vertex> out;
    out.reserve(curve.getNumPoints());
    for (int i = 0; i < curve.getNumPoints(); ++i)
        out.push_back({curve.getX(i), curve.getY(i), 0});
    return out;
}

// Its parts: points, polylines or rings, as the feature's geometry says.
bool addGeometry(const OGRGeometry &g, Feature &f)
{
    switch (wkbFlatten(g.getGeometryType())) {
    case wkbPoint: {
        const auto &p = *g.toPoint();
        f.geometry = Feature::Geometry::Point;
        f.parts.push_back({{p.getX(), p.getY(), p.Is3D() ? p.getZ() : 0}});
        return true;
    }
    case wkbLineString:
        f.geometry = Feature::Geometry::Line;
        f.parts.push_back(points(*g.toLineString()));
        return true;
    case wkbPolygon:
        f.geometry = Feature::Geometry::Area;
        for (const OGRLinearRing *ring : *g.toPolygon())
            f.parts.push_back(points(*ring));
        return true;
    case wkbMultiPoint:
    case wkbMultiLineString:
    case wkbMultiPolygon:
    case wkbGeometryCollection:
        for (const OGRGeometry *part : *g.toGeometryCollection())
            if (!addGeometry(*part, f))
                return false;
        return true;
    default:
        return false;
    }
}

// Record bookkeeping of the S-57 driver, not what the feature says.
const QStringList &recordFields()
{
    static const QStringList fields{u"RCID"_s, u"PRIM"_s, u"GRUP"_s, u"OBJL"_s, u"RVER"_s, u"AGEN"_s,
                                    u"FIDN"_s, u"FIDS"_s, u"LNAM"_s};
    return fields;
}

} // namespace

std::expected<Cell, QString> readS57(const QString &path)
{
    if (!QFileInfo(path).isFile())
        return std::unexpected(u"%1: no such file"_s.arg(path));
    RegisterOGRS57();
    QString gdalError;
    const ErrorsInto errors(&gdalError);
    const char *drivers[] = {"S57", nullptr};
    const char *options[] = {"UPDATES=APPLY", "SPLIT_MULTIPOINT=OFF", "RETURN_PRIMITIVES=OFF", "RETURN_LINKAGES=OFF",
                             "LNAM_REFS=OFF", "RECODE_BY_DSSI=ON", nullptr};
    std::unique_ptr<GDALDataset> dataset(
        GDALDataset::Open(path.toUtf8().constData(), GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers, options, nullptr));
    if (!dataset)
        return std::unexpected(u"%1: not an S-57 cell GDAL can read%2"_s.arg(path, gdalError.isEmpty() ? QString() : u": "_s + gdalError));
    Cell cell;
    for (OGRLayer *layer : dataset->GetLayers()) {
        const QString name = QString::fromUtf8(layer->GetName());
        if (name == u"DSID") {
            for (const auto &f : *layer) {
                const auto text = [&](const char *field) {
                    const int i = f->GetFieldIndex(field);
                    return i >= 0 && f->IsFieldSetAndNotNull(i) ? QString::fromUtf8(f->GetFieldAsString(i)).trimmed() : QString();
                };
                cell.name = text("DSID_DSNM");
                cell.edition = text("DSID_EDTN").toInt();
                cell.update = text("DSID_UPDN").toInt();
                cell.issued = text("DSID_ISDT");
                cell.usageBand = text("DSID_INTU").toInt();
                cell.scale = text("DSPM_CSCL").toInt();
                cell.comment = text("DSID_COMT");
            }
            continue;
        }
        if (!keptClasses().contains(name))
            continue;
        for (const auto &source : *layer) {
            const OGRGeometry *geometry = source->GetGeometryRef();
            if (!geometry || geometry->IsEmpty())
                continue; // a feature with no place (a light's sector table alone) draws nothing here
            Feature f;
            f.objectClass = name;
            if (!addGeometry(*geometry, f))
                return std::unexpected(u"%1: %2 feature %3 has a geometry of a kind charts do not have (%4)"_s.arg(
                    path, name).arg(source->GetFID()).arg(QString::fromUtf8(geometry->getGeometryName())));
            const OGRFeatureDefn *definition = source->GetDefnRef();
            for (int i = 0; i < definition->GetFieldCount(); ++i) {
                const QString field = QString::fromUtf8(definition->GetFieldDefn(i)->GetNameRef());
                if (!source->IsFieldSetAndNotNull(i) || recordFields().contains(field))
                    continue;
                const QString value = QString::fromUtf8(source->GetFieldAsString(i)).trimmed();
                if (!value.isEmpty())
                    f.attributes.insert(field, value);
            }
            cell.features.push_back(std::move(f));
        }
    }
    if (cell.name.isEmpty())
        return std::unexpected(u"%1: has no data set identification (DSID): not an S-57 cell%2"_s.arg(
            path, gdalError.isEmpty() ? QString() : u": "_s + gdalError));
    return cell;
}

} // namespace neptus::charts
