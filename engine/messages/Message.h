#pragma once

#include "messages/Schema.h"

#include <QByteArray>
#include <QVarLengthArray>
#include <QVariant>

#include <optional>
#include <span>
#include <vector>

namespace neptus::msg {

// One message value: its definition, the packet header it came with, and its
// field values, stored compactly (one 8-byte slot per scalar field, byte
// strings and nested messages beside) so that decoding makes one allocation
// for a message of scalars. Fields are reached by index (fast, resolve the
// index once with MessageDef::indexOf) or by abbrev.
//
// A message whose id the schema does not know is kept whole as an opaque
// payload (def() is null), so it can be logged and forwarded, never dropped.
class Message
{
public:
    struct Header
    {
        double timestamp = 0;
        quint16 src = 0xFFFF;
        quint8 srcEnt = 0xFF;
        quint16 dst = 0xFFFF;
        quint8 dstEnt = 0xFF;
        friend bool operator==(const Header &, const Header &) = default;
    };

    Message() = default;
    // A message of `def` with every field zero, empty or absent.
    explicit Message(const MessageDef *def);
    // A message the schema does not know: its id and raw payload bytes.
    static Message opaque(quint16 id, QByteArray payload);

    const MessageDef *def() const { return m_def; }
    quint16 id() const { return m_def ? m_def->id : m_opaqueId; }
    QString abbrev() const;
    bool isOpaque() const { return !m_def; }
    bool isMavlink() const { return m_def && m_def->mavlink; }
    const QByteArray &opaquePayload() const { return m_opaque; }
    int fieldCount() const { return m_def ? static_cast<int>(m_def->fields.size()) : 0; }
    const FieldDef &field(int index) const { return m_def->fields[static_cast<size_t>(index)]; }

    Header header;

    // --- Reading, by field index ---
    // Integer fields as integers; floating-point fields are truncated.
    qint64 integer(int index) const;
    // Any numeric field as a double.
    double number(int index) const;
    // plaintext and rawdata fields.
    const QByteArray &bytes(int index) const;
    QString text(int index) const { return QString::fromUtf8(bytes(index)); }
    // A message field: the nested message, or null when there is none.
    const Message *inlineMessage(int index) const;
    // A message-list field (also works for a message field: 0 or 1 entries).
    std::span<const Message> messages(int index) const;
    // Any field as a QVariant (numbers, QByteArray, QString), for generic views.
    // Nested messages are not converted; use inlineMessage()/messages().
    QVariant value(int index) const;
    // The display text of an enumerated or bitfield value ("SERVICE", "A|B").
    QString enumText(int index) const;

    // --- Writing, by field index ---
    void setInteger(int index, qint64 value);
    void setNumber(int index, double value);
    void setBytes(int index, QByteArray value);
    void setInlineMessage(int index, std::optional<Message> value);
    void setMessages(int index, std::vector<Message> values);

    // --- The same by field abbrev; an unknown abbrev reads as 0 / empty ---
    double number(QStringView abbrev) const;
    qint64 integer(QStringView abbrev) const;
    QString text(QStringView abbrev) const;

    // Raw storage, for the codec: the slot holds the value's bits (integers
    // sign- or zero-extended, fp32 and fp64 as their IEEE bit patterns).
    quint64 rawSlot(int index) const { return m_slots[field(index).storage]; }
    void setRawSlot(int index, quint64 bits) { m_slots[field(index).storage] = bits; }
    QByteArray &byteString(int index) { return m_byteStrings[field(index).storage]; }
    std::vector<Message> &messageList(int index) { return m_lists[field(index).storage]; }

    friend bool operator==(const Message &a, const Message &b);

private:
    friend struct CodecAccess;
    const MessageDef *m_def = nullptr;
    quint16 m_opaqueId = 0;
    // Inline room for the scalars of most messages: decoding EstimatedState
    // (20 scalars) allocates nothing. Likewise two byte strings and one
    // message list: a plan's Gotos, maneuvers and transitions (one or two
    // strings, a list) need no allocation of their own for them.
    QVarLengthArray<quint64, 24> m_slots;
    QVarLengthArray<QByteArray, 2> m_byteStrings;
    QVarLengthArray<std::vector<Message>, 1> m_lists;
    QByteArray m_opaque;
};

// A system id as it is written where the system has no name: "0x001f".
QString systemLabel(quint16 id);

} // namespace neptus::msg

Q_DECLARE_METATYPE(neptus::msg::Message)
