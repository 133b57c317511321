// neptus-msg: the first tool to reach for when a link misbehaves. Lists the
// message definitions, decodes IMC packets (hex) to JSON and encodes JSON back
// to packets, with the same schema and codec the console uses.
#include "core/DataFiles.h"
#include "messages/Codec.h"
#include "messages/MessageJson.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTextStream>

#include <cstdio>

using namespace neptus::msg;

namespace {

constexpr int usageError = 2;

int fail(const QString &message)
{
    std::fprintf(stderr, "neptus-msg: %s\n", qPrintable(message));
    return 1;
}

QByteArray readStandardInput()
{
    QFile in;
    if (!in.open(stdin, QIODevice::ReadOnly))
        return {};
    return in.readAll();
}

// Hex with or without spaces, "0x" prefixes or colons.
std::expected<QByteArray, QString> parseHex(QString text)
{
    text.remove(QStringLiteral("0x"), Qt::CaseInsensitive);
    QString digits;
    for (const QChar c : std::as_const(text)) {
        if (c.isSpace() || c == u':')
            continue;
        if (!isxdigit(c.toLatin1()))
            return std::unexpected(QStringLiteral("'%1' is not a hex digit").arg(c));
        digits.append(c);
    }
    if (digits.size() % 2 != 0)
        return std::unexpected(QStringLiteral("odd number of hex digits (%1)").arg(digits.size()));
    return QByteArray::fromHex(digits.toLatin1());
}

int list(const Schema &schema)
{
    QTextStream out(stdout);
    for (const auto &message : schema.messages())
        out << qSetFieldWidth(5) << Qt::right << message->id << qSetFieldWidth(0) << "  " << qSetFieldWidth(32)
            << Qt::left << message->abbrev << qSetFieldWidth(0) << message->fields.size() << " fields\n";
    out.flush();
    std::fprintf(stderr, "%zu messages, %d fields; %s %s; digest %s\n", schema.messages().size(), schema.fieldCount(),
                 qPrintable(schema.name()), qPrintable(schema.version()), schema.digest().constData());
    return 0;
}

int decode(const Codec &codec, const QStringList &inputs, bool compact)
{
    QStringList packets = inputs;
    if (packets == QStringList{QStringLiteral("-")})
        packets = QString::fromUtf8(readStandardInput()).split(u'\n', Qt::SkipEmptyParts);
    int failures = 0;
    for (qsizetype i = 0; i < packets.size(); ++i) {
        const QString where = packets.size() > 1 ? QStringLiteral("packet %1: ").arg(i + 1) : QString();
        const auto bytes = parseHex(packets[i]);
        if (!bytes) {
            fail(where + bytes.error());
            ++failures;
            continue;
        }
        const auto message = codec.decode(*bytes);
        if (!message) {
            fail(where + message.error().toString());
            ++failures;
            continue;
        }
        const QByteArray json = QJsonDocument(toJson(*message)).toJson(compact ? QJsonDocument::Compact : QJsonDocument::Indented);
        std::fwrite(json.constData(), 1, static_cast<size_t>(json.size()), stdout);
        if (compact)
            std::fputc('\n', stdout);
    }
    return failures == 0 ? 0 : 1;
}

int encode(const Codec &codec, const QStringList &inputs, Codec::ByteOrder order)
{
    QList<QByteArray> documents;
    if (inputs == QStringList{QStringLiteral("-")}) {
        const QByteArray all = readStandardInput();
        QJsonParseError error;
        const QJsonDocument whole = QJsonDocument::fromJson(all, &error);
        if (error.error == QJsonParseError::NoError)
            documents.append(all);
        else
            documents = all.split('\n'); // JSON Lines
    } else {
        for (const QString &input : inputs)
            documents.append(input.toUtf8());
    }
    QList<QJsonObject> objects;
    int line = 0;
    for (const QByteArray &document : std::as_const(documents)) {
        ++line;
        if (document.trimmed().isEmpty())
            continue;
        QJsonParseError error;
        const QJsonDocument json = QJsonDocument::fromJson(document, &error);
        if (error.error != QJsonParseError::NoError)
            return fail(QStringLiteral("input %1: JSON error at character %2: %3").arg(line).arg(error.offset).arg(error.errorString()));
        if (json.isArray()) {
            for (const QJsonValue &value : json.array())
                objects.append(value.toObject());
        } else {
            objects.append(json.object());
        }
    }
    int failures = 0;
    for (qsizetype i = 0; i < objects.size(); ++i) {
        const QString where = objects.size() > 1 ? QStringLiteral("message %1: ").arg(i + 1) : QString();
        const auto message = fromJson(codec.schema(), objects[i]);
        if (!message) {
            fail(where + message.error());
            ++failures;
            continue;
        }
        const auto packet = codec.encode(*message, order);
        if (!packet) {
            fail(where + packet.error().toString());
            ++failures;
            continue;
        }
        std::printf("%s\n", packet->toHex().constData());
    }
    return failures == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("neptus-msg"));
    QCoreApplication::setApplicationVersion(QStringLiteral(NEPTUS_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Lists message definitions, decodes IMC packets to JSON, encodes JSON to IMC packets.\n\n"
        "  neptus-msg list   [--defs FILE...]\n"
        "  neptus-msg decode [--defs FILE...] [--compact] HEX...|-\n"
        "  neptus-msg encode [--defs FILE...] [--big-endian] JSON...|-\n\n"
        "'-' reads standard input: one hex packet per line for decode; one JSON document, an array, or\n"
        "JSON Lines for encode. Definitions default to the project's msgdefs/ folder."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption defs(QStringLiteral("defs"), QStringLiteral("Message definition file (repeat for several)."),
                                  QStringLiteral("file"));
    const QCommandLineOption compact(QStringLiteral("compact"), QStringLiteral("decode: one line of JSON per packet."));
    const QCommandLineOption bigEndian(QStringLiteral("big-endian"), QStringLiteral("encode: write big-endian packets."));
    parser.addOptions({defs, compact, bigEndian});
    parser.addPositionalArgument(QStringLiteral("command"), QStringLiteral("list, decode or encode"));
    if (!parser.parse(QCoreApplication::arguments())) {
        std::fprintf(stderr, "neptus-msg: %s\n", qPrintable(parser.errorText()));
        return usageError;
    }
    if (parser.isSet(QStringLiteral("help")))
        parser.showHelp(0);
    if (parser.isSet(QStringLiteral("version")))
        parser.showVersion();

    QStringList arguments = parser.positionalArguments();
    const QString command = arguments.isEmpty() ? QString() : arguments.takeFirst();
    if (command != u"list" && command != u"decode" && command != u"encode") {
        std::fprintf(stderr, "neptus-msg: %s\n%s", command.isEmpty() ? "a command is needed" : qPrintable(QStringLiteral("unknown command '%1'").arg(command)),
                     qPrintable(parser.helpText()));
        return usageError;
    }
    if (command != u"list" && arguments.isEmpty()) {
        std::fprintf(stderr, "neptus-msg: %s needs input (or '-' for standard input)\n", qPrintable(command));
        return usageError;
    }

    QStringList files = parser.values(defs);
    if (files.isEmpty())
        files = Schema::filesIn(neptus::dataPath(QStringLiteral("msgdefs")));
    auto schema = Schema::load(files);
    if (!schema)
        return fail(schema.error().toString());
    const Codec codec(*schema);
    if (command == u"list")
        return list(**schema);
    if (command == u"decode")
        return decode(codec, arguments, parser.isSet(compact));
    return encode(codec, arguments, parser.isSet(bigEndian) ? Codec::ByteOrder::BigEndian : Codec::ByteOrder::LittleEndian);
}
