#pragma once

#include "messages/Message.h"
#include "xml/XmlElement.h"

#include <QString>

#include <expected>

namespace neptus::msg {

// IMC messages as XML, the form LSTS Neptus writes in its plans (start
// actions) and the IMC mission stylesheet makes: the element named after the
// message; one child element per field, holding its value as text (numbers,
// enumerated values by name or number, bitfields as "A|B", raw data as hex);
// a message field holds the nested message's element, a message-list field
// one element per message. Absent fields are zero. Attributes src, src_ent,
// dst, dst_ent and time set the header; others (imcv) are ignored.
//
// One addition: an angle field (unit "rad") may say unit="deg" and be given
// in degrees; it is converted here with radiansFromDegrees, the one
// conversion the direct encoders use too, so a stylesheet that copies
// degrees from a mission gives the same bytes as C++ that converts them.
std::expected<Message, QString> fromXml(const Schema &schema, const xml::Element &element);
xml::Element toXml(const Message &message);

double radiansFromDegrees(double degrees);

} // namespace neptus::msg
