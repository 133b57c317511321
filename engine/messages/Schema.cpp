#include "messages/Schema.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <limits>

namespace neptus::msg {

using xml::XmlDocument;
using xml::XmlError;

namespace {

struct TypeInfo
{
    FieldType type;
    const char *name;
    int size;
};

constexpr TypeInfo typeTable[] = {
    {FieldType::Int8, "int8_t", 1},        {FieldType::UInt8, "uint8_t", 1},
    {FieldType::Int16, "int16_t", 2},      {FieldType::UInt16, "uint16_t", 2},
    {FieldType::Int32, "int32_t", 4},      {FieldType::UInt32, "uint32_t", 4},
    {FieldType::Int64, "int64_t", 8},      {FieldType::UInt64, "uint64_t", 8}, {FieldType::Fp32, "fp32_t", 4},
    {FieldType::Fp64, "fp64_t", 8},        {FieldType::RawData, "rawdata", 0},
    {FieldType::PlainText, "plaintext", 0}, {FieldType::Message, "message", 0},
    {FieldType::MessageList, "message-list", 0},
};

std::optional<qint64> parseInteger(QStringView text)
{
    text = text.trimmed();
    bool ok = false;
    qint64 value = 0;
    if (text.startsWith(u"0x") || text.startsWith(u"0X"))
        value = static_cast<qint64>(text.mid(2).toULongLong(&ok, 16));
    else if (text.startsWith(u"-0x") || text.startsWith(u"-0X"))
        value = -static_cast<qint64>(text.mid(3).toULongLong(&ok, 16));
    else
        value = text.toLongLong(&ok, 10);
    if (!ok)
        return std::nullopt;
    return value;
}

// The range an integer type can hold, for checking enumeration values.
std::pair<qint64, qint64> integerRange(FieldType type)
{
    switch (type) {
    case FieldType::Int8: return {-128, 127};
    case FieldType::UInt8: return {0, 255};
    case FieldType::Int16: return {-32768, 32767};
    case FieldType::UInt16: return {0, 65535};
    case FieldType::Int32: return {std::numeric_limits<qint32>::min(), std::numeric_limits<qint32>::max()};
    case FieldType::UInt32: return {0, std::numeric_limits<quint32>::max()};
    default: return {std::numeric_limits<qint64>::min(), std::numeric_limits<qint64>::max()};
    }
}

bool isIdentifier(const QString &text)
{
    static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_][A-Za-z0-9_]*$"));
    return identifier.match(text).hasMatch();
}

} // namespace

QString typeName(FieldType type)
{
    return QString::fromLatin1(typeTable[static_cast<int>(type)].name);
}

std::optional<FieldType> typeFromName(QStringView name)
{
    for (const TypeInfo &info : typeTable) {
        if (name == QLatin1StringView(info.name))
            return info.type;
    }
    return std::nullopt;
}

int wireSize(FieldType type)
{
    return typeTable[static_cast<int>(type)].size;
}

bool isInteger(FieldType type)
{
    return type <= FieldType::UInt64;
}

bool isFloat(FieldType type)
{
    return type == FieldType::Fp32 || type == FieldType::Fp64;
}

// --- Enumeration -------------------------------------------------------------

const Enumeration::Value *Enumeration::find(qint64 value) const
{
    for (const Value &v : values) {
        if (v.value == value)
            return &v;
    }
    return nullptr;
}

std::optional<qint64> Enumeration::valueOf(QStringView abbrev) const
{
    for (const Value &v : values) {
        if (v.abbrev == abbrev)
            return v.value;
    }
    return std::nullopt;
}

QString Enumeration::format(qint64 value) const
{
    if (!bitfield) {
        const Value *v = find(value);
        return v ? v->abbrev : QString::number(value);
    }
    if (value == 0) {
        const Value *none = find(0);
        return none ? none->abbrev : QStringLiteral("0");
    }
    QStringList parts;
    quint64 rest = static_cast<quint64>(value);
    for (const Value &v : values) {
        const auto bits = static_cast<quint64>(v.value);
        if (bits != 0 && (rest & bits) == bits) {
            parts.append(v.abbrev);
            rest &= ~bits;
        }
    }
    if (rest != 0)
        parts.append(QStringLiteral("0x") + QString::number(rest, 16));
    return parts.join(u'|');
}

