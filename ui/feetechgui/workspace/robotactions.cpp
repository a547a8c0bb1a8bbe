// Robot actions: their enabled state and reasons, identify, the batch with its progress and
// result table, and the template dialogs.
#include "robotactions.h"

#include "batchprogram.h"
#include "batchresultdialog.h"
#include "busclient.h"
#include "feetechworkspace.h"
#include "identifyquestion.h"
#include "jointnames.h"
#include "profileactions.h"
#include "robottemplate.h"
#include "robottemplatedialog.h"
#include "servotree.h"

#include <QAction>
#include <QInputDialog>
#include <QMenu>
#include <QProgressDialog>
#include <QTreeWidget>

#include <algorithm>

RobotActions::RobotActions(feetech::BusClient *client, FeetechWorkspace *workspace)
    : QObject(workspace)
    , m_client(client)
    , m_workspace(workspace)
    , m_batch(new feetech::BatchProgram(client, this))
{
    m_identify = new QAction(tr("&Identify the servo"), this);
    m_identify->setObjectName(QStringLiteral("identifyAction"));
    m_applyProfile = new QAction(tr("Apply &profile to selected servos…"), this);
    m_applyProfile->setObjectName(QStringLiteral("applyProfileToSelectedAction"));
    m_applyTemplate = new QAction(tr("Apply &template settings to selected servos…"), this);
    m_applyTemplate->setObjectName(QStringLiteral("applyTemplateToSelectedAction"));
    m_saveTemplate = new QAction(tr("&Save as robot template…"), this);
    m_saveTemplate->setObjectName(QStringLiteral("saveRobotTemplateAction"));
    connect(m_identify, &QAction::triggered, this, [this] {
        const int index = m_workspace->currentIndex();
        if (index < 0 || index >= m_client->servos()->count())
            return;
        const feetech::ServoAddress servo = m_client->servos()->at(index).info.address();
        const feetech::JointNames joints = feetech::JointNames::of(*m_client);
        const QString name =
            joints.joint(servo).isEmpty() ? tr("servo ID %1").arg(servo.id) : joints.label(servo);
        if (!confirmIdentify(m_workspace, name))
            return;
        // The question runs its own event loop: the servo is looked up again after it.
        feetech::Refusal refusal;
        if (!identify(m_client->servos()->indexOf(servo), &refusal))
            emit problem(refusal.describe());
    });
    connect(m_applyProfile, &QAction::triggered, this, &RobotActions::chooseProfileToApply);
    connect(m_applyTemplate, &QAction::triggered, this, &RobotActions::chooseTemplateToApply);
    connect(m_saveTemplate, &QAction::triggered, this, &RobotActions::openSaveTemplateDialog);

    connect(m_client->servos(), &feetech::ServoList::servosChanged, this,
            &RobotActions::updateActions);
    connect(m_client, &feetech::BusClient::allTorqueOffRequested, this,
            &RobotActions::updateActions);
    connect(m_client, &feetech::BusClient::statusChanged, this, &RobotActions::updateActions);
    connect(m_client, &feetech::BusClient::busyChanged, this, &RobotActions::updateActions);
    connect(m_client->servos(), &feetech::ServoList::servoUpdated, this,
            &RobotActions::updateActions);
    connect(m_client, &feetech::BusClient::scanFinished, this, &RobotActions::updateActions);
    connect(m_workspace->servoTree(), &QTreeWidget::itemSelectionChanged, this,
            &RobotActions::updateActions);
    // Whoever started it (the servo tree or the joint table), an identify's outcome is told.
    connect(m_client, &feetech::BusClient::submitted, this, [this](feetech::OperationReply *reply) {
        if (reply->operation() != feetech::Operation::Identify)
            return;
        connect(reply, &feetech::OperationReply::finished, this,
                [this](const feetech::OperationResult &result) {
                    if (result.ok)
                        emit message(result.message);
                    else
                        emit problem(result.message);
                });
    });
    connect(m_batch, &feetech::BatchProgram::runningChanged, this, &RobotActions::updateActions);
    connect(m_batch, &feetech::BatchProgram::progress, this,
            [this](int done, int total, const QString &text) {
                if (!m_progress)
                    return;
                m_progress->setMaximum(total);
                m_progress->setValue(done);
                m_progress->setLabelText(text);
            });
    connect(m_batch, &feetech::BatchProgram::finished, this, &RobotActions::onBatchFinished);
    updateActions();
}

QList<QAction *> RobotActions::actions() const
{
    return {m_identify, m_applyProfile, m_applyTemplate, m_saveTemplate};
}

BatchResultDialog *RobotActions::resultDialog() const
{
    return m_results;
}

void RobotActions::addTo(QMenu *menu) const
{
    menu->setToolTipsVisible(true); // a disabled action says why
    menu->addAction(m_identify);
    menu->addSeparator();
    menu->addAction(m_applyProfile);
    menu->addAction(m_applyTemplate);
    menu->addSeparator();
    menu->addAction(m_saveTemplate);
}

