#pragma once

#include "core/Clock.h"
#include "messages/Codec.h"
#include "messages/MavlinkCodec.h"
#include "transport/DatagramPump.h"
#include "transport/OutputSink.h"
#include "transport/mavlink/MavlinkVehicle.h"

#include <QHash>
#include <QHostAddress>
#include <QObject>

#include <array>
#include <QTimer>

#include <atomic>
#include <expected>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

class QIODevice;
class QTcpSocket;

namespace neptus::transport {

// What the console knows of one MAVLink vehicle before it is heard (its
// vehicle definition's <link protocol="mavlink-…" system="…">).
struct MavlinkVehicleSettings
{
    QString name;          // what the console calls it; "" makes one from its type ("ardurover-1")
    QByteArray signingKey; // 32 bytes; empty: the link's
    QString stopMode;      // the mode Stop puts it in ("HOLD"); "": its family's for its type
    QString abortMode;     // the mode Abort puts it in ("RTL", "SURFACE", "LAND"); "": its family's
};

// How the console meets MAVLink vehicles on one link.
struct MavlinkConfig
{
    enum class Kind { Udp, Tcp, Serial };
    Kind kind = Kind::Udp;
    // UDP: where the console listens (ground stations listen on 14550; 0: any
    // free port), loopback unless a field setup names the boat network's address.
    QHostAddress bindAddress = QHostAddress::LocalHost;
    quint16 port = 14550;
    // UDP: vehicles to send to before they are heard (a vehicle that waits for
    // a ground station); TCP: the vehicle or simulator to connect to (5760).
    QList<std::pair<QHostAddress, quint16>> peers;
    // Serial: the device ("/dev/ttyUSB0") and its baud rate.
    QString serialDevice;
    qint32 baudRate = 57600;
    // Who the console is on MAVLink: a ground station (system 255, component 190).
    quint8 system = 255;
    quint8 component = 190;
    // A vehicle's id in the console: idBase + its MAVLink system id (each link its own 256).
    quint16 idBase = 0xEA00;
    QHash<quint8, MavlinkVehicleSettings> vehicles; // by MAVLink system id
    // Signing (MAVLink 2): frames to a vehicle are signed with its key (else
    // this one); with requireSigning, frames that are unsigned or do not
    // verify are refused before they are read.
    QByteArray signingKey;
    bool requireSigning = false;
    quint8 signingLinkId = 0;
    int heartbeatMs = 1000;
    // The messages asked of each vehicle (SET_MESSAGE_INTERVAL), and how often a second.
    std::vector<std::pair<QString, double>> streams = {
        {QStringLiteral("GLOBAL_POSITION_INT"), 5}, {QStringLiteral("ATTITUDE"), 5},   {QStringLiteral("VFR_HUD"), 2},
        {QStringLiteral("SYS_STATUS"), 1},          {QStringLiteral("BATTERY_STATUS"), 1}, {QStringLiteral("GPS_RAW_INT"), 1},
        {QStringLiteral("MISSION_CURRENT"), 1},     {QStringLiteral("EKF_STATUS_REPORT"), 1},
        {QStringLiteral("SCALED_PRESSURE"), 1}};
    bool readParameters = true;
    // A vehicle heard from one address is reached there; a heartbeat from
    // another address takes it over only after this long without a word from the first.
    int rebindAfterMs = 10000;
    int maxDatagramsPerSecond = 5000;
    const Clock *clock = &Clock::system();