std::optional<qint64> Enumeration::parse(QStringView text) const
{
    if (auto number = parseInteger(text))
        return number;
    if (!bitfield)
        return valueOf(text.trimmed());
    qint64 result = 0;
    for (QStringView part : text.split(u'|')) {
        part = part.trimmed();
        auto bits = parseInteger(part);
        if (!bits)
            bits = valueOf(part);
        if (!bits)
            return std::nullopt;
        result |= *bits;
    }
    return result;
}

// --- MessageDef ----------------------------------------------------------------

int MessageDef::indexOf(QStringView fieldAbbrev) const
{
    // A scan beats hashing for the few fields most messages have.
    if (fields.size() <= 16) {
        for (size_t i = 0; i < fields.size(); ++i) {
            if (fields[i].abbrev == fieldAbbrev)
                return static_cast<int>(i);
        }
        return -1;
    }
    return fieldIndex.value(fieldAbbrev.toString(), -1);
}

const FieldDef *MessageDef::field(QStringView fieldAbbrev) const
{
    const int index = indexOf(fieldAbbrev);
    return index < 0 ? nullptr : &fields[static_cast<size_t>(index)];
}

// --- Loader --------------------------------------------------------------------

class Schema::Loader
{
public:
    explicit Loader(Schema &schema)
        : m_schema(schema)
    {
    }

    std::expected<void, XmlError> add(const XmlDocument &document);
    std::expected<void, XmlError> finish();

private:
    using Result = std::expected<void, XmlError>;

    Result readEnumerations(const XmlDocument &doc, const xmlNode *section, bool bitfields);
    Result readValues(const XmlDocument &doc, const xmlNode *parent, Enumeration &into, FieldType type);
    Result readGroups(const XmlDocument &doc, const xmlNode *section);
    Result readHeader(const XmlDocument &doc, const xmlNode *header, const xmlNode *footer);
    Result readMessage(const XmlDocument &doc, const xmlNode *element);
    Result readField(const XmlDocument &doc, const xmlNode *element, MessageDef &message);

    QString where(const XmlDocument &doc, const xmlNode *node) const
    {
        return QStringLiteral("%1:%2").arg(doc.fileName()).arg(xmlGetLineNo(node));
    }

    struct PendingGroupMember
    {
        QString group;
        QString member;
        XmlError place;
    };
    struct PendingMessageType
    {
        MessageDef *message;
        size_t field;
        XmlError place;
    };

    Schema &m_schema;
    bool m_headerSeen = false;
    QHash<quint16, QString> m_idPlace;
    QHash<QString, QString> m_abbrevPlace;
    QHash<QString, QString> m_enumPlace;
    std::vector<PendingGroupMember> m_groupMembers;
    std::vector<PendingMessageType> m_messageTypes;
};

std::expected<void, XmlError> Schema::Loader::add(const XmlDocument &doc)
{
    const xmlNode *root = doc.root();
    if (xml::elementName(root) != u"messages")
        return std::unexpected(doc.errorAt(root, QStringLiteral("the root element is <%1>; message definitions "
                                                                "start with <messages>").arg(xml::elementName(root))));
    m_schema.m_files.append(doc.fileName());
    if (m_schema.m_name.isEmpty())
        m_schema.m_name = xml::attribute(root, "name");
    if (m_schema.m_version.isEmpty())
        m_schema.m_version = xml::attribute(root, "version");

    // Enumerations first: fields refer to them.
    for (const xmlNode *section : xml::childElements(root, "enumerations")) {
        if (auto ok = readEnumerations(doc, section, false); !ok)
            return ok;
    }
    for (const xmlNode *section : xml::childElements(root, "bitfields")) {
        if (auto ok = readEnumerations(doc, section, true); !ok)
            return ok;
    }
    for (const xmlNode *section : xml::childElements(root, "message-groups")) {
        if (auto ok = readGroups(doc, section); !ok)
            return ok;
    }
    if (auto ok = readHeader(doc, xml::firstChildElement(root, "header"), xml::firstChildElement(root, "footer")); !ok)
        return ok;
    for (const xmlNode *element : xml::childElements(root, "message")) {
        if (auto ok = readMessage(doc, element); !ok)
            return ok;
    }
    return {};
}

