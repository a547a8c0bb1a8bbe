// The GUI thread's handle on one operation submitted to a Feetech bus (BusClient): its progress
// and its result, the way a QNetworkReply is a request's.
#pragma once

#include "bustypes.h"

#include <QObject>

namespace feetech {

// Made by BusClient for each operation it submits, and owned by it: it deletes the reply (later)
// once finished has been emitted, so keep no pointer past that; connect to finished at once.
// An apply chain reports each step but the last as stepFinished, its last step as finished.
// Lost links, disconnects and All torque off that drop the operation finish it too (not ok).
class OperationReply : public QObject
{
    Q_OBJECT

public:
    OperationReply(Operation operation, quint8 id, qint32 baud, bool control,
                   QObject *parent = nullptr);

    Operation operation() const { return m_operation; }
    // The servo it was asked for, where it was then (ID 0 and baud 0 when it finds its own,
    // as motor set-up does, or covers the whole bus).
    quint8 id() const { return m_id; }
    qint32 baud() const { return m_baud; }
    // A control write (torque, goal, a move of all servos), reported in place by the page that
    // sent it rather than as news of the servo list.
    bool isControl() const { return m_control; }
    bool isFinished() const { return m_finished; }
    // The result once finished (the last step's for an apply chain); its detail carries what
    // the operation found, where it has more to say (OperationResult::detail).
    const OperationResult &result() const { return m_result; }

    // For BusClient: records the step or the result and emits the signal.
    void finishStep(const OperationResult &result);
    void reportProgress(const OperationProgress &step);

signals:
    // How far it has got (an apply chain's writes, a health check's servos with each one's
    // reading as the detail, a motor set-up's steps with a sentence).
    void progress(const feetech::OperationProgress &progress);
    void stepFinished(const feetech::OperationResult &result);
    void finished(const feetech::OperationResult &result);

private:
    Operation m_operation;
    quint8 m_id;
    qint32 m_baud;
    bool m_control;
    bool m_finished = false;
    OperationResult m_result;
};

} // namespace feetech
