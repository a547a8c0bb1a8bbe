// Saving the scanned servos' calibration (offsets and limits) to a LeRobot calibration file.
#pragma once

#include "fileerror.h"

#include <QObject>
#include <QStringList>
#include <QVector>

namespace feetech {
class BusClient;
}

class CalibrationSteps;

// Reads the offsets and limits of the scanned servos that have them (named by the default robot
// template where their IDs match it) and saves them as a LeRobot file.
class CalibrationSaver : public QObject
{
    Q_OBJECT

public:
    explicit CalibrationSaver(feetech::BusClient *client, QObject *parent = nullptr);
    // False and *error (NothingToSave) when nothing was started (no servo to save).
    bool save(const QString &path, util::FileError *error);

signals:
    void finished(bool ok, const QString &message);

private:
    feetech::BusClient *m_client = nullptr;
    CalibrationSteps *m_steps = nullptr;
    QString m_path;
    QString m_failure; // the first servo that could not be read
    QVector<int> m_indexes;
    QStringList m_names;
};
