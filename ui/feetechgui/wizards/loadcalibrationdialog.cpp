// The load calibration dialog: a LeRobot file's differences per joint, then verified writes.
#include "loadcalibrationdialog.h"

#include "armcalibration.h"
#include "busclient.h"
#include "calibrationsteps.h"
#include "palette.h"
#include "robottemplate.h"

#include <QDir>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace {

enum FileColumn {
    FileJointColumn,
    FileOffsetColumn,
    FileMinimumColumn,
    FileMaximumColumn,
    FileStatusColumn
};

} // namespace

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
    m_table->horizontalHeader()->setSectionResizeMode(FileStatusColumn, QHeaderView::Stretch);
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
        m_table->setItem(
            row, FileJointColumn,
            new QTableWidgetItem(
                tr("%1 (%2)").arg(feetech::jointDisplayName(motor.name)).arg(motor.id)));
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
    m_table->setItem(row, FileStatusColumn, item);
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
            const qint32 now = CalibrationSteps::lastRead(*m_client, index, wanted.at(i).key);
            changed = changed || now != wanted.at(i).value;
            m_table->setItem(
                row, FileOffsetColumn + i,
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
    m_table->horizontalHeader()->setSectionResizeMode(FileStatusColumn, QHeaderView::Stretch);
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
            if (CalibrationSteps::lastRead(*m_client, m_indexes.at(row), item.key) != item.value)
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
