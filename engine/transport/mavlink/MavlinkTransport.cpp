#include "transport/mavlink/MavlinkTransport.h"
#include "transport/imc/ImcUdpTransport.h"

#include <QCryptographicHash>
#include <QFile>
#include <QRegularExpression>
#include <QTcpSocket>
#include <QUdpSocket>

#include <QSerialPort>

#include <unistd.h>

namespace neptus::transport {

using namespace Qt::StringLiterals;

namespace {

constexpr quint8 mavTypeGcs = 6, mavAutopilotInvalid = 8;
constexpr quint16 cmdSetMessageInterval = 511, cmdDoSetMode = 176;
// Asked again this often until acknowledged, at most this many times.
constexpr qint64 streamRetryMs = 2000;
constexpr int streamAttempts = 3;
// Parameters: missing indices asked again after this long without one, in rounds.
constexpr qint64 parameterGapMs = 1000;
constexpr int parameterRounds = 4;
constexpr int parametersPerRound = 20; // ArduPilot queues 20 requests (GCS_Param.cpp); more are dropped
constexpr qint64 refusedReportMs = 60'000;
// Other addresses listed as claiming one vehicle, at most; forgotten after a minute of silence.
constexpr qsizetype maxImpostors = 16;
constexpr qint64 impostorForgetMs = 60'000;
// An overloaded host is said to be well again after this long without a drop.
constexpr qint64 overloadClearMs = 3000;

void setField(msg::Message &m, QStringView field, double value)
{
    if (const int i = m.def()->indexOf(field); i >= 0)
        m.setNumber(i, value);
}

} // namespace

std::expected<MavlinkConfig, QString> parseMavlinkLink(const QString &spec)
{
    MavlinkConfig config;
    const QString kind = spec.section(u':', 0, 0).toLower(), rest = spec.section(u':', 1);
    const auto port = [](QStringView text) -> std::optional<quint16> {
        bool ok = false;
        const uint value = text.toUInt(&ok);
        return ok && value <= 65535 ? std::optional<quint16>(quint16(value)) : std::nullopt;
    };
    const QString expected = u"a MAVLink link is udp:PORT, udp:ADDRESS:PORT, tcp:HOST:PORT or serial:DEVICE[:BAUD], not '%1'"_s.arg(spec);
    if (kind == u"udp") {
        config.kind = MavlinkConfig::Kind::Udp;
        const qsizetype colon = rest.lastIndexOf(u':');
        const auto p = port(colon < 0 ? QStringView(rest) : QStringView(rest).mid(colon + 1));
        if (!p)
            return std::unexpected(expected);
        config.port = *p;
        if (colon >= 0) {
            config.bindAddress = QHostAddress(rest.left(colon));
            if (config.bindAddress.isNull())
                return std::unexpected(u"%1: '%2' is not an address"_s.arg(spec, rest.left(colon)));
        }
        return config;
    }
    if (kind == u"tcp") {
        config.kind = MavlinkConfig::Kind::Tcp;
        const auto peer = hostAndPort(rest);
        if (!peer)
            return std::unexpected(expected);
        config.peers.append(*peer);
        return config;
    }
    if (kind == u"serial") {
        config.kind = MavlinkConfig::Kind::Serial;
        config.serialDevice = rest;
        if (const qsizetype colon = rest.lastIndexOf(u':'); colon > 0) {
            bool ok = false;
            const int baud = rest.mid(colon + 1).toInt(&ok);
            if (ok) {
                if (baud < 1200 || baud > 4000000)
                    return std::unexpected(u"%1: %2 is no baud rate"_s.arg(spec).arg(baud));
                config.baudRate = baud;
                config.serialDevice = rest.left(colon);
            }
        }
        if (config.serialDevice.isEmpty())
            return std::unexpected(expected);
        return config;
    }
    return std::unexpected(expected);
}

QString MavlinkConfig::linkName() const
{
    switch (kind) {
    case Kind::Udp:
        return u"MAVLink/UDP"_s;
    case Kind::Tcp:
        return u"MAVLink/TCP"_s;
    case Kind::Serial:
        return u"MAVLink/serial"_s;
    }
    return u"MAVLink"_s;
}

std::expected<QByteArray, QString> mavlinkKeyFromFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return std::unexpected(u"signing key %1: %2"_s.arg(path, file.errorString()));
    const QByteArray text = file.read(4096).trimmed();
    if (text.isEmpty())
        return std::unexpected(u"signing key %1: the file is empty (write a passphrase, or the key as 64 hex digits)"_s.arg(path));
    static const QRegularExpression hex(u"^[0-9a-fA-F]{64}$"_s);
    if (hex.match(QString::fromLatin1(text)).hasMatch())
        return QByteArray::fromHex(text);
    return QCryptographicHash::hash(text, QCryptographicHash::Sha256);
}

