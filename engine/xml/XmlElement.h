#pragma once

#include <QList>
#include <QString>

#include <libxml/tree.h>

#include <utility>
#include <vector>

class QXmlStreamWriter;

namespace neptus::xml {

// A small XML element tree kept as a value: name, attributes in document
// order, text (when it has no child elements) and children. What a mission
// keeps of the IMC messages its plans send as actions, and what
// msg::fromXml reads.
struct Element
{
    QString name;
    QList<std::pair<QString, QString>> attributes;
    QString text;
    std::vector<Element> children; // std::vector: QList cannot compare a type that holds itself

    QString attribute(const QString &name) const;
    const Element *child(const QString &name) const;
    friend bool operator==(const Element &, const Element &) = default;
};

// The element and everything under it; text trimmed.
Element readElement(const xmlNode *node);
// And written back, as read.
void writeElement(QXmlStreamWriter &out, const Element &element);
// Elements inside a wrapper element (<messages>…</messages>); nothing at all when there are none.
void writeElements(QXmlStreamWriter &out, const QString &wrapper, const QList<Element> &elements);

} // namespace neptus::xml
