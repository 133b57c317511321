// Speed of the MAVLink codec, whose definitions are read at run time
// (msgdefs/mavlink/ardupilotmega.xml), beside the MAVLink project's
// generated C library: the same headers as c_library_v2, generated at build
// time by pymavlink's mavgen (the generator c_library_v2 is made with, the
// pinned pymavlink of tools/python-packages.txt) from the same XML.
// Side by side in one run:
//  - GLOBAL_POSITION_INT, the message a vehicle sends most: decode (framing,
//    CRC with CRC_EXTRA, fields) and encode (fields, framing, CRC);
//  - a 100-item mission upload, as the messages go: MISSION_COUNT, 100
//    MISSION_REQUESTs, 100 MISSION_ITEM_INTs and the MISSION_ACK, each
//    encoded by one side and decoded by the other;
//  - ours only: the whole upload between the console's mission client and
//    the simulated ArduPilot (protocol logic included), in process.
// Run: tools/bench mavlink   (figures in BENCHMARKS.md)
#include "BenchMain.h"
#include "Schemas.h"
#include "messages/MavlinkCodec.h"
#include "plans/MavlinkMission.h"
#include "sim/MavlinkAutopilot.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Waddress-of-packed-member"
#pragma GCC diagnostic ignored "-Wcast-align"
#include <ardupilotmega/mavlink.h>
#pragma GCC diagnostic pop

#include <benchmark/benchmark.h>

using namespace neptus;

