#include "messages/Message.h"

#include <bit>
#include <cmath>

namespace neptus::msg {

namespace {

const QByteArray emptyBytes;

quint64 integerBits(FieldType type, qint64 value)
{
    // Store exactly what the wire type can carry, so that what is read back
    // is what would be sent.
    switch (type) {
    case FieldType::Int8: return static_cast<quint64>(static_cast<qint64>(static_cast<qint8>(value)));
    case FieldType::UInt8: return static_cast<quint8>(value);
    case FieldType::Int16: return static_cast<quint64>(static_cast<qint64>(static_cast<qint16>(value)));
    case FieldType::UInt16: return static_cast<quint16>(value);
    case FieldType::Int32: return static_cast<quint64>(static_cast<qint64>(static_cast<qint32>(value)));
    case FieldType::UInt32: return static_cast<quint32>(value);
    default: return static_cast<quint64>(value);
    }
}

} // namespace

Message::Message(const MessageDef *def)
    : m_def(def)
{
    if (!def)
        return;
    m_slots.resize(static_cast<qsizetype>(def->fields.size()) - def->byteStringCount - def->messageListCount);
    std::fill(m_slots.begin(), m_slots.end(), 0);
    if (def->byteStringCount > 0)
        m_byteStrings.resize(def->byteStringCount);
    if (def->messageListCount > 0)
        m_lists.resize(def->messageListCount);
}

Message Message::opaque(quint16 id, QByteArray payload)
{
    Message message;
    message.m_opaqueId = id;
    message.m_opaque = std::move(payload);
    return message;
}

QString Message::abbrev() const
{
    return m_def ? m_def->abbrev : QStringLiteral("Unknown(%1)").arg(m_opaqueId);
}

qint64 Message::integer(int index) const
{
    const FieldType type = field(index).type;
    if (isFloat(type)) {
        const double value = number(index);
        return std::isfinite(value) ? static_cast<qint64>(value) : 0;
    }
    if (!isInteger(type))
        return 0;
    return static_cast<qint64>(rawSlot(index));
}

double Message::number(int index) const
{
    const FieldDef &f = field(index);
    switch (f.type) {
    case FieldType::Fp32: return std::bit_cast<float>(static_cast<quint32>(rawSlot(index)));
    case FieldType::Fp64: return std::bit_cast<double>(rawSlot(index));
    case FieldType::UInt64:
    case FieldType::UInt32:
    case FieldType::UInt16:
    case FieldType::UInt8: return static_cast<double>(rawSlot(index));
    case FieldType::Int8:
    case FieldType::Int16:
    case FieldType::Int32:
    case FieldType::Int64: return static_cast<double>(static_cast<qint64>(rawSlot(index)));
    default: return 0;
    }
}

const QByteArray &Message::bytes(int index) const
{
    const FieldDef &f = field(index);
    if (f.type != FieldType::PlainText && f.type != FieldType::RawData)
        return emptyBytes;
    return m_byteStrings[f.storage];
}

const Message *Message::inlineMessage(int index) const
{
    const auto list = messages(index);
    return list.empty() ? nullptr : &list.front();
}

std::span<const Message> Message::messages(int index) const
{
    const FieldDef &f = field(index);
    if (f.type != FieldType::Message && f.type != FieldType::MessageList)
        return {};
    return m_lists[f.storage];
}

QVariant Message::value(int index) const
{
    const FieldDef &f = field(index);
    switch (f.type) {
    case FieldType::Fp32:
    case FieldType::Fp64: return number(index);
    case FieldType::UInt64:
    case FieldType::UInt32:
    case FieldType::UInt16:
    case FieldType::UInt8: return static_cast<quint64>(rawSlot(index));
    case FieldType::Int8:
    case FieldType::Int16:
    case FieldType::Int32:
    case FieldType::Int64: return integer(index);
    case FieldType::PlainText: return text(index);
    case FieldType::RawData: return bytes(index);
    case FieldType::Message:
    case FieldType::MessageList: return {};
    }
    return {};
}

QString Message::enumText(int index) const
{
    const FieldDef &f = field(index);
    return f.enumeration ? f.enumeration->format(integer(index)) : QString::number(integer(index));
}

void Message::setInteger(int index, qint64 value)
{
    const FieldType type = field(index).type;
    if (isFloat(type))
        setNumber(index, static_cast<double>(value));
    else if (isInteger(type))
        setRawSlot(index, integerBits(type, value));
}

void Message::setNumber(int index, double value)
{
    const FieldType type = field(index).type;
    if (type == FieldType::Fp32)
        setRawSlot(index, std::bit_cast<quint32>(static_cast<float>(value)));
    else if (type == FieldType::Fp64)
        setRawSlot(index, std::bit_cast<quint64>(value));
    else if (isInteger(type))
        setRawSlot(index, integerBits(type, std::isfinite(value) ? static_cast<qint64>(value) : 0));
}

void Message::setBytes(int index, QByteArray value)
{
    const FieldType type = field(index).type;
    if (type == FieldType::PlainText || type == FieldType::RawData)
        byteString(index) = std::move(value);
}

void Message::setInlineMessage(int index, std::optional<Message> value)
{
    std::vector<Message> list;
    if (value)
        list.push_back(std::move(*value));
    setMessages(index, std::move(list));
}

void Message::setMessages(int index, std::vector<Message> values)
{
    const FieldType type = field(index).type;
    if (type == FieldType::Message || type == FieldType::MessageList)
        messageList(index) = std::move(values);
}

double Message::number(QStringView abbrev) const
{
    const int index = m_def ? m_def->indexOf(abbrev) : -1;
    return index < 0 ? 0 : number(index);
}

qint64 Message::integer(QStringView abbrev) const
{
    const int index = m_def ? m_def->indexOf(abbrev) : -1;
    return index < 0 ? 0 : integer(index);
}

QString Message::text(QStringView abbrev) const
{
    const int index = m_def ? m_def->indexOf(abbrev) : -1;
    return index < 0 ? QString() : text(index);
}

bool operator==(const Message &a, const Message &b)
{
    return a.m_def == b.m_def && a.m_opaqueId == b.m_opaqueId && a.header == b.header && a.m_slots == b.m_slots
           && a.m_byteStrings == b.m_byteStrings && a.m_lists == b.m_lists && a.m_opaque == b.m_opaque;
}

QString systemLabel(quint16 id)
{
    return QStringLiteral("0x%1").arg(id, 4, 16, QLatin1Char('0'));
}

} // namespace neptus::msg
