// Saving a LeRobot calibration file: the servos' offsets and limits read, checked and written.
#include "calibrationsaver.h"

#include "armcalibration.h"
#include "busclient.h"
#include "calibrationjointspage.h"
#include "calibrationsteps.h"
#include "lerobotcalibration.h"
#include "robottemplate.h"

#include <QDir>

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
                CalibrationSteps::lastRead(*m_client, index,
                                           QString::fromUtf16(feetech::kOffsetKey)),
                CalibrationSteps::lastRead(*m_client, index,
                                           QString::fromUtf16(feetech::kMinimumLimitKey)),
                CalibrationSteps::lastRead(*m_client, index,
                                           QString::fromUtf16(feetech::kMaximumLimitKey))};
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
    for (const ArmJoint &joint : armJoints(*m_client, feetech::defaultRobotTemplateIn(templates))) {
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
