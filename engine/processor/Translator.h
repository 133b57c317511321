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
//
// The helper is started at the first translation and kept for the whole
// program (two, so a translation on the GUI thread does not wait behind an
// export; translations one after the other in each), with the stylesheets it
// compiled: a translation pays neither the start nor the compile (14-18 ms
// each, issue #39). A stylesheet is compiled again when a file of its folder
// changes. A helper that was stopped, crashed or ended is replaced at the
// next translation; it ends with the program.
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

// What the helper did so far (for tests and benchmarks).
struct TranslatorStatus
{
    qint64 pid = 0;        // the first helper, the one used when none is busy (0: not running)
    int started = 0;       // helpers started (these counts: both helpers')
    int compiled = 0;      // stylesheets compiled (not found compiled)
    int translations = 0;  // answers received
};
TranslatorStatus translatorStatus();

} // namespace neptus::processor
