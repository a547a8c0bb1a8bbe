// Doctor run over the GUI's bus client: read each servo found in turn, then diagnose.
#include "doctorcheck.h"

#include "busclient.h"
#include "parametermodel.h"

namespace feetech {

namespace {

// A whole table read takes milliseconds; this is for a read that was never started.
constexpr std::chrono::seconds kReadGuard {10};

} // namespace

DoctorCheck::DoctorCheck(BusClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    qRegisterMetaType<QVector<feetech::DoctorFinding>>();
    m_guard.setSingleShot(true);
    m_guard.setInterval(kReadGuard);
    connect(&m_guard, &QTimer::timeout, this, [this] {
        ++m_next; // its condition stays unknown: no finding is made of it
        readNext();
    });
}

void DoctorCheck::start(const BusObservation &seen, const QVector<ExpectedServo> &expected)
{
    m_seen = seen;
    m_seen.found.clear();
    m_seen.conditions.clear();
    for (int i = 0; i < m_client->servos()->count(); ++i)
        m_seen.found.append(m_client->servos()->at(i).info);
    m_expected = expected;
    m_next = 0;
    m_running = true;
    readNext();
}

void DoctorCheck::readNext()
{
    if (!m_running)
        return;
    if (m_next >= m_seen.found.size() || !m_client->link()->isConnected()) {
        m_running = false;
        m_guard.stop();
        emit finished(diagnoseBus(m_seen, m_expected));
        return;
    }
    emit progress(m_next, int(m_seen.found.size()));
    const ServoInfo &servo = m_seen.found.at(m_next);
    const int index = m_client->servos()->indexOf(servo.address());
    if (index < 0) {
        ++m_next;
        readNext();
        return;
    }
    m_guard.start();
    if (OperationReply *reply = m_client->readServo(index)) {
        // A read that comes after the guard gave up on it is no longer the one looked at.
        connect(reply, &OperationReply::finished, this,
                [this, reading = m_next](const OperationResult &result) {
                    // A read the lost link dropped leaves the servo's condition unknown.
                    if (m_running && m_guard.isActive() && m_next == reading
                        && result.failure != feetech::OperationFailure::LinkLost)
                        onRead(result.ok);
                });
    }
}

void DoctorCheck::onRead(bool readable)
{
    m_guard.stop();
    const ServoInfo servo = m_seen.found.at(m_next);
    const int index = m_client->servos()->indexOf(servo.address());
    if (index >= 0) {
        const model::ParameterModel *values = m_client->servos()->parameters(index);
        m_seen.conditions.append(servoCondition(
            servo, readable, [values](const QString &key) { return values->deviceValue(key); }));
    }
    ++m_next;
    readNext();
}

} // namespace feetech
