// Motor set-up wizard: check, find, set up and stop through the client, and what each reported.
#include "setupwizard.h"

#include "registertable.h"

#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

namespace {

QString servoDescription(const feetech::ServoInfo &servo)
{
    return SetupWizard::tr("servo %1 at %2, model %3, firmware %4")
        .arg(servo.id)
        .arg(feetech::baudText(servo.baud), servo.model.name, servo.firmware());
}

QString stepList(const QStringList &steps)
{
    QString html = QStringLiteral("<ul style=\"margin-left: 0px; -qt-list-indent: 1;\">");
    for (const QString &step : steps)
        html += QStringLiteral("<li>%1</li>").arg(step.toHtmlEscaped());
    return html + QStringLiteral("</ul>");
}

} // namespace

void SetupWizard::startWork(Work work, const QString &text)
{
    m_work = work;
    m_stopping = false;
    m_progress->setRange(0, 0); // busy until the first step reports
    m_progress->show();
    m_step->setText(text);
    m_step->show();
    updateActions();
}

void SetupWizard::endWork()
{
    m_work = Work::None;
    m_stopping = false;
    m_progress->hide();
    m_step->hide();
    updateActions();
}

void SetupWizard::checkBus()
{
    if (isWorking() || !m_client->isConnected() || m_client->isBusy() || m_joints.isEmpty())
        return;
    QString error;
    if (!m_client->motorSetup()->checkJoints(m_robot.baud, feetech::jointChecks(m_robot), &error)) {
        showOutcome(error.toHtmlEscaped(), palette::Tone::Error);
        return;
    }
    startWork(Work::Checking,
              tr("Asking every joint's ID at %1…").arg(feetech::baudText(m_robot.baud)));
}

void SetupWizard::find()
{
    if (isWorking() || m_current < 0)
        return;
    m_found.reset();
    QString error;
    if (!m_client->motorSetup()->find(currentTarget(), &error)) {
        showOutcome(error.toHtmlEscaped(), palette::Tone::Error);
        updateActions();
        return;
    }
    showOutcome({}, palette::Tone::Accent);
    startWork(Work::Finding, tr("Looking for the servo at every baud rate…"));
}

void SetupWizard::setUp()
{
    if (isWorking() || m_current < 0 || !m_found)
        return;
    QString error;
    if (!m_client->motorSetup()->setUp(currentTarget(), &error)) {
        showOutcome(error.toHtmlEscaped(), palette::Tone::Error);
        return;
    }
    showOutcome({}, palette::Tone::Accent);
    startWork(Work::SettingUp, tr("Looking for the servo at every baud rate…"));
}

void SetupWizard::stop()
{
    if (!isWorking() || m_stopping)
        return;
    m_stopping = true;
    m_client->motorSetup()->cancel();
    m_step->setText(tr("Stopping after this step…"));
    updateActions();
}

void SetupWizard::onProgress(int step, int steps, const QString &text)
{
    if (!isWorking())
        return;
    m_progress->setRange(0, steps);
    m_progress->setValue(step - 1); // the step has begun, not ended
    if (!m_stopping)
        m_step->setText(tr("Step %1 of %2: %3").arg(step).arg(steps).arg(text));
}

void SetupWizard::onFinished(const feetech::MotorSetupResult &result)
{
    const Work work = m_work;
    endWork();
    if (work == Work::Finding && !result.setUp)
        onFound(result);
    else if (work == Work::SettingUp && result.setUp)
        onSetUp(result);
}