namespace {

const msg::MavlinkCodec &codec()
{
    static const msg::MavlinkCodec c(test::mavlinkSchema());
    return c;
}

msg::Message make(const char *name, std::initializer_list<std::pair<const char *, double>> fields)
{
    msg::Message m(test::mavlinkSchema()->byAbbrev(QString::fromLatin1(name)));
    for (const auto &[field, value] : fields)
        m.setNumber(m.def()->indexOf(QString::fromLatin1(field)), value);
    return m;
}

msg::Message position()
{
    return make("GLOBAL_POSITION_INT", {{"time_boot_ms", 123456}, {"lat", 411854582}, {"lon", -87060003}, {"alt", 1200},
                                        {"relative_alt", 50}, {"vx", 120}, {"vy", -30}, {"vz", 0}, {"hdg", 9000}});
}

QByteArray positionFrame()
{
    msg::MavlinkCodec::Options o;
    o.system = 1;
    o.component = 1;
    return *codec().encode(position(), o);
}

void BM_DecodeGlobalPositionInt_Ours(benchmark::State &state)
{
    const QByteArray frame = positionFrame();
    for (auto _ : state) {
        auto m = codec().decode(frame);
        benchmark::DoNotOptimize(m->integer(1));
    }
    state.SetBytesProcessed(state.iterations() * frame.size());
}

void BM_DecodeGlobalPositionInt_C(benchmark::State &state)
{
    const QByteArray frame = positionFrame();
    mavlink_message_t message;
    mavlink_status_t status{};
    for (auto _ : state) {
        for (const char byte : frame)
            if (mavlink_parse_char(MAVLINK_COMM_0, quint8(byte), &message, &status)) {
                mavlink_global_position_int_t p;
                mavlink_msg_global_position_int_decode(&message, &p);
                benchmark::DoNotOptimize(p.lat);
            }
    }
    state.SetBytesProcessed(state.iterations() * frame.size());
}

void BM_EncodeGlobalPositionInt_Ours(benchmark::State &state)
{
    msg::Message m = position();
    const int lat = m.def()->indexOf(u"lat");
    msg::MavlinkCodec::Options o;
    QByteArray out;
    qint64 i = 0;
    for (auto _ : state) {
        m.setInteger(lat, 411854582 + (i++ & 1023)); // a new position each time, as a stream has
        o.sequence = quint8(i);
        benchmark::DoNotOptimize(codec().encode(m, o, out));
    }
}

void BM_EncodeGlobalPositionInt_C(benchmark::State &state)
{
    mavlink_message_t message;
    uint8_t out[MAVLINK_MAX_PACKET_LEN];
    qint64 i = 0;
    for (auto _ : state) {
        mavlink_msg_global_position_int_pack(255, 190, &message, 123456, int32_t(411854582 + (i++ & 1023)), -87060003, 1200, 50, 120,
                                             -30, 0, 9000);
        benchmark::DoNotOptimize(mavlink_msg_to_send_buffer(out, &message));
    }
}

// The 100-item upload's messages, each encoded then decoded by the other end.
void BM_Upload100Messages_Ours(benchmark::State &state)
{
    const auto schema = test::mavlinkSchema();
    msg::Message count = make("MISSION_COUNT", {{"count", 100}}), request = make("MISSION_REQUEST", {}),
                 item = make("MISSION_ITEM_INT", {{"command", 16}, {"frame", 3}, {"autocontinue", 1}, {"z", 5}}),
                 ack = make("MISSION_ACK", {});
    const int requestSeq = request.def()->indexOf(u"seq"), itemSeq = item.def()->indexOf(u"seq"), x = item.def()->indexOf(u"x"),
              y = item.def()->indexOf(u"y");
    msg::MavlinkCodec::Options station, vehicle;
    vehicle.system = 1;
    vehicle.component = 1;
    QByteArray frame;
    for (auto _ : state) {
        codec().encode(count, station, frame);
        benchmark::DoNotOptimize(codec().decode(frame)->integer(0));
        for (int seq = 0; seq < 100; ++seq) {
            request.setInteger(requestSeq, seq);
            codec().encode(request, vehicle, frame);
            const auto asked = codec().decode(frame);
            item.setInteger(itemSeq, asked->integer(requestSeq));
            item.setInteger(x, 411854582 + seq * 100);
            item.setInteger(y, -87060003 - seq * 100);
            codec().encode(item, station, frame);
            benchmark::DoNotOptimize(codec().decode(frame)->integer(x));
        }
        codec().encode(ack, vehicle, frame);
        benchmark::DoNotOptimize(codec().decode(frame)->integer(0));
    }
    state.SetItemsProcessed(state.iterations() * 202);
}

void BM_Upload100Messages_C(benchmark::State &state)
{
    mavlink_message_t message, received;
    mavlink_status_t status{};
    uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
    const auto carry = [&](uint16_t length) {
        for (uint16_t i = 0; i < length; ++i)
            if (mavlink_parse_char(MAVLINK_COMM_1, buffer[i], &received, &status))
                return true;
        return false;
    };
    for (auto _ : state) {
        mavlink_msg_mission_count_pack(255, 190, &message, 1, 1, 100, MAV_MISSION_TYPE_MISSION);
        carry(mavlink_msg_to_send_buffer(buffer, &message));
        benchmark::DoNotOptimize(mavlink_msg_mission_count_get_count(&received));
        for (uint16_t seq = 0; seq < 100; ++seq) {
            mavlink_msg_mission_request_pack(1, 1, &message, 255, 190, seq, MAV_MISSION_TYPE_MISSION);
            carry(mavlink_msg_to_send_buffer(buffer, &message));
            const uint16_t asked = mavlink_msg_mission_request_get_seq(&received);
            mavlink_msg_mission_item_int_pack(255, 190, &message, 1, 1, asked, MAV_FRAME_GLOBAL_RELATIVE_ALT, 16, 0, 1, 0, 0, 0, 0,
                                              411854582 + seq * 100, -87060003 - seq * 100, 5, MAV_MISSION_TYPE_MISSION);
            carry(mavlink_msg_to_send_buffer(buffer, &message));
            mavlink_mission_item_int_t item;
            mavlink_msg_mission_item_int_decode(&received, &item);
            benchmark::DoNotOptimize(item.x);
        }
        mavlink_msg_mission_ack_pack(1, 1, &message, 255, 190, MAV_MISSION_ACCEPTED, MAV_MISSION_TYPE_MISSION);
        carry(mavlink_msg_to_send_buffer(buffer, &message));
        benchmark::DoNotOptimize(mavlink_msg_mission_ack_get_type(&received));
    }
    state.SetItemsProcessed(state.iterations() * 202);
}

// The whole protocol, in process: the console's mission client uploading 100
// items to the simulated ArduPilot, every message through both codecs.
void BM_Upload100Protocol_Ours(benchmark::State &state)
{
    std::vector<plans::MissionItem> items(101);
    for (size_t i = 1; i < items.size(); ++i) {
        items[i].x = 411854582 + int(i) * 100;
        items[i].y = -87060003 - int(i) * 100;
    }
    for (auto _ : state) {
        sim::MavlinkAutopilot vehicle(test::mavlinkSchema(), {});
        plans::MavlinkMissionClient *self = nullptr;
        std::vector<QByteArray> toVehicle;
        plans::MavlinkMissionClient client(test::mavlinkSchema(), 0xEA01, [&](const msg::Message &m) -> std::expected<void, QString> {
            toVehicle.push_back(*codec().encode(m, {}));
            return {};
        });
        self = &client;
        bool done = false;
        QObject::connect(&client, &plans::MavlinkMissionClient::finished, [&](const auto &r) { done = r.ok; });
        client.upload(plans::MissionType::Mission, items);
        msg::MavlinkCodec::Options o;
        o.system = 1;
        while (!toVehicle.empty()) {
            const QByteArray frame = toVehicle.front();
            toVehicle.erase(toVehicle.begin());
            for (const msg::Message &answer : vehicle.receive(*codec().decode(frame), 0)) {
                auto back = codec().decode(*codec().encode(answer, o));
                back->header.src = 0xEA01;
                self->receive(*back);
            }
        }
        if (!done)
            state.SkipWithError("the upload did not finish");
    }
    state.SetItemsProcessed(state.iterations() * 100);
}

} // namespace

BENCHMARK(BM_DecodeGlobalPositionInt_Ours);
BENCHMARK(BM_DecodeGlobalPositionInt_C);
BENCHMARK(BM_EncodeGlobalPositionInt_Ours);
BENCHMARK(BM_EncodeGlobalPositionInt_C);
BENCHMARK(BM_Upload100Messages_Ours)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Upload100Messages_C)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Upload100Protocol_Ours)->Unit(benchmark::kMicrosecond);

int main(int argc, char **argv)
{
    return neptus::test::runBenchmarks(argc, argv);
}
