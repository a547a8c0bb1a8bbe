// What an operation has while the session runs it: the session's parts and its turn on the bus.
#include "operationcontext.h"

#include "feetechsession.h"
#include "feetechsession_p.h"
#include "linksession.h"

namespace feetech {

OperationContext::OperationContext(Session &session)
    : m_session(session)
{ }

BusExchange &OperationContext::bus() const
{
    return *m_session.d->bus;
}

BusScan &OperationContext::scan() const
{
    return *m_session.d->scan;
}

GuidedFlows &OperationContext::flows() const
{
    return *m_session.d->flows;
}

ApplyFlow &OperationContext::apply() const
{
    return *m_session.d->apply;
}

MotorSetup &OperationContext::motorSetup() const
{
    return *m_session.d->motorSetup;
}

JointIdentify &OperationContext::identify() const
{
    return *m_session.d->identify;
}

MotionReplay &OperationContext::replay() const
{
    return *m_session.d->replay;
}

HealthCheck &OperationContext::health() const
{
    return *m_session.d->health;
}

HealthMoveTest &OperationContext::moveTest() const
{
    return *m_session.d->moveTest;
}

GuardKeeper &OperationContext::guard() const
{
    return *m_session.d->guard;
}

bool OperationContext::isLinkOpen() const
{
    return m_session.d->link->isOpen();
}

void OperationContext::finish(const OperationResult &result) const
{
    m_session.finishOperation(result);
}

GuidedFlows::Finish OperationContext::finisher() const
{
    Session *session = &m_session;
    return [session](const OperationResult &result) {
        session->finishOperation(result);
    };
}

void OperationContext::reportStep(const OperationResult &step) const
{
    OperationResult reported = step;
    reported.ticket = m_session.d->current.operation.ticket;
    emit m_session.operationFinished(reported);
}

void OperationContext::reportProgress(const OperationProgress &progress) const
{
    OperationProgress reported = progress;
    reported.ticket = m_session.d->current.operation.ticket;
    emit m_session.operationProgress(reported);
}

void OperationContext::continueLater(Operation next, std::function<void()> resume) const
{
    m_session.continueLater(next, std::move(resume));
}

void OperationContext::pauseFor(std::chrono::milliseconds delay,
                                std::function<void(bool torqueOffMeanwhile)> resume) const
{
    m_session.pauseFor(delay, std::move(resume));
}

void OperationContext::noteStatus(quint8 id, qint32 baud, quint8 statusByte) const
{
    emit m_session.statusSeen(id, baud, statusByte);
}

void OperationContext::noteMemory(quint8 id, qint32 baud, int address, const QByteArray &bytes,
                                  quint8 statusByte) const
{
    emit m_session.memoryRead(id, baud, address, bytes, ReadSource::ReadBack, statusByte);
}

} // namespace feetech
