// Goals streamed to one servo from a slider: one goal write on the wire at a time, and only the
// newest goal waiting behind it.
#pragma once

#include "parametermodel.h"
#include "refusal.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QVector>

#include <optional>

namespace feetech {

class BusClient;
class OperationReply;
struct OperationResult;

class GoalStreamer : public QObject
{
    Q_OBJECT

public:
    // A goal write with no answer after this long is taken as lost: the next goal goes out.
    static constexpr int kDefaultStaleMs = 2000;

    explicit GoalStreamer(BusClient *client, QObject *parent = nullptr);

    // Queues `goal` when a goal write is still on the wire (and not stale), replacing whatever
    // waited: true. False when nothing is in the way and the caller should send it now.
    bool queueIfBusy(qint32 goal);

    // Sends the goal write `values` to servo `index` through BusClient::writeValues; the reply,
    // or nullptr and *refusal when it was refused. Anything queued is older and is dropped.
    OperationReply *send(int index, const QVector<model::WriteItem> &values,
                         Refusal *refusal = nullptr);

    int writesInFlight() const { return m_inFlight; }
    std::optional<qint32> queuedGoal() const { return m_queued; }
    void dropQueued() { m_queued.reset(); }
    // The link went down: nothing comes back from the writes it dropped.
    void forgetWrites();

    void setStaleMs(int milliseconds) { m_staleMs = milliseconds; }

signals:
    // The last write in flight succeeded and `goal` waited behind it: send it now. A failing
    // write drops the queued goal instead, so a failing servo is not chased with stale goals.
    void queuedGoalDue(qint32 goal);

private:
    void onWriteFinished(const OperationResult &result);

    QPointer<BusClient> m_client;
    int m_inFlight = 0;
    QElapsedTimer m_sentAt;
    std::optional<qint32> m_queued;
    int m_staleMs = kDefaultStaleMs;
};

} // namespace feetech