    // "MAVLink/UDP", "MAVLink/TCP", "MAVLink/serial".
    QString linkName() const;
};

// A link as the command line and the settings write it: "udp:14550" (listen
// on loopback), "udp:10.0.0.5:14550" (on the boat network's address),
// "tcp:127.0.0.1:5760" (connect to a vehicle or SITL), "serial:/dev/ttyUSB0"
// or "serial:/dev/ttyUSB0:115200". An error says what was expected.
std::expected<MavlinkConfig, QString> parseMavlinkLink(const QString &spec);

// "mypassphrase" → the 32-byte key MAVProxy's and QGroundControl's signing
// setup make of it (SHA-256 of the passphrase); a file holding 64 hex digits
// is the key itself. An error names the file and why.
std::expected<QByteArray, QString> mavlinkKeyFromFile(const QString &path);

// MAVLink vehicles over UDP, TCP or a serial line, several behind one link
// (told apart by their MAVLink system id). A vehicle is met by its HEARTBEAT
// (an autopilot's: not a ground station's, not a camera's); from then on the
// console sends it a ground station's HEARTBEAT every second, asks it for
// the messages the console shows (SET_MESSAGE_INTERVAL, asked again until
// acknowledged) and reads its parameters (PARAM_REQUEST_LIST, missing
// indices asked again one by one), with the progress as the "Parameters"
// entity's state.
//
// Everything a vehicle sends goes on as it is (`received`, the MAVLink
// messages in the tree under the vehicle) and as what it means in the
// console's words (`derived`, MavlinkVehicle: Announce, EstimatedState,
// FuelLevel, EntityStates, …), each under the vehicle's console id; what it
// means is also recorded as IMC (the packet tap), and every frame both ways
// as a tlog (the frame tap).
//
// Commands: MAVLink messages published to a vehicle go to its system and
// autopilot component (target_system, target_component filled in) over the
// address it was heard from; an IMC Abort becomes its abort mode, an IMC
// EntityList query is answered here. A heartbeat from another address does
// not redirect commands while the vehicle is heard (sourcesChanged says who
// claims it), and on a link that requires signing nothing unsigned is read.
//
// UDP is read and decoded off the GUI thread (DatagramPump); TCP and serial
// on the thread the transport lives in. `received` and `derived` are
// emitted on the thread that read the frame.
class MavlinkTransport : public QObject, public OutputSink
{
    Q_OBJECT

public:
    using FrameTap = std::function<void(QByteArrayView frame)>;

    MavlinkTransport(std::shared_ptr<const msg::Schema> mavlink, std::shared_ptr<const msg::Schema> imc, MavlinkConfig config,
                     QObject *parent = nullptr);
    ~MavlinkTransport() override;

    // Binds the socket, connects or opens the device; an error says why.
    // TCP keeps trying to connect every 2 s after a first failure.
    std::expected<void, QString> start();
    QString linkName() const { return m_config.linkName(); }
    quint16 port() const { return m_port; }
    int maxDatagramsPerSecond() const { return m_config.maxDatagramsPerSecond; }
    // IMC packets of what vehicles mean, and MAVLink frames both ways, for the recorder.
    void setPacketTap(PacketTap tap) { m_tap = std::move(tap); }
    void setFrameTap(FrameTap tap) { m_frameTap = std::move(tap); }

    // Bytes as they arrived from `from`:`fromPort` (a datagram, or a piece of
    // a stream when fromPort is 0), on the caller's thread: tests and the fuzz target.
    void receive(QByteArrayView bytes, const QHostAddress &from, quint16 fromPort);

    // OutputSink: to a vehicle by its console id.
    std::expected<void, QString> publish(quint16 system, const msg::Message &message) override;

    // The ground station's HEARTBEAT to every vehicle (and the UDP peers);
    // streams and parameters asked again where due.
    void heartbeat();
    void service();

