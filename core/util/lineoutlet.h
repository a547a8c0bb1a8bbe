// Output lines written to a file descriptor by a thread of their own, so that a reader who stops
// reading (a paused pager, a full pipe) never stops the program that writes them.
#pragma once

#include <QIODevice>

#include <chrono>
#include <functional>
#include <memory>

namespace util {

// A write-only device for QTextStream. What is written goes to a bounded queue that a thread
// of the outlet's own writes to the descriptor. While full, a writer either waits for room
// (WhenFull::Wait: every line arrives, as with a plain file) or loses whole lines, which are
// counted (WhenFull::Drop: for streams whose bytes on the bus must never wait); once there is
// room again, the line `droppedLine` makes of the count stands where they were.
class LineOutlet : public QIODevice
{
    Q_OBJECT

public:
    enum class WhenFull { Wait, Drop };
    static constexpr qsizetype kDefaultCapacity = 256 * 1024;
    // How long the outlet waits, when it goes, for a reader that reads nothing.
    static constexpr std::chrono::milliseconds kDefaultStall {500};

    explicit LineOutlet(int descriptor, qsizetype capacity = kDefaultCapacity,
                        QObject *parent = nullptr);
    // Waits for what is queued to be written: all of it (Wait), or for as long as the reader
    // takes some within the stall time (Drop); a reader that reads nothing is then left behind.
    ~LineOutlet() override;

    void setWhenFull(WhenFull whenFull);
    WhenFull whenFull() const;
    // The line that stands for `count` lost lines (its '\n' included); none when not set.
    void setDroppedLine(std::function<QByteArray(qint64 count)> droppedLine);
    // Lines lost since the outlet was made.
    qint64 droppedLines() const;
    // Waits until the queue is written, or nothing was written for `stall`; whether all was.
    bool drain(std::chrono::milliseconds stall = kDefaultStall);

    bool isSequential() const override { return true; }

protected:
    qint64 readData(char *data, qint64 maxSize) override;
    qint64 writeData(const char *data, qint64 size) override;

private:
    struct Shared;
    void enqueue(const QByteArray &lines);

    std::shared_ptr<Shared> m_shared;
    QByteArray m_partial; // the start of a line whose end has not been written yet
};

} // namespace util
