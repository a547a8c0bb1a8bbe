// The junction of a shared bus: a program's bytes to the port, the port's bytes back to it, and
// ServoBench's own requests slotted in between the program's transactions.
#pragma once

#include "feetechpacket.h"
#include "sharerecording.h"
#include "streamframer.h"
#include "transactiontracker.h"
#include "transport.h"

#include <QElapsedTimer>

#include <chrono>

namespace seriallink {
class PreciseTimer;
} // namespace seriallink

namespace share {

// What passed through a share, each way.
struct ShareCounters
{
    qint64 framesFromProgram = 0;
    qint64 framesToProgram = 0;
    qint64 bytesFromProgram = 0;
    qint64 bytesToProgram = 0;
    qint64 garbledBytes = 0; // bytes either way that made no valid frame (passed on all the same)
    qint64 unanswered = 0; // the program's requests that got fewer answers than they ask for
    qint64 ownTransactions = 0; // ServoBench's own requests (the watch's reads)
    qint64 heldBytes = 0; // the program's bytes that waited for an own request to be answered
    qint64 bytesWhileAway = 0; // the program's bytes sent while the adapter was gone: lost
    // The program's requests that waited for an own request while it sent another: it had
    // given up on them, so they were not sent (their answers would have reached it as answers
    // to the next).
    qint64 givenUp = 0;
};

// The request engine talks to the gate as its transport: an own request waits until no
// request of the program is outstanding (all its answers in, or its time up and no late answer
// still possible), the program is not in the middle of a frame and its side has been quiet a
// moment, then goes alone; while it
// is out, a frame from the bus is its answer only if it is what it asked for (a late answer to
// the program's request still goes to the program); bytes the program sends meanwhile wait, in
// order, until that request is answered or its time is up, and go on then, less any request the
// program sent another after (it no longer waits for that one's answer). Everything else passes at
// once, byte for byte, the adapter's echo and garbage included. Lives in the thread of the port.
class BusGate : public seriallink::Transport
{
    Q_OBJECT

public:
    // How long the program's side must have been quiet (nothing sent, nothing heard) before an
    // own request goes: a program whose transaction just ended is about to send its next.
    static constexpr std::chrono::microseconds kQuietBeforeOwn {2000};

    explicit BusGate(seriallink::Transport &port, QObject *parent = nullptr);
    ~BusGate() override;

    // Transport: the engine's side.
    bool isOpen() const override;
    qint32 baudRate() const override;
    void write(const QByteArray &bytes) override;
    QByteArray discardInput() override;
    void deliverPendingInput() override;

    // Bytes the program wrote to its port.
    void fromProgram(const QByteArray &bytes);
    // The port runs at a new rate (the program set it): waits are counted at that rate.
    void setBaudRate(qint32 baud);
    // The port went away: what waited is lost, nothing is outstanding any more.
    void portLost();
    // Every transaction still open ends now, as it is (the share stops).
    void endAll();

    const ShareCounters &counters() const { return m_counters; }
    // Microseconds since the gate was made: the time line of transactions and frames.
    qint64 nowUs() const { return m_clock.nsecsElapsed() / 1000; }
    // Whether the program has a request outstanding or is in the middle of a frame.
    bool programBusy() const;

signals:
    // To be written to the program's side, at once.
    void toProgram(const QByteArray &bytes);
    // Every frame (or run of bytes that is none) as it passed, for the recording.
    void framePassed(const share::RecordedFrame &frame);
    // A transaction (the program's, or an own one) ended.
    void transactionEnded(const share::SharedTransaction &transaction);

private:
    void onPortBytes(const QByteArray &bytes);
    // Microseconds until the program's side has been quiet long enough; 0 when it has.
    qint64 quietInUs() const;
    void forwardProgramBytes(const QByteArray &bytes);
    void startOwnRequest();
    // The held bytes less every request that a later one followed while they waited.
    QByteArray withoutGivenUp(const QByteArray &held);
    // Starts an own request at a boundary, lets held bytes go once it is answered.
    void pump();
    void armDeadline();
    void onDeadline();
    // The program's requests as they pass: counted, recorded, and waited for.
    void passProgramFrames();

    seriallink::Transport &m_port;
    feetech::FrameFormat m_format;
    seriallink::StreamFramer m_programFramer;
    seriallink::StreamFramer m_portFramer;
    TransactionTracker m_program;
    TransactionTracker m_own;
    seriallink::PreciseTimer *m_deadline = nullptr;
    QByteArray m_ownWaiting; // an own request waiting for a boundary
    bool m_ownActive = false;
    QByteArray m_held; // the program's bytes waiting for the own request's answer
    qint64 m_programActivityUs = -(qint64(1) << 40); // the last byte either way on its side
    ShareCounters m_counters;
    QElapsedTimer m_clock;
};

} // namespace share
