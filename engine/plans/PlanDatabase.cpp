#include "plans/PlanDatabase.h"

#include <QCryptographicHash>

#include <algorithm>

namespace neptus::plans {

std::expected<QByteArray, QString> planMd5(const msg::Codec &codec, const msg::Message &specification)
{
    if (specification.abbrev() != u"PlanSpecification")
        return std::unexpected(QStringLiteral("a %1 is not a PlanSpecification").arg(specification.abbrev()));
    auto packet = codec.encode(specification);
    if (!packet)
        return std::unexpected(packet.error().toString());
    const QByteArrayView payload = QByteArrayView(*packet).sliced(msg::Codec::headerSize,
        packet->size() - msg::Codec::headerSize - msg::Codec::footerSize);
    return QCryptographicHash::hash(payload, QCryptographicHash::Md5);
}

QByteArray databaseMd5(QList<std::pair<QString, QByteArray>> plans)
{
    // DUNE orders by plan id as its database does: byte order of the UTF-8 ids.
    std::sort(plans.begin(), plans.end(), [](const auto &a, const auto &b) { return a.first.toUtf8() < b.first.toUtf8(); });
    QCryptographicHash md5(QCryptographicHash::Md5);
    for (const auto &[id, planHash] : std::as_const(plans))
        md5.addData(planHash);
    return md5.result();
}

Sync compare(const msg::Codec &codec, const msg::Message &specification, const msg::Message &databaseState)
{
    const QString id = specification.text(u"plan_id");
    const auto md5 = planMd5(codec, specification);
    const int list = databaseState.def() ? databaseState.def()->indexOf(u"plans_info") : -1;
    if (list < 0)
        return Sync::Absent;
    for (const msg::Message &info : databaseState.messages(list)) {
        if (info.text(u"plan_id") == id)
            return md5 && info.bytes(info.def()->indexOf(u"md5")) == *md5 ? Sync::Same : Sync::Differs;
    }
    return Sync::Absent;
}

} // namespace neptus::plans
