// Qt Quick Test runner for the project's tst_*.qml files, with the project's
// QML modules (Neptus.Engine, Neptus.Components, Neptus.Shell) built in.
#include <QQuickStyle>
#include <QtQml/qqmlextensionplugin.h>
#include <QtQuickTest>

Q_IMPORT_QML_PLUGIN(Neptus_EnginePlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ComponentsPlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ShellPlugin)

class Setup : public QObject
{
    Q_OBJECT
public slots:
    void applicationAvailable()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("neptus-qt-tests"));
        QQuickStyle::setStyle(QStringLiteral("Basic"));
    }
};

QUICK_TEST_MAIN_WITH_SETUP(neptus_qml, Setup)

#include "main.moc"
