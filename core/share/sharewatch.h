// The watch of a shared bus: one READ of a servo the program uses, in the program's idle gaps.
#pragma once

#include "busgate.h"
#include "observedservos.h"

#include <QObject>
#include <QTimer>

#include <chrono>

namespace seriallink {
class RequestEngine;
}

namespace share {

// Off by default. When the program has left the bus quiet long enough for one more
// transaction, reads one servo it has seen: first its identity and limits, then (in turn with
// the others) torque, goal, lock and the feedback block. One READ at a time, no retries, at
// most one per interval, so the program's own loop barely notices; its bytes that come during
// the READ wait in the gate until it is answered.
class ShareWatch : public QObject
{
    Q_OBJECT

public:
    // How quiet the bus must be, at least, before a READ goes.
    static constexpr std::chrono::microseconds kLeastGap = BusGate::kQuietBeforeOwn;
    // At most one READ this often.
    static constexpr std::chrono::milliseconds kInterval {50};

    ShareWatch(seriallink::RequestEngine &engine, BusGate &gate, const ObservedServos &servos,
               QObject *parent = nullptr);

    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }
    // The program sent or heard something: the quiet starts again.
    void noteActivity();
    qint64 readsSent() const { return m_reads; }

private:
    void onQuiet();
    void readNext();

    seriallink::RequestEngine &m_engine;
    BusGate &m_gate;
    const ObservedServos &m_servos;
    QTimer m_quiet;
    bool m_enabled = false;
    bool m_reading = false;
    qint64 m_lastReadUs = -1;
    int m_next = 0; // index into the servos seen, round robin
    qint64 m_reads = 0;
};

} // namespace share
