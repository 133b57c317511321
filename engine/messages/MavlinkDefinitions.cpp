// MAVLink's XML dialects read into the schema model (Schema::MavlinkLoader):
// the same MessageDef, FieldDef and Enumeration the IMC reader fills, plus
// what MAVLink's rules work out from a definition — each message's wire order
// (fields sorted by element size, largest first, the extensions after them
// as declared), its payload lengths and its CRC_EXTRA (CRC-16/MCRF4XX of
// "NAME ", then "type name " of each field in wire order and an array's
// length, leaving the extensions out).
#include "messages/Crc16.h"
#include "messages/Schema.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <functional>

namespace neptus::msg {

using namespace Qt::StringLiterals;
using xml::XmlDocument;
using xml::XmlError;

namespace {

struct MavType
{
    FieldType type;
    int size;
    const char *crcName; // as it goes into CRC_EXTRA
};

// Element types: MAVLink's names, and "char" (a text when an array).
std::optional<MavType> mavlinkType(QStringView name)
{
    static const std::pair<const char *, MavType> types[] = {
        {"int8_t", {FieldType::Int8, 1, "int8_t"}},       {"uint8_t", {FieldType::UInt8, 1, "uint8_t"}},
        {"int16_t", {FieldType::Int16, 2, "int16_t"}},    {"uint16_t", {FieldType::UInt16, 2, "uint16_t"}},
        {"int32_t", {FieldType::Int32, 4, "int32_t"}},    {"uint32_t", {FieldType::UInt32, 4, "uint32_t"}},
        {"int64_t", {FieldType::Int64, 8, "int64_t"}},    {"uint64_t", {FieldType::UInt64, 8, "uint64_t"}},
        {"float", {FieldType::Fp32, 4, "float"}},         {"double", {FieldType::Fp64, 8, "double"}},
        {"char", {FieldType::Int8, 1, "char"}},           {"uint8_t_mavlink_version", {FieldType::UInt8, 1, "uint8_t"}},
    };
    for (const auto &[n, t] : types)
        if (name == QLatin1StringView(n))
            return t;
    return std::nullopt;
}

// A field as declared: what CRC_EXTRA and the wire order are made from.
struct Declared
{
    QString name;
    MavType type;
    int arrayLength = 0; // 0: a scalar
    bool extension = false;
    int firstField = 0;  // its first FieldDef (numeric arrays take one per element)
};

} // namespace

class Schema::MavlinkLoader
{
public:
    using Read = Schema::ReadByName;

    MavlinkLoader(Schema &schema, Read read)
        : m_schema(schema)
        , m_read(std::move(read))
    {
    }

    // A dialect file, after the files it includes (each read once).
    std::expected<void, XmlError> addFile(const QString &path, int depth = 0);
    std::expected<void, XmlError> finish();

private:
    using Result = std::expected<void, XmlError>;
    Result readEnum(const XmlDocument &doc, const xmlNode *element);
    Result readMessage(const XmlDocument &doc, const xmlNode *element);

    struct PendingEnum
    {
        MessageDef *message;
        size_t field;
        QString name;
        XmlError place;
    };