QString MavlinkTransport::Endpoint::name() const
{
    return address.isNull() ? u"the link"_s : u"%1:%2"_s.arg(address.toString()).arg(port);
}

MavlinkTransport::MavlinkTransport(std::shared_ptr<const msg::Schema> mavlink, std::shared_ptr<const msg::Schema> imc,
                                   MavlinkConfig config, QObject *parent)
    : QObject(parent)
    , m_schema(mavlink)
    , m_codec(std::move(mavlink))
    , m_imc(imc)
    , m_imcCodec(std::move(imc))
    , m_config(std::move(config))
{
    m_signing.key = m_config.signingKey;
    m_signing.linkId = m_config.signingLinkId;
    m_heartbeat.setInterval(m_config.heartbeatMs);
    connect(&m_heartbeat, &QTimer::timeout, this, &MavlinkTransport::heartbeat);
    m_service.setInterval(250);
    connect(&m_service, &QTimer::timeout, this, &MavlinkTransport::service);
    m_reconnect.setInterval(2000);
    m_reconnect.setSingleShot(true);
    connect(&m_reconnect, &QTimer::timeout, this, &MavlinkTransport::connectTcp);
}

MavlinkTransport::~MavlinkTransport()
{
    m_pump.reset(); // stops reading before the socket closes
    if (m_fd >= 0)
        ::close(m_fd);
    if (m_tcp)
        m_tcp->disconnect(this);
}

void MavlinkTransport::emitAll(Later &later)
{
    for (auto &f : later)
        f();
    later.clear();
}

std::expected<void, QString> MavlinkTransport::start()
{
    const QString name = linkName();
    switch (m_config.kind) {
    case MavlinkConfig::Kind::Udp: {
        QUdpSocket socket;
        if (!socket.bind(m_config.bindAddress, m_config.port))
            return std::unexpected(u"%1: cannot listen on %2:%3: %4"_s.arg(name, m_config.bindAddress.toString())
                                       .arg(m_config.port).arg(socket.errorString()));
        m_port = socket.localPort();
        m_fd = ::dup(int(socket.socketDescriptor()));
        if (m_fd < 0)
            return std::unexpected(u"%1: cannot keep the socket: %2"_s.arg(name, qt_error_string(errno)));
        DatagramReader::Limits limits;
        limits.datagramsPerSecond = m_config.maxDatagramsPerSecond;
        m_pump = std::make_unique<DatagramPump>(
            std::vector<int>{m_fd}, limits, [this](const DatagramReader::Datagram &d) { receive(d.bytes, d.from, d.port); },
            [this](const QHash<QString, int> &overRate, const QHash<QString, int> &behind) {
                QSet<QString> hosts;
                for (auto it = overRate.cbegin(); it != overRate.cend(); ++it)
                    hosts.insert(it.key());
                for (auto it = behind.cbegin(); it != behind.cend(); ++it)
                    hosts.insert(it.key());
                {
                    std::lock_guard lock(m_mutex);
                    for (const QString &host : hosts)
                        m_overloadedMs.insert(host, nowMs());
                }
                for (const QString &host : hosts)
                    emit overloaded(host, overRate.value(host), behind.value(host));
            });
        break;
    }
    case MavlinkConfig::Kind::Tcp: {
        if (m_config.peers.isEmpty())
            return std::unexpected(u"%1: no address to connect to (--mavlink-tcp HOST:PORT)"_s.arg(name));
        m_framer = std::make_unique<msg::MavlinkFramer>(m_codec);
        auto socket = std::make_unique<QTcpSocket>();
        m_tcp = socket.get();
        connect(m_tcp, &QTcpSocket::readyRead, this, [this] { streamBytes(m_tcp); });
        connect(m_tcp, &QTcpSocket::disconnected, this, [this] { m_reconnect.start(); });
        connect(m_tcp, &QTcpSocket::errorOccurred, this, [this] {
            if (m_tcp->state() != QAbstractSocket::ConnectedState)
                m_reconnect.start();
        });
        m_device = std::move(socket);
        connectTcp();
        break;
    }
    case MavlinkConfig::Kind::Serial: {
        auto port = std::make_unique<QSerialPort>(m_config.serialDevice);
        port->setBaudRate(m_config.baudRate);
        if (!port->open(QIODevice::ReadWrite))
            return std::unexpected(u"%1: cannot open %2 at %3 baud: %4"_s.arg(name, m_config.serialDevice)
                                       .arg(m_config.baudRate).arg(port->errorString()));
        m_framer = std::make_unique<msg::MavlinkFramer>(m_codec);
        QSerialPort *raw = port.get();
        connect(raw, &QSerialPort::readyRead, this, [this, raw] { streamBytes(raw); });
        m_device = std::move(port);
        break;
    }
    }
    m_heartbeat.start();
    m_service.start();
    heartbeat();
    return {};
}