std::expected<void, XmlError> Schema::Loader::readEnumerations(const XmlDocument &doc, const xmlNode *section,
                                                               bool bitfields)
{
    auto &list = bitfields ? m_schema.m_bitfields : m_schema.m_enumerations;
    for (const xmlNode *def : xml::childElements(section, "def")) {
        auto enumeration = std::make_unique<Enumeration>();
        enumeration->name = xml::attribute(def, "name");
        enumeration->abbrev = xml::attribute(def, "abbrev");
        enumeration->prefix = xml::attribute(def, "prefix");
        enumeration->bitfield = bitfields;
        if (!isIdentifier(enumeration->abbrev))
            return std::unexpected(doc.errorAt(def, QStringLiteral("%1 needs an abbrev that is an identifier, not '%2'")
                                                        .arg(bitfields ? u"bitfield" : u"enumeration")
                                                        .arg(enumeration->abbrev)));
        const QString key = (bitfields ? QStringLiteral("bitfield ") : QStringLiteral("enumeration "))
                            + enumeration->abbrev;
        if (m_enumPlace.contains(key))
            return std::unexpected(doc.errorAt(def, QStringLiteral("%1 is defined twice (first at %2)")
                                                        .arg(key, m_enumPlace.value(key))));
        m_enumPlace.insert(key, where(doc, def));
        // Global definitions do not know the width of the fields that use
        // them; values are checked against each field's type when it refers.
        if (auto ok = readValues(doc, def, *enumeration, FieldType::Int64); !ok)
            return ok;
        list.push_back(std::move(enumeration));
    }
    return {};
}

std::expected<void, XmlError> Schema::Loader::readValues(const XmlDocument &doc, const xmlNode *parent,
                                                         Enumeration &into, FieldType type)
{
    const auto [low, high] = integerRange(type);
    for (const xmlNode *element : xml::childElements(parent, "value")) {
        Enumeration::Value value;
        const auto number = parseInteger(xml::attribute(element, "id"));
        if (!number)
            return std::unexpected(doc.errorAt(element, QStringLiteral("value id '%1' is not an integer")
                                                            .arg(xml::attribute(element, "id"))));
        value.value = *number;
        value.abbrev = xml::attribute(element, "abbrev");
        value.name = xml::attribute(element, "name");
        if (value.abbrev.isEmpty())
            return std::unexpected(doc.errorAt(element, QStringLiteral("value %1 has no abbrev").arg(*number)));
        if (value.value < low || value.value > high)
            return std::unexpected(doc.errorAt(element, QStringLiteral("value %1 (%2) does not fit the field's type %3")
                                                            .arg(value.abbrev).arg(value.value).arg(typeName(type))));
        if (into.find(value.value) && !into.bitfield)
            return std::unexpected(doc.errorAt(element, QStringLiteral("value %1 is listed twice").arg(value.value)));
        if (into.valueOf(value.abbrev))
            return std::unexpected(doc.errorAt(element, QStringLiteral("value abbrev %1 is listed twice").arg(value.abbrev)));
        into.values.push_back(std::move(value));
    }
    return {};
}

std::expected<void, XmlError> Schema::Loader::readGroups(const XmlDocument &doc, const xmlNode *section)
{
    for (const xmlNode *element : xml::childElements(section, "message-group")) {
        const QString abbrev = xml::attribute(element, "abbrev");
        if (!isIdentifier(abbrev))
            return std::unexpected(doc.errorAt(element, QStringLiteral("message group needs an identifier abbrev, not '%1'")
                                                            .arg(abbrev)));
        auto existing = std::find_if(m_schema.m_groups.begin(), m_schema.m_groups.end(),
                                     [&](const MessageGroup &g) { return g.abbrev == abbrev; });
        if (existing == m_schema.m_groups.end()) {
            // A later file may add members to a group an earlier one declared.
            m_schema.m_groups.push_back({xml::attribute(element, "name"), abbrev, {}});
            existing = std::prev(m_schema.m_groups.end());
        }
        for (const xmlNode *member : xml::childElements(element, "message-type")) {
            const QString name = xml::attribute(member, "abbrev");
            if (!existing->members.contains(name))
                existing->members.append(name);
            m_groupMembers.push_back({abbrev, name, doc.errorAt(member, {})});
        }
    }
    return {};
}

