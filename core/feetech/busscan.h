// The Feetech bus scan: a broadcast probe per rate, a PING per ID, a patient second look.
#pragma once

#include "feetech/busexchange.h"
#include "feetech/bustypes.h"

#include <QObject>

#include <optional>

namespace feetech {

// Asks every ID of a range at every chosen rate and identifies whoever answers. A missing ID
// costs what the line's measured answer time says, not a fixed wait; servos that answered late
// or garbled are asked once more, with time to spare, before the scan moves on.
// Lives in the session's thread; the session runs one scan at a time, as an operation.
class BusScan : public QObject
{
    Q_OBJECT

public:
    explicit BusScan(BusExchange &bus, QObject *parent = nullptr);

    void start(const feetech::ScanOptions &options);
    // Stops after the ID being asked; servos found so far stay found.
    void cancel();
    // The link ended: forget the scan without a word (the session reports it).
    void abandon() { m_scan.reset(); }
    bool isRunning() const { return m_scan.has_value(); }

signals:
    void progress(int done, int total, qint32 baud);
    void servoFound(const feetech::ServoInfo &servo);
    void finished(bool completed, const QString &message);

private:
    void scanBaud(int baudIndex);
    void probe(int baudIndex, int round);
    void scanId(int baudIndex, int id);
    void recheck(int baudIndex);
    // A scan's PING; the scan ends when the link does, otherwise `then` hears the answer.
    void scanPing(int id, std::optional<std::chrono::microseconds> timeout, int retries,
                  ExchangeDone then);
    void identifyFound(quint8 id, qint32 baud, std::function<void()> then);
    void end(bool completed, const QString &message);

    struct State
    {
        ScanOptions options;
        int done = 0;
        int total = 0;
        int found = 0;
        bool cancelled = false;
        // IDs that answered too late or garbled during the sweep of this rate.
        QVector<int> recheck;
        QVector<int> foundIds;
    };

    BusExchange &m_bus;
    std::optional<State> m_scan;
};

} // namespace feetech
