#pragma once

#include "messages/Codec.h"

#include <QByteArrayView>
#include <QHash>
#include <QReadWriteLock>
#include <QString>

#include <memory>
#include <optional>

namespace neptus::msg {

// The message definitions in force for each peer: the console's own for
// everyone, and others for systems built from another IMC revision (a DUNE
// vehicle whose IMC.xml numbers some messages differently), named by id or by
// the name the system announces. Transports pick the codec by the sender id
// in a packet's header before decoding it, and encode what they send to a
// system with that system's definitions. Thread-safe (transports decode on
// their own threads).
class SchemaSet
{
public:
    explicit SchemaSet(std::shared_ptr<const Schema> defaults);

    const Codec &defaults() const { return *m_defaults; }
    const Schema &defaultSchema() const { return m_defaults->schema(); }

    // Definitions for one system, by IMC id or by the name it announces.
    void setFor(quint16 system, std::shared_ptr<const Schema> schema);
    // `system` is an IMC id as text ("0x00d1", "209") or the name it announces.
    void setFor(const QString &system, std::shared_ptr<const Schema> schema);
    // A system announced its name (called by the transports on every Announce):
    // definitions given for that name now apply to its id.
    void learnName(quint16 system, const QString &name);

    // The codec for packets from `system`: its own definitions, else the defaults.
    std::shared_ptr<const Codec> codecFor(quint16 system) const;
    // Whether `system` has definitions of its own.
    bool hasOwn(quint16 system) const;

    // The sender id of an IMC packet, read from its header without decoding
    // it (the header is the same in every IMC revision); none when the bytes
    // are too short or do not start with an IMC sync number.
    std::optional<quint16> senderOf(QByteArrayView packet) const;

    // Decodes a packet with its sender's definitions.
    std::expected<Message, CodecError> decode(QByteArrayView packet) const;
    // `message`, made with any definitions, in the definitions of `system`
    // (the same message by name and field names); an error names what does not fit.
    std::expected<Message, QString> forSystem(quint16 system, const Message &message) const;

private:
    std::shared_ptr<const Codec> m_defaults;
    mutable QReadWriteLock m_lock;
    QHash<quint16, std::shared_ptr<const Codec>> m_byId;
    QHash<QString, std::shared_ptr<const Codec>> m_byName;
};

} // namespace neptus::msg