std::expected<void, XmlError> Schema::Loader::readHeader(const XmlDocument &doc, const xmlNode *header,
                                                         const xmlNode *footer)
{
    if (!header && !footer)
        return {};
    // The codec implements IMC's packet layout; a file that declares another
    // one would be decoded wrongly, so it is refused.
    static const std::pair<const char *, FieldType> imcHeader[] = {
        {"sync", FieldType::UInt16}, {"mgid", FieldType::UInt16},  {"size", FieldType::UInt16},
        {"timestamp", FieldType::Fp64}, {"src", FieldType::UInt16}, {"src_ent", FieldType::UInt8},
        {"dst", FieldType::UInt16},  {"dst_ent", FieldType::UInt8},
    };
    auto check = [&](const xmlNode *section, auto begin, auto end, const char *what) -> Result {
        if (!section)
            return std::unexpected(doc.errorAt(header ? header : footer,
                                               QStringLiteral("a file that declares a header must declare a footer too, and the other way round")));
        const auto fields = xml::childElements(section, "field");
        auto expected = begin;
        for (const xmlNode *field : fields) {
            if (expected == end || xml::attribute(field, "abbrev") != QLatin1StringView(expected->first)
                || typeFromName(xml::attribute(field, "type")) != expected->second)
                return std::unexpected(doc.errorAt(field, QStringLiteral("unsupported %1: Neptus-Qt speaks the IMC packet layout "
                                                                         "(header sync, mgid, size, timestamp, src, src_ent, dst, dst_ent; "
                                                                         "footer crc16)").arg(QLatin1StringView(what))));
            ++expected;
        }
        if (expected != end)
            return std::unexpected(doc.errorAt(section, QStringLiteral("the %1 lacks field %2").arg(QLatin1StringView(what))
                                                            .arg(QLatin1StringView(expected->first))));
        return {};
    };
    if (auto ok = check(header, std::begin(imcHeader), std::end(imcHeader), "header"); !ok)
        return ok;
    static const std::pair<const char *, FieldType> imcFooter[] = {{"crc16", FieldType::UInt16}};
    if (auto ok = check(footer, std::begin(imcFooter), std::end(imcFooter), "footer"); !ok)
        return ok;

    const xmlNode *syncField = xml::childElements(header, "field").constFirst();
    const auto sync = parseInteger(xml::attribute(syncField, "value"));
    if (!sync || *sync < 0 || *sync > 0xFFFF || ((*sync >> 8) & 0xFF) == (*sync & 0xFF))
        return std::unexpected(doc.errorAt(syncField, QStringLiteral("the sync field needs a 16-bit value whose two bytes differ "
                                                                     "(it tells the byte order), not '%1'")
                                                          .arg(xml::attribute(syncField, "value"))));
    if (m_headerSeen && m_schema.m_sync != *sync)
        return std::unexpected(doc.errorAt(syncField, QStringLiteral("sync 0x%1 differs from the 0x%2 of an earlier file")
                                                          .arg(*sync, 4, 16, QLatin1Char('0'))
                                                          .arg(m_schema.m_sync, 4, 16, QLatin1Char('0'))));
    m_schema.m_sync = static_cast<quint16>(*sync);
    m_headerSeen = true;
    return {};
}