void SetupWizard::onFound(const feetech::MotorSetupResult &result)
{
    const feetech::MotorSearch &search = result.search;
    if (m_current < 0)
        return;
    const feetech::RobotJoint &joint = m_robot.joints.at(m_current);
    if (!result.ok) {
        if (!result.stopped) {
            m_joints[m_current].state = JointState::Failed;
            m_joints[m_current].reason = result.message;
        }
        // Every message of a search that found no single servo says what to do next.
        QString html = QStringLiteral("<b>%1</b>").arg(result.message.toHtmlEscaped());
        if (search.needsNothingWrittenNote())
            html += QStringLiteral("<br>") + tr("Nothing was written to any servo.");
        showOutcome(html, result.stopped ? palette::Tone::Warning : palette::Tone::Error);
        showJoints();
        updateActions();
        return;
    }
    m_found = search.servo;
    m_joints[m_current].reason.clear();
    if (m_joints[m_current].state == JointState::Failed)
        m_joints[m_current].state = JointState::ToDo;
    QString html =
        tr("<b>Found one servo:</b> %1.").arg(servoDescription(search.servo).toHtmlEscaped());
    const int other = jointAnsweringAt(search.servo);
    if (other >= 0 && m_joints.at(other).state == JointState::Done) {
        html += QStringLiteral("<br><span style=\"color: %1\">%2</span>")
                    .arg(palette::toneColor(palette::Tone::Warning, palette()).name(),
                         tr("It answers where %1 should: it may be the %1 servo, already set "
                            "up. Set it up as %2 only if it is the %2 servo.")
                             .arg(m_robot.joints.at(other).name, joint.name)
                             .toHtmlEscaped());
    }
    html += QStringLiteral("<br>")
        + tr("Press <i>Set up</i> to give it ID %2, %3 and the %1 settings (%n value(s), "
             "each read back).",
             nullptr, int(joint.settings.size()))
              .arg(joint.name.toHtmlEscaped())
              .arg(joint.id)
              .arg(feetech::baudText(m_robot.baud));
    showOutcome(html, palette::Tone::Accent);
    showJoints();
    updateActions();
}

void SetupWizard::onSetUp(const feetech::MotorSetupResult &result)
{
    m_found.reset();
    if (m_current < 0)
        return;
    if (!result.ok) {
        // A stop before anything was written leaves the joint as it was.
        if (!result.stopped || result.steps.size() > 1) {
            m_joints[m_current].state = JointState::Failed;
            m_joints[m_current].reason = result.message;
        }
        QString html = QStringLiteral("<b>%1</b>").arg(result.message.toHtmlEscaped());
        if (result.search.needsNothingWrittenNote())
            html += QStringLiteral("<br>") + tr("Nothing was written to any servo.");
        if (result.steps.size() > 1) // more than the find
            html += QStringLiteral("<br>") + tr("Done before that:") + stepList(result.steps);
        showOutcome(html, result.stopped ? palette::Tone::Warning : palette::Tone::Error);
        showJoints();
        updateActions();
        return;
    }
    m_joints[m_current].state = JointState::Done;
    m_joints[m_current].reason.clear();
    const QString done = result.message;
    m_current = nextToDo(m_current);
    QString html = QStringLiteral("<b>%1</b>").arg(done.toHtmlEscaped()) + stepList(result.steps);
    html += m_current >= 0 ? tr("Unplug it and connect the next servo: <b>%1</b>.")
                                 .arg(m_robot.joints.at(m_current).name.toHtmlEscaped())
                           : tr("Every joint is set up.");
    showOutcome(html, palette::Tone::Good);
    showJoints();
    showCurrent();
    updateActions();
}

void SetupWizard::onChecked(const QVector<feetech::JointCheck> &joints, bool ok,
                            const QString &message)
{
    if (m_work != Work::Checking)
        return;
    endWork();
    if (!ok) {
        showOutcome(message.toHtmlEscaped(), palette::Tone::Error);
        return;
    }
    int done = 0;
    for (int i = 0; i < joints.size() && i < m_joints.size(); ++i) {
        const feetech::JointCheck &checked = joints.at(i);
        Joint &joint = m_joints[i];
        if (checked.done()) {
            joint = {JointState::Done, {}};
        } else if (checked.found) { // something else answers there: not set up as this joint
            joint = {JointState::ToDo, checked.problem()};
        }
        // A joint whose servo does not answer keeps its state: set up in this session, its
        // servo was unplugged for the next one.
        done += joint.state == JointState::Done ? 1 : 0;
    }
    if (m_current < 0 || m_joints.at(m_current).state == JointState::Done)
        m_current = nextToDo(m_current < 0 ? -1 : m_current);
    m_found.reset();
    showOutcome(
        tr("Checked the bus at %1: %2 of %n joint(s) set up.", nullptr, int(m_joints.size()))
            .arg(feetech::baudText(m_robot.baud))
            .arg(done),
        palette::Tone::Accent);
    showJoints();
    showCurrent();
    updateActions();
}
