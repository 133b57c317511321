#pragma once

#include "xml/XmlDocument.h"

#include <QByteArray>
#include <QHash>
#include <QList>
#include <QSet>
#include <QString>
#include <QStringList>

#include <expected>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace neptus::msg {

// Wire types of a field. IMC's names them int8_t … fp64_t, rawdata,
// plaintext, message, message-list; MAVLink's uint64_t is IMC's missing one.
enum class FieldType : quint8 {
    Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Fp32, Fp64,
    RawData, PlainText, Message, MessageList,
};

QString typeName(FieldType type);
std::optional<FieldType> typeFromName(QStringView name);
// Bytes on the wire for fixed-size types; 0 for the variable-size ones.
int wireSize(FieldType type);
bool isInteger(FieldType type);
bool isFloat(FieldType type);

// Named values of an integer field: an enumeration (one value) or a bitfield
// (any combination of bits). Global (`<enumerations>`, `<bitfields>`) or inline.
struct Enumeration
{
    struct Value
    {
        qint64 value = 0;
        QString abbrev;
        QString name;
    };

    QString name;
    QString abbrev; // empty for inline ones
    QString prefix;
    bool bitfield = false;
    std::vector<Value> values;

    const Value *find(qint64 value) const;
    std::optional<qint64> valueOf(QStringView abbrev) const;
    // Enumeration: the value's abbrev, else the number. Bitfield: "A|B", with
    // bits that have no name added as a number ("A|0x40"); 0 with no name is "0".
    QString format(qint64 value) const;
    // The inverse of format(); also accepts plain numbers.
    std::optional<qint64> parse(QStringView text) const;
};

struct MessageDef;

struct FieldDef
{
    QString name;
    QString abbrev;
    FieldType type = FieldType::UInt8;
    QString unit;
    QString min;   // as written in the definition, empty if none
    QString max;
    QString value; // fixed or default value as written
    const Enumeration *enumeration = nullptr;
    // For message and message-list fields: the message or group the values
    // must belong to, as written; empty means any message.
    QString messageType;
    // The ids `messageType` allows; empty means any message.
    QSet<quint16> allowedIds;
    int line = 0;
    // MAVLink: a char[N] (plaintext) or uint8_t[N] (rawdata) field takes N
    // bytes on the wire whatever its value (0: IMC's length-prefixed ones).
    // A numeric array (float q[4]) is a field per element, "q[0]" … "q[3]".
    int fixedLength = 0;
    bool extension = false; // MAVLink 2 extension field (after <extensions/>)

    // Where the value lives inside a Message: the slot for scalars, or the
    // index into its byte strings or message lists.
    int storage = 0;
};

// What the codec needs of a field, packed in 4 bytes so that a message's
// fields sit in one or two cache lines while decoding.
struct WireField
{
    FieldType type;
    quint8 size;     // bytes on the wire for fixed-size types, else 0
    quint16 storage; // FieldDef::storage
};

struct MessageDef
{
    quint16 id = 0;
    // A MAVLink message: its id is MAVLink's (HEARTBEAT 0, SYS_STATUS 1), not
    // IMC's, so a system that is both (a MAVLink vehicle in IMC words) keeps them apart.
    bool mavlink = false;
    QString name;
    QString abbrev;
    QString category;
    QString file;
    int line = 0;
    std::vector<FieldDef> fields;
    std::vector<std::unique_ptr<Enumeration>> inlineEnumerations;

    std::vector<WireField> wire; // one per field, in order
    int byteStringCount = 0;   // plaintext and rawdata fields
    int messageListCount = 0;  // message and message-list fields
    int fixedPayloadSize = 0;  // bytes of the fixed-size fields

    // MAVLink: the fields in wire order (by element size, largest first, then
    // the extensions as declared), each with its byte offset in the payload;
    // the payload's length without and with the extensions; CRC_EXTRA.
    struct MavlinkField
    {
        FieldType type;
        quint8 size;     // bytes of the element (a fixed-length string's whole length)
        quint16 storage;
        quint16 offset;
        quint16 field;   // index into `fields`
    };
    std::vector<MavlinkField> mavlinkWire;
    int mavlinkBaseLength = 0;
    int mavlinkLength = 0;
    quint8 crcExtra = 0;

