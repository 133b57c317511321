#pragma once

#include "xml/XmlDocument.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <expected>
#include <functional>
#include <utility>

namespace neptus::processor {

// Applies a stylesheet (Stylesheet's hardening) in a process of its own,
// neptus-xslt, beside the running program: XSLT can run for ever or fill
// memory, and a stylesheet a user dropped in must not take the console with
// it. Past `seconds` (wall clock, and as much CPU time) or `megabytes` of
// address space the helper is stopped and the error says which limit.
struct TranslateLimits
{
    int seconds = 10;
    int megabytes = 1024;
};

std::expected<QByteArray, xml::XmlError> translate(const QString &stylesheet, QByteArrayView input,
                                                   const QString &inputName,
                                                   const QList<std::pair<QByteArray, QString>> &parameters = {},
                                                   TranslateLimits limits = {});

// The same, with the input made by `makeInput` while the helper starts and
// compiles the stylesheet (the two take about as long for a large plan).
std::expected<QByteArray, xml::XmlError> translate(const QString &stylesheet, const std::function<QByteArray()> &makeInput,
                                                   const QString &inputName,
                                                   const QList<std::pair<QByteArray, QString>> &parameters = {},
                                                   TranslateLimits limits = {});

// Where the helper is: beside the running program.
QString translatorHelper();

} // namespace neptus::processor
