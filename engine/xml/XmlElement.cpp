#include "xml/XmlElement.h"

#include <QXmlStreamWriter>

#include "xml/XmlDocument.h"

namespace neptus::xml {

QString Element::attribute(const QString &name) const
{
    for (const auto &[key, value] : attributes) {
        if (key == name)
            return value;
    }
    return {};
}

const Element *Element::child(const QString &name) const
{
    for (const Element &c : children) {
        if (c.name == name)
            return &c;
    }
    return nullptr;
}

Element readElement(const xmlNode *node)
{
    Element element;
    element.name = elementName(node);
    for (const xmlAttr *a = node->properties; a; a = a->next)
        element.attributes.append({QString::fromUtf8(reinterpret_cast<const char *>(a->name)), attributeValue(a)});
    for (const xmlNode *child : childElements(node))
        element.children.push_back(readElement(child));
    if (element.children.empty())
        element.text = textContent(node).trimmed();
    return element;
}

void writeElement(QXmlStreamWriter &out, const Element &element)
{
    out.writeStartElement(element.name);
    for (const auto &[name, value] : element.attributes)
        out.writeAttribute(name, value);
    if (element.children.empty()) {
        if (!element.text.isEmpty())
            out.writeCharacters(element.text);
    } else {
        for (const Element &child : element.children)
            writeElement(out, child);
    }
    out.writeEndElement();
}

void writeElements(QXmlStreamWriter &out, const QString &wrapper, const QList<Element> &elements)
{
    if (elements.isEmpty())
        return;
    out.writeStartElement(wrapper);
    for (const Element &element : elements)
        writeElement(out, element);
    out.writeEndElement();
}

} // namespace neptus::xml
