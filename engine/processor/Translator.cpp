#include "processor/Translator.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>

namespace neptus::processor {

QString translatorHelper()
{
    return QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("neptus-xslt"));
}

std::expected<QByteArray, xml::XmlError> translate(const QString &stylesheet, QByteArrayView input,
                                                   const QString &inputName,
                                                   const QList<std::pair<QByteArray, QString>> &parameters,
                                                   TranslateLimits limits)
{
    return translate(stylesheet, [input] { return input.toByteArray(); }, inputName, parameters, limits);
}

std::expected<QByteArray, xml::XmlError> translate(const QString &stylesheet, const std::function<QByteArray()> &makeInput,
                                                   const QString &inputName,
                                                   const QList<std::pair<QByteArray, QString>> &parameters,
                                                   TranslateLimits limits)
{
    const auto failure = [&](const QString &why) { return std::unexpected(xml::XmlError{stylesheet, 0, 0, why}); };
    QStringList args{stylesheet, inputName, QString::number(limits.megabytes), QString::number(limits.seconds)};
    for (const auto &[name, value] : parameters)
        args << QString::fromUtf8(name) + u'=' + value;
    QProcess helper;
    helper.start(translatorHelper(), args);
    if (!helper.waitForStarted(5000))
        return failure(QStringLiteral("cannot start %1: %2").arg(translatorHelper(), helper.errorString()));
    // The helper compiles the stylesheet while the input is made.
    helper.write(makeInput());
    helper.closeWriteChannel();
    QByteArray output;
    QElapsedTimer clock;
    clock.start();
    const qint64 limitMs = qint64(limits.seconds) * 1000 + 500;
    while (helper.state() != QProcess::NotRunning && clock.elapsed() < limitMs) {
        helper.waitForReadyRead(50);
        output += helper.readAllStandardOutput();
        if (output.size() > qsizetype(limits.megabytes) * 1024 * 1024) {
            helper.kill();
            helper.waitForFinished(5000);
            return failure(QStringLiteral("stopped: its output passed %1 MB").arg(limits.megabytes));
        }
    }
    if (helper.state() != QProcess::NotRunning) {
        helper.kill();
        helper.waitForFinished(5000);
        return failure(QStringLiteral("stopped: it ran longer than its %1 s limit").arg(limits.seconds));
    }
    output += helper.readAllStandardOutput();
    const QString errors = QString::fromUtf8(helper.readAllStandardError()).trimmed();
    if (helper.exitStatus() == QProcess::CrashExit || (helper.exitCode() != 0 && errors.isEmpty())) {
        // Killed by its CPU-time limit (SIGXCPU), or ended when memory ran out.
        if (clock.elapsed() >= qint64(limits.seconds) * 1000 - 100)
            return failure(QStringLiteral("stopped: it ran longer than its %1 s limit").arg(limits.seconds));
        return failure(QStringLiteral("stopped: it used more than its %1 MB of memory").arg(limits.megabytes));
    }
    if (helper.exitCode() != 0) {
        // "file:line:column: message" or "file: message", as Stylesheet reports it.
        static const QRegularExpression located(QStringLiteral(R"(^(.*?)(?::(\d+))?(?::(\d+))?: (.*)$)"),
                                                QRegularExpression::DotMatchesEverythingOption);
        const auto match = located.match(errors);
        if (match.hasMatch())
            return std::unexpected(xml::XmlError{match.captured(1), match.captured(2).toInt(), match.captured(3).toInt(),
                                                 match.captured(4)});
        return failure(errors.contains(QStringLiteral("out of memory"), Qt::CaseInsensitive)
                           ? QStringLiteral("stopped: it used more than its %1 MB of memory (%2)").arg(limits.megabytes).arg(errors)
                           : errors);
    }
    return output;
}

} // namespace neptus::processor
