// The Control page's writes: torque, goals from the slider (one on the wire, the newest
// waiting), mode changes after a warning, and what the servo answers to them.
#include "controlpage.h"

#include "busclient.h"
#include "goalrange.h"
#include "motiontestpanel.h"
#include "registerkeys.h"
#include "registerwidgets.h"
#include "servoparameters.h"
#include "widgethelpers.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>

#include <algorithm>

using namespace feetech::registerkeys;

namespace {
// A goal write with no answer after this long is taken as lost: the slider sends again.
constexpr int kGoalWriteStaleMs = 2000;
} // namespace

bool ControlPage::write(WriteKind kind, const QVector<model::WriteItem> &values)
{
    QString error;
    feetech::OperationReply *reply = m_client->writeValues(m_index, values, &error);
    if (!reply) {
        setStatus(tr("%1: %2").arg(servoName(), error), Severity::Error);
        return false;
    }
    if (kind == WriteKind::Goal)
        ++m_goalsInFlight;
    else if (kind == WriteKind::Torque)
        ++m_torqueWritesInFlight;
    connect(reply, &feetech::OperationReply::finished, this,
            [this, kind, id = m_servo->first](const feetech::OperationResult &result) {
                onWriteFinished(kind, id, result);
            });
    return true;
}

void ControlPage::setTorque(int modeId)
{
    const auto value = ready()
        ? m_client->servo(m_index).info.table().torqueValue(feetech::TorqueMode(modeId))
        : std::nullopt;
    if (!value) {
        syncFromDevice();
        return;
    }
    setStatus({}, Severity::Info);
    if (testRunsHere()) {
        // Switching torque under a running test would leave it measuring nonsense.
        m_testPanel->stop();
    }
    if (!write(WriteKind::Torque, {{kTorqueEnable, *value}}))
        syncFromDevice(); // the buttons go back to what the servo has
}

void ControlPage::onSliderMoved(int value)
{
    {
        const QSignalBlocker blocker(m_goal);
        m_goal->setValue(value);
    }
    if (!ready() || testRunsHere())
        return;
    // One goal on the wire at a time; a newer one replaces whatever waits behind it.
    if (m_goalsInFlight > 0 && m_goalSentAt.isValid()
        && m_goalSentAt.elapsed() < kGoalWriteStaleMs) {
        m_queuedGoal = value;
        return;
    }
    moveTo(value);
}

bool ControlPage::moveTo(qint32 position, QString *error)
{
    const auto refuse = [this, error](const QString &why) {
        setStatus(why, Severity::Error);
        if (error)
            *error = why;
        return false;
    };
    if (!ready())
        return refuse(m_index < 0 ? tr("No servo is selected.")
                                  : tr("The servo cannot be moved now: the bus is not "
                                       "connected or its model is unknown."));
    if (testRunsHere())
        return refuse(tr("A test is moving %1: stop it first.").arg(servoName()));
    const auto range = feetech::goalRange(*m_client, m_index);
    if (!range)
        return refuse(tr("%1 has no goal position register.").arg(servoName()));
    if (!range->contains(position))
        return refuse(tr("Goal %1 is outside %2, %3 to %4 steps: nothing was sent.")
                          .arg(position)
                          .arg(range->fromAngleLimits ? tr("the servo's angle limits")
                                                      : tr("the goal position range"))
                          .arg(range->minimum)
                          .arg(range->maximum));

    const feetech::RegisterTable &table = m_client->servo(m_index).info.table();
    QVector<model::WriteItem> values;
    if (table.find(kAcceleration))
        values.append({kAcceleration, m_acceleration->value()});
    if (table.find(kGoalSpeed))
        values.append({kGoalSpeed, m_speed->value()});
    values.append({kGoalPosition, position});
    if (!write(WriteKind::Goal, values)) {
        if (error)
            *error = statusText();
        return false;
    }
    const bool torqueWritePending = m_torqueWritesInFlight > 0;
    const auto torque = m_client->parameters(m_index)->deviceValue(kTorqueEnable);
    if (!torqueWritePending && torque
        && m_client->servo(m_index).info.table().torqueMode(*torque) == feetech::TorqueMode::Off)
        setStatus(tr("Torque is off: %1 keeps the goal but does not move until torque is on.")
                      .arg(servoName()),
                  Severity::Warning);
    else if (m_status->property("severity").toInt() == int(Severity::Error))
        setStatus({}, Severity::Info); // an earlier refusal no longer applies
    m_goalSentAt.start();
    m_queuedGoal.reset(); // this one is newer than anything waiting
    {
        const QSignalBlocker spinBlocker(m_goal);
        const QSignalBlocker sliderBlocker(m_slider);
        m_goal->setValue(position);
        m_slider->setValue(position);
    }
    return true;
}

void ControlPage::changeMode()
{
    if (!ready() || m_mode->currentIndex() < 0)
        return;
    const qint64 value = m_mode->currentData().toLongLong();
    const auto device = m_client->parameters(m_index)->deviceValue(kMode);
    if (device && *device == value) {
        m_modeEdited = false;
        updateEnabled();
        return;
    }
    if (m_confirmMoves) {
        const int deviceIndex = device ? m_mode->findData(qint32(*device)) : -1;
        const QString from = deviceIndex >= 0 ? m_mode->itemText(deviceIndex) : tr("unknown");
        QMessageBox box(
            QMessageBox::Warning, tr("Change the operating mode?"),
            tr("%1 will change from “%2” to “%3”.").arg(servoName(), from, m_mode->currentText()),
            QMessageBox::Ok | QMessageBox::Cancel, this);
        box.setInformativeText(
            tr("The servo will move differently from now on: in speed or PWM mode the goal "
               "registers make it turn continuously instead of holding a position. The mode is "
               "written to EEPROM and kept after power-off."));
        box.button(QMessageBox::Ok)->setText(tr("Change mode"));
        box.setDefaultButton(QMessageBox::Cancel);
        if (box.exec() != QMessageBox::Ok)
            return;
    }
    setStatus({}, Severity::Info);
    write(WriteKind::Mode, {{kMode, value}});
}

void ControlPage::onWriteFinished(WriteKind kind, quint8 id, const feetech::OperationResult &result)
{
    // A link that went down set the counts to 0 already.
    if (kind == WriteKind::Goal)
        m_goalsInFlight = std::max(0, m_goalsInFlight - 1);
    else if (kind == WriteKind::Torque)
        m_torqueWritesInFlight = std::max(0, m_torqueWritesInFlight - 1);
    if (kind == WriteKind::Mode)
        m_modeEdited = false;
    if (!result.ok) {
        if (kind == WriteKind::Goal)
            m_queuedGoal.reset(); // do not chase a failing servo with stale goals
        setStatus(tr("Writing to servo ID %1 failed: %2").arg(id).arg(result.message),
                  Severity::Error);
    } else if (kind == WriteKind::Goal && m_queuedGoal && m_goalsInFlight == 0) {
        // Queued for the servo shown: a change of servo clears the queue.
        const qint32 next = *m_queuedGoal;
        m_queuedGoal.reset();
        moveTo(next);
    }
    syncFromDevice();
    updateEnabled();
}

void ControlPage::onAllTorqueOff()
{
    m_queuedGoal.reset();
    if (ready())
        m_torqueOff->setChecked(true); // the read-back confirms it
    m_torqueState->setText(tr("Off: All torque off was sent to every servo."));
    setStatus(tr("All torque off: torque is off on every servo of the bus."), Severity::Warning);
}
