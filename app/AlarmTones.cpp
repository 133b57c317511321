#include "AlarmTones.h"

#include "alarms/AlarmLevel.h"

#include <QFile>
#include <QtEndian>

#include <cmath>
#include <numbers>

using namespace Qt::StringLiterals;

QByteArray AlarmTones::wav(double hz, int beeps, double beepSeconds, double gapSeconds)
{
    constexpr int rate = 22050;
    QByteArray samples;
    const int beep = static_cast<int>(beepSeconds * rate), gap = static_cast<int>(gapSeconds * rate);
    for (int b = 0; b < beeps; ++b) {
        for (int i = 0; i < beep; ++i) {
            // A short fade in and out: no clicks.
            const double edge = std::min({1.0, i / (0.01 * rate), (beep - i) / (0.01 * rate)});
            const auto v = static_cast<qint16>(0.6 * 32767 * edge * std::sin(2 * std::numbers::pi * hz * i / rate));
            samples.append(reinterpret_cast<const char *>(&v), 2); // little-endian hosts (x86, ARM)
        }
        samples.append(QByteArray(2 * (b + 1 < beeps ? gap : 0), '\0'));
    }
    QByteArray out;
    const auto u32 = [&](quint32 v) { v = qToLittleEndian(v); out.append(reinterpret_cast<const char *>(&v), 4); };
    const auto u16 = [&](quint16 v) { v = qToLittleEndian(v); out.append(reinterpret_cast<const char *>(&v), 2); };
    out.append("RIFF");
    u32(static_cast<quint32>(36 + samples.size()));
    out.append("WAVEfmt ");
    u32(16);
    u16(1); // PCM
    u16(1); // mono
    u32(rate);
    u32(rate * 2);
    u16(2);
    u16(16);
    out.append("data");
    u32(static_cast<quint32>(samples.size()));
    return out + samples;
}

QUrl AlarmTones::url(int level)
{
    using namespace neptus::alarms;
    if (level < Warning)
        return {};
    if (!m_dir)
        m_dir = std::make_unique<QTemporaryDir>();
    const QString path = m_dir->filePath(u"alarm-%1.wav"_s.arg(level));
    if (!QFile::exists(path)) {
        const QByteArray bytes = level >= Failure ? wav(1175, 3, 0.12, 0.06)
                               : level >= Error   ? wav(880, 2, 0.15, 0.10)
                                                  : wav(660, 1, 0.30, 0);
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size())
            return {};
    }
    return QUrl::fromLocalFile(path);
}
