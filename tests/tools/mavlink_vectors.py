#!/usr/bin/env python3
"""MAVLink test vectors made by pymavlink (an independent implementation, from
PyPI), for the console's codec to decode and encode byte for byte.

For every message of the ardupilotmega dialect: a MAVLink 2 frame, a signed
MAVLink 2 frame, and, for ids under 256, a MAVLink 1 frame; values chosen
from the message id and field index (deterministic), some trailing fields zero
so that MAVLink 2 leaves bytes out, extensions sometimes set and sometimes not.
Writes one JSON object a line on stdout:

  {"name": ..., "id": ..., "version": 1|2, "signed": bool, "seq": ..., "system": ...,
   "component": ..., "link": ..., "timestamp": ..., "frame": hex,
   "fields": [[name, value as text], ...]}

Field names as the console's schema has them: a numeric array's elements are
"name[i]"; char arrays are text (hex of its bytes), uint8_t arrays bytes
(hex); floats are written as their exact value (repr), integers as text.
"""
import json
import struct
import sys

from pymavlink.dialects.v10 import ardupilotmega as v1
from pymavlink.dialects.v20 import ardupilotmega as v2

KEY = bytes(range(32))


def value_of(kind, msg_id, index, element, zero):
    """A value of `kind`, the same for the same message, field and element."""
    if zero:
        return 0
    seed = (msg_id * 131 + index * 17 + element * 7) % 1000003
    if kind in ('float', 'double'):
        v = (seed % 20000 - 10000) / 4.0  # exact in a float
        return struct.unpack('<f', struct.pack('<f', v))[0] if kind == 'float' else v
    bits = {'int8_t': 8, 'uint8_t': 8, 'char': 8, 'int16_t': 16, 'uint16_t': 16,
            'int32_t': 32, 'uint32_t': 32, 'int64_t': 64, 'uint64_t': 64}[kind]
    raw = (seed * 2654435761 + element) & ((1 << bits) - 1)
    if kind.startswith('int') and raw >= 1 << (bits - 1):
        raw -= 1 << bits
    return raw


def make(module, cls, variant):
    """Arguments for `cls` and the field list to expect."""
    args = []
    expected = []
    count = len(cls.fieldnames)
    lengths = dict(zip(cls.ordered_fieldnames, cls.array_lengths))  # array_lengths follow the wire order
    for index, (name, kind) in enumerate(zip(cls.fieldnames, cls.fieldtypes)):
        length = lengths[name]
        # variant 1: the last third of the fields zero (trailing zeros left out)
        zero = variant == 1 and index >= count - max(1, count // 3)
        if name == 'mavlink_version':
            args.append(3)
            expected.append([name, '3'])
            continue
        if kind == 'char' and length:
            n = 0 if zero else (length if (cls.id + index) % 3 == 0 else max(1, length // 2))
            text = bytes((65 + (cls.id + index + i) % 26) for i in range(n))
            args.append(text)
            expected.append([name, text.hex()])
        elif kind == 'uint8_t' and length:
            data = bytes(value_of(kind, cls.id, index, i, zero) for i in range(length))
            args.append(list(data))
            expected.append([name, data.hex()])
        elif length:
            values = [value_of(kind, cls.id, index, i, zero) for i in range(length)]
            args.append(values)
            for i, v in enumerate(values):
                expected.append(['%s[%d]' % (name, i), repr(v)])
        else:
            v = value_of(kind, cls.id, index, 0, zero)
            args.append(v)
            expected.append([name, repr(v)])
    return args, expected


def main():
    out = sys.stdout
    for dialect, version in ((v2, 2), (v1, 1)):
        for msg_id in sorted(dialect.mavlink_map):
            if version == 1 and msg_id > 255:
                continue
            cls = dialect.mavlink_map[msg_id]
            for variant, signed in ((0, False), (1, False), (0, True)):
                if signed and version == 1:
                    continue
                args, expected = make(dialect, cls, variant)
                mav = dialect.MAVLink(None, srcSystem=(msg_id % 250) + 1, srcComponent=(msg_id * 7) % 256)
                mav.seq = (msg_id * 3 + variant) % 256
                link, timestamp = 0, 0
                if signed:
                    link, timestamp = msg_id % 256, 600000000000 + msg_id
                    mav.signing.secret_key = KEY
                    mav.signing.link_id = link
                    mav.signing.timestamp = timestamp
                    mav.signing.sign_outgoing = True
                frame = cls(*args).pack(mav, force_mavlink1=(version == 1))
                out.write(json.dumps({'name': cls.msgname, 'id': msg_id, 'version': version, 'signed': signed,
                                      'seq': (msg_id * 3 + variant) % 256, 'system': (msg_id % 250) + 1,
                                      'component': (msg_id * 7) % 256, 'link': link, 'timestamp': timestamp,
                                      'frame': frame.hex(), 'fields': expected}) + '\n')


if __name__ == '__main__':
    main()
