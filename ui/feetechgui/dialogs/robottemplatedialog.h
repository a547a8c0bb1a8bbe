// "Save as robot template": a template edited from a built-in or saved one or from the servos
// the scan found, checked as loading checks it, and saved where the set-up wizards find it.
#pragma once

#include "bustypes.h"
#include "robottemplate.h"

#include <QDialog>

#include <functional>
#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace feetech {
class BusClient;
struct OperationResult;
} // namespace feetech

class RobotTemplateDialog : public QDialog
{
    Q_OBJECT

public:
    enum Column { NameColumn, IdColumn, ModelColumn, FullTurnColumn, SettingsColumn, ColumnCount };

    explicit RobotTemplateDialog(feetech::BusClient *client, QWidget *parent = nullptr);

    QComboBox *baseChooser() const { return m_base; }
    QLineEdit *nameEdit() const { return m_name; }
    QComboBox *baudChooser() const { return m_baud; }
    QTableWidget *jointTable() const { return m_joints; }
    QComboBox *servoChooser() const { return m_servo; }
    QLabel *errorLabel() const { return m_error; }
    QPushButton *saveButton() const { return m_save; }

    // Fills the editor from the base at `at` in baseChooser() (the templates, then the servos
    // the scan found).
    void startFrom(int at);
    // The template as edited, checked by robotTemplateFromJson on exactly what would be
    // written; nothing and *error (what loading it would say) when it is not valid.
    std::optional<feetech::RobotTemplate> edited(QString *error) const;
    // Where it would be saved: userRobotTemplateFolder()/<name>.json.
    QString targetPath() const;
    // Saves (after asking before an overwrite); false and *error when nothing was saved.
    bool save(QString *error = nullptr);
    // Takes the values of the registers the selected joint sets from the servo chosen in
    // servoChooser() (read first if it has not been).
    void takeSettingsFromServo();

    // Tests answer the overwrite question themselves.
    void setOverwriteQuestion(std::function<bool(const QString &path)> ask);

signals:
    void saved(const QString &path);

private:
    void fill(const feetech::RobotTemplate &robot);
    void addJointRow(const feetech::RobotJoint &joint);
    void validate();
    void applyServoValues(int row, int index);
    void onOperationFinished(const feetech::OperationResult &result);

    feetech::BusClient *m_client = nullptr;
    QVector<feetech::RobotTemplate> m_templates;
    QComboBox *m_base = nullptr;
    QLineEdit *m_name = nullptr;
    QComboBox *m_baud = nullptr;
    QTableWidget *m_joints = nullptr;
    QComboBox *m_servo = nullptr;
    QLabel *m_error = nullptr;
    QLabel *m_path = nullptr;
    QPushButton *m_save = nullptr;
    std::function<bool(const QString &path)> m_askOverwrite;
    std::optional<std::pair<int, feetech::ServoAddress>> m_pendingRead; // row, servo
    bool m_filling = false;
};