std::expected<void, XmlError> Schema::Loader::readMessage(const XmlDocument &doc, const xmlNode *element)
{
    auto message = std::make_unique<MessageDef>();
    const auto id = parseInteger(xml::attribute(element, "id"));
    if (!id || *id < 0 || *id >= noMessage)
        return std::unexpected(doc.errorAt(element, QStringLiteral("message id '%1' must be an integer from 0 to 65534")
                                                        .arg(xml::attribute(element, "id"))));
    message->id = static_cast<quint16>(*id);
    message->abbrev = xml::attribute(element, "abbrev");
    message->name = xml::attribute(element, "name");
    message->category = xml::attribute(element, "category");
    message->file = doc.fileName();
    message->line = static_cast<int>(xmlGetLineNo(element));
    if (!isIdentifier(message->abbrev))
        return std::unexpected(doc.errorAt(element, QStringLiteral("message %1 needs an abbrev that is an identifier, not '%2'")
                                                        .arg(*id).arg(message->abbrev)));
    if (message->name.isEmpty())
        message->name = message->abbrev;
    if (m_idPlace.contains(message->id))
        return std::unexpected(doc.errorAt(element, QStringLiteral("message id %1 (%2) is already used by %3")
                                                        .arg(*id).arg(message->abbrev, m_idPlace.value(message->id))));
    if (m_abbrevPlace.contains(message->abbrev))
        return std::unexpected(doc.errorAt(element, QStringLiteral("message name %1 (id %2) is already used at %3")
                                                        .arg(message->abbrev).arg(*id).arg(m_abbrevPlace.value(message->abbrev))));
    m_idPlace.insert(message->id, QStringLiteral("%1 at %2").arg(message->abbrev, where(doc, element)));
    m_abbrevPlace.insert(message->abbrev, QStringLiteral("%1 (id %2)").arg(where(doc, element)).arg(*id));

    for (const xmlNode *field : xml::childElements(element, "field")) {
        if (auto ok = readField(doc, field, *message); !ok)
            return ok;
    }
    m_schema.m_messages.push_back(std::move(message));
    return {};
}

std::expected<void, XmlError> Schema::Loader::readField(const XmlDocument &doc, const xmlNode *element,
                                                        MessageDef &message)
{
    FieldDef field;
    field.abbrev = xml::attribute(element, "abbrev");
    field.name = xml::attribute(element, "name");
    field.unit = xml::attribute(element, "unit");
    field.min = xml::attribute(element, "min");
    field.max = xml::attribute(element, "max");
    field.value = xml::attribute(element, "value");
    field.messageType = xml::attribute(element, "message-type");
    field.line = static_cast<int>(xmlGetLineNo(element));
    auto fail = [&](const QString &what) {
        return std::unexpected(doc.errorAt(element, QStringLiteral("%1.%2: %3")
                                                        .arg(message.abbrev, field.abbrev.isEmpty() ? QStringLiteral("?") : field.abbrev, what)));
    };
    if (!isIdentifier(field.abbrev))
        return fail(QStringLiteral("a field needs an abbrev that is an identifier"));
    if (field.name.isEmpty())
        field.name = field.abbrev;
    if (message.fieldIndex.contains(field.abbrev))
        return fail(QStringLiteral("the message has two fields named %1").arg(field.abbrev));
    const QString type = xml::attribute(element, "type");
    const auto parsed = typeFromName(type);
    if (!parsed)
        return fail(QStringLiteral("unknown type '%1' (known: int8_t, uint8_t, int16_t, uint16_t, int32_t, uint32_t, "
                                   "int64_t, uint64_t, fp32_t, fp64_t, rawdata, plaintext, message, message-list)").arg(type));
    field.type = *parsed;
    if (!field.messageType.isEmpty() && field.type != FieldType::Message && field.type != FieldType::MessageList)
        return fail(QStringLiteral("message-type is only for message and message-list fields"));

    const QString enumDef = xml::attribute(element, "enum-def");
    const QString bitfieldDef = xml::attribute(element, "bitfield-def");
    const bool hasValues = xml::firstChildElement(element, "value") != nullptr;
    if (!enumDef.isEmpty() || !bitfieldDef.isEmpty() || hasValues) {
        if (!isInteger(field.type))
            return fail(QStringLiteral("enumerated values need an integer type, not %1").arg(type));
        const Enumeration *global = nullptr;
        if (!enumDef.isEmpty()) {
            global = m_schema.enumeration(enumDef);
            if (!global)
                return fail(QStringLiteral("enum-def '%1' names no enumeration").arg(enumDef));
        } else if (!bitfieldDef.isEmpty()) {
            global = m_schema.bitfield(bitfieldDef);
            if (!global)
                return fail(QStringLiteral("bitfield-def '%1' names no bitfield").arg(bitfieldDef));
        }
        if (global) {
            const auto [low, high] = integerRange(field.type);
            for (const auto &value : global->values) {
                if (value.value < low || value.value > high)
                    return fail(QStringLiteral("%1 value %2 (%3) does not fit %4").arg(global->abbrev, value.abbrev)
                                    .arg(value.value).arg(type));
            }
            field.enumeration = global;
        } else {
            auto local = std::make_unique<Enumeration>();
            local->name = field.name;
            local->prefix = xml::attribute(element, "prefix");
            local->bitfield = field.unit == u"Bitfield";
            if (auto ok = readValues(doc, element, *local, field.type); !ok)
                return ok;
            field.enumeration = local.get();
            message.inlineEnumerations.push_back(std::move(local));
        }
    }
    message.fieldIndex.insert(field.abbrev, static_cast<int>(message.fields.size()));
    message.fields.push_back(std::move(field));
    if (!message.fields.back().messageType.isEmpty())
        m_messageTypes.push_back({&message, message.fields.size() - 1, doc.errorAt(element, {})});
    return {};
}

