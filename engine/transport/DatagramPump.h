#pragma once

#include "transport/DatagramReader.h"

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace neptus::transport {

// A link's receive path off the GUI thread: UDP sockets read on a thread of
// their own (DatagramReader: a bounded queue per sending host, a host over
// its rate losing its own datagrams), and taken from the queues one host at a
// time in turn on a second thread, which hands each to `handle` (decode,
// record, ingest — all thread-safe in the console) and what was dropped to
// `dropped`. A busy GUI thread delays and loses nothing.
class DatagramPump
{
public:
    using Handle = std::function<void(const DatagramReader::Datagram &datagram)>;
    // Datagrams dropped since the last call: over their host's rate, or behind a full queue.
    using Dropped = std::function<void(const QHash<QString, int> &overRate, const QHash<QString, int> &behind)>;

    DatagramPump(std::vector<int> fds, DatagramReader::Limits limits, Handle handle, Dropped dropped);
    // Stops taking, then reading; the sockets stay open (the caller's).
    ~DatagramPump();
    DatagramPump(const DatagramPump &) = delete;
    DatagramPump &operator=(const DatagramPump &) = delete;

private:
    void run();

    Handle m_handle;
    Dropped m_dropped;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_woken = false, m_stopping = false;
    std::unique_ptr<DatagramReader> m_reader;
    std::thread m_thread;
};

} // namespace neptus::transport
