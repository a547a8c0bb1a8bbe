// The joint table's bus actions: Move all as one SYNC WRITE per baud rate, torque switches and
// register reads.
#include "jointtable.h"

#include "busclient.h"
#include "registerkeys.h"
#include "servoparameters.h"

#include <QHash>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>

using namespace feetech::registerkeys;

bool JointTable::setTorque(int row, bool on, QString *error)
{
    const int index = servoIndex(row);
    if (index < 0) {
        if (error)
            *error = tr("That servo is no longer on the bus.");
        return false;
    }
    const feetech::TorqueMode mode = on ? feetech::TorqueMode::On : feetech::TorqueMode::Off;
    const auto value = m_client->servo(index).info.table().torqueValue(mode);
    QString why = tr("its model has no torque enable");
    feetech::OperationReply *reply =
        value ? m_client->writeValues(index, {{kTorqueEnable, *value}}, &why) : nullptr;
    if (!reply) {
        if (error)
            *error = tr("%1: torque not switched %2: %3")
                         .arg(servoName(row), on ? tr("on") : tr("off"), why);
        return false;
    }
    connect(reply, &feetech::OperationReply::finished, this,
            [this, id = m_rows.at(row).id, baud = m_rows.at(row).baud](
                const feetech::OperationResult &result) { onTorqueWritten(id, baud, result); });
    m_rows[row].torqueRequested = mode;
    refreshRow(row);
    return true;
}

bool JointTable::moveAll(QString *error)
{
    const auto refuse = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (!m_client->isConnected())
        return refuse(tr("The bus is not connected: nothing was sent."));
    if (rowCount() == 0)
        return refuse(tr("No servos: scan the bus first."));

    QVector<feetech::BusClient::Goal> goals;
    QSet<qint32> bauds;
    QStringList skipped;
    QStringList torqueOff;
    QStringList ids;
    for (int row = 0; row < rowCount(); ++row) {
        const int index = servoIndex(row);
        const std::optional<feetech::PositionRange> range = targetRange(row);
        if (index < 0 || !range) {
            skipped.append(servoName(row));
            continue;
        }
        const std::optional<qint32> target = m_rows.at(row).target;
        if (!target)
            return refuse(tr("%1 has no target: type one, load a pose or use “Targets from "
                             "present positions”. Nothing was sent.")
                              .arg(servoName(row)));
        if (!range->contains(*target))
            return refuse(tr("%1: the target %2 is outside its range %3 to %4. Nothing was "
                             "sent.")
                              .arg(servoName(row))
                              .arg(*target)
                              .arg(range->minimum)
                              .arg(range->maximum));
        // In wheel, PWM or step mode the goal register means something else (or nothing).
        if (const auto mode = deviceValue(row, kMode); mode && *mode != 0) {
            const feetech::Register *reg = m_client->servo(index).info.table().find(kMode);
            return refuse(tr("%1 is in %2 mode; a goal position only moves a servo in position "
                             "mode. Nothing was sent.")
                              .arg(servoName(row),
                                   reg ? feetech::displayValue(*reg, qint32(*mode))
                                       : QString::number(*mode)));
        }
        const auto torque = deviceValue(row, kTorqueEnable);
        if (torque
            && m_client->servo(index).info.table().torqueMode(*torque) == feetech::TorqueMode::Off)
            torqueOff.append(servoName(row));
        goals.append({index, *target});
        bauds.insert(m_rows.at(row).baud);
        ids.append(QString::number(m_rows.at(row).id));
    }
    if (goals.isEmpty())
        return refuse(tr("No servo here can be moved: their models are unknown."));
    QString why;
    const QVector<feetech::OperationReply *> replies = m_client->moveAll(goals, &why);
    if (replies.isEmpty())
        return refuse(tr("Nothing was sent: %1").arg(why));
    m_movesInFlight += int(replies.size());
    for (feetech::OperationReply *reply : replies)
        connect(reply, &feetech::OperationReply::finished, this, &JointTable::onMoveFinished);

    QStringList report;
    report.append(bauds.size() == 1
                      ? tr("Targets sent to IDs %1 in one SYNC WRITE.").arg(ids.join(tr(", ")))
                      : tr("Targets sent to IDs %1 in %2 SYNC WRITEs, one per baud rate.")
                            .arg(ids.join(tr(", ")))
                            .arg(bauds.size()));
    if (!torqueOff.isEmpty())
        report.append(tr("Torque is off on %1: it will not move until torque is on.")
                          .arg(torqueOff.join(tr(", "))));
    if (!skipped.isEmpty())
        report.append(tr("Not moved (unknown model): %1.").arg(skipped.join(tr(", "))));
    setMessage(report.join(u' '),
               torqueOff.isEmpty() && skipped.isEmpty() ? Tone::Success : Tone::Warning);
    return true;
}

bool JointTable::readPositions(QString *error)
{
    if (!m_client->isConnected()) {
        if (error)
            *error = tr("The bus is not connected.");
        return false;
    }
    if (rowCount() == 0) {
        if (error)
            *error = tr("No servos: scan the bus first.");
        return false;
    }
    for (int row = 0; row < rowCount(); ++row) {
        const int index = servoIndex(row);
        if (index >= 0)
            m_client->readServo(index);
    }
    setMessage(tr("Reading %1 servos…").arg(rowCount()), Tone::Info);
    return true;
}

bool JointTable::identify(int row, QString *error)
{
    const int index = servoIndex(row);
    if (index < 0) {
        if (error)
            *error = tr("That servo is no longer on the bus.");
        return false;
    }
    QString why;
    if (!m_client->identifyJoint(index, &why)) {
        if (error)
            *error = tr("%1 cannot be identified now: %2").arg(servoName(row), why);
        return false;
    }
    setMessage(tr("Identifying %1: watch which horn moves…").arg(servoName(row)), Tone::Info);
    return true;
}

QPushButton *JointTable::identifyButton(int row) const
{
    return qobject_cast<QPushButton *>(m_table->cellWidget(row, IdentifyColumn));
}

void JointTable::refreshIdentifyButtons()
{
    for (int row = 0; row < rowCount(); ++row) {
        QPushButton *button = identifyButton(row);
        if (!button)
            continue;
        const QString why = m_client->identifyBlocker(servoIndex(row));
        button->setEnabled(why.isEmpty());
        button->setToolTip(why.isEmpty() ? tr("Wiggle %1 slowly with little torque, then put it "
                                              "back as it was")
                                               .arg(servoName(row))
                                         : why);
    }
}

void JointTable::onMoveAllClicked()
{
    QString error;
    if (!moveAll(&error))
        setMessage(error, Tone::Error);
}

void JointTable::onReadClicked()
{
    QString error;
    if (!readPositions(&error))
        setMessage(error, Tone::Error);
}
