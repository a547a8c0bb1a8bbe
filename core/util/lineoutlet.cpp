// Output lines written to a descriptor by a thread of their own, lost and counted when told so.
#include "lineoutlet.h"

#include <cerrno>
#include <condition_variable>
#include <mutex>
#include <thread>

#include <unistd.h>

namespace util {

namespace {

// A writer waiting for room sees it free up a piece at a time, and the stall clock sees progress
// while a slow reader takes a long queue.
constexpr qsizetype kWritePiece = 16 * 1024;

} // namespace

struct LineOutlet::Shared
{
    std::mutex mutex;
    std::condition_variable work; // the writer thread: something queued, or the outlet goes
    std::condition_variable room; // writers and drain(): some of the queue was written
    QByteArray queue;
    qsizetype inFlight = 0; // taken from the queue by the thread and not written yet
    qsizetype capacity = 0;
    int descriptor = -1;
    quint64 progress = 0; // pieces written: drain() tells a slow reader from one that stopped
    bool closing = false;
    bool broken = false; // the descriptor refused a write: nothing more is written
    WhenFull whenFull = WhenFull::Wait;
    qint64 dropped = 0;
    qint64 unreported = 0; // lost lines that no line has stood for yet
    std::function<QByteArray(qint64)> droppedLine;

    qsizetype queued() const { return queue.size() + inFlight; }
    bool empty() const { return queued() == 0 || broken; }

    void run()
    {
        std::unique_lock lock(mutex);
        for (;;) {
            work.wait(lock, [this] { return closing || !queue.isEmpty(); });
            if (queue.isEmpty())
                return;
            const QByteArray chunk = std::exchange(queue, {});
            inFlight = chunk.size();
            for (qsizetype done = 0; done < chunk.size() && !broken;) {
                lock.unlock();
                const qsizetype piece = qMin(kWritePiece, chunk.size() - done);
                const ssize_t written =
                    ::write(descriptor, chunk.constData() + done, size_t(piece));
                lock.lock();
                if (written < 0 && errno == EINTR)
                    continue;
                if (written <= 0) {
                    broken = true;
                    break;
                }
                done += written;
                inFlight -= written;
                ++progress;
                room.notify_all();
            }
            inFlight = 0;
            room.notify_all();
        }
    }
};

LineOutlet::LineOutlet(int descriptor, qsizetype capacity, QObject *parent)
    : QIODevice(parent)
    , m_shared(std::make_shared<Shared>())
{
    m_shared->descriptor = descriptor;
    m_shared->capacity = capacity;
    std::thread([shared = m_shared] { shared->run(); }).detach();
    open(QIODevice::WriteOnly | QIODevice::Unbuffered);
}

LineOutlet::~LineOutlet()
{
    if (!m_partial.isEmpty())
        enqueue(std::exchange(m_partial, {}));
    if (whenFull() == WhenFull::Wait) {
        std::unique_lock lock(m_shared->mutex);
        m_shared->room.wait(lock, [this] { return m_shared->empty(); });
    } else {
        drain();
    }
    // A thread still in write() is left to it: it owns what it needs, and the process ends.
    const std::lock_guard lock(m_shared->mutex);
    m_shared->closing = true;
    m_shared->work.notify_all();
}

void LineOutlet::setWhenFull(WhenFull whenFull)
{
    const std::lock_guard lock(m_shared->mutex);
    m_shared->whenFull = whenFull;
}

LineOutlet::WhenFull LineOutlet::whenFull() const
{
    const std::lock_guard lock(m_shared->mutex);
    return m_shared->whenFull;
}

void LineOutlet::setDroppedLine(std::function<QByteArray(qint64)> droppedLine)
{
    const std::lock_guard lock(m_shared->mutex);
    m_shared->droppedLine = std::move(droppedLine);
}

qint64 LineOutlet::droppedLines() const
{
    const std::lock_guard lock(m_shared->mutex);
    return m_shared->dropped;
}

bool LineOutlet::drain(std::chrono::milliseconds stall)
{
    std::unique_lock lock(m_shared->mutex);
    quint64 seen = m_shared->progress;
    while (!m_shared->empty()) {
        const bool moved = m_shared->room.wait_for(
            lock, stall, [&] { return m_shared->empty() || m_shared->progress != seen; });
        if (!moved)
            return false;
        seen = m_shared->progress;
    }
    return !m_shared->broken;
}

qint64 LineOutlet::readData(char *, qint64)
{
    return -1; // write-only
}

qint64 LineOutlet::writeData(const char *data, qint64 size)
{
    m_partial.append(data, size);
    const qsizetype end = m_partial.lastIndexOf('\n');
    if (end >= 0) {
        enqueue(m_partial.left(end + 1));
        m_partial.remove(0, end + 1);
    } else if (m_partial.size() > m_shared->capacity) {
        enqueue(std::exchange(m_partial, {})); // a line longer than the queue goes as it is
    }
    return size;
}

void LineOutlet::enqueue(const QByteArray &lines)
{
    Shared &shared = *m_shared;
    std::unique_lock lock(shared.mutex);
    if (shared.broken)
        return;
    if (shared.whenFull == WhenFull::Wait) {
        shared.room.wait(lock, [&] {
            return shared.broken || shared.queued() == 0
                || shared.queued() + lines.size() <= shared.capacity;
        });
    } else {
        const QByteArray standIn = shared.unreported > 0 && shared.droppedLine
            ? shared.droppedLine(shared.unreported)
            : QByteArray();
        if (shared.queued() > 0
            && shared.queued() + standIn.size() + lines.size() > shared.capacity) {
            const qint64 lost = qMax<qint64>(1, lines.count('\n'));
            shared.dropped += lost;
            shared.unreported += lost;
            return;
        }
        shared.queue += standIn;
        shared.unreported = 0;
    }
    shared.queue += lines;
    shared.work.notify_one();
}

} // namespace util
