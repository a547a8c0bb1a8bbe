// Goals streamed to one servo from a slider: one goal write on the wire, the newest waiting.
#include "goalstreamer.h"

#include "busclient.h"
#include "operationreply.h"

#include <algorithm>

namespace feetech {

GoalStreamer::GoalStreamer(BusClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{ }

bool GoalStreamer::queueIfBusy(qint32 goal)
{
    if (m_inFlight > 0 && m_sentAt.isValid() && m_sentAt.elapsed() < m_staleMs) {
        m_queued = goal;
        return true;
    }
    return false;
}

OperationReply *GoalStreamer::send(int index, const QVector<model::WriteItem> &values,
                                   Refusal *refusal)
{
    OperationReply *reply = m_client->writeValues(index, values, refusal);
    if (!reply)
        return nullptr;
    ++m_inFlight;
    m_sentAt.start();
    m_queued.reset(); // this one is newer than anything waiting
    connect(reply, &OperationReply::finished, this, &GoalStreamer::onWriteFinished);
    return reply;
}

void GoalStreamer::forgetWrites()
{
    m_inFlight = 0;
    m_queued.reset();
}

void GoalStreamer::onWriteFinished(const OperationResult &result)
{
    // A link that went down set the count to 0 already.
    m_inFlight = std::max(0, m_inFlight - 1);
    if (!result.ok) {
        m_queued.reset();
    } else if (m_queued && m_inFlight == 0) {
        const qint32 next = *m_queued;
        m_queued.reset();
        emit queuedGoalDue(next);
    }
}

} // namespace feetech
