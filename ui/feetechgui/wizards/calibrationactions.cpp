// The Robot menu's calibration entries: the wizard opened, a file saved or loaded.
#include "calibrationactions.h"

#include "busclient.h"
#include "calibrationfiles.h"
#include "calibrationjointspage.h"
#include "calibrationsaver.h"
#include "calibrationwizard.h"
#include "loadcalibrationdialog.h"
#include "recentfiles.h"
#include "replacemotorwizard.h"
#include "robottemplate.h"
#include "setupwizard.h"

#include <QAction>
#include <QFileDialog>
#include <QMenu>

namespace {

// Application-modal, not window-modal: the set-up wizard is a window of its own (modeless), and
// no set-up may run while calibrations are written.
void showApplicationModal(QDialog *dialog)
{
    dialog->setWindowModality(Qt::ApplicationModal);
    dialog->show();
}

} // namespace

CalibrationActions::CalibrationActions(QMenu *menu, feetech::BusClient *client, QWidget *window)
    : QObject(menu)
    , m_client(client)
    , m_window(window)
{
    m_calibrate = menu->addAction(tr("&Calibrate arm…"), this, &CalibrationActions::openWizard);
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

void CalibrationActions::openWizard()
{
    if (!m_wizard) {
        // A set-up gives servos new IDs and settings under the joints being recorded.
        for (QDialog *setUp :
             {static_cast<QDialog *>(m_window->findChild<SetupWizard *>()),
              static_cast<QDialog *>(m_window->findChild<ReplaceMotorWizard *>())}) {
            if (setUp && setUp->isVisible()) {
                emit problem(tr("Close the motor set-up (%1) before calibrating: it changes the "
                                "servos' IDs and settings.")
                                 .arg(setUp->windowTitle()));
                setUp->raise();
                setUp->activateWindow();
                return;
            }
        }
        m_wizard = new CalibrationWizard(m_client, m_window);
        m_wizard->setAttribute(Qt::WA_DeleteOnClose);
    }
    emit wizardOpening(m_wizard);
    m_wizard->show();
    m_wizard->raise();
    m_wizard->activateWindow();
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
    const QString path = chooseCalibrationFileToSave(m_window, tr("Save calibration"),
                                                     feetech::defaultRobotTemplateIn(templates));
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
        m_window, tr("Load calibration"),
        defaultCalibrationFolder(feetech::defaultRobotTemplateIn(templates)),
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
