// Doctor panel: the findings list, the expectation, re-scan, and the guided moves it offers.
#include "doctorpanel.h"

#include "busclient.h"
#include "robottemplate.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace {

const QString kExpectationKey = QStringLiteral("doctor/expectation");

// The finding's title (what its code means) leads; the code itself, for scripts and servoctl
// doctor --json, stays at the end in small grey letters.
enum FindingColumn { TitleColumn, IdsColumn, MessageColumn, CodeColumn, FindingColumns };

QString idsText(const QVector<int> &ids)
{
    QStringList texts;
    for (const int id : ids)
        texts.append(QString::number(id));
    return texts.join(QStringLiteral(", "));
}

QString moveText(const feetech::ServoMove &move)
{
    if (move.newId >= 0 && move.newBaud > 0)
        return DoctorPanel::tr("Move servo %1 (%2) to ID %3 at %4")
            .arg(move.servo.id)
            .arg(feetech::baudText(move.servo.baud))
            .arg(move.newId)
            .arg(feetech::baudText(move.newBaud));
    if (move.newId >= 0)
        return DoctorPanel::tr("Move servo %1 to ID %2").arg(move.servo.id).arg(move.newId);
    return DoctorPanel::tr("Move servo %1 to %2")
        .arg(move.servo.id)
        .arg(feetech::baudText(move.newBaud));
}

} // namespace

DoctorPanel::DoctorPanel(feetech::BusClient *client, QWidget *parent)
    : QDockWidget(tr("Doctor"), parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("doctorPanel"));
    auto *body = new QWidget(this);
    auto *layout = new QVBoxLayout(body);

    m_summary = new QLabel(tr("Scan a bus: when it comes back short, the doctor says why."), body);
    m_summary->setObjectName(QStringLiteral("doctorSummary"));
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);

    auto *expectRow = new QHBoxLayout;
    expectRow->addWidget(new QLabel(tr("The bus should hold:"), body));
    m_expectation = new QComboBox(body);
    m_expectation->setObjectName(QStringLiteral("doctorExpectation"));
    m_expectation->addItem(tr("the servos found last time on this port"), QString());
    for (const feetech::RobotTemplate &robot : feetech::availableRobotTemplates())
        m_expectation->addItem(robot.name, robot.name);
    const int remembered = m_expectation->findData(QSettings().value(kExpectationKey).toString());
    m_expectation->setCurrentIndex(std::max(remembered, 0));
    m_expectation->setToolTip(tr("A robot template: its joints' IDs in chain order, at its rate"));
    connect(m_expectation, &QComboBox::currentIndexChanged, this,
            [this] { QSettings().setValue(kExpectationKey, m_expectation->currentData()); });
    expectRow->addWidget(m_expectation, 1);
    // On the expectation's row, not under the findings: in a dock a few rows high they stay in
    // sight.
    m_rescan = new QPushButton(tr("Re-scan"), body);
    m_rescan->setObjectName(QStringLiteral("doctorRescanButton"));
    m_rescan->setToolTip(tr("Ask the port again and scan the rates that answer"));
    connect(m_rescan, &QPushButton::clicked, this, &DoctorPanel::rescanRequested);
    expectRow->addWidget(m_rescan);
    m_move = new QPushButton(tr("Move the servo"), body);
    m_move->setObjectName(QStringLiteral("doctorMoveButton"));
    m_move->setEnabled(false);
    connect(m_move, &QPushButton::clicked, this, [this] { moveSelected(); });
    expectRow->addWidget(m_move);
    layout->addLayout(expectRow);

    m_list = new QTreeWidget(body);
    m_list->setObjectName(QStringLiteral("doctorFindings"));
    m_list->setColumnCount(FindingColumns);
    m_list->setHeaderLabels(
        {tr("Finding"), tr("IDs"), tr("What is wrong and what to do"), tr("Code")});
    m_list->setRootIsDecorated(false);
    m_list->setWordWrap(true);
    m_list->header()->setStretchLastSection(false);
    m_list->header()->setSectionResizeMode(TitleColumn, QHeaderView::ResizeToContents);
    m_list->header()->setSectionResizeMode(IdsColumn, QHeaderView::ResizeToContents);
    m_list->header()->setSectionResizeMode(MessageColumn, QHeaderView::Stretch);
    m_list->header()->setSectionResizeMode(CodeColumn, QHeaderView::ResizeToContents);
    connect(m_list, &QTreeWidget::currentItemChanged, this, &DoctorPanel::updateMove);
    layout->addWidget(m_list, 1);

    // A dock a few rows high scrolls its controls rather than make the window taller than a
    // 1366x768 screen.
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(body);
    setWidget(scroll);
}