void MavlinkTransport::connectTcp()
{
    if (!m_tcp || m_tcp->state() != QAbstractSocket::UnconnectedState)
        return;
    m_framer = std::make_unique<msg::MavlinkFramer>(m_codec); // a new connection: no half frame of the last one
    const auto &[host, port] = m_config.peers.front();
    m_tcp->connectToHost(host, port);
}

void MavlinkTransport::streamBytes(QIODevice *device)
{
    const QByteArray bytes = device->readAll();
    receive(bytes, {}, 0);
}

// --- Receiving -----------------------------------------------------------------------

void MavlinkTransport::receive(QByteArrayView bytes, const QHostAddress &from, quint16 fromPort)
{
    const Endpoint endpoint{from, fromPort};
    if (fromPort == 0 && m_framer) { // a stream: frames may be split across reads
        m_framer->feed(bytes);
        while (auto frame = m_framer->next())
            this->frame(*frame, endpoint);
        return;
    }
    // A datagram: one frame or several back to back, nothing else.
    while (!bytes.isEmpty()) {
        const qsizetype length = msg::MavlinkCodec::frameLength(bytes);
        if (length == 0 || length > bytes.size()) {
            ++m_decodeErrors;
            const quint8 system = bytes.size() > 5 && quint8(bytes[0]) == msg::MavlinkCodec::stx2 ? quint8(bytes[5])
                                  : bytes.size() > 3 && quint8(bytes[0]) == msg::MavlinkCodec::stx1 ? quint8(bytes[3]) : 0;
            emit decodeFailed(system ? quint16(m_config.idBase + system) : quint16(0xFFFF), endpoint.name(),
                              length == 0 ? u"%1 bytes that are not a MAVLink frame"_s.arg(bytes.size())
                                          : u"a frame cut short: %1 of %2 bytes"_s.arg(bytes.size()).arg(length));
            return;
        }
        frame(bytes.first(length), endpoint);
        bytes = bytes.sliced(length);
    }
}

QByteArray MavlinkTransport::keyForLocked(quint8 system) const
{
    const QByteArray own = m_config.vehicles.value(system).signingKey;
    return own.isEmpty() ? m_config.signingKey : own;
}

QString MavlinkTransport::signingRefusalLocked(QByteArrayView frame, const msg::MavlinkFrame &header)
{
    const QByteArray key = keyForLocked(header.system);
    // A telemetry radio's own RADIO_STATUS (109) and RADIO (166) come unsigned: ArduPilot takes them
    // (GCS_Signing.cpp, accept_unsigned_callback), and so does this link.
    if (!header.isSigned)
        return m_config.requireSigning && header.messageId != 109 && header.messageId != 166
                   ? u"unsigned frame on a link that requires signing"_s : QString();
    if (key.isEmpty())
        return m_config.requireSigning ? u"signed with a key this console does not have"_s : QString();
    if (!msg::MavlinkCodec::signatureValid(frame, key))
        return u"its signature does not verify with the key"_s;
    if (!m_signingStreams.fresh(header, std::max(m_signing.timestamp, msg::MavlinkSigning::now())))
        return u"replayed (its signing timestamp is not newer than its stream's last, or more than a minute old)"_s;
    return {};
}

