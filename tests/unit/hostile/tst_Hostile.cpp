// What an attacker on the network, or a careless file, sends the console:
// each test here froze, fooled or exhausted the console before its fix. They
// run with a time limit (ctest TIMEOUT): a regression shows as a timeout, not
// as a flaky timing assertion.
#include "messages/Schema.h"
#include "session/Console.h"

#include "Schemas.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace neptus;

namespace {

transport::ImcUdpConfig unbound()
{
    transport::ImcUdpConfig config;
    config.port = 0;
    config.discovery = false;
    return config;
}

} // namespace

// One 64 KB PlanSpecification with 32,000 start actions froze the GUI for
// about 4 s: list items were found by name with a scan of every sibling.
TEST(Hostile, AHugeMessageListIsIngestedInLinearTime)
{
    session::Console console(test::shippedSchema());
    auto *imc = console.attachImc(std::make_unique<transport::ImcUdpTransport>(console.schemaSet(), unbound()));
    const msg::Schema &schema = *test::shippedSchema();
    msg::Message plan(schema.byAbbrev(u"PlanSpecification"));
    plan.header.src = 0x66;
    std::vector<msg::Message> actions(32'000, msg::Message(schema.byAbbrev(u"Heartbeat")));
    plan.setMessages(plan.def()->indexOf(u"start_actions"), std::move(actions));
    const auto packet = msg::Codec(test::shippedSchema()).encode(plan);
    ASSERT_TRUE(packet) << packet.error().toString().toStdString();
    EXPECT_GT(packet->size(), 64'000);
    for (int i = 0; i < 20; ++i) // one every 2 s kept it frozen for 40 s
        imc->receive(*packet, QHostAddress::LocalHost, 6002);
    const tree::VariableTree &tree = console.tree();
    EXPECT_NE(tree.find(u"0x0066/PlanSpecification/start_actions/31999"), tree::noNode);
    EXPECT_EQ(tree.snapshot(tree.find(u"0x0066/PlanSpecification/start_actions")).value.toInt(), 32'000);
}

// Definitions loaded in quadratic time (each field checked against every
// earlier one): 40,000 fields took 6.7 s; 60,000 take over 30 s in a debug build.
TEST(Hostile, DefinitionsWithManyFieldsLoadInLinearTime)
{
    QByteArray xml = "<messages name=\"Big\" version=\"1\">\n<message id=\"2000\" name=\"Big\" abbrev=\"Big\">\n";
    for (int i = 0; i < 60'000; ++i)
        xml += "<field name=\"F\" abbrev=\"f" + QByteArray::number(i) + "\" type=\"uint8_t\"/>\n";
    xml += "</message>\n</messages>\n";
    const auto schema = msg::Schema::fromData({{QStringLiteral("big.xml"), xml}});
    ASSERT_TRUE(schema) << schema.error().toString().toStdString();
    const msg::MessageDef *big = (*schema)->byAbbrev(u"Big");
    ASSERT_TRUE(big);
    EXPECT_EQ(big->fields.size(), 60'000u);
    EXPECT_EQ(big->indexOf(u"f59999"), 59'999);
    EXPECT_EQ(big->indexOf(u"nope"), -1);

    xml.replace("abbrev=\"f59999\"", "abbrev=\"f7\"");
    const auto twice = msg::Schema::fromData({{QStringLiteral("big.xml"), xml}});
    ASSERT_FALSE(twice);
    EXPECT_TRUE(twice.error().message.contains(QStringLiteral("two fields named f7"))) << twice.error().toString().toStdString();
}

// A 100 MB definitions file was refused as "the file is 64 MiB".
TEST(Hostile, AnOversizedFileIsRefusedWithItsTrueSize)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("huge.xml"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    ASSERT_TRUE(file.resize(qint64(100) << 20)); // sparse: nothing is written
    file.close();
    const auto schema = msg::Schema::load({path});
    ASSERT_FALSE(schema);
    EXPECT_TRUE(schema.error().toString().contains(QStringLiteral("100 MiB"))) << schema.error().toString().toStdString();
    EXPECT_TRUE(schema.error().toString().contains(QStringLiteral("64 MiB"))) << "and the limit";
}
