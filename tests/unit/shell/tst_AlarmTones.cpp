// The alarm sounds are WAV files any player reads: a valid header, the
// length of their beeps, and one sound per level.
#include "AlarmTones.h"

#include "alarms/AlarmLevel.h"

#include <QFile>
#include <QtEndian>

#include <gtest/gtest.h>

TEST(AlarmTones, AreWavFilesOfTheirBeeps)
{
    const QByteArray wav = AlarmTones::wav(880, 2, 0.15, 0.10);
    ASSERT_GE(wav.size(), 44);
    EXPECT_EQ(wav.left(4), "RIFF");
    EXPECT_EQ(wav.mid(8, 8), "WAVEfmt ");
    EXPECT_EQ(qFromLittleEndian<quint32>(wav.constData() + 4), static_cast<quint32>(wav.size() - 8));
    EXPECT_EQ(qFromLittleEndian<quint16>(wav.constData() + 22), 1) << "mono";
    EXPECT_EQ(qFromLittleEndian<quint32>(wav.constData() + 24), 22050u);
    const quint32 data = qFromLittleEndian<quint32>(wav.constData() + 40);
    EXPECT_EQ(data, static_cast<quint32>(2 * (2 * 3307 + 2205))) << "two beeps of 0.15 s and one gap of 0.1 s";
    EXPECT_EQ(wav.size(), 44 + static_cast<qsizetype>(data));

    AlarmTones tones;
    EXPECT_TRUE(tones.url(neptus::alarms::Info).isEmpty());
    const QUrl warning = tones.url(neptus::alarms::Warning), failure = tones.url(neptus::alarms::Failure);
    EXPECT_NE(warning, failure);
    QFile file(failure.toLocalFile());
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(file.read(4), "RIFF");
}