void MavlinkTransport::frame(QByteArrayView bytes, const Endpoint &from)
{
    msg::MavlinkFrame header;
    auto decoded = m_codec.decode(bytes, &header);
    if (!decoded) {
        ++m_decodeErrors;
        emit decodeFailed(header.system ? quint16(m_config.idBase + header.system) : quint16(0xFFFF), from.name(),
                          decoded.error().toString());
        return;
    }
    if (header.system == m_config.system)
        return; // our own, relayed back
    msg::Message message = std::move(*decoded);
    const quint16 id = quint16(m_config.idBase + header.system);
    Later later;
    // Whether the frame is read on (else only what `later` says of it is told).
    const bool read = [&] {
        std::lock_guard lock(m_mutex);
        if (const QString refusal = signingRefusalLocked(bytes, header); !refusal.isEmpty()) {
            ++m_refused;
            // Said once per system a minute, whoever sends: a flood of refused frames is no flood of alarms.
            const qint64 now = nowMs();
            qint64 &reported = m_refusedReportMs[header.system];
            if (reported == 0 || now - reported >= refusedReportMs) {
                reported = now;
                later.push_back([this, id, peer = from.name(), refusal] { emit refused(id, peer, refusal); });
            }
            return false;
        }
        if (message.isOpaque()) {
            ++m_decodeErrors;
            later.push_back([this, id, peer = from.name(), msgid = header.messageId] {
                emit decodeFailed(id, peer, u"message id %1 is not in the loaded MAVLink dialects"_s.arg(msgid));
            });
            return false;
        }
        const QString &type = message.def()->abbrev;
        auto found = m_vehicles.find(header.system);
        if (found == m_vehicles.end()) {
            // Met by an autopilot's HEARTBEAT: not a ground station's, not a camera's or gimbal's.
            if (type != u"HEARTBEAT" || message.integer(u"type") == mavTypeGcs
                || message.integer(u"autopilot") == mavAutopilotInvalid)
                return false;
            Vehicle v;
            v.component = header.component;
            v.endpoint = from;
            v.settings = m_config.vehicles.value(header.system);
            QString name = v.settings.name;
            if (name.isEmpty()) {
                const int mavType = int(message.integer(u"type"));
                name = u"%1-%2"_s.arg(msg::mavlink::familyName(msg::mavlink::familyOf(int(message.integer(u"autopilot"))), mavType))
                           .arg(header.system);
            }
            v.adapter = std::make_unique<MavlinkVehicle>(header.system, id, name, m_imc);
            for (const auto &[stream, hz] : m_config.streams)
                if (const msg::MessageDef *def = m_schema->byAbbrev(stream); def && hz > 0)
                    v.streams.push_back({def->id, hz});
            found = m_vehicles.emplace(header.system, std::move(v)).first;
            later.push_back([this, id, name] { emit systemDiscovered(id, name); });
        }
        Vehicle &v = found->second;
        const qint64 now = nowMs();
        if (!(from == v.endpoint)) {
            // Another address claims this vehicle: it takes it over only once
            // the first has been silent a while, and only with a heartbeat.
            const bool silent = now - v.lastMs > m_config.rebindAfterMs;
            const QString host = DatagramReader::hostName(from.address); // a port per frame is still one host
            if (!(silent && type == u"HEARTBEAT" && header.component == v.component)) {
                ++m_refused;
                const bool fresh = !v.impostors.contains(host);
                if (fresh && v.impostors.size() >= maxImpostors)
                    return false; // counted, not listed
                v.impostors.insert(host, now);
                if (fresh) {
                    v.sources = QStringList{v.endpoint.name()} + v.impostors.keys();
                    later.push_back([this, id, sources = v.sources, destination = v.endpoint.name()] {
                        emit sourcesChanged(id, sources, destination);
                    });
                    later.push_back([this, id, host] {
                        emit refused(id, host, u"claims to be this vehicle from another address: ignored"_s);
                    });
                }
                return false;
            }
            v.endpoint = from;
            v.impostors.clear();
            v.sources = QStringList{from.name()};
            later.push_back([this, id, sources = v.sources, destination = from.name()] {
                emit sourcesChanged(id, sources, destination);
            });
        }
        v.lastMs = now;
        message.header.src = id;
        message.header.srcEnt = header.component == v.component ? 0xFF : header.component;
        message.header.dst = 0xFFFF;
        message.header.timestamp = now / 1000.0;
        handleLocked(v, message, later);
        return true;
    }();
    if (!read) {
        emitAll(later);
        return;
    }
    if (m_frameTap)
        m_frameTap(bytes);
    emit received(message, bytes.size());
    emitAll(later);
}