    QList<quint16> vehicles() const;
    // Where commands to a vehicle go ("127.0.0.1:14551", "tcp 127.0.0.1:5760").
    QString destination(quint16 id) const;
    // A vehicle's parameters as read so far, by name.
    std::map<QString, double> parameters(quint16 id) const;
    // Its mode's name and armed state ("", false until heard).
    std::pair<QString, bool> mode(quint16 id) const;
    // The mode Stop puts it in: its settings', else its family's ("HOLD"); "" for no such vehicle.
    QString stopMode(quint16 id) const;
    // The plan the vehicle holds, for its progress (PlanControlState): the
    // plan's id and, per mission item, the maneuver it belongs to.
    void setMission(quint16 id, const QString &planId, const QStringList &maneuverOfItem);
    // Frames refused (unsigned or badly signed on a signing link, from an
    // impostor's address) and frames that did not decode, since the start.
    quint64 refusedFrames() const { return m_refused; }
    int decodeErrors() const { return m_decodeErrors; }

signals:
    // A MAVLink message from a vehicle (header: src its console id, srcEnt
    // 0xFF for its autopilot, else the component id) and the size of its frame.
    void received(const neptus::msg::Message &message, qsizetype bytes);
    // What a MAVLink message means, in IMC (MavlinkVehicle).
    void derived(const neptus::msg::Message &message);
    void systemDiscovered(quint16 system, const QString &name);
    void decodeFailed(quint16 system, const QString &peer, const QString &reason);
    // Several addresses claim one vehicle: who, and where commands go.
    void sourcesChanged(quint16 system, const QStringList &senders, const QString &destination);
    // Frames refused on a signing link, or from an impostor (the first of
    // each kind per sender, then once a minute).
    void refused(quint16 system, const QString &peer, const QString &reason);
    // A STATUSTEXT (MAV_SEVERITY 0 emergency … 7 debug), in the vehicle's words.
    void statusText(quint16 system, int severity, const QString &text);
    void overloaded(const QString &host, int overRate, int behind);

private:
    struct Endpoint
    {
        QHostAddress address; // null on a stream link (TCP, serial)
        quint16 port = 0;
        QString name() const;
        bool operator==(const Endpoint &other) const { return address == other.address && port == other.port; }
    };
    struct Stream
    {
        quint32 messageId = 0;
        double hz = 0;
        int asked = 0;        // times asked
        qint64 askedMs = 0;
        bool acknowledged = false;
    };
    struct Vehicle
    {
        std::unique_ptr<MavlinkVehicle> adapter;
        quint8 component = 1; // its autopilot's
        Endpoint endpoint;
        qint64 lastMs = 0;
        QHash<QString, qint64> impostors; // hosts that claimed it, when last
        QStringList sources;
        MavlinkVehicleSettings settings;
        std::vector<Stream> streams;
        // Parameters: by index as they come, their count, when asking next.
        std::map<int, std::pair<QString, double>> parameters;
        int parameterCount = -1;
        qint64 parameterMs = 0;
        int parameterRounds = 0;
        int listRequests = 0;     // PARAM_REQUEST_LIST sent again while no answer came
        bool parametersAsked = false;
        QString parameterReport;
        qint64 parameterReportMs = 0;
    };
    using Later = std::vector<std::function<void()>>;
    static void emitAll(Later &later);

    qint64 nowMs() const { return m_config.clock->now().toMSecsSinceEpoch(); }
    double now() const { return nowMs() / 1000.0; }
    void frame(QByteArrayView frame, const Endpoint &from);
    // Whether a frame may be read (signing); why not, else "".
    QString signingRefusalLocked(QByteArrayView frame, const msg::MavlinkFrame &header);
    QByteArray keyForLocked(quint8 system) const;
    void handleLocked(Vehicle &v, const msg::Message &message, Later &later);
    void parametersLocked(Vehicle &v, Later &later, bool progressOnly);
    std::expected<void, QString> sendLocked(const msg::Message &message, const Vehicle *to);
    std::expected<void, QString> writeLocked(const QByteArray &frame, const Endpoint &to);
    msg::Message mavlinkMessage(const char *name) const;
    msg::Message commandLong(quint16 command, std::initializer_list<float> params) const;
    msg::Message manualControl(const Vehicle &v, const QString &actions) const;
    std::expected<msg::Message, QString> setMode(const Vehicle &v, const QString &mode) const;
    Vehicle *vehicleLocked(quint16 id);
    const Vehicle *vehicleLocked(quint16 id) const;
    void streamBytes(QIODevice *device);
    void connectTcp();

    std::shared_ptr<const msg::Schema> m_schema;
    msg::MavlinkCodec m_codec;
    std::shared_ptr<const msg::Schema> m_imc;
    msg::Codec m_imcCodec;
    MavlinkConfig m_config;
    PacketTap m_tap;
    FrameTap m_frameTap;
    mutable std::mutex m_mutex; // guards the vehicles, signing state, sequence and sending
    std::map<quint8, Vehicle> m_vehicles;
    msg::MavlinkSigningStreams m_signingStreams;
    std::array<qint64, 256> m_refusedReportMs{}; // by system id: when a refusal was last said
    QHash<QString, qint64> m_overloadedMs;       // hosts said to overload the link, when last
    msg::MavlinkSigning m_signing;            // our timestamp, and the link's key
    quint8 m_sequence = 0;
    QByteArray m_buffer;
    int m_fd = -1;
    quint16 m_port = 0;
    QTimer m_heartbeat;
    QTimer m_service;
    std::unique_ptr<DatagramPump> m_pump;
    // Stream links: the device, and the frames found in what it reads.
    std::unique_ptr<QIODevice> m_device;
    QTcpSocket *m_tcp = nullptr;
    std::unique_ptr<msg::MavlinkFramer> m_framer;
    QTimer m_reconnect;
    std::atomic<int> m_decodeErrors = 0;
    std::atomic<quint64> m_refused = 0;
};

} // namespace neptus::transport
