// The reply to one operation submitted to a Feetech bus: its steps and its result.
#include "operationreply.h"

namespace feetech {

OperationReply::OperationReply(Operation operation, quint8 id, qint32 baud, bool control,
                               QObject *parent)
    : QObject(parent)
    , m_operation(operation)
    , m_id(id)
    , m_baud(baud)
    , m_control(control)
{
    m_result.operation = operation;
}

void OperationReply::finishStep(const OperationResult &result)
{
    if (m_finished)
        return;
    m_result = result;
    m_result.control = m_control;
    if (!result.final) {
        emit stepFinished(m_result);
        return;
    }
    m_finished = true;
    emit finished(m_result);
}

void OperationReply::reportProgress(const OperationProgress &step)
{
    if (!m_finished)
        emit progress(step);
}

} // namespace feetech