void MavlinkTransport::handleLocked(Vehicle &v, const msg::Message &message, Later &later)
{
    const QString &type = message.def()->abbrev;
    const bool first = !v.adapter->heard();
    std::vector<msg::Message> meaning = v.adapter->translate(message, now());
    for (msg::Message &m : meaning) {
        if (m_tap && m_imcCodec.encode(m, m_buffer))
            m_tap(m_buffer);
        later.push_back([this, m = std::move(m)] { emit derived(m); });
    }
    if (first && type == u"HEARTBEAT") {
        // Met: its streams and parameters are asked for now (service() asks again where due).
        for (Stream &s : v.streams)
            s.askedMs = 0;
        if (m_config.readParameters) {
            sendLocked(mavlinkMessage("PARAM_REQUEST_LIST"), &v);
            v.parametersAsked = true;
            v.parameterMs = nowMs();
            parametersLocked(v, later, true);
        }
    }
    if (type == u"COMMAND_ACK" && message.integer(u"command") == cmdSetMessageInterval && message.integer(u"result") == 0
        && (message.integer(u"target_system") == 0 || message.integer(u"target_system") == m_config.system)) {
        // Which stream it was is not in the ACK: the oldest asked and unacknowledged one.
        for (Stream &s : v.streams)
            if (!s.acknowledged && s.asked > 0) {
                s.acknowledged = true;
                break;
            }
    } else if (type == u"PARAM_VALUE") {
        const int index = int(message.integer(u"param_index"));
        const int count = int(message.integer(u"param_count"));
        const QString name = message.text(u"param_id");
        if (index != 0xFFFF && count > 0) {
            v.parameters[index] = {name, message.number(u"param_value")};
            v.parameterCount = count;
            v.parameterMs = nowMs();
        } else {
            // A change the vehicle announces (index 65535): the value, where it is known by name.
            for (auto &[i, named] : v.parameters)
                if (named.first == name)
                    named.second = message.number(u"param_value");
        }
        if (v.parametersAsked)
            parametersLocked(v, later, true);
    } else if (type == u"STATUSTEXT") {
        later.push_back([this, id = v.adapter->consoleId(), severity = int(message.integer(u"severity")),
                         text = message.text(u"text")] { emit statusText(id, severity, text); });
    }
}

// Where the parameter list is: all read, still coming, or some missing (asked again, index by index).
void MavlinkTransport::parametersLocked(Vehicle &v, Later &later, bool progressOnly)
{
    const int have = int(v.parameters.size());
    const qint64 now = nowMs();
    int state = 0; // BOOT
    QString text;
    if (v.parameterCount < 0) {
        text = u"reading parameters"_s;
        // The list's request (or its first answers) lost on a radio: asked again, a few times;
        // an answer that comes later is still taken.
        if (!progressOnly && now - v.parameterMs >= parameterGapMs * 3 && v.listRequests < parameterRounds) {
            ++v.listRequests;
            sendLocked(mavlinkMessage("PARAM_REQUEST_LIST"), &v);
            v.parameterMs = now;
        }
    } else if (have >= v.parameterCount) {
        state = 1; // NORMAL
        text = u"%1 parameters read"_s.arg(v.parameterCount);
        v.parametersAsked = false;
    } else if (!progressOnly && now - v.parameterMs >= parameterGapMs) {
        if (v.parameterRounds >= parameterRounds) {
            QStringList missing;
            for (int i = 0; i < v.parameterCount && missing.size() < 5; ++i)
                if (!v.parameters.contains(i))
                    missing << QString::number(i);
            state = 2; // FAULT
            text = u"%1 of %2 parameters read; %3 never came (indices %4%5)"_s.arg(have).arg(v.parameterCount)
                       .arg(v.parameterCount - have).arg(missing.join(u", "_s), v.parameterCount - have > 5 ? u", …"_s : QString());
            v.parametersAsked = false;
        } else {
            ++v.parameterRounds;
            int asked = 0;
            for (int i = 0; i < v.parameterCount && asked < parametersPerRound; ++i) {
                if (v.parameters.contains(i))
                    continue;
                msg::Message read = mavlinkMessage("PARAM_REQUEST_READ");
                setField(read, u"param_index", i);
                sendLocked(read, &v);
                ++asked;
            }
            v.parameterMs = now;
            text = u"reading parameters: %1 of %2 (asking again for %3)"_s.arg(have).arg(v.parameterCount).arg(asked);
        }
    } else {
        text = u"reading parameters: %1 of %2"_s.arg(have).arg(v.parameterCount);
    }
    if (text.isEmpty() || (text == v.parameterReport))
        return;
    // Progress at most twice a second; the end at once.
    if (state == 0 && now - v.parameterReportMs < 500 && !v.parameterReport.isEmpty())
        return;
    v.parameterReport = text;
    v.parameterReportMs = now;
    msg::Message m = v.adapter->parameterState(state, text, now / 1000.0);
    if (m_tap && m_imcCodec.encode(m, m_buffer))
        m_tap(m_buffer);
    later.push_back([this, m = std::move(m)] { emit derived(m); });
}

