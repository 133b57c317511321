#pragma once

#include <QByteArray>
#include <QString>

#include <expected>
#include <functional>

namespace neptus {

// Writes a file the way nothing is lost if the program dies half way: the
// bytes go to a temporary file beside `path` that replaces it only once
// complete; the previous version is kept as `path` + ".bak" (itself replaced
// atomically). The hook, for tests, runs after the temporary file is written
// and before it replaces the old one.
// Writes a file whole or not at all (a temporary file beside `path` replaces
// it once complete); an error names the path and why ("No space left on
// device").
std::expected<void, QString> saveFileAtomically(const QString &path, const QByteArray &bytes);

std::expected<void, QString> saveFileKeepingPrevious(const QString &path, const QByteArray &bytes,
                                                     const std::function<void()> &beforeReplace = {});

} // namespace neptus
