#include "messages/SchemaSet.h"

#include "messages/MessageJson.h"

#include <QReadLocker>
#include <QWriteLocker>

namespace neptus::msg {

SchemaSet::SchemaSet(std::shared_ptr<const Schema> defaults)
    : m_defaults(std::make_shared<const Codec>(std::move(defaults)))
{
}

void SchemaSet::setFor(quint16 system, std::shared_ptr<const Schema> schema)
{
    QWriteLocker lock(&m_lock);
    m_byId.insert(system, std::make_shared<const Codec>(std::move(schema)));
}

void SchemaSet::setFor(const QString &system, std::shared_ptr<const Schema> schema)
{
    bool isId = false;
    if (const uint id = system.toUInt(&isId, 0); isId && id < 0xFFFF) {
        setFor(quint16(id), std::move(schema));
        return;
    }
    QWriteLocker lock(&m_lock);
    m_byName.insert(system, std::make_shared<const Codec>(std::move(schema)));
}

void SchemaSet::learnName(quint16 system, const QString &name)
{
    {
        QReadLocker lock(&m_lock);
        const auto it = m_byName.constFind(name);
        if (it == m_byName.cend() || m_byId.value(system) == *it)
            return;
    }
    QWriteLocker lock(&m_lock);
    m_byId.insert(system, m_byName.value(name));
}

std::shared_ptr<const Codec> SchemaSet::codecFor(quint16 system) const
{
    QReadLocker lock(&m_lock);
    if (m_byId.isEmpty())
        return m_defaults;
    return m_byId.value(system, m_defaults);
}

bool SchemaSet::hasOwn(quint16 system) const
{
    QReadLocker lock(&m_lock);
    return m_byId.contains(system);
}

std::optional<quint16> SchemaSet::senderOf(QByteArrayView packet) const
{
    if (packet.size() < Codec::headerSize)
        return std::nullopt;
    const auto byte = [&](qsizetype i) { return static_cast<quint8>(packet[i]); };
    const quint16 sync = m_defaults->schema().syncNumber();
    // Header: sync, mgid, size (2 bytes each), timestamp (8), then src.
    if (byte(0) == (sync & 0xFF) && byte(1) == (sync >> 8))
        return static_cast<quint16>(byte(14) | (byte(15) << 8));
    if (byte(0) == (sync >> 8) && byte(1) == (sync & 0xFF))
        return static_cast<quint16>((byte(14) << 8) | byte(15));
    return std::nullopt;
}

std::expected<Message, CodecError> SchemaSet::decode(QByteArrayView packet) const
{
    {
        QReadLocker lock(&m_lock);
        if (m_byId.isEmpty())
            return m_defaults->decode(packet);
    }
    const auto sender = senderOf(packet);
    return (sender ? codecFor(*sender) : m_defaults)->decode(packet);
}

std::expected<Message, QString> SchemaSet::forSystem(quint16 system, const Message &message) const
{
    const std::shared_ptr<const Codec> codec = codecFor(system);
    const Schema &schema = codec->schema();
    if (message.isOpaque() || schema.byId(message.id()) == message.def())
        return message; // already in those definitions
    // The same message by name: JSON carries it by names, not ids or offsets.
    auto converted = fromJson(schema, toJson(message));
    if (!converted)
        return std::unexpected(QStringLiteral("%1 does not fit the definitions of system %2 (%3 %4): %5")
                                   .arg(message.abbrev(), systemLabel(system), schema.name(), schema.version(),
                                        converted.error()));
    converted->header = message.header;
    return converted;
}

} // namespace neptus::msg
