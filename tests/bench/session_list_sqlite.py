"""The session list's "which systems each session kept positions of" on a large
operation database (SQLite): scanning every position, as before schema version 2,
against reading session_systems. Builds the database first (about a minute, 850 MB):

    tools/dev python3 tests/bench/session_list_sqlite.py build/tmp/sessions.sqlite
"""
import os
import sqlite3
import sys
import time

path = sys.argv[1]
if not os.path.exists(path):
    db = sqlite3.connect(path)
    # Schema version 1's positions table (engine/database/Database.cpp).
    db.execute("CREATE TABLE positions (session TEXT NOT NULL, seq BIGINT NOT NULL, t BIGINT NOT NULL, system TEXT NOT NULL, "
               "imc_id INTEGER, lat DOUBLE PRECISION NOT NULL, lon DOUBLE PRECISION NOT NULL, depth DOUBLE PRECISION, "
               "altitude DOUBLE PRECISION, heading DOUBLE PRECISION, speed DOUBLE PRECISION, PRIMARY KEY (session, seq, t))")
    db.execute("CREATE INDEX positions_system_t ON positions (system, t)")
    # 40 sessions of 3 hours, 6 systems at 2 positions a second: 5.2 M rows.
    for s in range(40):
        session = "session-%02d-3f9ee785f868abcd" % s
        rows, seq = [], 0
        for k in range(3 * 3600 * 2):
            for system in range(6):
                seq += 1
                rows.append((session, seq, 1790000000000 + s * 10**8 + k * 500, "vehicle-%d" % system, system,
                             0.718, -0.15, 3.0, 10.0, 1.0, 1.5))
        db.executemany("INSERT INTO positions VALUES (?,?,?,?,?,?,?,?,?,?,?)", rows)
        db.commit()
    db.close()

db = sqlite3.connect(path)
print("positions:", db.execute("SELECT COUNT(*) FROM positions").fetchone()[0], "rows,", os.path.getsize(path) // 2**20, "MB")
db.execute("DROP TABLE IF EXISTS session_systems")
db.commit()
db.close()


def timed(what, query):
    """Three reads of `query`, each on a fresh connection (as the session list's worker opens one)."""
    for _ in range(3):
        db = sqlite3.connect(path)
        t = time.time()
        pairs = db.execute(query).fetchall()
        print("%s: %.2f ms, %d pairs" % (what, (time.time() - t) * 1000, len(pairs)))
        db.close()


timed("scanning positions", "SELECT DISTINCT session, system FROM positions ORDER BY session, system")
db = sqlite3.connect(path)
t = time.time()
# Schema version 2's migration, once per database.
db.execute("CREATE TABLE session_systems (session TEXT NOT NULL, system TEXT NOT NULL, PRIMARY KEY (session, system))")
db.execute("INSERT INTO session_systems (session, system) SELECT DISTINCT session, system FROM positions")
db.commit()
print("the migration's fill, once: %.0f ms" % ((time.time() - t) * 1000))
db.close()
timed("reading session_systems", "SELECT session, system FROM session_systems ORDER BY session, system")
