#include "transport/DatagramPump.h"

namespace neptus::transport {

namespace {

// Datagrams taken in one go, then the queues looked at again.
constexpr int datagramsPerTake = 256;

} // namespace

DatagramPump::DatagramPump(std::vector<int> fds, DatagramReader::Limits limits, Handle handle, Dropped dropped)
    : m_handle(std::move(handle))
    , m_dropped(std::move(dropped))
{
    m_reader = std::make_unique<DatagramReader>(std::move(fds), limits, [this] {
        {
            std::lock_guard lock(m_mutex);
            m_woken = true;
        }
        m_wake.notify_one();
    });
    m_thread = std::thread([this] { run(); });
}

DatagramPump::~DatagramPump()
{
    {
        std::lock_guard lock(m_mutex);
        m_stopping = true;
    }
    m_wake.notify_one();
    m_thread.join();
    m_reader.reset();
}

void DatagramPump::run()
{
    for (;;) {
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [this] { return m_woken || m_stopping; });
            if (m_stopping)
                return;
            m_woken = false;
        }
        for (;;) {
            const DatagramReader::Batch batch = m_reader->take(datagramsPerTake);
            if ((!batch.dropped.isEmpty() || !batch.behind.isEmpty()) && m_dropped)
                m_dropped(batch.dropped, batch.behind);
            for (const DatagramReader::Datagram &datagram : batch.datagrams)
                m_handle(datagram);
            if (!batch.more)
                break;
            std::lock_guard lock(m_mutex);
            if (m_stopping)
                return;
        }
    }
}

} // namespace neptus::transport
