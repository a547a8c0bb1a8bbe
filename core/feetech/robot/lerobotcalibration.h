// LeRobot's calibration files: one JSON object of motors by joint name, and where LeRobot keeps
// them.
#pragma once

#include "fileerror.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <QVector>

#include <optional>

namespace feetech {

// What LeRobot keeps of one motor: positions and offset in steps, the offset as the signed value
// of the offset register (present = physical - homing_offset).
struct LeRobotMotor
{
    QString name; // "shoulder_pan"
    int id = 1;
    // LeRobot inverts the direction in software for 1: no register holds it, so it lives in the
    // file only (ServoBench writes 0 for a new joint and keeps what an existing file says).
    int driveMode = 0;
    qint32 homingOffset = 0;
    qint32 rangeMin = 0;
    qint32 rangeMax = 4095;
};

// The bounds a file's values are checked against: the STS3215's offset register and encoder.
constexpr qint32 kLeRobotMaximumOffset = 2047;
constexpr qint32 kLeRobotMaximumPosition = 4095;
// LeRobot writes a range_max of 4096 (one past the last position) to the servo and its files
// without complaint; a file may hold it. No position reaches 4095 or 4096: both mean no bound.
constexpr qint32 kLeRobotLargestLimit = 4096;

// A motor name as LeRobot's robots use them: ASCII letters, digits and _, a letter first
// ("shoulder_pan").
bool isLeRobotMotorName(const QString &name);

// The motors of a file in ID order; nothing and *error naming `source`, the joint and the field
// when the document is not an object of motors, a field is missing, not a whole number or out of
// range, range_min is not below range_max, or an ID or name repeats.
std::optional<QVector<LeRobotMotor>>
leRobotCalibrationFromJson(const QByteArray &json, const QString &source, util::FileError *error);
// The file LeRobot writes: motors in the order given, indented by four spaces.
QByteArray leRobotCalibrationToJson(const QVector<LeRobotMotor> &motors);

// Reads and checks a file; nothing and *error (naming the file) when it cannot be used.
std::optional<QVector<LeRobotMotor>> loadLeRobotCalibration(const QString &path,
                                                            util::FileError *error);
// Saves atomically; false and *error (naming the file) when it could not, or when a value is one
// a file cannot hold (what is saved, loads).
bool saveLeRobotCalibration(const QVector<LeRobotMotor> &motors, const QString &path,
                            util::FileError *error);
// drive_mode is LeRobot's software setting, held by no register: a file saved over `path` keeps
// each joint's drive_mode from the file there, by joint name (nothing when there is none).
void keepDriveModes(QVector<LeRobotMotor> &motors, const QString &path);

// The motor of `motors` with ID `id`; nullptr when there is none.
const LeRobotMotor *leRobotMotorWithId(const QVector<LeRobotMotor> &motors, int id);
// A file's motors after some of its joints were calibrated anew (a motor replaced): each joint of
// `calibrated` takes the place of the file's joint of the same ID, with the file's name and
// drive_mode; the file's other joints stay as they are. A calibrated joint the file lacks is
// left out: check with leRobotMotorWithId first.
QVector<LeRobotMotor> updatedLeRobotCalibration(QVector<LeRobotMotor> file,
                                                const QVector<LeRobotMotor> &calibrated);
// Loads the file at `path`, updates it with `calibrated` and saves it back; false and *error
// when it cannot be read or saved, or lacks a joint of `calibrated` (then it is left as it was).
bool updateLeRobotCalibrationFile(const QVector<LeRobotMotor> &calibrated, const QString &path,
                                  util::FileError *error);

// Where LeRobot keeps calibration files, as it finds it: $HF_LEROBOT_CALIBRATION, else
// $HF_LEROBOT_HOME/calibration, else $HF_HOME/lerobot/calibration, with HF_HOME defaulting to
// $XDG_CACHE_HOME/huggingface and that to ~/.cache/huggingface.
QString leRobotCalibrationFolder();
// The folders under it that may hold a robot template's arm, the usual one first:
// "robots/so101_follower" for the SO-101 follower (LeRobot from 0.4 also uses
// "robots/so_follower" for both SO arms), "teleoperators/so100_leader" for the SO-100 leader;
// none for any other arm.
QStringList leRobotArmFolders(const QString &templateName);
// The folder LeRobot reads the arm of `templateName` from: the first of its leRobotArmFolders
// that exists under leRobotCalibrationFolder(), else the usual one (which may not exist yet);
// empty for an arm LeRobot does not know.
QString leRobotArmFolder(const QString &templateName);

} // namespace feetech