std::expected<void, XmlError> Schema::Loader::finish()
{
    auto placed = [](XmlError place, const QString &message) {
        place.message = message;
        return std::unexpected(place);
    };
    std::sort(m_schema.m_messages.begin(), m_schema.m_messages.end(),
              [](const auto &a, const auto &b) { return a->id < b->id; });
    for (const auto &message : m_schema.m_messages)
        m_schema.m_byAbbrev.insert(message->abbrev, message.get());
    if (!m_schema.m_messages.empty())
        m_schema.m_byId.assign(m_schema.m_messages.back()->id + 1u, nullptr);
    for (const auto &message : m_schema.m_messages)
        m_schema.m_byId[message->id] = message.get();

    for (const PendingGroupMember &pending : m_groupMembers) {
        if (!m_schema.byAbbrev(pending.member))
            return placed(pending.place, QStringLiteral("message group %1 lists %2, which no definition declares")
                                             .arg(pending.group, pending.member));
    }
    for (const PendingMessageType &pending : m_messageTypes) {
        FieldDef &field = pending.message->fields[pending.field];
        if (const MessageDef *single = m_schema.byAbbrev(field.messageType)) {
            field.allowedIds.insert(single->id);
        } else if (const MessageGroup *group = m_schema.group(field.messageType)) {
            for (const QString &member : group->members)
                field.allowedIds.insert(m_schema.byAbbrev(member)->id);
        } else {
            return placed(pending.place, QStringLiteral("%1.%2: message-type '%3' names no message or message group")
                                             .arg(pending.message->abbrev, field.abbrev, field.messageType));
        }
    }

    // Where each field's value lives in a Message, and the fixed payload size.
    for (const auto &message : m_schema.m_messages) {
        int slot = 0;
        for (FieldDef &field : message->fields) {
            switch (field.type) {
            case FieldType::RawData:
            case FieldType::PlainText:
                field.storage = message->byteStringCount++;
                break;
            case FieldType::Message:
            case FieldType::MessageList:
                field.storage = message->messageListCount++;
                break;
            default:
                field.storage = slot++;
                message->fixedPayloadSize += wireSize(field.type);
                break;
            }
            message->wire.push_back({field.type, static_cast<quint8>(wireSize(field.type)),
                                     static_cast<quint16>(field.storage)});
        }
    }
    m_schema.m_digest = QCryptographicHash::hash(m_schema.canonicalText(), QCryptographicHash::Md5).toHex();
    return {};
}

// --- Schema --------------------------------------------------------------------

