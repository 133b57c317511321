#pragma once

#include <QObject>
#include <QTemporaryDir>
#include <QUrl>
#include <QtQml/qqmlregistration.h>

#include <memory>

// The alarm sounds, one per level, made as WAV files when first asked for
// (no sound files to ship or lose): Warning one low chime, Error two
// beeps, Failure three high, fast beeps — told apart without looking.
class AlarmTones : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_SINGLETON

public:
    using QObject::QObject;
    // The sound of an alarm level (Warning, Error, Failure); empty below Warning.
    Q_INVOKABLE QUrl url(int level);
    // The WAV bytes (16-bit mono PCM, 22,050 Hz) of `beeps` beeps of `hz`.
    static QByteArray wav(double hz, int beeps, double beepSeconds, double gapSeconds);

private:
    std::unique_ptr<QTemporaryDir> m_dir;
};