// --- Sending -------------------------------------------------------------------------

msg::Message MavlinkTransport::mavlinkMessage(const char *name) const
{
    return msg::Message(m_schema->byAbbrev(QString::fromLatin1(name)));
}

msg::Message MavlinkTransport::commandLong(quint16 command, std::initializer_list<float> params) const
{
    msg::Message m = mavlinkMessage("COMMAND_LONG");
    setField(m, u"command", command);
    int i = 1;
    for (const float p : params)
        setField(m, u"param%1"_s.arg(i++), p);
    return m;
}

// A joystick's RemoteActions ("Heading=0.25;Thrust=0.80;Vertical=0", each
// -1 … 1) as MANUAL_CONTROL, the way ArduPilot reads it: ArduSub takes x as
// forward (Thrust), r as yaw (Heading, right positive) and z as the vertical
// stick around 500 (GCS_MAVLink, Sub::transform_manual_control_to_rc_override);
// Rover takes y as steering and z as throttle, -1000 … 1000. A released stick
// sends zeros: neutral, the vehicle stops. ArduPilot forgets an override 3 s
// after the last one (Sub: "Lost manual control", its pilot-input failsafe).
msg::Message MavlinkTransport::manualControl(const Vehicle &v, const QString &actions) const
{
    QHash<QString, double> value;
    for (const QString &pair : actions.split(u';', Qt::SkipEmptyParts)) {
        const qsizetype equals = pair.indexOf(u'=');
        if (equals > 0)
            value.insert(pair.left(equals).trimmed().toLower(), std::clamp(pair.mid(equals + 1).toDouble(), -1.0, 1.0));
    }
    const auto axis = [&](const char *name) { return std::lround(value.value(QString::fromLatin1(name)) * 1000); };
    msg::Message m = mavlinkMessage("MANUAL_CONTROL");
    setField(m, u"target", v.adapter->mavlinkSystem());
    if (v.adapter->kind() == msg::mavlink::Kind::Underwater) {
        setField(m, u"x", axis("thrust"));
        setField(m, u"y", axis("lateral"));
        setField(m, u"z", 500 + axis("vertical") / 2);
        setField(m, u"r", axis("heading"));
    } else {
        setField(m, u"x", 0);
        setField(m, u"y", axis("heading"));
        setField(m, u"z", axis("thrust"));
        setField(m, u"r", 0);
    }
    return m;
}

std::expected<msg::Message, QString> MavlinkTransport::setMode(const Vehicle &v, const QString &mode) const
{
    const auto params = msg::mavlink::setModeParams(v.adapter->family(), v.adapter->mavType(), mode);
    if (!params) // never something else instead (a mistyped abort mode must not mean RTL)
        return std::unexpected(u"%1 has no mode called %2"_s.arg(v.adapter->name(), mode));
    return commandLong(cmdDoSetMode, {(*params)[0], (*params)[1], (*params)[2]});
}

