#pragma once

// What the layout parser and writer share. Internal to neptus-layout.

#include "LayoutDocument.h"

#include <QString>

#include <expected>
#include <memory>

namespace neptus::layout::detail {

// Indents every line after the first by `indent` (empty lines stay empty).
QString indentRest(const QString &text, const QString &indent);

// The root object of a layout's text, and the comments before and after it.
std::expected<std::unique_ptr<LayoutObject>, LayoutError> parseObjects(const QString &text, QString &header,
                                                                      QString &footer);
// Writes an object and its children at `depth`, properties in a fixed order.
void writeObject(QString &out, const LayoutObject &object, int depth);
void writeComments(QString &out, const QString &comments, const QString &indent);

} // namespace neptus::layout::detail
