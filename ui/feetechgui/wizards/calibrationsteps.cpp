// Calibration steps: one servo read or verified write after the other, through the bus client.
#include "calibrationsteps.h"

#include "armcalibration.h"
#include "busclient.h"

CalibrationSteps::CalibrationSteps(feetech::BusClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        // The link went down: nothing running will report any more.
        while (isRunning() && !m_client->link()->isConnected()) {
            m_allOk = false;
            emit stepFinished(m_next - 1, false, tr("The bus was disconnected."));
            startNext();
        }
    });
}

qint32 CalibrationSteps::lastRead(const feetech::BusClient &client, int index, const QString &key)
{
    return qint32(client.servos()->parameters(index)->deviceValue(key).value_or(0));
}

bool CalibrationSteps::start(const QVector<Step> &steps)
{
    if (isRunning())
        return false;
    m_steps = steps;
    m_next = 0;
    m_allOk = true;
    startNext();
    return true;
}

void CalibrationSteps::startNext()
{
    while (m_next < m_steps.size()) {
        const Step &step = m_steps.at(m_next++);
        emit progress(m_next - 1, int(m_steps.size()));
        feetech::Refusal refusal;
        feetech::OperationReply *reply = step.writes.isEmpty()
            ? m_client->readServo(step.index)
            : m_client->writeValues(step.index, step.writes, &refusal);
        if (reply && m_client->link()->isConnected()) {
            // A step the lost link already ended is not ended again.
            connect(reply, &feetech::OperationReply::finished, this,
                    [this, running = m_next](const feetech::OperationResult &result) {
                        // A lost link is reported by the status handler, once.
                        if (m_next == running
                            && result.failure != feetech::OperationFailure::LinkLost)
                            onOperationFinished(result);
                    });
            return;
        }
        m_allOk = false;
        emit stepFinished(m_next - 1, false,
                          !refusal ? tr("The bus is not connected.") : refusal.describe());
    }
    m_next = int(m_steps.size()) + 1;
    emit progress(int(m_steps.size()), int(m_steps.size()));
    emit finished(m_allOk);
}

void CalibrationSteps::onOperationFinished(const feetech::OperationResult &result)
{
    if (!isRunning())
        return;
    const Step &step = m_steps.at(m_next - 1);
    if (step.index >= m_client->servos()->count())
        return;
    bool ok = result.ok;
    QString message = result.message;
    if (ok && !step.writes.isEmpty()) {
        // The read-back reached the model before the result: compare with what was written.
        QHash<QString, qint32> readBack;
        const model::ParameterModel *parameters = m_client->servos()->parameters(step.index);
        for (const model::WriteItem &item : step.writes) {
            if (const auto value = parameters->deviceValue(item.key))
                readBack.insert(item.key, qint32(*value));
        }
        const QStringList mismatches = feetech::calibrationMismatches(step.writes, readBack);
        ok = mismatches.isEmpty();
        message = ok ? tr("Written and verified.")
                     : tr("Verification failed: %1").arg(mismatches.join(QStringLiteral("; ")));
    }
    m_allOk = m_allOk && ok;
    emit stepFinished(m_next - 1, ok, message);
    startNext();
}
