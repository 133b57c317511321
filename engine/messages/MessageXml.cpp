#include "messages/MessageJson.h"
#include "messages/MessageXml.h"

#include <QJsonArray>
#include <QJsonObject>

#include <numbers>

namespace neptus::msg {

using namespace Qt::StringLiterals;

double radiansFromDegrees(double degrees)
{
    return degrees * (std::numbers::pi / 180);
}

namespace {

// The element as MessageJson's object (which then checks every value).
std::expected<QJsonObject, QString> toJsonObject(const Schema &schema, const xml::Element &element, const QString &path)
{
    const MessageDef *def = schema.byAbbrev(element.name);
    if (!def)
        return std::unexpected(u"%1: no IMC message is called '%2'"_s.arg(path, element.name));
    QJsonObject fields;
    for (const xml::Element &child : element.children) {
        const QString fieldPath = path + u'/' + child.name;
        const FieldDef *field = def->field(child.name);
        if (!field)
            return std::unexpected(u"%1: %2 has no field '%3'"_s.arg(fieldPath, def->abbrev, child.name));
        if (fields.contains(child.name))
            return std::unexpected(u"%1: given twice"_s.arg(fieldPath));
        switch (field->type) {
        case FieldType::Message: {
            if (child.children.empty()) {
                fields.insert(child.name, QJsonValue::Null);
                break;
            }
            if (child.children.size() > 1)
                return std::unexpected(u"%1: holds one message, not %2"_s.arg(fieldPath).arg(child.children.size()));
            auto inner = toJsonObject(schema, child.children.front(), fieldPath);
            if (!inner)
                return std::unexpected(inner.error());
            fields.insert(child.name, *inner);
            break;
        }
        case FieldType::MessageList: {
            QJsonArray list;
            for (const xml::Element &item : child.children) {
                auto inner = toJsonObject(schema, item, fieldPath);
                if (!inner)
                    return std::unexpected(inner.error());
                list.append(*inner);
            }
            fields.insert(child.name, list);
            break;
        }
        case FieldType::Fp32:
        case FieldType::Fp64: {
            bool ok = false;
            double value = child.text.toDouble(&ok);
            if (!ok)
                return std::unexpected(u"%1: '%2' is not a number"_s.arg(fieldPath, child.text));
            const QString unit = child.attribute(u"unit"_s);
            if (unit == u"deg" && field->unit == u"rad")
                value = radiansFromDegrees(value);
            else if (!unit.isEmpty() && unit != field->unit)
                return std::unexpected(u"%1: unit '%2' where %3 is in '%4'"_s.arg(fieldPath, unit, child.name, field->unit));
            fields.insert(child.name, value);
            break;
        }
        case FieldType::PlainText:
        case FieldType::RawData:
            fields.insert(child.name, child.text);
            break;
        default: {
            // Integers: a name, a number, or a number written as 3.0.
            bool ok = false;
            const double number = child.text.toDouble(&ok);
            if (ok && !field->enumeration && number == static_cast<double>(static_cast<qint64>(number)))
                fields.insert(child.name, number);
            else
                fields.insert(child.name, child.text);
        }
        }
    }
    return QJsonObject{{u"abbrev"_s, def->abbrev}, {u"fields"_s, fields}};
}

} // namespace

std::expected<Message, QString> fromXml(const Schema &schema, const xml::Element &element)
{
    auto json = toJsonObject(schema, element, element.name);
    if (!json)
        return std::unexpected(json.error());
    for (const char *key : {"src", "src_ent", "dst", "dst_ent"}) {
        const QString value = element.attribute(QString::fromLatin1(key));
        if (!value.isEmpty())
            json->insert(QString::fromLatin1(key), value.toDouble());
    }
    if (const QString time = element.attribute(u"time"_s); !time.isEmpty())
        json->insert(u"timestamp"_s, time.toDouble());
    auto message = fromJson(schema, *json);
    if (!message)
        return std::unexpected(u"%1: %2"_s.arg(element.name, message.error()));
    return message;
}

xml::Element toXml(const Message &message)
{
    xml::Element element;
    element.name = message.abbrev();
    for (int i = 0; i < message.fieldCount(); ++i) {
        const FieldDef &field = message.field(i);
        xml::Element child;
        child.name = field.abbrev;
        switch (field.type) {
        case FieldType::Message:
            if (const Message *inner = message.inlineMessage(i))
                child.children.push_back(toXml(*inner));
            break;
        case FieldType::MessageList:
            for (const Message &inner : message.messages(i))
                child.children.push_back(toXml(inner));
            break;
        case FieldType::RawData:
            child.text = QString::fromLatin1(message.bytes(i).toHex());
            break;
        case FieldType::PlainText:
            child.text = message.text(i);
            break;
        case FieldType::Fp32:
        case FieldType::Fp64:
            child.text = QString::number(message.number(i), 'g', 17);
            break;
        default:
            child.text = field.enumeration ? message.enumText(i) : QString::number(message.integer(i));
        }
        element.children.push_back(child);
    }
    return element;
}

} // namespace neptus::msg
