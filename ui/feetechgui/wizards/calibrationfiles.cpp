// LeRobot calibration files from and to the bus: saving, the load dialog, the Robot menu entries.
#include "calibrationfiles.h"

#include "armcalibration.h"
#include "busclient.h"
#include "calibrationsteps.h"
#include "calibrationwizard.h"
#include "palette.h"
#include "recentfiles.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace {

enum Column { JointColumn, OffsetColumn, MinimumColumn, MaximumColumn, StatusColumn };

// Register `key` of servo `index` as last read; 0 when it was never read.
qint32 deviceValue(const feetech::BusClient &client, int index, const QString &key)
{
    return qint32(client.servos()->parameters(index)->deviceValue(key).value_or(0));
}

// Application-modal, not window-modal: the set-up wizard is a window of its own (modeless), and
// no set-up may run while joints are recorded or calibrations written.
void showApplicationModal(QDialog *dialog)
{
    dialog->setWindowModality(Qt::ApplicationModal);
    dialog->show();
}

const feetech::RobotTemplate *defaultTemplate(const QVector<feetech::RobotTemplate> &templates)
{
    const int chosen = defaultRobotTemplate(templates);
    return chosen >= 0 ? &templates.at(chosen) : nullptr;
}

} // namespace

CalibrationSaver::CalibrationSaver(feetech::BusClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_steps(new CalibrationSteps(client, this))
{
    connect(m_steps, &CalibrationSteps::stepFinished, this,
            [this](int step, bool ok, const QString &message) {
                if (!ok && m_failure.isEmpty())
                    m_failure = tr("Servo %1 could not be read: %2; nothing was saved.")
                                    .arg(m_client->servos()->at(m_indexes.at(step)).info.id)
                                    .arg(message);
            });
    connect(m_steps, &CalibrationSteps::finished, this, [this](bool allOk) {
        if (!allOk) {
            emit finished(false, m_failure);
            return;
        }
        QVector<feetech::LeRobotMotor> motors;
        for (int i = 0; i < m_indexes.size(); ++i) {
            const int index = m_indexes.at(i);
            const feetech::LeRobotMotor motor {
                m_names.at(i),
                m_client->servos()->at(index).info.id,
                0,
                deviceValue(*m_client, index, QString::fromUtf16(feetech::kOffsetKey)),
                deviceValue(*m_client, index, QString::fromUtf16(feetech::kMinimumLimitKey)),
                deviceValue(*m_client, index, QString::fromUtf16(feetech::kMaximumLimitKey))};
            if (motor.rangeMin >= motor.rangeMax) {
                emit finished(false,
                              tr("Servo %1 holds the limits %2 to %3, which are no "
                                 "calibrated range; nothing was saved.")
                                  .arg(motor.id)
                                  .arg(motor.rangeMin)
                                  .arg(motor.rangeMax));
                return;
            }
            motors.append(motor);
        }
        feetech::keepDriveModes(motors, m_path);
        util::FileError error;
        if (!feetech::saveLeRobotCalibration(motors, m_path, &error)) {
            emit finished(false, error.describe());
            return;
        }
        emit finished(true,
                      tr("Saved the calibration of %n joint(s) to %1.", nullptr, int(motors.size()))
                          .arg(QDir::toNativeSeparators(m_path)));
    });
}

bool CalibrationSaver::save(const QString &path, util::FileError *error)
{
    const QVector<feetech::RobotTemplate> templates = feetech::availableRobotTemplates();
    m_path = path;
    m_failure.clear();
    m_indexes.clear();
    m_names.clear();
    QVector<CalibrationSteps::Step> steps;
    for (const ArmJoint &joint : armJoints(*m_client, defaultTemplate(templates))) {
        const feetech::ServoInfo &info = m_client->servos()->at(joint.index).info;
        if (!info.hasTable() || !feetech::calibrationLimits(info.table()))
            continue;
        m_indexes.append(joint.index);
        m_names.append(joint.joint.name);
        steps.append(CalibrationSteps::Step {joint.index, {}});
    }
    if (steps.isEmpty()) {
        util::report(error,
                     util::FileError(util::FileError::Code::NothingToSave,
                                     tr("No servo on the bus has a position offset to save.")));
        return false;
    }
    return m_steps->start(steps);
}

LoadCalibrationDialog::LoadCalibrationDialog(feetech::BusClient *client,
                                             const QVector<feetech::LeRobotMotor> &motors,
                                             const QString &path, QWidget *parent)
    : QDialog(parent)
    , m_client(client)
    , m_steps(new CalibrationSteps(client, this))
    , m_motors(motors)
{
    setWindowTitle(tr("Load calibration"));
    setObjectName(QStringLiteral("loadCalibrationDialog"));
    resize(760, 380);
    auto *layout = new QVBoxLayout(this);
    auto *intro = new QLabel(tr("What %1 would change on each joint (now → file). Nothing is "
                                "written until you press Write.")
                                 .arg(QDir::toNativeSeparators(path)),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);
    m_table = new QTableWidget(int(motors.size()), 5, this);
    m_table->setObjectName(QStringLiteral("calibrationDiffTable"));
    m_table->setHorizontalHeaderLabels(
        {tr("Joint"), tr("Offset"), tr("Min limit"), tr("Max limit"), tr("Status")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(StatusColumn, QHeaderView::Stretch);
    layout->addWidget(m_table, 1);
    m_summary = new QLabel(tr("Reading the servos…"), this);
    m_summary->setObjectName(QStringLiteral("loadCalibrationSummary"));
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
    m_progress = new QProgressBar(this);
    m_progress->hide();
    layout->addWidget(m_progress);
    m_write = new QPushButton(tr("&Write"), this);
    m_write->setObjectName(QStringLiteral("writeLoadedCalibrationButton"));
    m_write->setAutoDefault(false);
    m_write->setEnabled(false);
    connect(m_write, &QPushButton::clicked, this, &LoadCalibrationDialog::writeChanges);
    m_close = new QPushButton(tr("Cancel"), this);
    m_close->setAutoDefault(false);
    connect(m_close, &QPushButton::clicked, this, &QDialog::reject);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_write);
    buttons->addWidget(m_close);
    layout->addLayout(buttons);

    QVector<CalibrationSteps::Step> steps;
    for (int row = 0; row < motors.size(); ++row) {
        const feetech::LeRobotMotor &motor = motors.at(row);
        m_table->setItem(row, JointColumn,
                         new QTableWidgetItem(tr("%1 (%2)").arg(motor.name).arg(motor.id)));
        int found = -1;
        for (int index = 0; index < client->servos()->count() && found < 0; ++index) {
            if (client->servos()->at(index).info.id == motor.id)
                found = index;
        }
        m_indexes.append(found);
        m_readFailures.append(QString());
        if (found >= 0) {
            steps.append(CalibrationSteps::Step {found, {}});
            m_readRows.append(row);
        }
    }
    connect(m_steps, &CalibrationSteps::stepFinished, this,
            [this](int step, bool ok, const QString &message) {
                if (!m_writing && !ok && step < m_readRows.size())
                    m_readFailures[m_readRows.at(step)] =
                        message.isEmpty() ? tr("no answer") : message;
                if (m_writing && step < m_writeRows.size())
                    setStatus(m_writeRows.at(step), ok ? tr("Written and verified") : message, !ok);
            });
    connect(m_steps, &CalibrationSteps::progress, this, [this](int done, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(done);
    });
    connect(m_steps, &CalibrationSteps::finished, this, [this](bool allOk) {
        if (!m_writing) {
            onRead(allOk);
            return;
        }
        m_writing = false;
        m_close->setText(tr("Close"));
        m_close->setEnabled(true);
        m_summary->setText(allOk ? tr("Every change was written and verified.")
                                 : tr("Not every change was written: see the status column."));
        emit writingFinished(allOk);
    });
    if (steps.isEmpty())
        onRead(true);
    else
        m_steps->start(steps);
}

void LoadCalibrationDialog::setStatus(int row, const QString &text, bool problem)
{
    auto *item = new QTableWidgetItem(text);
    if (problem)
        item->setForeground(palette::toneColor(palette::Tone::Error, m_table->palette()));
    m_table->setItem(row, StatusColumn, item);
}

void LoadCalibrationDialog::onRead(bool allOk)
{
    m_writeRows.clear();
    for (int row = 0; row < m_motors.size(); ++row) {
        const feetech::LeRobotMotor &motor = m_motors.at(row);
        const int index = m_indexes.at(row);
        if (index < 0) {
            setStatus(row, tr("Servo %1 is not on the bus: nothing written").arg(motor.id), true);
            continue;
        }
        if (!m_readFailures.at(row).isEmpty()) {
            // Its device values are stale or were never read: nothing to diff against.
            setStatus(row,
                      tr("Servo %1 could not be read (%2): nothing written")
                          .arg(motor.id)
                          .arg(m_readFailures.at(row)),
                      true);
            continue;
        }
        const QVector<model::WriteItem> wanted =
            feetech::calibrationWrites(motor.homingOffset, motor.rangeMin, motor.rangeMax);
        bool changed = false;
        for (int i = 0; i < wanted.size(); ++i) {
            const qint32 now = deviceValue(*m_client, index, wanted.at(i).key);
            changed = changed || now != wanted.at(i).value;
            m_table->setItem(
                row, OffsetColumn + i,
                new QTableWidgetItem(now == wanted.at(i).value
                                         ? QString::number(now)
                                         : tr("%1 → %2").arg(now).arg(wanted.at(i).value)));
        }
        if (!changed) {
            setStatus(row, tr("Unchanged"), false);
        } else if (m_client->servos()->parameters(index)->deviceValue(
                       QStringLiteral("torque_enable"))
                   != std::optional<qint64>(0)) {
            // A new offset under torque would move the horn to the old goal's new place.
            setStatus(row,
                      tr("Torque is on: the new offset would move the horn. Switch torque off "
                         "(support the arm) and load again."),
                      true);
        } else {
            setStatus(row, tr("To write"), false);
            m_writeRows.append(row);
        }
    }
    m_table->resizeColumnsToContents();
    m_table->horizontalHeader()->setSectionResizeMode(StatusColumn, QHeaderView::Stretch);
    m_write->setEnabled(!m_writeRows.isEmpty());
    m_summary->setText(!allOk ? tr("Not every servo could be read: those joints are not written.")
                           : m_writeRows.isEmpty()
                           ? tr("Nothing to write.")
                           : tr("Write %n joint(s) to EEPROM (locked writes, verified)?", nullptr,
                                int(m_writeRows.size())));
    m_ready = true;
    emit ready();
}

void LoadCalibrationDialog::writeChanges()
{
    if (!m_ready || m_writing || m_writeRows.isEmpty())
        return;
    QVector<CalibrationSteps::Step> steps;
    for (const int row : std::as_const(m_writeRows)) {
        const feetech::LeRobotMotor &motor = m_motors.at(row);
        QVector<model::WriteItem> changes;
        for (const model::WriteItem &item :
             feetech::calibrationWrites(motor.homingOffset, motor.rangeMin, motor.rangeMax)) {
            if (deviceValue(*m_client, m_indexes.at(row), item.key) != item.value)
                changes.append(item);
        }
        steps.append({m_indexes.at(row), changes});
    }
    m_writing = true;
    m_write->setEnabled(false);
    m_close->setEnabled(false); // what is half written cannot be taken back
    m_progress->show();
    m_summary->setText(tr("Writing to EEPROM and verifying…"));
    m_steps->start(steps);
}

CalibrationActions::CalibrationActions(QMenu *menu, feetech::BusClient *client, QWidget *window)
    : QObject(menu)
    , m_client(client)
    , m_window(window)
{
    m_calibrate = menu->addAction(tr("&Calibrate arm…"), this, [this] {
        auto *wizard = new CalibrationWizard(m_client, m_window);
        wizard->setAttribute(Qt::WA_DeleteOnClose);
        showApplicationModal(wizard);
    });
    m_calibrate->setObjectName(QStringLiteral("calibrateArmAction"));
    m_calibrate->setToolTip(tr("Record each joint's range by hand and centre it on the encoder"));
    m_save = menu->addAction(tr("&Save calibration…"), this, &CalibrationActions::saveCalibration);
    m_save->setObjectName(QStringLiteral("saveCalibrationAction"));
    m_save->setToolTip(tr("Save the servos' offsets and limits as a LeRobot calibration file"));
    m_load = menu->addAction(tr("&Load calibration…"), this, &CalibrationActions::loadCalibration);
    m_load->setObjectName(QStringLiteral("loadCalibrationAction"));
    m_load->setToolTip(tr("Write a LeRobot calibration file to the servos, after showing what "
                          "changes"));
    connect(client, &feetech::BusClient::statusChanged, this, &CalibrationActions::updateEnabled);
    connect(client->servos(), &feetech::ServoList::servosChanged, this,
            &CalibrationActions::updateEnabled);
    connect(client, &feetech::BusClient::scanFinished, this, &CalibrationActions::updateEnabled);
    updateEnabled();
}

void CalibrationActions::updateEnabled()
{
    const bool ready = m_client->link()->isConnected() && !m_client->isScanning()
        && m_client->servos()->count() > 0;
    for (QAction *action : {m_calibrate, m_save, m_load})
        action->setEnabled(ready);
}

void CalibrationActions::saveCalibration()
{
    const QVector<feetech::RobotTemplate> templates = feetech::availableRobotTemplates();
    const QString path =
        QFileDialog::getSaveFileName(m_window, tr("Save calibration"),
                                     QDir(defaultCalibrationFolder(defaultTemplate(templates)))
                                         .filePath(QStringLiteral("arm.json")),
                                     tr("LeRobot calibration (*.json)"));
    if (path.isEmpty())
        return;
    auto *saver = new CalibrationSaver(m_client, this);
    connect(saver, &CalibrationSaver::finished, this, [this, saver](bool ok, const QString &text) {
        saver->deleteLater();
        emit ok ? message(text) : problem(text);
    });
    util::FileError error;
    if (saver->save(path, &error)) {
        recentfiles::add(recentfiles::Kind::Calibration, path);
    } else {
        saver->deleteLater();
        emit problem(error.describe());
    }
}

void CalibrationActions::loadCalibration()
{
    const QVector<feetech::RobotTemplate> templates = feetech::availableRobotTemplates();
    const QString path = QFileDialog::getOpenFileName(
        m_window, tr("Load calibration"), defaultCalibrationFolder(defaultTemplate(templates)),
        tr("LeRobot calibration (*.json)"));
    if (path.isEmpty())
        return;
    util::FileError error;
    const auto motors = feetech::loadLeRobotCalibration(path, &error);
    if (!motors) {
        emit problem(error.describe());
        return;
    }
    recentfiles::add(recentfiles::Kind::Calibration, path);
    auto *dialog = new LoadCalibrationDialog(m_client, *motors, path, m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    showApplicationModal(dialog);
}
