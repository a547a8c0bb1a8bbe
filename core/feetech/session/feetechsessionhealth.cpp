// The Feetech session's health check and its move test, queued like every other operation.
#include "feetechsession.h"

#include "linksession.h"

#include <QCoreApplication>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};

} // namespace

namespace feetech {

void Session::checkHealth(const QVector<ServoInfo> &servos, int reads)
{
    m_health->clearCancel();
    enqueue(Operation::HealthCheck, [this, servos, reads] { checkNextServo(servos, 0, reads); });
}

void Session::checkNextServo(QVector<ServoInfo> servos, int done, int reads)
{
    const int total = int(servos.size());
    if (done >= total || m_health->isCancelled()) {
        const bool stopped = done < total;
        finishOperation({Operation::HealthCheck,
                         !stopped,
                         stopped ? Tr::tr("The health check was stopped after %1 of %n servo(s).",
                                          nullptr, total)
                                       .arg(done)
                                 : Tr::tr("%n servo(s) checked.", nullptr, total),
                         {},
                         {}});
        return;
    }
    m_health->read(servos.at(done), reads, [this, servos, done, reads](const HealthReading &r) {
        if (!m_link->isOpen())
            return; // onLinkDown has ended the check
        emit healthRead(r);
        emit progress(done + 1, int(servos.size()));
        // Between two servos the bus is free: All torque off never waits for a whole check.
        continueLater(Operation::HealthCheck,
                      [this, servos, done, reads] { checkNextServo(servos, done + 1, reads); });
    });
}

void Session::cancelHealthCheck()
{
    m_health->cancel();
}

void Session::moveTest(const ServoInfo &servo)
{
    const quint64 epoch = m_torqueOffEpoch;
    enqueue(Operation::MoveTest, [this, servo, epoch] {
        if (refusedAfterTorqueOff(Operation::MoveTest, epoch))
            return;
        m_guard->noteDriven(servo); // the guard watches the move as it does any other
        m_moveTest->run(
            servo,
            [this, epoch](std::chrono::milliseconds delay,
                          std::function<void(bool torqueOff)> resume) {
                pauseFor(Operation::MoveTest, delay,
                         [this, epoch, resume] { resume(epoch != m_torqueOffEpoch); });
            },
            [this, servo](const MoveTestResult &result) {
                emit moveTested(result);
                finishOperation({Operation::MoveTest, result.ok, result.message, servo, {}});
            });
    });
}

} // namespace feetech