QVector<feetech::ExpectedServo> DoctorPanel::expected(const QString &port) const
{
    const QString robotName = m_expectation->currentData().toString();
    if (robotName.isEmpty())
        return feetech::rememberedServos(port);
    for (const feetech::RobotTemplate &robot : feetech::availableRobotTemplates()) {
        if (robot.name != robotName)
            continue;
        QVector<feetech::ExpectedServo> joints;
        for (const feetech::RobotJoint &joint : robot.joints)
            joints.append({quint8(joint.id), robot.baud});
        return joints;
    }
    return feetech::rememberedServos(port);
}

void DoctorPanel::showChecking(const QString &port)
{
    m_summary->setText(tr("Looking at the bus on %1…").arg(port));
    m_list->clear();
    m_findings.clear();
    updateMove();
}

void DoctorPanel::showFindings(const QString &port, const QVector<feetech::DoctorFinding> &findings)
{
    m_findings = findings;
    m_list->clear();
    for (const feetech::DoctorFinding &finding : findings) {
        auto *item = new QTreeWidgetItem(m_list,
                                         {feetech::doctorTitle(finding.code), idsText(finding.ids),
                                          finding.message, finding.code});
        QFont title = item->font(TitleColumn);
        title.setBold(true);
        item->setFont(TitleColumn, title);
        item->setToolTip(TitleColumn,
                         tr("%1 (code %2)").arg(item->text(TitleColumn), finding.code));
        item->setToolTip(MessageColumn, finding.message);
        QFont code = item->font(CodeColumn);
        if (code.pointSizeF() > 0)
            code.setPointSizeF(code.pointSizeF() * 0.85);
        item->setFont(CodeColumn, code);
        item->setForeground(CodeColumn,
                            m_list->palette().brush(QPalette::Disabled, QPalette::Text));
        item->setToolTip(CodeColumn, tr("The finding's code, as servoctl doctor prints it"));
    }
    m_summary->setText(
        findings.isEmpty()
            ? tr("The bus on %1 holds what was expected.").arg(port)
            : tr("The bus on %1: %n finding(s).", nullptr, int(findings.size())).arg(port));
    if (!findings.isEmpty())
        m_list->setCurrentItem(m_list->topLevelItem(0));
    updateMove();
}

void DoctorPanel::updateMove()
{
    const int row = m_list->currentItem() ? m_list->indexOfTopLevelItem(m_list->currentItem()) : -1;
    const bool offered = row >= 0 && row < m_findings.size() && !m_findings.at(row).moves.isEmpty();
    m_move->setEnabled(offered && !m_moving && m_client->link()->isConnected());
    m_move->setText(offered ? moveText(m_findings.at(row).moves.first()) : tr("Move the servo"));
}

void DoctorPanel::moveSelected(bool confirm)
{
    const int row = m_list->currentItem() ? m_list->indexOfTopLevelItem(m_list->currentItem()) : -1;
    if (row < 0 || row >= m_findings.size() || m_findings.at(row).moves.isEmpty())
        return;
    const feetech::ServoMove move = m_findings.at(row).moves.first();
    const int index = m_client->servos()->indexOf(move.servo.address());
    if (index < 0) {
        emit problem(tr("Servo %1 is no longer on the bus; re-scan first.").arg(move.servo.id));
        return;
    }
    if (confirm
        && QMessageBox::question(this, tr("Move the servo"),
                                 tr("%1? Its EEPROM is written and read back.").arg(moveText(move)),
                                 QMessageBox::Ok | QMessageBox::Cancel, QMessageBox::Cancel)
            != QMessageBox::Ok)
        return;
    feetech::Refusal refusal;
    m_moving = move;
    feetech::OperationReply *reply = move.newId >= 0
        ? m_client->changeId(index, move.newId, &refusal)
        : m_client->changeBaud(index, move.newBaud, &refusal);
    if (reply) {
        connect(reply, &feetech::OperationReply::finished, this, &DoctorPanel::onOperationFinished);
    } else {
        m_moving.reset();
        emit problem(refusal.describe());
    }
    updateMove();
}

void DoctorPanel::onOperationFinished(const feetech::OperationResult &result)
{
    using feetech::Operation;
    if (!m_moving)
        return;
    if (!result.ok) {
        m_moving.reset();
        updateMove();
        emit problem(result.message);
        return;
    }
    if (result.operation == Operation::ChangeId && m_moving->newBaud > 0) {
        changeBaudIfAsked();
        return;
    }
    emit message(result.message);
    m_moving.reset();
    emit rescanRequested(); // the doctor looks again at the bus it changed
}

void DoctorPanel::changeBaudIfAsked()
{
    const int index = m_client->servos()->indexOf({quint8(m_moving->newId), m_moving->servo.baud});
    feetech::Refusal refusal;
    feetech::OperationReply *reply =
        index < 0 ? nullptr : m_client->changeBaud(index, m_moving->newBaud, &refusal);
    if (!reply) {
        m_moving.reset();
        updateMove();
        emit problem(!refusal ? tr("The servo moved to its new ID could not be found to "
                                   "change its rate; re-scan.")
                              : refusal.describe());
        return;
    }
    connect(reply, &feetech::OperationReply::finished, this, &DoctorPanel::onOperationFinished);
}
