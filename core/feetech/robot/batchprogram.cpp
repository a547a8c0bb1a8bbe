// Programming several servos in turn: read, diff, apply, settle each one's outcome, go on.
#include "batchprogram.h"

#include "busclient.h"

#include <QCoreApplication>

namespace feetech {

BatchProgram::BatchProgram(BusClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    qRegisterMetaType<feetech::ProgramOutcome>();
    connect(m_client, &BusClient::statusChanged, this, &BatchProgram::onStatusChanged);
}

bool BatchProgram::start(const QVector<int> &indexes, const SettingsFile &file, QString *error)
{
    const auto refuse = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (isRunning())
        return refuse(tr("Servos are being programmed already."));
    if (!m_client || !m_client->link()->isConnected())
        return refuse(tr("The bus is not connected."));
    if (m_client->isBusy())
        return refuse(tr("Another operation is still running."));
    m_servos.clear();
    for (const int index : indexes) {
        if (index >= 0 && index < m_client->servos()->count())
            m_servos.append(
                {m_client->servos()->at(index).info.id, m_client->servos()->at(index).info.baud});
    }
    if (m_servos.isEmpty())
        return refuse(tr("Select the servos to program first."));
    m_file = file;
    m_outcomes.clear();
    m_next = 0;
    m_phase = Phase::Reading;
    emit runningChanged(true);
    QMetaObject::invokeMethod(this, &BatchProgram::next, Qt::QueuedConnection);
    return true;
}

void BatchProgram::next()
{
    if (!isRunning())
        return;
    if (m_next >= m_servos.size()) {
        m_phase = Phase::Idle;
        emit runningChanged(false);
        emit finished(m_outcomes);
        return;
    }
    const auto [id, baud] = m_servos.at(m_next++);
    m_current = {};
    m_current.id = id;
    m_current.baud = baud;
    emit progress(
        int(m_outcomes.size()), int(m_servos.size()),
        tr("Programming servo ID %1 (%2 of %3)…").arg(id).arg(m_next).arg(m_servos.size()));
    const int index = m_client->servos()->indexOf({id, baud});
    if (index < 0) {
        failCurrent(tr("Servo ID %1 is no longer on the bus.").arg(id));
        return;
    }
    if (const Refusal blocker = m_client->writeBlocker(index)) {
        failCurrent(blocker.describe());
        return;
    }
    if (m_client->servos()->parameters(index)->hasEdits()) {
        failCurrent(
            tr("Servo ID %1 has edits that are not applied: apply or revert them first.").arg(id));
        return;
    }
    QString error;
    if (!m_file->valuesFor(m_client->servos()->at(index).info, &error)) {
        failCurrent(error);
        return;
    }
    // A fresh read: the diff is against what the servo holds now.
    m_phase = Phase::Reading;
    OperationReply *reply = m_client->readServo(index);
    if (!reply) { // the bus went away
        failCurrent(m_client->writeBlocker(index).describe());
        return;
    }
    connect(reply, &OperationReply::finished, this, &BatchProgram::onOperationFinished);
}

void BatchProgram::onOperationFinished(const OperationResult &result)
{
    if (!isRunning())
        return;
    if (m_phase == Phase::Reading && result.operation == Operation::Read) {
        if (!result.ok) {
            failCurrent(result.message);
            return;
        }
        diffAndWrite(m_client->servos()->indexOf({m_current.id, m_current.baud}));
    } else if (m_phase == Phase::Writing && result.operation == Operation::Write) {
        settle(result);
    }
}

void BatchProgram::diffAndWrite(int index)
{
    if (index < 0) {
        failCurrent(tr("Servo ID %1 is no longer on the bus.").arg(m_current.id));
        return;
    }
    QString error;
    const ServoInfo &info = m_client->servos()->at(index).info;
    const auto wanted = m_file->batchValuesFor(info, &m_current.leftOut, &error);
    if (!wanted) {
        failCurrent(error);
        return;
    }
    model::ParameterModel &parameters = *m_client->servos()->parameters(index);
    const QVector<model::WriteItem> changed = changedValues(
        *wanted, [&parameters](const QString &key) { return parameters.deviceValue(key); },
        m_file->clearedBitsFor(info));
    for (const model::WriteItem &item : changed)
        m_current.changed.append(item.key);
    const QString refused =
        torqueRefusal(info, changed, parameters.deviceValue(QStringLiteral("torque_enable")));
    if (!refused.isEmpty()) {
        failCurrent(refused);
        return;
    }
    if (changed.isEmpty()) {
        m_current.status = ProgramOutcome::Status::Unchanged;
        m_outcomes.append(m_current);
        QMetaObject::invokeMethod(this, &BatchProgram::next, Qt::QueuedConnection);
        return;
    }
    for (const model::WriteItem &item : changed) {
        if (!parameters.edit(item.key, item.value, &error)) {
            parameters.revertAll();
            failCurrent(error);
            return;
        }
    }
    Refusal refusal;
    OperationReply *reply = m_client->apply(index, &refusal);
    if (!reply) {
        parameters.revertAll();
        failCurrent(refusal.describe());
        return;
    }
    connect(reply, &OperationReply::finished, this, &BatchProgram::onOperationFinished);
    m_phase = Phase::Writing;
}

void BatchProgram::settle(const OperationResult &result)
{
    const int index = m_client->servos()->indexOf({m_current.id, m_current.baud});
    QStringList unverified;
    if (model::ParameterModel *parameters = m_client->servos()->parameters(index)) {
        for (const QString &key : std::as_const(m_current.changed)) {
            const model::State state = parameters->state(key);
            if (state != model::State::Verified)
                unverified.append(tr("%1 is %2").arg(key, model::ParameterModel::stateName(state)));
        }
        // The outcome is in the result table: no edit of the batch stays pending.
        parameters->revertAll();
    }
    if (!result.ok)
        m_current.error = result.message;
    else if (!unverified.isEmpty())
        m_current.error = tr("not verified: %1").arg(unverified.join(QStringLiteral(", ")));
    m_current.status =
        m_current.error.isEmpty() ? ProgramOutcome::Status::Ok : ProgramOutcome::Status::Failed;
    m_outcomes.append(m_current);
    QMetaObject::invokeMethod(this, &BatchProgram::next, Qt::QueuedConnection);
}

void BatchProgram::failCurrent(const QString &error)
{
    m_current.status = ProgramOutcome::Status::Failed;
    m_current.error = error;
    m_outcomes.append(m_current);
    QMetaObject::invokeMethod(this, &BatchProgram::next, Qt::QueuedConnection);
}

void BatchProgram::onStatusChanged(const seriallink::ConnectionStatus &status)
{
    if (!isRunning()
        || (status.state != seriallink::ConnectionState::Disconnected
            && status.state != seriallink::ConnectionState::Lost))
        return;
    // Whatever was under way and everything after it fails, each with the reason.
    const QString why = tr("The bus was disconnected.");
    if (m_outcomes.size() < m_next) {
        m_current.status = ProgramOutcome::Status::Failed;
        m_current.error = why;
        m_outcomes.append(m_current);
    }
    while (m_next < m_servos.size()) {
        ProgramOutcome skipped;
        skipped.id = m_servos.at(m_next).first;
        skipped.baud = m_servos.at(m_next).second;
        skipped.error = why;
        m_outcomes.append(skipped);
        ++m_next;
    }
    m_phase = Phase::Idle;
    emit runningChanged(false);
    emit finished(m_outcomes);
}

} // namespace feetech
