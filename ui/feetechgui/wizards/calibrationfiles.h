// Where the calibration wizard and the Robot menu offer to save and open LeRobot calibration files.
#pragma once

#include <QString>

class QWidget;

namespace feetech {
struct RobotTemplate;
}

// Where to offer loading a LeRobot file for `robot`: its folder in LeRobot's calibration folder
// when that exists, else the folder of the calibration file used last, else the nearest folder
// of LeRobot's that exists.
QString defaultCalibrationFolder(const feetech::RobotTemplate *robot);
// The file to offer saving `robot`'s calibration as: for an arm LeRobot knows, in the folder
// LeRobot reads it from (feetech::leRobotArmFolder, which may not exist yet), named as the file
// used last there or else my_arm.json (LeRobot's arm ID is the file's name); for any other arm
// my_arm.json in defaultCalibrationFolder.
QString suggestedCalibrationFile(const feetech::RobotTemplate *robot);
// Asks where to save `robot`'s calibration, starting at suggestedCalibrationFile. Its folders
// are made first, so that the dialog can open there; those the user did not save into are
// removed again. Empty when the user cancelled.
QString chooseCalibrationFileToSave(QWidget *parent, const QString &title,
                                    const feetech::RobotTemplate *robot);