void RobotActions::updateActions()
{
    // Connected and scanned: every robot action needs the servos the scan found.
    QString why;
    if (!m_client->link()->isConnected())
        why = tr("Connect to a Feetech bus first.");
    else if (m_client->isScanning())
        why = tr("The scan is still running.");
    else if (m_client->servos()->count() == 0)
        why = tr("Scan the bus first: no servos are known.");
    const bool ready = why.isEmpty();

    const int current = m_workspace->currentIndex();
    const QString identifyWhy = ready ? m_client->identify()->blocker(current).describe() : why;
    m_identify->setText(
        current >= 0 ? tr("&Identify servo ID %1").arg(m_client->servos()->at(current).info.id)
                     : tr("&Identify the servo"));
    m_identify->setEnabled(identifyWhy.isEmpty());
    m_identify->setToolTip(
        identifyWhy.isEmpty()
            ? tr("Move the servo a little each way, slowly and with little torque, then put it "
                 "back as it was: you see which servo of the arm it is")
            : identifyWhy);

    QString batchWhy = why;
    if (batchWhy.isEmpty() && m_batch->isRunning())
        batchWhy = tr("Servos are being programmed.");
    else if (batchWhy.isEmpty() && m_client->isBusy())
        batchWhy = tr("Another operation is still running.");
    else if (batchWhy.isEmpty() && m_workspace->servoTree()->selectedServos().isEmpty())
        batchWhy = tr("Select servos in the tree first (Ctrl+click or Shift+click for several).");
    for (QAction *action : {m_applyProfile, m_applyTemplate}) {
        action->setEnabled(batchWhy.isEmpty());
        action->setToolTip(batchWhy.isEmpty() ? tr("Write, verify and report each selected "
                                                   "servo in turn")
                                              : batchWhy);
    }
    m_saveTemplate->setEnabled(ready);
    m_saveTemplate->setToolTip(ready ? tr("Describe this arm as a template the set-up wizards "
                                          "offer")
                                     : why);
}

bool RobotActions::identify(int index, feetech::Refusal *refusal)
{
    if (!m_client->identify()->start(index, refusal))
        return false;
    emit message(tr("Identifying servo ID %1: watch which horn moves…")
                     .arg(m_client->servos()->at(index).info.id));
    return true;
}

bool RobotActions::applyToSelected(const feetech::SettingsFile &file, QString *error)
{
    if (!m_batch->start(m_workspace->servoTree()->selectedServos(), file, error))
        return false;
    m_batchSource = file.source();
    m_progress = new QProgressDialog(m_workspace);
    m_progress->setObjectName(QStringLiteral("batchProgress"));
    m_progress->setAttribute(Qt::WA_DeleteOnClose);
    m_progress->setWindowTitle(tr("Programming servos"));
    m_progress->setLabelText(tr("Starting…"));
    m_progress->setCancelButton(nullptr); // each servo's write is short; it finishes
    m_progress->setMinimumDuration(0);
    m_progress->setRange(0, 0);
    m_progress->show();
    return true;
}

void RobotActions::onBatchFinished()
{
    if (m_progress)
        m_progress->close();
    if (m_results)
        m_results->close();
    m_results = new BatchResultDialog(m_batchSource, m_batch->outcomes(), m_workspace);
    m_results->setAttribute(Qt::WA_DeleteOnClose);
    m_results->open();
    const bool failed =
        std::any_of(m_batch->outcomes().cbegin(), m_batch->outcomes().cend(), [](const auto &o) {
            return o.status == feetech::ProgramOutcome::Status::Failed;
        });
    if (failed)
        emit problem(
            tr("Programming %1: some servos failed; see the result table.").arg(m_batchSource));
    else
        emit message(tr("Programming %1: done.").arg(m_batchSource));
}

void RobotActions::chooseProfileToApply()
{
    const QString path = profileactions::chooseLoadPath(m_workspace);
    if (path.isEmpty())
        return;
    util::FileError unreadable;
    const auto file = feetech::SettingsFile::load(path, &unreadable);
    QString error;
    if (!file)
        emit problem(unreadable.describe());
    else if (!applyToSelected(*file, &error))
        emit problem(error);
}

void RobotActions::chooseTemplateToApply()
{
    QStringList problems;
    const QVector<feetech::RobotTemplate> templates = feetech::availableRobotTemplates(&problems);
    if (!problems.isEmpty())
        emit problem(problems.join(u' '));
    QStringList names;
    for (const feetech::RobotTemplate &robot : templates)
        names.append(feetech::robotDisplayName(robot.name));
    bool chosen = false;
    const QString name = QInputDialog::getItem(
        m_workspace, tr("Apply template settings"),
        tr("Each selected servo gets the settings of the template's joint "
           "with its ID:"),
        names, std::max(0, feetech::defaultRobotTemplate(templates)), false, &chosen);
    const int at = int(names.indexOf(name));
    if (!chosen || at < 0)
        return;
    QString error;
    if (!applyToSelected(feetech::SettingsFile::fromTemplate(templates.at(at)), &error))
        emit problem(error);
}

void RobotActions::openSaveTemplateDialog()
{
    auto *dialog = new RobotTemplateDialog(m_client, m_workspace);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &RobotTemplateDialog::saved, this, [this](const QString &path) {
        emit message(tr("Robot template saved to %1").arg(path));
    });
    dialog->open();
}