template<typename ReadDocument>
std::expected<std::shared_ptr<const Schema>, XmlError> Schema::build(qsizetype count, ReadDocument read)
{
    auto schema = std::shared_ptr<Schema>(new Schema);
    Loader loader(*schema);
    for (qsizetype i = 0; i < count; ++i) {
        auto doc = read(i);
        if (!doc)
            return std::unexpected(doc.error());
        if (auto ok = loader.add(*doc); !ok)
            return std::unexpected(ok.error());
    }
    if (auto ok = loader.finish(); !ok)
        return std::unexpected(ok.error());
    return schema;
}

std::expected<std::shared_ptr<const Schema>, XmlError> Schema::load(const QStringList &files)
{
    if (files.isEmpty())
        return std::unexpected(XmlError{{}, 0, 0, QStringLiteral("no message definition files given")});
    auto first = XmlDocument::load(files.front());
    if (!first)
        return std::unexpected(first.error());
    if (xml::elementName(first->root()) == u"mavlink") // includes are read from beside the file that names them
        return buildMavlink(files, [](const QString &path) { return XmlDocument::load(path); });
    return build(files.size(), [&](qsizetype i) { return i == 0 ? std::move(first) : XmlDocument::load(files[i]); });
}

QStringList Schema::filesIn(const QString &directory)
{
    const QDir dir(directory);
    QStringList files;
    for (const QString &name : dir.entryList({QStringLiteral("*.xml")}, QDir::Files, QDir::Name))
        files.append(dir.filePath(name));
    return files;
}

std::expected<std::shared_ptr<const Schema>, XmlError>
Schema::fromData(const QList<std::pair<QString, QByteArray>> &documents)
{
    if (!documents.isEmpty() && QByteArrayView(documents.front().second).contains("<mavlink>")) {
        // Includes are found among the documents, by file name.
        return buildMavlink({documents.front().first}, [documents](const QString &name) -> std::expected<XmlDocument, XmlError> {
            for (const auto &[file, data] : documents)
                if (file == name || QFileInfo(file).fileName() == QFileInfo(name).fileName())
                    return XmlDocument::parse(data, file);
            return std::unexpected(XmlError{name, 0, 0, QStringLiteral("%1: no such document given").arg(name)});
        });
    }
    return build(documents.size(),
                 [&](qsizetype i) { return XmlDocument::parse(documents[i].second, documents[i].first); });
}

const MessageDef *Schema::byAbbrev(QStringView abbrev) const
{
    return m_byAbbrev.value(abbrev.toString(), nullptr);
}

const Enumeration *Schema::enumeration(QStringView abbrev) const
{
    for (const auto &e : m_enumerations) {
        if (e->abbrev == abbrev)
            return e.get();
    }
    return nullptr;
}

const Enumeration *Schema::bitfield(QStringView abbrev) const
{
    for (const auto &e : m_bitfields) {
        if (e->abbrev == abbrev)
            return e.get();
    }
    return nullptr;
}

const MessageGroup *Schema::group(QStringView abbrev) const
{
    for (const MessageGroup &g : m_groups) {
        if (g.abbrev == abbrev)
            return &g;
    }
    return nullptr;
}

int Schema::fieldCount() const
{
    int count = 0;
    for (const auto &message : m_messages)
        count += static_cast<int>(message->fields.size());
    return count;
}

QByteArray Schema::canonicalText() const
{
    QByteArray text;
    text += "imc-layout sync=" + QByteArray::number(m_sync, 16) + '\n';
    for (const auto &message : m_messages) {
        text += "message " + QByteArray::number(message->id) + ' ' + message->abbrev.toUtf8() + '\n';
        for (const FieldDef &field : message->fields) {
            text += "  " + field.abbrev.toUtf8() + ' ' + typeName(field.type).toUtf8();
            if (!field.unit.isEmpty())
                text += " unit=" + field.unit.toUtf8();
            if (!field.messageType.isEmpty())
                text += " of=" + field.messageType.toUtf8();
            if (field.enumeration) {
                text += field.enumeration->bitfield ? " bits" : " enum";
                for (const auto &value : field.enumeration->values)
                    text += ' ' + QByteArray::number(value.value) + '=' + value.abbrev.toUtf8();
            }
            text += '\n';
        }
    }
    return text;
}

} // namespace neptus::msg
