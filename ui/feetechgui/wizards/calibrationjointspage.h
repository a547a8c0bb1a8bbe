// The calibration wizard's first page: the robot template, the joints to calibrate, the order.
#pragma once

#include "armcalibration.h"
#include "robottemplate.h"

#include <QStringList>
#include <QVector>
#include <QWidget>

namespace feetech {
class BusClient;
} // namespace feetech

class QComboBox;
class QPushButton;
class QRadioButton;
class QTableWidget;

// The joints of the scanned servos as a robot template names them: a joint whose ID the template
// has takes its name and full-turn flag, any other servo is "id_N". `index` is the client's.
struct ArmJoint
{
    int index = 0;
    feetech::RobotJoint joint;
};
QVector<ArmJoint> armJoints(const feetech::BusClient &client, const feetech::RobotTemplate *robot);

class CalibrationJointsPage : public QWidget
{
    Q_OBJECT

public:
    // The joints ticked, in the table's order, up to the first one refused.
    struct Choice
    {
        QVector<int> indexes; // as the client lists them
        QVector<feetech::JointRecording> recordings; // nothing recorded yet
        QStringList described; // "name (ID n)"
    };

    explicit CalibrationJointsPage(feetech::BusClient *client, QWidget *parent = nullptr);

    // What is ticked; false and *error when a joint is refused or none is ticked.
    bool choose(Choice *choice, QString *error) const;
    feetech::CalibrationOrder order() const;
    const feetech::RobotTemplate *chosenTemplate() const; // nullptr: joints named by ID

    QPushButton *nextButton() const { return m_next; }

    // Ticks the servo with ID `id` alone, named `name` (a replaced motor, calibrated into its
    // arm's file), and locks the choice; false when no scanned servo has that ID.
    bool keepOnly(int id, const QString &name, bool fullTurn);

private:
    void fillJointTable();

    feetech::BusClient *m_client = nullptr;
    QVector<feetech::RobotTemplate> m_templates;
    QComboBox *m_template = nullptr;
    QTableWidget *m_jointTable = nullptr;
    QRadioButton *m_rangeFirst = nullptr;
    QRadioButton *m_middleFirst = nullptr;
    QPushButton *m_next = nullptr;
};
