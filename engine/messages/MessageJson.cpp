#include "messages/MessageJson.h"

#include <QJsonArray>
#include <QJsonValue>
#include <QRegularExpression>
#include <QStringConverter>

#include <cmath>
#include <limits>

namespace neptus::msg {

namespace {

QJsonValue numberToJson(double value)
{
    if (std::isnan(value))
        return QStringLiteral("NaN");
    if (std::isinf(value))
        return value > 0 ? QStringLiteral("Infinity") : QStringLiteral("-Infinity");
    return value;
}

bool isValidUtf8(const QByteArray &bytes)
{
    QStringDecoder decoder(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    const QString text = decoder.decode(bytes);
    Q_UNUSED(text);
    return !decoder.hasError();
}

QJsonValue fieldToJson(const Message &message, int index)
{
    const FieldDef &field = message.field(index);
    switch (field.type) {
    case FieldType::Fp32:
    case FieldType::Fp64: return numberToJson(message.number(index));
    case FieldType::PlainText: {
        const QByteArray &bytes = message.bytes(index);
        if (isValidUtf8(bytes))
            return QString::fromUtf8(bytes);
        return QJsonObject{{QStringLiteral("hex"), QString::fromLatin1(bytes.toHex())}};
    }
    case FieldType::RawData: return QString::fromLatin1(message.bytes(index).toHex());
    case FieldType::Message: {
        const Message *inner = message.inlineMessage(index);
        return inner ? QJsonValue(toJsonWithoutHeader(*inner)) : QJsonValue(QJsonValue::Null);
    }
    case FieldType::MessageList: {
        QJsonArray array;
        for (const Message &entry : message.messages(index))
            array.append(toJsonWithoutHeader(entry));
        return array;
    }
    default:
        if (field.enumeration) {
            const QString text = message.enumText(index);
            bool isNumber = false;
            text.toLongLong(&isNumber);
            if (!isNumber)
                return text;
        }
        return message.integer(index);
    }
}

QJsonObject bodyToJson(const Message &message, QJsonObject object)
{
    if (message.isOpaque()) {
        object.insert(QStringLiteral("mgid"), message.id());
        object.insert(QStringLiteral("opaque"), QString::fromLatin1(message.opaquePayload().toHex()));
        return object;
    }
    object.insert(QStringLiteral("abbrev"), message.abbrev());
    QJsonObject fields;
    for (int i = 0; i < message.fieldCount(); ++i)
        fields.insert(message.field(i).abbrev, fieldToJson(message, i));
    object.insert(QStringLiteral("fields"), fields);
    return object;
}

// Reads JSON into messages, remembering where it is for error messages.
class Reader
{
public:
    explicit Reader(const Schema &schema)
        : m_schema(schema)
    {
    }

    std::expected<Message, QString> message(const QJsonObject &json, const QString &path, bool withHeader);

private:
    std::expected<void, QString> field(Message &message, int index, const QJsonValue &value, const QString &path);
    std::expected<qint64, QString> integer(const QJsonValue &value, const QString &path, qint64 low, qint64 high,
                                           const Enumeration *enumeration = nullptr);
    std::expected<double, QString> number(const QJsonValue &value, const QString &path);

    const Schema &m_schema;
};

QString at(const QString &path)
{
    return path.isEmpty() ? QStringLiteral("(top)") : path;
}

std::expected<qint64, QString> Reader::integer(const QJsonValue &value, const QString &path, qint64 low, qint64 high,
                                               const Enumeration *enumeration)
{
    qint64 result = 0;
    if (value.isString()) {
        std::optional<qint64> parsed;
        if (enumeration) {
            parsed = enumeration->parse(value.toString());
        } else {
            bool ok = false;
            const qint64 v = value.toString().toLongLong(&ok, 0);
            if (ok)
                parsed = v;
        }
        if (!parsed)
            return std::unexpected(QStringLiteral("%1: '%2' is not %3").arg(at(path), value.toString(),
                enumeration ? QStringLiteral("a value of %1 (%2)").arg(enumeration->abbrev.isEmpty() ? enumeration->name : enumeration->abbrev,
                                                                      [&] { QStringList names; for (const auto &v : enumeration->values) names << v.abbrev; return names.join(QStringLiteral(", ")); }())
                            : QStringLiteral("an integer")));
        result = *parsed;
    } else if (value.isDouble()) {
        constexpr qint64 sentinel = std::numeric_limits<qint64>::min();
        result = value.toInteger(sentinel);
        if (result == sentinel && value.toDouble() != static_cast<double>(sentinel))
            return std::unexpected(QStringLiteral("%1: %2 is not an integer").arg(at(path)).arg(value.toDouble()));
    } else {
        return std::unexpected(QStringLiteral("%1: expected an integer").arg(at(path)));
    }
    if (result < low || result > high)
        return std::unexpected(QStringLiteral("%1: %2 is outside %3..%4").arg(at(path)).arg(result).arg(low).arg(high));
    return result;
}

std::expected<double, QString> Reader::number(const QJsonValue &value, const QString &path)
{
    if (value.isDouble())
        return value.toDouble();
    if (value.isString()) {
        const QString text = value.toString();
        if (text == u"NaN")
            return std::numeric_limits<double>::quiet_NaN();
        if (text == u"Infinity")
            return std::numeric_limits<double>::infinity();
        if (text == u"-Infinity")
            return -std::numeric_limits<double>::infinity();
        bool ok = false;
        const double v = text.toDouble(&ok);
        if (ok)
            return v;
    }
    return std::unexpected(QStringLiteral("%1: expected a number").arg(at(path)));
}

std::expected<void, QString> Reader::field(Message &message, int index, const QJsonValue &value, const QString &path)
{
    const FieldDef &def = message.field(index);
    switch (def.type) {
    case FieldType::Fp32:
    case FieldType::Fp64: {
        auto v = number(value, path);
        if (!v)
            return std::unexpected(v.error());
        message.setNumber(index, *v);
        return {};
    }
    case FieldType::PlainText: {
        if (value.isString()) {
            message.setBytes(index, value.toString().toUtf8());
            return {};
        }
        if (value.isObject() && value.toObject().value(QStringLiteral("hex")).isString()) {
            message.setBytes(index, QByteArray::fromHex(value.toObject().value(QStringLiteral("hex")).toString().toLatin1()));
            return {};
        }
        return std::unexpected(QStringLiteral("%1: expected a string").arg(at(path)));
    }
    case FieldType::RawData: {
        const QString hex = value.toString();
        static const QRegularExpression hexDigits(QStringLiteral("^([0-9a-fA-F]{2})*$"));
        if (!value.isString() || !hexDigits.match(hex).hasMatch())
            return std::unexpected(QStringLiteral("%1: expected bytes as a string of hex digit pairs").arg(at(path)));
        message.setBytes(index, QByteArray::fromHex(hex.toLatin1()));
        return {};
    }
    case FieldType::Message: {
        if (value.isNull()) {
            message.setInlineMessage(index, std::nullopt);
            return {};
        }
        if (!value.isObject())
            return std::unexpected(QStringLiteral("%1: expected a message object or null").arg(at(path)));
        auto inner = this->message(value.toObject(), path, false);
        if (!inner)
            return std::unexpected(inner.error());
        message.setInlineMessage(index, std::move(*inner));
        return {};
    }
    case FieldType::MessageList: {
        if (!value.isArray())
            return std::unexpected(QStringLiteral("%1: expected an array of messages").arg(at(path)));
        std::vector<Message> list;
        const QJsonArray array = value.toArray();
        for (qsizetype k = 0; k < array.size(); ++k) {
            const QString itemPath = QStringLiteral("%1[%2]").arg(path).arg(k);
            if (!array[k].isObject())
                return std::unexpected(QStringLiteral("%1: expected a message object").arg(itemPath));
            auto inner = this->message(array[k].toObject(), itemPath, false);
            if (!inner)
                return std::unexpected(inner.error());
            list.push_back(std::move(*inner));
        }
        message.setMessages(index, std::move(list));
        return {};
    }
    default: {
        qint64 low = std::numeric_limits<qint64>::min(), high = std::numeric_limits<qint64>::max();
        switch (def.type) {
        case FieldType::Int8: low = -128; high = 127; break;
        case FieldType::UInt8: low = 0; high = 255; break;
        case FieldType::Int16: low = -32768; high = 32767; break;
        case FieldType::UInt16: low = 0; high = 65535; break;
        case FieldType::Int32: low = std::numeric_limits<qint32>::min(); high = std::numeric_limits<qint32>::max(); break;
        case FieldType::UInt32: low = 0; high = std::numeric_limits<quint32>::max(); break;
        default: break;
        }
        auto v = integer(value, path, low, high, def.enumeration);
        if (!v)
            return std::unexpected(v.error());
        message.setInteger(index, *v);
        return {};
    }
    }
}

std::expected<Message, QString> Reader::message(const QJsonObject &json, const QString &path, bool withHeader)
{
    const QString prefix = path.isEmpty() ? QString() : path + u'.';
    Message message;
    if (json.contains(QStringLiteral("opaque"))) {
        auto id = integer(json.value(QStringLiteral("mgid")), prefix + QStringLiteral("mgid"), 0, 65534);
        if (!id)
            return std::unexpected(id.error());
        const QString hex = json.value(QStringLiteral("opaque")).toString();
        message = Message::opaque(static_cast<quint16>(*id), QByteArray::fromHex(hex.toLatin1()));
    } else {
        const QJsonValue abbrev = json.value(QStringLiteral("abbrev"));
        const MessageDef *def = nullptr;
        if (abbrev.isString()) {
            def = m_schema.byAbbrev(abbrev.toString());
            if (!def)
                return std::unexpected(QStringLiteral("%1abbrev: no message is called '%2'").arg(prefix, abbrev.toString()));
        } else if (json.contains(QStringLiteral("mgid"))) {
            auto id = integer(json.value(QStringLiteral("mgid")), prefix + QStringLiteral("mgid"), 0, 65534);
            if (!id)
                return std::unexpected(id.error());
            def = m_schema.byId(static_cast<quint16>(*id));
            if (!def)
                return std::unexpected(QStringLiteral("%1mgid: no message has id %2").arg(prefix).arg(*id));
        } else {
            return std::unexpected(QStringLiteral("%1: a message needs \"abbrev\" (or \"mgid\")").arg(at(path)));
        }
        message = Message(def);
        const QJsonValue fieldsValue = json.value(QStringLiteral("fields"));
        if (!fieldsValue.isUndefined() && !fieldsValue.isObject())
            return std::unexpected(QStringLiteral("%1fields: expected an object").arg(prefix));
        const QJsonObject fields = fieldsValue.toObject();
        for (auto it = fields.begin(); it != fields.end(); ++it) {
            const int index = def->indexOf(it.key());
            if (index < 0)
                return std::unexpected(QStringLiteral("%1fields.%2: %3 has no field '%2'").arg(prefix, it.key(), def->abbrev));
            if (auto ok = field(message, index, it.value(), prefix + QStringLiteral("fields.") + it.key()); !ok)
                return std::unexpected(ok.error());
        }
    }
    if (withHeader) {
        if (json.contains(QStringLiteral("timestamp"))) {
            auto t = number(json.value(QStringLiteral("timestamp")), prefix + QStringLiteral("timestamp"));
            if (!t)
                return std::unexpected(t.error());
            message.header.timestamp = *t;
        }
        struct HeaderKey { const char *key; qint64 high; };
        const HeaderKey keys[] = {{"src", 65535}, {"src_ent", 255}, {"dst", 65535}, {"dst_ent", 255}};
        for (const HeaderKey &key : keys) {
            const QString name = QString::fromLatin1(key.key);
            if (!json.contains(name))
                continue;
            auto v = integer(json.value(name), prefix + name, 0, key.high);
            if (!v)
                return std::unexpected(v.error());
            if (name == u"src") message.header.src = static_cast<quint16>(*v);
            else if (name == u"src_ent") message.header.srcEnt = static_cast<quint8>(*v);
            else if (name == u"dst") message.header.dst = static_cast<quint16>(*v);
            else message.header.dstEnt = static_cast<quint8>(*v);
        }
    }
    return message;
}

} // namespace

QJsonObject toJson(const Message &message)
{
    QJsonObject object;
    object.insert(QStringLiteral("mgid"), message.id());
    object.insert(QStringLiteral("timestamp"), numberToJson(message.header.timestamp));
    object.insert(QStringLiteral("src"), message.header.src);
    object.insert(QStringLiteral("src_ent"), message.header.srcEnt);
    object.insert(QStringLiteral("dst"), message.header.dst);
    object.insert(QStringLiteral("dst_ent"), message.header.dstEnt);
    return bodyToJson(message, object);
}

QJsonObject toJsonWithoutHeader(const Message &message)
{
    return bodyToJson(message, {});
}

std::expected<Message, QString> fromJson(const Schema &schema, const QJsonObject &json)
{
    return Reader(schema).message(json, {}, true);
}

QString toText(const Message &message)
{
    if (message.isOpaque())
        return QStringLiteral("%1 (%2 bytes, not in the schema)").arg(message.abbrev()).arg(message.opaquePayload().size());
    QStringList parts{message.abbrev()};
    for (int i = 0; i < message.fieldCount(); ++i) {
        const FieldDef &field = message.field(i);
        QString value;
        switch (field.type) {
        case FieldType::Fp32:
        case FieldType::Fp64: value = QString::number(message.number(i), 'g', 7); break;
        case FieldType::PlainText: value = u'"' + message.text(i) + u'"'; break;
        case FieldType::RawData: value = QStringLiteral("<%1 bytes>").arg(message.bytes(i).size()); break;
        case FieldType::Message: {
            const Message *inner = message.inlineMessage(i);
            value = inner ? u'{' + toText(*inner) + u'}' : QStringLiteral("none");
            break;
        }
        case FieldType::MessageList: value = QStringLiteral("[%1 messages]").arg(message.messages(i).size()); break;
        default: value = message.enumText(i); break;
        }
        const bool showUnit = !field.unit.isEmpty() && !field.enumeration && field.unit != u"Enumerated"
                              && field.unit != u"Bitfield" && field.unit != u"List" && field.unit != u"TupleList";
        parts.append(field.abbrev + u'=' + value + (showUnit ? u' ' + field.unit : QString()));
    }
    return parts.join(u' ');
}

} // namespace neptus::msg