    QHash<QString, int> fieldIndex; // abbrev → index, made while loading
    int indexOf(QStringView fieldAbbrev) const;
    const FieldDef *field(QStringView fieldAbbrev) const;
};

struct MessageGroup
{
    QString name;
    QString abbrev;
    QStringList members; // message abbrevs
};

// Message definitions loaded at run time: one "messages defined in XML"
// model, filled from either protocol's format —
//  - IMC: one or more files of `<messages>` with `<enumerations>`,
//    `<bitfields>`, `<message-groups>`, `<header>`, `<footer>` and `<message>`;
//  - MAVLink: a dialect file (`<mavlink>` with `<include>`, `<enums>`,
//    `<messages>`), its includes read from beside it (common.xml includes
//    standard.xml, which includes minimal.xml), enums extended across files
//    as MAVLink allows; each message's wire order, payload lengths and
//    CRC_EXTRA worked out from the definition as MAVLink's rules say.
// Immutable once loaded; share it with std::shared_ptr<const Schema>.
class Schema
{
public:
    static constexpr quint16 noMessage = 0xFFFF;
    enum class Protocol { Imc, Mavlink };

    // Loads and combines the files in order. Any problem is an error naming
    // the file and line: unknown types, dangling references, duplicate ids or
    // names (also across files), unsupported headers.
    static std::expected<std::shared_ptr<const Schema>, xml::XmlError> load(const QStringList &files);
    // The definition files of a folder (*.xml, by name): how msgdefs/ is loaded.
    static QStringList filesIn(const QString &directory);
    // The same from documents already in memory (name, contents), for tests and fuzzing.
    static std::expected<std::shared_ptr<const Schema>, xml::XmlError>
    fromData(const QList<std::pair<QString, QByteArray>> &documents);

    const MessageDef *byId(quint16 id) const
    {
        return id < m_byId.size() ? m_byId[id] : nullptr;
    }
    const MessageDef *byAbbrev(QStringView abbrev) const;
    const std::vector<std::unique_ptr<MessageDef>> &messages() const { return m_messages; }
    const Enumeration *enumeration(QStringView abbrev) const;
    const Enumeration *bitfield(QStringView abbrev) const;
    int enumerationCount() const { return static_cast<int>(m_enumerations.size()); }
    int bitfieldCount() const { return static_cast<int>(m_bitfields.size()); }
    const std::vector<MessageGroup> &groups() const { return m_groups; }
    const MessageGroup *group(QStringView abbrev) const;
    int fieldCount() const;

    Protocol protocol() const { return m_protocol; }
    // The packet's synchronisation number (0xFE54 for IMC 5).
    quint16 syncNumber() const { return m_sync; }
    QString name() const { return m_name; }
    QString version() const { return m_version; }
    QStringList files() const { return m_files; }

    // MD5 of a canonical text of everything that affects the wire format
    // (ids, names, field order, types, enumerations), in hex. Two peers with
    // the same digest encode and decode alike, whatever their comments or
    // formatting; different digests mean they may not.
    QByteArray digest() const { return m_digest; }
    QByteArray canonicalText() const;

private:
    class Loader;
    friend class Loader;
    class MavlinkLoader;
    friend class MavlinkLoader;
    // MAVLink: the dialect files (and what they include), read with `read`
    // (a path or a name → the document).
    using ReadByName = std::function<std::expected<xml::XmlDocument, xml::XmlError>(const QString &)>;
    static std::expected<std::shared_ptr<const Schema>, xml::XmlError> buildMavlink(const QStringList &names, ReadByName read);
    template<typename ReadDocument>
    static std::expected<std::shared_ptr<const Schema>, xml::XmlError> build(qsizetype count, ReadDocument read);

    std::vector<std::unique_ptr<MessageDef>> m_messages; // by id
    std::vector<const MessageDef *> m_byId;
    QHash<QString, const MessageDef *> m_byAbbrev;
    std::vector<std::unique_ptr<Enumeration>> m_enumerations;
    std::vector<std::unique_ptr<Enumeration>> m_bitfields;
    std::vector<MessageGroup> m_groups;
    Protocol m_protocol = Protocol::Imc;
    quint16 m_sync = 0xFE54;
    QString m_name;
    QString m_version;
    QStringList m_files;
    QByteArray m_digest;
};

} // namespace neptus::msg