    Schema &m_schema;
    Read m_read;
    QSet<QString> m_files; // read already (by file name)
    QString m_version = u"3"_s;
    QHash<QString, Enumeration *> m_enums;
    QHash<Enumeration *, qint64> m_enumHighest;
    QHash<quint16, QString> m_idPlace;
    QHash<QString, QString> m_namePlace;
    std::vector<PendingEnum> m_pendingEnums;
    std::map<const MessageDef *, std::vector<Declared>> m_declared;
};

std::expected<void, XmlError> Schema::MavlinkLoader::addFile(const QString &path, int depth)
{
    const QString name = QFileInfo(path).fileName();
    if (m_files.contains(name))
        return {};
    if (depth > 16)
        return std::unexpected(XmlError{path, 0, 0, u"%1: includes nest deeper than 16 files (a cycle?)"_s.arg(path)});
    m_files.insert(name);
    auto doc = m_read(path);
    if (!doc)
        return std::unexpected(doc.error());
    const xmlNode *root = doc->root();
    if (xml::elementName(root) != u"mavlink")
        return std::unexpected(doc->errorAt(root, u"the root element is <%1>; a MAVLink dialect starts with <mavlink>"_s
                                                      .arg(xml::elementName(root))));
    for (const xmlNode *include : xml::childElements(root, "include")) {
        const QString included = xml::textContent(include).trimmed();
        if (included.isEmpty() || included.contains(u'/') || included.contains(u'\\'))
            return std::unexpected(doc->errorAt(include, u"<include> names '%1': a file beside this one is expected"_s.arg(included)));
        if (auto ok = addFile(QFileInfo(path).dir().filePath(included), depth + 1); !ok)
            return ok;
    }
    m_schema.m_files.append(doc->fileName());
    if (const xmlNode *version = xml::firstChildElement(root, "version"))
        m_version = xml::textContent(version).trimmed();
    for (const xmlNode *section : xml::childElements(root, "enums"))
        for (const xmlNode *element : xml::childElements(section, "enum"))
            if (auto ok = readEnum(*doc, element); !ok)
                return ok;
    for (const xmlNode *section : xml::childElements(root, "messages"))
        for (const xmlNode *element : xml::childElements(section, "message"))
            if (auto ok = readMessage(*doc, element); !ok)
                return ok;
    return {};
}

// An enum, or more entries of one declared in another file (MAVLink lets a
// dialect extend common.xml's MAV_CMD); an entry without a value follows the highest so far.
std::expected<void, XmlError> Schema::MavlinkLoader::readEnum(const XmlDocument &doc, const xmlNode *element)
{
    const QString name = xml::attribute(element, "name");
    if (name.isEmpty())
        return std::unexpected(doc.errorAt(element, u"an <enum> needs a name"_s));
    Enumeration *e = m_enums.value(name);
    if (!e) {
        auto made = std::make_unique<Enumeration>();
        made->name = made->abbrev = name;
        made->bitfield = xml::attribute(element, "bitmask") == u"true";
        e = made.get();
        m_schema.m_enumerations.push_back(std::move(made));
        m_enums.insert(name, e);
        m_enumHighest.insert(e, -1);
    }
    for (const xmlNode *entry : xml::childElements(element, "entry")) {
        Enumeration::Value value;
        value.abbrev = value.name = xml::attribute(entry, "name");
        if (value.abbrev.isEmpty())
            return std::unexpected(doc.errorAt(entry, u"%1: an <entry> needs a name"_s.arg(name)));
        // What people read: the entry's description ("Current mission operation cancelled (e.g. …)").
        if (const xmlNode *description = xml::firstChildElement(entry, "description"))
            if (const QString said = xml::textContent(description).simplified(); !said.isEmpty())
                value.name = said;
        const QString text = xml::attribute(entry, "value");
        if (text.isEmpty()) {
            value.value = m_enumHighest.value(e) + 1;
        } else {
            bool ok = false;
            value.value = text.startsWith(u"0x"_s) ? qint64(text.mid(2).toULongLong(&ok, 16)) : text.toLongLong(&ok);
            if (!ok)
                return std::unexpected(doc.errorAt(entry, u"%1.%2: value '%3' is not an integer"_s.arg(name, value.abbrev, text)));
        }
        m_enumHighest[e] = std::max(m_enumHighest.value(e), value.value);
        e->values.push_back(std::move(value));
    }
    return {};
}

std::expected<void, XmlError> Schema::MavlinkLoader::readMessage(const XmlDocument &doc, const xmlNode *element)
{
    auto message = std::make_unique<MessageDef>();
    message->mavlink = true;
    bool ok = false;
    const qint64 id = xml::attribute(element, "id").toLongLong(&ok);
    message->abbrev = message->name = xml::attribute(element, "name");
    message->file = doc.fileName();
    message->line = static_cast<int>(xmlGetLineNo(element));
    // Ids past 65534 are MAVLink 2's 24-bit ones: none of the standard dialects uses them yet.
    if (!ok || id < 0 || id >= noMessage)
        return std::unexpected(doc.errorAt(element, u"message %1: id '%2' must be an integer from 0 to 65534"_s
                                                        .arg(message->abbrev, xml::attribute(element, "id"))));
    message->id = quint16(id);
    static const QRegularExpression identifier(u"^[A-Za-z_][A-Za-z0-9_]*$"_s);
    if (!identifier.match(message->abbrev).hasMatch())
        return std::unexpected(doc.errorAt(element, u"message %1 needs a name that is an identifier, not '%2'"_s.arg(id).arg(message->abbrev)));
    if (m_idPlace.contains(message->id))
        return std::unexpected(doc.errorAt(element, u"message id %1 (%2) is already used by %3"_s.arg(id).arg(message->abbrev, m_idPlace.value(message->id))));
    if (m_namePlace.contains(message->abbrev))
        return std::unexpected(doc.errorAt(element, u"message name %1 (id %2) is already used at %3"_s.arg(message->abbrev).arg(id).arg(m_namePlace.value(message->abbrev))));
    const QString place = u"%1:%2"_s.arg(doc.fileName()).arg(message->line);
    m_idPlace.insert(message->id, message->abbrev + u" at "_s + place);
    m_namePlace.insert(message->abbrev, place);

    std::vector<Declared> declared;
    bool extensions = false;
    for (const xmlNode *child : xml::childElements(element)) {
        const QString tag = xml::elementName(child);
        if (tag == u"extensions") {
            extensions = true;
            continue;
        }
        if (tag != u"field")
            continue;
        Declared d;
        d.name = xml::attribute(child, "name");
        d.extension = extensions;
        const auto fail = [&](const QString &what) {
            return std::unexpected(doc.errorAt(child, u"%1.%2: %3"_s.arg(message->abbrev, d.name.isEmpty() ? u"?"_s : d.name, what)));
        };
        if (!identifier.match(d.name).hasMatch())
            return fail(u"a field needs a name that is an identifier"_s);
        QString type = xml::attribute(child, "type");
        static const QRegularExpression array(u"^(\\w+)\\[(\\d+)\\]$"_s);
        if (const auto match = array.match(type); match.hasMatch()) {
            type = match.captured(1);
            d.arrayLength = match.captured(2).toInt();
            if (d.arrayLength < 1 || d.arrayLength > 255)
                return fail(u"array length %1 is not 1 to 255"_s.arg(d.arrayLength));
        }
        const auto t = mavlinkType(type);
        if (!t || (type == u"uint8_t_mavlink_version" && d.arrayLength))
            return fail(u"unknown type '%1' (known: int8_t … uint64_t, float, double, char, uint8_t_mavlink_version, "
                        "and arrays of them as type[N])"_s.arg(xml::attribute(child, "type")));
        d.type = *t;
        d.firstField = int(message->fields.size());
        FieldDef base;
        base.unit = xml::attribute(child, "units");
        base.line = static_cast<int>(xmlGetLineNo(child));
        base.extension = extensions;
        if (type == u"uint8_t_mavlink_version")
            base.value = m_version; // HEARTBEAT.mavlink_version: the dialect's version, whoever fills it
        const QString enumName = xml::attribute(child, "enum");
        const auto add = [&](FieldDef f) {
            if (message->fieldIndex.contains(f.abbrev))
                return false;
            message->fieldIndex.insert(f.abbrev, int(message->fields.size()));
            if (!enumName.isEmpty() && isInteger(f.type))
                m_pendingEnums.push_back({message.get(), message->fields.size(), enumName, doc.errorAt(child, {})});
            message->fields.push_back(std::move(f));
            return true;
        };
        bool added = true;
        if (d.arrayLength && (type == u"char" || type == u"uint8_t")) {
            // A fixed-length text or byte string: one field.
            FieldDef f = base;
            f.abbrev = f.name = d.name;
            f.type = type == u"char" ? FieldType::PlainText : FieldType::RawData;
            f.fixedLength = d.arrayLength;
            added = add(std::move(f));
        } else if (d.arrayLength) {
            for (int i = 0; i < d.arrayLength && added; ++i) {
                FieldDef f = base;
                f.abbrev = f.name = u"%1[%2]"_s.arg(d.name).arg(i);
                f.type = t->type;
                added = add(std::move(f));
            }
        } else {
            FieldDef f = base;
            f.abbrev = f.name = d.name;
            f.type = t->type;
            added = add(std::move(f));
        }
        if (!added)
            return fail(u"the message has two fields named %1"_s.arg(d.name));
        declared.push_back(std::move(d));
    }
    m_declared[message.get()] = std::move(declared);
    m_schema.m_messages.push_back(std::move(message));
    return {};
}

std::expected<void, XmlError> Schema::MavlinkLoader::finish()
{
    for (const PendingEnum &pending : m_pendingEnums) {
        const Enumeration *e = m_enums.value(pending.name);
        if (!e) {
            XmlError error = pending.place;
            error.message = u"%1.%2: enum '%3' names no enum of the dialect"_s.arg(
                pending.message->abbrev, pending.message->fields[pending.field].abbrev, pending.name);
            return std::unexpected(error);
        }
        pending.message->fields[pending.field].enumeration = e;
    }
    std::sort(m_schema.m_messages.begin(), m_schema.m_messages.end(), [](const auto &a, const auto &b) { return a->id < b->id; });
    for (const auto &message : m_schema.m_messages)
        m_schema.m_byAbbrev.insert(message->abbrev, message.get());
    if (!m_schema.m_messages.empty())
        m_schema.m_byId.assign(m_schema.m_messages.back()->id + 1u, nullptr);
    for (const auto &message : m_schema.m_messages)
        m_schema.m_byId[message->id] = message.get();

    for (const auto &m : m_schema.m_messages) {
        MessageDef &def = *m;
        int slot = 0;
        for (FieldDef &field : def.fields)
            field.storage = field.type == FieldType::PlainText || field.type == FieldType::RawData ? def.byteStringCount++ : slot++;
        // The wire order: the declared fields by element size (stable), the extensions after.
        std::vector<const Declared *> order;
        for (const Declared &d : m_declared[&def])
            order.push_back(&d);
        const auto firstExtension = std::find_if(order.begin(), order.end(), [](const Declared *d) { return d->extension; });
        std::stable_sort(order.begin(), firstExtension, [](const Declared *a, const Declared *b) { return a->type.size > b->type.size; });
        QByteArray crcText = def.abbrev.toLatin1() + ' ';
        QByteArray lengths;
        int offset = 0;
        for (const Declared *d : order) {
            if (!d->extension) {
                crcText += QByteArray(d->type.crcName) + ' ' + d->name.toLatin1() + ' ';
                if (d->arrayLength)
                    crcText += char(d->arrayLength);
            }
            const FieldDef &first = def.fields[size_t(d->firstField)];
            if (first.fixedLength) {
                def.mavlinkWire.push_back({first.type, quint8(first.fixedLength), quint16(first.storage), quint16(offset), quint16(d->firstField)});
                offset += first.fixedLength;
            } else {
                for (int i = 0; i < std::max(1, d->arrayLength); ++i) {
                    const FieldDef &f = def.fields[size_t(d->firstField + i)];
                    def.mavlinkWire.push_back({f.type, quint8(d->type.size), quint16(f.storage), quint16(offset), quint16(d->firstField + i)});
                    offset += d->type.size;
                }
            }
            if (!d->extension)
                def.mavlinkBaseLength = offset;
        }
        def.mavlinkLength = offset;
        if (def.mavlinkLength > 255) {
            XmlError error{def.file, def.line, 0, u"%1: a payload of %2 bytes is over MAVLink's 255"_s.arg(def.abbrev).arg(def.mavlinkLength)};
            return std::unexpected(error);
        }
        const quint16 crc = crcMcrf4xx(crcText);
        def.crcExtra = quint8((crc & 0xFF) ^ (crc >> 8));
    }
    m_schema.m_digest = QCryptographicHash::hash(m_schema.canonicalText(), QCryptographicHash::Md5).toHex();
    return {};
}

std::expected<std::shared_ptr<const Schema>, XmlError> Schema::buildMavlink(const QStringList &names, ReadByName read)
{
    auto schema = std::shared_ptr<Schema>(new Schema);
    schema->m_protocol = Protocol::Mavlink;
    schema->m_sync = 0xFD;
    MavlinkLoader loader(*schema, read);
    for (const QString &name : names)
        if (auto ok = loader.addFile(name); !ok)
            return std::unexpected(ok.error());
    if (auto ok = loader.finish(); !ok)
        return std::unexpected(ok.error());
    schema->m_name = QFileInfo(names.front()).completeBaseName();
    schema->m_version = u"MAVLink 2"_s;
    return schema;
}

} // namespace neptus::msg
