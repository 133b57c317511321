#include "transport/LinkStatistics.h"
#include "qmlmodels/LinkStatisticsModel.h"

#include <QAbstractItemModelTester>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::transport;

TEST(LinkStatistics, RatesPerSystemAndPerTypeOverEachTick)
{
    ManualClock clock(QDateTime::fromMSecsSinceEpoch(1'000'000, QTimeZone::UTC));
    LinkStatistics stats(&clock);
    for (int i = 0; i < 20; ++i)
        stats.received(0x1f, QStringLiteral("IMC/UDP"), 350, QStringLiteral("EstimatedState"), true, 110);
    for (int i = 0; i < 4; ++i)
        stats.received(0x1f, QStringLiteral("IMC/UDP"), 281, QStringLiteral("Unknown(281)"), false, 27);
    clock.advance(2000);
    stats.tick();
    const auto s = stats.system(0x1f);
    EXPECT_EQ(s.link, QStringLiteral("IMC/UDP"));
    EXPECT_EQ(s.messages, 24u);
    EXPECT_EQ(s.bytes, 20u * 110 + 4 * 27);
    EXPECT_DOUBLE_EQ(s.messageRate, 12.0);
    EXPECT_DOUBLE_EQ(s.byteRate, (20 * 110 + 4 * 27) / 2.0);
    ASSERT_EQ(s.types.size(), 2u);
    EXPECT_EQ(s.types[0].id, 281) << "by id";
    EXPECT_FALSE(s.types[0].known);
    EXPECT_DOUBLE_EQ(s.types[1].rate, 10.0);
    EXPECT_EQ(s.unknownTypes(), 1);

    clock.advance(1000); // a silent second: rates drop to zero, totals stay
    stats.tick();
    EXPECT_DOUBLE_EQ(stats.system(0x1f).messageRate, 0.0);
    EXPECT_EQ(stats.system(0x1f).messages, 24u);

    stats.decodeFailed(0x1f, QStringLiteral("IMC/UDP"), QStringLiteral("127.0.0.1:6002"), QStringLiteral("bad CRC"));
    stats.decodeFailed(LinkStatistics::unknownSystem, QStringLiteral("IMC/UDP"), QStringLiteral("10.0.0.9:1"), QStringLiteral("bad sync"));
    EXPECT_EQ(stats.system(0x1f).decodeErrors, 1u);
    EXPECT_EQ(stats.system(0x1f).lastError, QStringLiteral("bad CRC"));
    EXPECT_EQ(stats.system(0x1f).lastErrorMs, clock.now().toMSecsSinceEpoch());
    EXPECT_EQ(stats.systems().size(), 2u);
    EXPECT_EQ(stats.systems().back().id, LinkStatistics::unknownSystem);
}

TEST(LinkStatisticsModel, ASystemARowWithNamesAndEntities)
{
    LinkStatistics stats;
    tree::VariableTree tree;
    LinkStatisticsModel model(&stats, &tree);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    tree.setSystemName(0x20, QStringLiteral("caravela"));
    stats.received(0x20, QStringLiteral("DDS"), 350, QStringLiteral("EstimatedState"), true, 110);
    stats.received(0x1f, QStringLiteral("IMC/UDP"), 350, QStringLiteral("EstimatedState"), true, 110);
    stats.received(0x1f, QStringLiteral("IMC/UDP"), 150, QStringLiteral("Heartbeat"), true, 22);
    stats.received(0x1f, QStringLiteral("IMC/UDP"), 150, QStringLiteral("Heartbeat"), true, 22);
    model.refresh();
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_EQ(model.data(model.index(0), LinkStatisticsModel::SystemRole).toString(), QStringLiteral("0x001f"));
    EXPECT_EQ(model.data(model.index(1), LinkStatisticsModel::SystemRole).toString(), QStringLiteral("caravela"));
    EXPECT_EQ(model.data(model.index(1), LinkStatisticsModel::LinkRole).toString(), QStringLiteral("DDS"));
    EXPECT_EQ(model.data(model.index(0), LinkStatisticsModel::TypesRole).toInt(), 2);
    const QVariantList types = model.typesOf(0x1f);
    ASSERT_EQ(types.size(), 2);
    EXPECT_EQ(types[0].toMap().value(QStringLiteral("abbrev")).toString(), QStringLiteral("Heartbeat")) << "busiest first";

    stats.received(0x10, QStringLiteral("IMC/UDP"), 150, QStringLiteral("Heartbeat"), true, 22);
    model.refresh();
    ASSERT_EQ(model.rowCount(), 3) << "a new system is inserted in id order";
    EXPECT_EQ(model.data(model.index(0), LinkStatisticsModel::SystemIdRole).toInt(), 0x10);
}
