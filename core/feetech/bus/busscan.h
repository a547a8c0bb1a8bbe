// The Feetech bus scan: a broadcast probe per rate, a PING per ID, a patient second look.
#pragma once

#include "busexchange.h"
#include "bustypes.h"
#include "feetechpacket.h"
#include "scanpace.h"
#include "streamframer.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>

#include <deque>
#include <optional>

namespace feetech {

// Asks every ID of a range at every chosen rate and identifies whoever answers. A missing ID
// costs what the answers heard on this link say (ScanPace), not a fixed wait; servos that
// answered late or garbled are asked once more, with time to spare, before the scan moves on.
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
    // What a missing ID costs now at `baud`: the wait for the first byte of its answer.
    // `patient`: the whole allowance, whatever the link has shown.
    std::chrono::microseconds pingWait(qint32 baud, bool patient = false) const;

signals:
    void progress(int done, int total, qint32 baud);
    void servoFound(const feetech::ServoInfo &servo);
    void finished(bool completed, const QString &message);

private:
    void scanBaud(int baudIndex);
    void probe(int baudIndex, int round);
    void lookAgainAtSilentRates();
    void scanId(int baudIndex, int id);
    void closeSweep(int baudIndex);
    void recheck(int baudIndex);
    void broadcastPing(std::chrono::microseconds wait,
                       std::function<void(const seriallink::TransactionResult &)> then);
    // A scan's PING; the scan ends when the link does, otherwise `then` hears the answer.
    void scanPing(int id, std::optional<std::chrono::microseconds> timeout, int retries,
                  ExchangeDone then);
    // Reads the identity of a servo that answered (`statusBits`: its PING answer's error bits)
    // and whether it shares its ID, then reports it found.
    void identifyFound(quint8 id, qint32 baud, quint8 statusBits, std::function<void()> then);
    void checkShared(std::shared_ptr<ServoInfo> servo, std::function<void()> then);
    void reportFound(const ServoInfo &servo);
    void end(bool completed, const QString &message);
    // An answer named `id` outside its own wait: it is asked again, patiently.
    void answeredLate(quint8 id);
    // Bytes that name no one came: any ID whose wait ended lately may have sent them.
    void heardUnnamed();
    void askAgain(int id); // in the recheck after the sweep of this rate
    void onFrameHeard(const QByteArray &frame);
    void onStrayBytes(const QByteArray &bytes);
    std::chrono::microseconds lateWindow() const;

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
        int asking = -1; // the ID of the PING (or identity READ) on its way
        int sweptUpTo = -1; // the highest ID the sweep of this rate has asked
        bool answeredAtRate = false; // the opening broadcast PING was answered
        bool probing = false; // a broadcast PING is on its way
        QHash<int, int> timesRechecked;
        // The IDs of this rate that stayed silent, with when their wait ended (m_clock, µs).
        std::deque<std::pair<int, qint64>> silent;
        ScanPace pace; // across rates: what the link adds beyond the wire does not change
        // Rates skipped because nothing answered their broadcast PING, and whether they are
        // being looked at again (once, patiently, when the whole scan found nobody).
        QVector<qint32> silentRates;
        bool secondLook = false;
    };

    BusExchange &m_bus;
    std::optional<State> m_scan;
    QElapsedTimer m_clock;
    FrameFormat m_format;
    // Input the engine discarded while no request waited (a late answer between two PINGs).
    seriallink::StreamFramer m_strays {m_format};
};

} // namespace feetech