std::expected<void, QString> MavlinkTransport::writeLocked(const QByteArray &frame, const Endpoint &to)
{
    if (m_fd >= 0) {
        if (auto sent = sendDatagram(m_fd, frame, to.address, to.port, m_config.bindAddress.protocol() == QAbstractSocket::IPv6Protocol);
            !sent)
            return std::unexpected(u"cannot send to %1: %2"_s.arg(to.name(), sent.error()));
    } else if (m_device && m_device->isOpen() && (!m_tcp || m_tcp->state() == QAbstractSocket::ConnectedState)) {
        if (m_device->write(frame) != frame.size())
            return std::unexpected(u"cannot write to %1: %2"_s.arg(linkName(), m_device->errorString()));
    } else {
        return std::unexpected(u"%1 is not connected"_s.arg(linkName()));
    }
    if (m_frameTap)
        m_frameTap(frame);
    return {};
}

std::expected<void, QString> MavlinkTransport::sendLocked(const msg::Message &message, const Vehicle *to)
{
    msg::Message addressed = message;
    if (to) {
        if (const int i = addressed.def()->indexOf(u"target_system"); i >= 0)
            addressed.setInteger(i, to->adapter->mavlinkSystem());
        if (const int i = addressed.def()->indexOf(u"target_component"); i >= 0)
            addressed.setInteger(i, to->component);
    }
    msg::MavlinkCodec::Options options;
    options.sequence = m_sequence++;
    options.system = m_config.system;
    options.component = m_config.component;
    msg::MavlinkSigning vehicleSigning;
    const QByteArray key = to ? keyForLocked(to->adapter->mavlinkSystem()) : m_config.signingKey;
    if (!key.isEmpty()) {
        m_signing.timestamp = std::max(m_signing.timestamp, msg::MavlinkSigning::now());
        vehicleSigning = m_signing;
        vehicleSigning.key = key;
        options.signing = &vehicleSigning;
    }
    if (auto encoded = m_codec.encode(addressed, options, m_buffer); !encoded)
        return std::unexpected(u"%1 does not encode: %2"_s.arg(message.abbrev(), encoded.error().toString()));
    if (options.signing)
        m_signing.timestamp = vehicleSigning.timestamp;
    const QByteArray frame = m_buffer;
    if (to)
        return writeLocked(frame, to->endpoint);
    // To everyone: the vehicles heard and the peers named.
    QList<Endpoint> targets;
    for (const auto &[system, v] : m_vehicles)
        if (!targets.contains(v.endpoint))
            targets << v.endpoint;
    if (m_fd >= 0)
        for (const auto &[address, port] : m_config.peers)
            if (!targets.contains(Endpoint{address, port}))
                targets << Endpoint{address, port};
    if (m_fd < 0 && targets.isEmpty())
        targets << Endpoint{};
    std::expected<void, QString> result;
    for (const Endpoint &target : targets)
        if (auto sent = writeLocked(frame, target); !sent)
            result = sent;
    return result;
}

std::expected<void, QString> MavlinkTransport::publish(quint16 system, const msg::Message &message)
{
    if (!message.def())
        return std::unexpected(u"an undefined message is not sent"_s);
    Later later;
    std::expected<void, QString> result;
    {
        std::lock_guard lock(m_mutex);
        Vehicle *v = vehicleLocked(system);
        if (!v)
            return std::unexpected(u"no MAVLink vehicle is 0x%1 on %2"_s.arg(uint(system), 4, 16, QChar(u'0')).arg(linkName()));
        if (message.isMavlink()) {
            result = sendLocked(message, v);
        } else if (message.abbrev() == u"Abort") {
            const QString mode = !v->settings.abortMode.isEmpty() ? v->settings.abortMode : v->adapter->defaultAbortMode();
            if (auto command = setMode(*v, mode))
                result = sendLocked(*command, v);
            else
                result = std::unexpected(command.error());
        } else if (message.abbrev() == u"RemoteActions") {
            result = sendLocked(manualControl(*v, message.text(u"actions")), v);
        } else if (message.abbrev() == u"EntityList" || message.abbrev() == u"EntityInfo") {
            // The console asks who its entities are: the adapter's, said here.
            later.push_back([this, m = v->adapter->entityList(now())] { emit derived(m); });
        } else {
            result = std::unexpected(u"%1 speaks MAVLink: %2 has no MAVLink equivalent"_s.arg(v->adapter->name(), message.abbrev()));
        }
    }
    // Answers go on after the caller is done sending (it may be ingesting).
    if (!later.empty())
        QMetaObject::invokeMethod(this, [later = std::move(later)]() mutable { emitAll(later); }, Qt::QueuedConnection);
    return result;
}

