#pragma once

// Access to the real-world fixtures in ../shared/fixtures (beside the
// checkout, never copied into it). Where that folder is absent a test that
// needs it is reported as skipped, with the reason.

#include "Paths.h"
#include <QFile>
#include <QFileInfo>
#include <QString>

#include <gtest/gtest.h>

namespace neptus::test {

inline QString fixturePath(const char *relative)
{
    return sharedPath(QStringLiteral("fixtures/") + QString::fromUtf8(relative));
}

// One line of a vectors file: "name length hex".
struct Vector
{
    QString name;
    QByteArray bytes;
};

inline std::vector<Vector> readVectors(const QString &path)
{
    std::vector<Vector> vectors;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return vectors;
    while (!file.atEnd()) {
        const QList<QByteArray> parts = file.readLine().trimmed().split(' ');
        if (parts.size() != 3)
            continue;
        Vector vector{QString::fromUtf8(parts[0]), QByteArray::fromHex(parts[2])};
        EXPECT_EQ(vector.bytes.size(), parts[1].toInt()) << "vector " << parts[0].constData();
        vectors.push_back(std::move(vector));
    }
    return vectors;
}

// The packet of the vector called `name` in imc/vectors.txt; empty if absent.
inline QByteArray vectorNamed(const char *name)
{
    for (const auto &v : readVectors(fixturePath("imc/vectors.txt"))) {
        if (v.name == QLatin1StringView(name))
            return v.bytes;
    }
    return {};
}

} // namespace neptus::test

// Skips the test, visibly and with the reason, when a fixture is missing.
#define NEPTUS_REQUIRE_FIXTURE(variable, relative)                                                             \
    const QString variable = ::neptus::test::fixturePath(relative);                                          \
    if (!QFileInfo::exists(variable))                                                                          \
    GTEST_SKIP() << "fixture " << relative << " is not at " << variable.toStdString()                         \
                 << " (../shared beside the checkout is absent)"
