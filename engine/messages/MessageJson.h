#pragma once

#include "messages/Message.h"

#include <QJsonObject>
#include <QString>

#include <expected>

namespace neptus::msg {

// Messages as JSON, for inspectors, exports and neptus-msg:
//   {"abbrev": "EstimatedState", "mgid": 350, "timestamp": 1.7e9, "src": 31,
//    "src_ent": 44, "dst": 65535, "dst_ent": 255, "fields": {"lat": 0.71, ...}}
// Enumerated and bitfield values are written by name ("SERVICE", "A|B");
// rawdata as hex; plaintext as a string, or {"hex": "..."} when it is not
// UTF-8; NaN and infinities as "NaN", "Infinity", "-Infinity"; a nested
// message as an object without header keys, none as null; a message-list as
// an array. A message the schema does not know: {"mgid": N, "opaque": "hex"}.
// fromJson() reads all of that back (names or numbers for enumerations), so
// decode → JSON → encode gives the same bytes.
QJsonObject toJson(const Message &message);
// Inline messages: no header keys.
QJsonObject toJsonWithoutHeader(const Message &message);

// Errors name the path of the bad key ("fields.maneuvers[2].data.lat") and what
// was expected.
std::expected<Message, QString> fromJson(const Schema &schema, const QJsonObject &json);

// One line for logs and consoles: "EstimatedState lat=0.71 rad lon=-0.15 rad ...".
QString toText(const Message &message);

} // namespace neptus::msg
