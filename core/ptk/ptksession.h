// The PTK programmer session: polls the eight queries, writes N1..N12 and verifies by reading back.
#pragma once

#include "linktypes.h"
#include "ptkframe.h"
#include "ptkparameters.h"
#include "requestengine.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <chrono>

namespace seriallink {
class LinkSession;
}

namespace ptk {

struct SessionTiming
{
    // PTK's own cadence: one query every 50 ms, a full refresh every 400 ms.
    std::chrono::milliseconds pollInterval {50};
    bool fastPolling = false; // the next query as soon as the last one is answered
    // PTK's software and the reverse-engineered firmware leave 50 ms between write frames.
    std::chrono::milliseconds writeGap {50};
    // How often a port that went away is looked for again.
    std::chrono::milliseconds reconnectInterval {500};
    // 40 ms for an answer: behind an FTDI adapter at its default 16 ms latency timer, the echo
    // and the answer of one query can come in two of its packets, 32 ms apart.
    seriallink::EngineTiming engine {std::chrono::milliseconds(40)};
};

// Where a set of values came from: background polling, an explicit read, or the read-back
// that verifies an Apply.
enum class ReadSource { Poll, Read, ReadBack };

// Lives in a link worker thread (or the CLI's main thread); driven only by signals and timers.
class Session : public QObject
{
    Q_OBJECT

public:
    explicit Session(const SessionTiming &timing = {}, QObject *parent = nullptr);
    ~Session() override;

    const SessionTiming &timing() const { return m_timing; }
    const seriallink::LinkCounters &counters() const;
    const seriallink::ConnectionStatus &status() const;
    seriallink::LinkSession &link() { return *m_link; }
    bool isApplying() const { return m_phase == Phase::Writing || m_phase == Phase::ReadingBack; }

    // Slots, called through QMetaObject::invokeMethod from other threads.
    void open(const QString &portName, qint32 baud, seriallink::EchoMode echo);
    void close();
    void setPolling(bool enabled);
    void setPollInterval(int milliseconds, bool fast);
    // One sweep of the eight queries now, ahead of polls.
    void readAll();
    // Writes the full sequence with `values` (complete, in wire units), then reads back.
    void apply(const ptk::ParameterSet &values);
    // A frame built by hand (the packet window), sent once between the polls; a query waits
    // for its reply. What comes back is in the packet log; frameSent says how it went.
    void sendFrame(const QByteArray &frame, bool expectsReply);

signals:
    void statusChanged(const seriallink::ConnectionStatus &status);
    void valuesRead(const ptk::ParameterSet &values, ptk::ReadSource source);
    void readFinished(bool ok, const QString &message);
    void applyProgress(int done, int total);
    void applyFinished(bool ok, const QString &message);
    void frameSent(bool ok, const QString &message);
    void packetLogged(const seriallink::PacketLogEntry &entry);
    void countersChanged(const seriallink::LinkCounters &counters);

private:
    enum class Phase { Idle, Polling, Reading, Writing, ReadingBack };

    void onLinkDown(const QString &message, seriallink::Failure failure);
    void pollNext();
    void submitQuery(int index, seriallink::Transaction::Priority priority,
                     std::function<void(bool ok)> then);
    void startSweep(Phase phase);
    void sweepStep(int index, Phase phase, QVector<QString> failed);
    void writeStep(int index);
    void noteAnswer(bool ok);
    void resumePolling();

    SessionTiming m_timing;
    ptk::FrameFormat m_format;
    seriallink::LinkSession *m_link = nullptr;
    seriallink::RequestEngine *m_engine = nullptr; // the link's
    QTimer *m_pollTimer = nullptr;
    Phase m_phase = Phase::Idle;
    bool m_pollingEnabled = true;
    bool m_pollInFlight = false;
    int m_nextPoll = 0;
    QVector<Request> m_writes;
};

} // namespace ptk

Q_DECLARE_METATYPE(ptk::ParameterSet)
Q_DECLARE_METATYPE(ptk::ReadSource)