void MavlinkTransport::heartbeat()
{
    msg::Message beat = mavlinkMessage("HEARTBEAT");
    setField(beat, u"type", mavTypeGcs);
    setField(beat, u"autopilot", mavAutopilotInvalid);
    setField(beat, u"system_status", 4); // MAV_STATE_ACTIVE
    setField(beat, u"mavlink_version", 3);
    std::lock_guard lock(m_mutex);
    if (m_fd >= 0 || m_device)
        sendLocked(beat, nullptr);
}

void MavlinkTransport::service()
{
    Later later;
    {
        std::lock_guard lock(m_mutex);
        const qint64 now = nowMs();
        for (auto &[system, v] : m_vehicles) {
            if (!v.adapter->heard())
                continue;
            for (Stream &s : v.streams) {
                if (s.acknowledged || s.asked >= streamAttempts || now - s.askedMs < streamRetryMs)
                    continue;
                ++s.asked;
                s.askedMs = now;
                sendLocked(commandLong(cmdSetMessageInterval, {float(s.messageId), float(1e6 / s.hz)}), &v);
            }
            if (v.parametersAsked)
                parametersLocked(v, later, false);
            // Claims from other addresses that stopped are forgotten (the sources alarm goes).
            const qsizetype before = v.impostors.size();
            v.impostors.removeIf([&](const auto &claim) { return now - claim.value() >= impostorForgetMs; });
            if (v.impostors.size() != before)
                later.push_back([this, id = v.adapter->consoleId(), sources = QStringList{v.endpoint.name()} + v.impostors.keys(),
                                 destination = v.endpoint.name()] { emit sourcesChanged(id, sources, destination); });
        }
        for (auto it = m_overloadedMs.begin(); it != m_overloadedMs.end();) {
            if (now - it.value() < overloadClearMs) {
                ++it;
                continue;
            }
            later.push_back([this, host = it.key()] { emit overloaded(host, 0, 0); }); // well again
            it = m_overloadedMs.erase(it);
        }
    }
    emitAll(later);
}

// --- What is known -------------------------------------------------------------------

MavlinkTransport::Vehicle *MavlinkTransport::vehicleLocked(quint16 id)
{
    if (id < m_config.idBase || id > m_config.idBase + 255)
        return nullptr;
    const auto found = m_vehicles.find(quint8(id - m_config.idBase));
    return found == m_vehicles.end() ? nullptr : &found->second;
}

const MavlinkTransport::Vehicle *MavlinkTransport::vehicleLocked(quint16 id) const
{
    return const_cast<MavlinkTransport *>(this)->vehicleLocked(id);
}

QList<quint16> MavlinkTransport::vehicles() const
{
    std::lock_guard lock(m_mutex);
    QList<quint16> ids;
    for (const auto &[system, v] : m_vehicles)
        ids << v.adapter->consoleId();
    return ids;
}

QString MavlinkTransport::destination(quint16 id) const
{
    std::lock_guard lock(m_mutex);
    const Vehicle *v = vehicleLocked(id);
    if (!v)
        return {};
    return m_fd >= 0 ? v->endpoint.name() : linkName();
}

std::map<QString, double> MavlinkTransport::parameters(quint16 id) const
{
    std::lock_guard lock(m_mutex);
    std::map<QString, double> out;
    if (const Vehicle *v = vehicleLocked(id))
        for (const auto &[index, named] : v->parameters)
            out[named.first] = named.second;
    return out;
}

std::pair<QString, bool> MavlinkTransport::mode(quint16 id) const
{
    std::lock_guard lock(m_mutex);
    const Vehicle *v = vehicleLocked(id);
    if (!v || !v->adapter->heard())
        return {};
    return {v->adapter->modeName(), v->adapter->armed()};
}

QString MavlinkTransport::stopMode(quint16 id) const
{
    std::lock_guard lock(m_mutex);
    const Vehicle *v = vehicleLocked(id);
    if (!v)
        return {};
    return !v->settings.stopMode.isEmpty() ? v->settings.stopMode : v->adapter->defaultStopMode();
}

void MavlinkTransport::setMission(quint16 id, const QString &planId, const QStringList &maneuverOfItem)
{
    std::lock_guard lock(m_mutex);
    if (Vehicle *v = vehicleLocked(id))
        v->adapter->setMission(planId, maneuverOfItem);
}

} // namespace neptus::transport
