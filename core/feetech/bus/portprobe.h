// The port probe: who answers on a port, without writing anything to a servo.
#pragma once

#include "portprobereport.h"

#include <QMetaType>
#include <QObject>
#include <QString>
#include <QVector>

#include <chrono>
#include <memory>

class QTimer;

namespace seriallink {
class PortTransport;
}

namespace feetech {

struct ProbeTiming
{
    // How long a PTK query waits for its reply at 115200.
    std::chrono::milliseconds ptkWait {200};
    // How long a broadcast PING waits for the first byte of an answer at each Feetech rate.
    std::chrono::milliseconds feetechWait {100};
    // Once answers begin, how long the rest of them (collided or not) may take to come in.
    std::chrono::milliseconds settle {20};
};

// Asks a port who is there, one question at a time: a PTK query at 115200, then (unless a PTK
// servo answered) a broadcast PING at each Feetech rate. Only queries and PINGs go out, so no
// servo's state changes. Lives in one thread (a SessionThread in the GUI), event-driven.
class PortProbe : public QObject
{
    Q_OBJECT

public:
    explicit PortProbe(const ProbeTiming &timing = {}, QObject *parent = nullptr);
    ~PortProbe() override;

    void start(const QString &portPath);
    // Ends after the question on its way; the report says it was cancelled.
    void cancel() { m_cancelled = true; }
    bool isRunning() const { return m_running; }

    // How many questions a whole probe asks (for a progress bar).
    static int stepCount();

signals:
    void progress(int done, int total, const QString &step);
    void finished(const feetech::PortProbeReport &report);

private:
    void ask(int step);
    void onReceived(const QByteArray &bytes);
    void endQuestion();
    void finish();

    ProbeTiming m_timing;
    std::unique_ptr<seriallink::PortTransport> m_transport;
    QTimer *m_deadline = nullptr;
    PortProbeReport m_report;
    int m_step = 0;
    QByteArray m_request;
    QByteArray m_heard;
    bool m_answering = false; // bytes beyond the echo came: the settle time runs
    bool m_cancelled = false;
    bool m_running = false;
};

} // namespace feetech
