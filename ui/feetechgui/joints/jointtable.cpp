// Joint table: rows kept in step with the bus client and the monitor, drawn by JointTableView;
// Move all as one SYNC WRITE per baud rate, torque switches, register reads and identify.
#include "jointtable.h"

#include "jointnames.h"

#include "busclient.h"
#include "identifyquestion.h"
#include "jointtableposes.h"
#include "jointtableview.h"
#include "moveallplan.h"
#include "palette.h"
#include "registerkeys.h"
#include "servoparameters.h"
#include "widgethelpers.h"

#include <QHBoxLayout>
#include <QHash>
#include <QLabel>
#include <QPushButton>
#include <QSet>
#include <QShowEvent>
#include <QVBoxLayout>

#include <cmath>

using namespace feetech::registerkeys;
using widgethelpers::actionButton;

JointTable::JointTable(feetech::BusClient *client, QWidget *parent)
    : QWidget(parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("jointTable"));
    auto *layout = new QVBoxLayout(this);

    // ---- where the positions come from
    auto *hintRow = new QHBoxLayout;
    m_hint = new QLabel(this);
    m_hint->setObjectName(QStringLiteral("liveHint"));
    m_hint->setWordWrap(true);
    hintRow->addWidget(m_hint, 1);
    m_read =
        actionButton(tr("Read positions"), "readPositionsButton",
                     tr("Read every servo's registers now: positions, limits and torque"), this);
    hintRow->addWidget(m_read);
    // The row keeps its height when the button goes away with the monitor running.
    m_hint->setMinimumHeight(m_read->sizeHint().height());
    layout->addLayout(hintRow);

    // ---- the table
    m_table = new JointTableView(this);
    layout->addWidget(m_table, 1);

    // ---- actions
    auto *actions = new QHBoxLayout;
    m_capture = actionButton(tr("Targets from present positions"), "captureButton",
                             tr("Copy every servo's present position into its target"), this);
    m_poses = new JointTablePoses(this);
    m_moveAll = actionButton(tr("Move all"), "moveAllButton",
                             tr("Send every target at once: one SYNC WRITE per baud rate"), this);
    m_moveAll->setMinimumWidth(140);
    QFont bold = m_moveAll->font();
    bold.setBold(true);
    m_moveAll->setFont(bold);
    actions->addWidget(m_capture);
    actions->addWidget(m_poses->loadButton());
    actions->addWidget(m_poses->saveButton());
    actions->addSpacing(12);
    actions->addWidget(m_poses->poseLabel());
    actions->addStretch(1);
    actions->addWidget(m_moveAll);
    layout->addLayout(actions);

    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("jointMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_message);

    connect(m_read, &QPushButton::clicked, this, &JointTable::onReadClicked);
    connect(m_capture, &QPushButton::clicked, this, &JointTable::onCaptureClicked);
    connect(m_moveAll, &QPushButton::clicked, this, &JointTable::onMoveAllClicked);
    connect(m_table, &JointTableView::targetEdited, this, &JointTable::setTarget);
    connect(m_table, &JointTableView::torqueToggled, this, &JointTable::onTorqueToggled);

    connect(m_client->servos(), &feetech::ServoList::servosChanged, this, &JointTable::rebuild);
    connect(m_client->servos(), &feetech::ServoList::servoUpdated, this, [this](int index) {
        if (index < 0 || index >= m_client->servos()->count())
            return;
        const feetech::ServoInfo &info = m_client->servos()->at(index).info;
        const int row = rowOf(info.address());
        if (row < 0)
            return;
        const qint64 readMs = m_client->servos()->parameters(index)->lastReadMs(kPresentPosition);
        if (readMs != m_rows[row].modelReadMs) {
            m_rows[row].modelReadMs = readMs;
            m_rows[row].sampleNewer = false;
        }
        refreshRow(row);
        refreshIdentifyButtons(); // a motion test may hold the servo now, or have let it go
    });
    connect(m_client->telemetry(), &feetech::TelemetryHub::samplesReceived, this,
            &JointTable::onTelemetry);
    connect(m_client->telemetry(), &feetech::TelemetryHub::streamingChanged, this, [this] {
        for (int row = 0; row < rowCount(); ++row)
            refreshPosition(row);
        refreshHint();
    });
    connect(m_client->telemetry(), &feetech::TelemetryHub::statsChanged, this, [this] {
        for (int row = 0; row < rowCount(); ++row)
            refreshPosition(row);
        refreshHint();
    });
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        // Reconnected, the servos found again are read again (asked once per connection).
        if (!m_client->link()->isConnected())
            m_readAsked.clear();
        refreshHint();
        refreshButtons();
    });
    connect(m_client, &feetech::BusClient::busyChanged, this, &JointTable::refreshIdentifyButtons);
    // Whoever started it (this table or the servo tree), an identify's outcome shows here.
    connect(m_client, &feetech::BusClient::submitted, this, [this](feetech::OperationReply *reply) {
        if (reply->operation() != feetech::Operation::Identify)
            return;
        connect(reply, &feetech::OperationReply::finished, this,
                [this](const feetech::OperationResult &result) {
                    setMessage(result.message, result.ok ? Tone::Success : Tone::Error);
                });
    });

    rebuild();
    setMessage(tr("Targets only move servos when you press Move all."), Tone::Info);
}

int JointTable::rowOf(const feetech::ServoAddress &servo) const
{
    for (int row = 0; row < rowCount(); ++row) {
        if (m_rows.at(row).servo == servo)
            return row;
    }
    return -1;
}

int JointTable::servoIndex(int row) const
{
    if (row < 0 || row >= rowCount())
        return -1;
    return m_client->servos()->indexOf(m_rows.at(row).servo);
}

QVector<feetech::JointTarget> JointTable::joints() const
{
    QVector<feetech::JointTarget> joints;
    for (int row = 0; row < rowCount(); ++row)
        joints.append({m_rows.at(row).servo, m_rows.at(row).target, targetRange(row)});
    return joints;
}

std::optional<qint64> JointTable::deviceValue(int row, const QString &key) const
{
    const int index = servoIndex(row);
    if (index < 0)
        return std::nullopt;
    return m_client->servos()->parameters(index)->deviceValue(key);
}

bool JointTable::isPositionLive(int row) const
{
    const int index = servoIndex(row);
    if (index < 0 || !m_client->telemetry()->isStreamed(index)
        || !m_client->telemetry()->latestSample(index))
        return false;
    // A servo the stream has given up on keeps its last sample, which is no longer live.
    const Row &entry = m_rows.at(row);
    for (const feetech::ServoTelemetry &servo : m_client->telemetry()->stats().servos) {
        if (feetech::ServoAddress {servo.id, servo.baud} == entry.servo)
            return !servo.missing;
    }
    return true;
}

std::optional<feetech::FeedbackSample> JointTable::sampleSource(int row) const
{
    const int index = servoIndex(row);
    if (index < 0)
        return std::nullopt;
    std::optional<feetech::FeedbackSample> sample = m_client->telemetry()->latestSample(index);
    if (!sample)
        return std::nullopt;
    // A read after the last sample is the newer news, unless the monitor is still streaming.
    if (isPositionLive(row) || m_rows.at(row).sampleNewer || !deviceValue(row, kPresentPosition))
        return sample;
    return std::nullopt;
}

std::optional<qint32> JointTable::position(int row) const
{
    if (const auto sample = sampleSource(row)) {
        if (const auto value = sample->value(feetech::Quantity::Position))
            return qint32(std::lround(*value));
    }
    if (const auto value = deviceValue(row, kPresentPosition))
        return qint32(*value);
    return std::nullopt;
}

std::optional<bool> JointTable::moving(int row) const
{
    if (const auto sample = sampleSource(row))
        return sample->moving;
    if (const auto value = deviceValue(row, kMoving))
        return *value != 0;
    return std::nullopt;
}

std::optional<feetech::PositionRange> JointTable::targetRange(int row) const
{
    const int index = servoIndex(row);
    if (index < 0)
        return std::nullopt;
    return feetech::goalRange(*m_client, index);
}

void JointTable::setTarget(int row, qint32 target)
{
    if (row < 0 || row >= rowCount())
        return;
    m_rows[row].target = target;
    refreshTarget(row);
    refreshButtons();
}

std::optional<qint32> JointTable::target(int row) const
{
    if (row < 0 || row >= rowCount())
        return std::nullopt;
    return m_rows.at(row).target;
}

QString JointTable::message() const
{
    return m_message->text();
}

QString JointTable::servoName(int row) const
{
    const int index = servoIndex(row);
    if (index < 0)
        return tr("ID %1").arg(m_rows.at(row).servo.id);
    // By joint where the arm matches a template ("shoulder_pan (ID 1)"), as the tree says.
    const feetech::JointNames joints = feetech::JointNames::of(*m_client);
    const feetech::ServoInfo &info = m_client->servos()->at(index).info;
    if (!joints.joint(info.address()).isEmpty())
        return joints.label(info.address());
    return tr("ID %1 (%2)").arg(info.id).arg(info.model.name);
}

void JointTable::setMessage(const QString &text, Tone tone)
{
    m_message->setText(text);
    const bool dark = palette::isDark(palette());
    QPalette colours = m_message->palette();
    switch (tone) {
    case Tone::Info:
        m_message->setPalette(QPalette());
        return;
    case Tone::Success:
        colours.setColor(QPalette::WindowText, palette::toneColor(palette::Tone::Good, dark));
        break;
    case Tone::Warning:
        colours.setColor(QPalette::WindowText, palette::toneColor(palette::Tone::Warning, dark));
        break;
    case Tone::Error:
        colours.setColor(QPalette::WindowText, palette::toneColor(palette::Tone::Error, dark));
        break;
    }
    m_message->setPalette(colours);
}

// ---- rows

void JointTable::rebuild()
{
    // Targets belong to servos, not to row numbers: they survive a new scan of the same bus.
    QHash<feetech::ServoAddress, qint32> targets;
    for (const Row &row : std::as_const(m_rows)) {
        if (row.target)
            targets.insert(row.servo, *row.target);
    }
    m_rows.clear();
    for (int index = 0; index < m_client->servos()->count(); ++index) {
        const feetech::ServoInfo &info = m_client->servos()->at(index).info;
        Row row;
        row.servo = info.address();
        if (targets.contains(row.servo))
            row.target = targets.value(row.servo);
        row.modelReadMs = m_client->servos()->parameters(index)->lastReadMs(kPresentPosition);
        m_rows.append(row);
    }
    m_table->resetRows(rowCount());
    for (int row = 0; row < rowCount(); ++row) {
        auto *identify = new QPushButton(tr("Identify"), m_table);
        identify->setObjectName(QStringLiteral("identifyButton"));
        connect(identify, &QPushButton::clicked, this, [this, servo = m_rows.at(row).servo] {
            if (rowOf(servo) < 0 || !confirmIdentify(this, servoName(rowOf(servo))))
                return;
            // The question ran its own event loop: the row is looked up again after it.
            QString error;
            if (!this->identify(rowOf(servo), &error))
                setMessage(error, Tone::Error);
        });
        m_table->setCellWidget(row, JointTableView::IdentifyColumn, identify);
        refreshRow(row);
    }
    refreshHint();
    refreshButtons();
    readWhileShown(false);
}

void JointTable::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (event->spontaneous())
        return; // the window shown again (un-minimised), not the tab opened
    m_readAsked.clear();
    readWhileShown(true);
}

void JointTable::readWhileShown(bool all)
{
    if (!isVisible() || !m_client->link()->isConnected())
        return;
    int asked = 0;
    for (int row = 0; row < rowCount(); ++row) {
        const int index = servoIndex(row);
        const feetech::ServoAddress &servo = m_rows.at(row).servo;
        if (index < 0
            || (!all && (m_client->servos()->at(index).read || m_readAsked.contains(servo))))
            continue;
        m_readAsked.insert(servo);
        m_client->readServo(index);
        ++asked;
    }
    if (asked > 0)
        setMessage(tr("Reading %n servo(s)…", nullptr, asked), Tone::Info);
}

void JointTable::refreshHint()
{
    int live = 0;
    for (int row = 0; row < rowCount(); ++row) {
        if (isPositionLive(row))
            ++live;
    }
    QString text;
    bool offerRead = true;
    if (rowCount() == 0) {
        text = tr("Scan the bus to list its servos here.");
        offerRead = false;
    } else if (!m_client->telemetry()->isStreaming()) {
        text = tr("<b>Live positions:</b> the monitor is not running, so positions are the last "
                  "values read (grey) and may be stale. Start the monitor to see live positions, "
                  "or read them now.");
    } else if (live < rowCount()) {
        text = tr("<b>Live positions</b> from the monitor; servos it does not watch show the "
                  "last value read, in grey.");
    } else {
        text = tr("<b>Live positions</b> from the monitor.");
        offerRead = false;
    }
    // Called for every telemetry batch: only a change is worth a new layout.
    if (m_hint->text() != text)
        m_hint->setText(text);
    if (m_read->isVisibleTo(this) != offerRead)
        m_read->setVisible(offerRead);
}

void JointTable::refreshButtons()
{
    const bool connected = m_client->link()->isConnected();
    const bool rows = rowCount() > 0;
    bool anyTarget = false;
    for (const Row &row : std::as_const(m_rows))
        anyTarget = anyTarget || row.target.has_value();
    m_read->setEnabled(connected && rows);
    m_capture->setEnabled(rows);
    m_moveAll->setEnabled(connected && anyTarget);
    m_poses->updateButtons();
    refreshIdentifyButtons();
}

void JointTable::onTelemetry(const QVector<feetech::FeedbackSample> &samples)
{
    QSet<int> rows;
    for (const feetech::FeedbackSample &sample : samples) {
        const int row = rowOf({sample.id, sample.baud});
        if (row >= 0)
            rows.insert(row);
    }
    for (const int row : std::as_const(rows)) {
        m_rows[row].sampleNewer = true;
        refreshPosition(row);
    }
    refreshHint(); // the first sample of a servo makes its position live
}

void JointTable::onMoveFinished(const feetech::OperationResult &result)
{
    if (m_movesInFlight <= 0)
        return;
    --m_movesInFlight;
    if (!result.ok)
        setMessage(tr("Move all failed: %1").arg(result.message), Tone::Error);
}

void JointTable::onTorqueWritten(const feetech::ServoAddress &servo,
                                 const feetech::OperationResult &result)
{
    const int row = rowOf(servo);
    if (row < 0 || !m_rows.at(row).torqueRequested)
        return;
    const bool requestedOn = *m_rows.at(row).torqueRequested == feetech::TorqueMode::On;
    m_rows[row].torqueRequested.reset();
    // A write the lost link dropped is no failure of the servo's: the window shows the link.
    if (!result.ok && result.failure != feetech::OperationFailure::LinkLost)
        setMessage(tr("%1: torque was not switched %2: %3")
                       .arg(servoName(row), requestedOn ? tr("on") : tr("off"), result.message),
                   Tone::Error);
    refreshRow(row);
}

void JointTable::onTorqueToggled(int row, bool on)
{
    if (row >= rowCount())
        return;
    QString error;
    if (!setTorque(row, on, &error)) {
        setMessage(error, Tone::Error);
        refreshRow(row); // the tick goes back to what the servo reports
    }
}

// ---- cells

void JointTable::refreshRow(int row)
{
    if (row < 0 || row >= rowCount())
        return;
    const int index = servoIndex(row);
    if (index < 0)
        return;
    const feetech::ServoInfo &info = m_client->servos()->at(index).info;
    JointTableView::Torque torque;
    torque.device = deviceValue(row, kTorqueEnable);
    torque.mode = torque.device ? info.table().torqueMode(*torque.device) : std::nullopt;
    Row &state = m_rows[row];
    if (state.torqueRequested && torque.mode == state.torqueRequested)
        state.torqueRequested.reset(); // read back as asked
    torque.requested = state.torqueRequested;
    m_table->showServo(row, info, torque);
    refreshPosition(row);
    refreshTarget(row);
}

void JointTable::refreshPosition(int row)
{
    if (row < 0 || row >= rowCount() || servoIndex(row) < 0)
        return;
    m_table->showPosition(row, position(row), isPositionLive(row), moving(row));
}

void JointTable::refreshTarget(int row)
{
    if (row < 0 || row >= rowCount() || servoIndex(row) < 0)
        return;
    m_table->showTarget(row, targetRange(row), m_rows.at(row).target);
}

// ---- actions

bool JointTable::setTorque(int row, bool on, QString *error)
{
    const int index = servoIndex(row);
    if (index < 0) {
        if (error)
            *error = tr("That servo is no longer on the bus.");
        return false;
    }
    const feetech::TorqueMode mode = on ? feetech::TorqueMode::On : feetech::TorqueMode::Off;
    const auto value = m_client->servos()->at(index).info.table().torqueValue(mode);
    feetech::Refusal refusal;
    feetech::OperationReply *reply =
        value ? m_client->writeValues(index, {{kTorqueEnable, *value}}, &refusal) : nullptr;
    if (!reply) {
        const QString why = value ? refusal.describe() : tr("its model has no torque enable");
        if (error)
            *error = tr("%1: torque not switched %2: %3")
                         .arg(servoName(row), on ? tr("on") : tr("off"), why);
        return false;
    }
    connect(reply, &feetech::OperationReply::finished, this,
            [this, servo = m_rows.at(row).servo](const feetech::OperationResult &result) {
                onTorqueWritten(servo, result);
            });
    m_rows[row].torqueRequested = mode;
    refreshRow(row);
    return true;
}

bool JointTable::moveAll(QString *error)
{
    const auto refuse = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (!m_client->link()->isConnected())
        return refuse(tr("The bus is not connected: nothing was sent."));
    if (rowCount() == 0)
        return refuse(tr("No servos: scan the bus first."));

    QVector<feetech::MoveAllJoint> joints;
    for (int row = 0; row < rowCount(); ++row) {
        const int index = servoIndex(row);
        feetech::MoveAllJoint joint;
        joint.baud = m_rows.at(row).servo.baud;
        joint.known = index >= 0;
        joint.target = m_rows.at(row).target;
        joint.range = targetRange(row);
        joint.mode = deviceValue(row, kMode);
        const auto torque = deviceValue(row, kTorqueEnable);
        joint.torqueOff = index >= 0 && torque
            && m_client->servos()->at(index).info.table().torqueMode(*torque)
                == feetech::TorqueMode::Off;
        joints.append(joint);
    }
    const feetech::MoveAllPlan plan = feetech::planMoveAll(joints);
    const int refused = plan.refusedRow;
    switch (plan.refusal) {
    case feetech::MoveAllPlan::Refusal::None:
        break;
    case feetech::MoveAllPlan::Refusal::NoTarget:
        return refuse(tr("%1 has no target: type one, load a pose or use “Targets from "
                         "present positions”. Nothing was sent.")
                          .arg(servoName(refused)));
    case feetech::MoveAllPlan::Refusal::OutOfRange:
        return refuse(tr("%1: the target %2 is outside its range %3 to %4. Nothing was "
                         "sent.")
                          .arg(servoName(refused))
                          .arg(*joints.at(refused).target)
                          .arg(joints.at(refused).range->minimum)
                          .arg(joints.at(refused).range->maximum));
    case feetech::MoveAllPlan::Refusal::NotPositionMode: {
        const qint64 mode = *joints.at(refused).mode;
        const feetech::Register *reg =
            m_client->servos()->at(servoIndex(refused)).info.table().find(kMode);
        return refuse(
            tr("%1 is in %2 mode; a goal position only moves a servo in position "
               "mode. Nothing was sent.")
                .arg(servoName(refused),
                     reg ? feetech::displayValue(*reg, qint32(mode)) : QString::number(mode)));
    }
    case feetech::MoveAllPlan::Refusal::NothingMovable:
        return refuse(tr("No servo here can be moved: their models are unknown."));
    }

    QVector<feetech::BusClient::Goal> goals;
    QStringList ids;
    for (const int row : plan.rows) {
        goals.append({servoIndex(row), *m_rows.at(row).target});
        ids.append(QString::number(m_rows.at(row).servo.id));
    }
    feetech::Refusal refusal;
    const QVector<feetech::OperationReply *> replies = m_client->moveAll(goals, &refusal);
    if (replies.isEmpty())
        return refuse(tr("Nothing was sent: %1").arg(refusal.describe()));
    m_movesInFlight += int(replies.size());
    for (feetech::OperationReply *reply : replies)
        connect(reply, &feetech::OperationReply::finished, this, &JointTable::onMoveFinished);

    const auto names = [this](const QVector<int> &rows) {
        QStringList names;
        for (const int row : rows)
            names.append(servoName(row));
        return names.join(tr(", "));
    };
    QStringList report;
    report.append(plan.syncWrites == 1
                      ? tr("Targets sent to IDs %1 in one SYNC WRITE.").arg(ids.join(tr(", ")))
                      : tr("Targets sent to IDs %1 in %2 SYNC WRITEs, one per baud rate.")
                            .arg(ids.join(tr(", ")))
                            .arg(plan.syncWrites));
    if (!plan.torqueOff.isEmpty())
        report.append(tr("Torque is off on %1: it will not move until torque is on.")
                          .arg(names(plan.torqueOff)));
    if (!plan.skipped.isEmpty())
        report.append(tr("Not moved (unknown model): %1.").arg(names(plan.skipped)));
    setMessage(report.join(u' '),
               plan.torqueOff.isEmpty() && plan.skipped.isEmpty() ? Tone::Success : Tone::Warning);
    return true;
}

bool JointTable::readPositions(QString *error)
{
    if (!m_client->link()->isConnected()) {
        if (error)
            *error = tr("The bus is not connected.");
        return false;
    }
    if (rowCount() == 0) {
        if (error)
            *error = tr("No servos: scan the bus first.");
        return false;
    }
    for (int row = 0; row < rowCount(); ++row) {
        const int index = servoIndex(row);
        if (index >= 0)
            m_client->readServo(index);
    }
    setMessage(tr("Reading %1 servos…").arg(rowCount()), Tone::Info);
    return true;
}

bool JointTable::identify(int row, QString *error)
{
    const int index = servoIndex(row);
    if (index < 0) {
        if (error)
            *error = tr("That servo is no longer on the bus.");
        return false;
    }
    feetech::Refusal refusal;
    if (!m_client->identify()->start(index, &refusal)) {
        if (error)
            *error = tr("%1 cannot be identified now: %2").arg(servoName(row), refusal.describe());
        return false;
    }
    setMessage(tr("Identifying %1: watch which horn moves…").arg(servoName(row)), Tone::Info);
    return true;
}

QPushButton *JointTable::identifyButton(int row) const
{
    return qobject_cast<QPushButton *>(m_table->cellWidget(row, JointTableView::IdentifyColumn));
}

void JointTable::refreshIdentifyButtons()
{
    for (int row = 0; row < rowCount(); ++row) {
        QPushButton *button = identifyButton(row);
        if (!button)
            continue;
        const QString why = m_client->identify()->blocker(servoIndex(row)).describe();
        button->setEnabled(why.isEmpty());
        button->setToolTip(why.isEmpty() ? tr("Wiggle %1 slowly with little torque, then put it "
                                              "back as it was")
                                               .arg(servoName(row))
                                         : why);
    }
}

void JointTable::onMoveAllClicked()
{
    QString error;
    if (!moveAll(&error))
        setMessage(error, Tone::Error);
}

void JointTable::onReadClicked()
{
    QString error;
    if (!readPositions(&error))
        setMessage(error, Tone::Error);
}

int JointTable::capturePositions()
{
    int filled = 0;
    QStringList missing;
    for (int row = 0; row < rowCount(); ++row) {
        if (!targetRange(row))
            continue; // a servo that cannot be moved needs no target
        if (const std::optional<qint32> value = position(row)) {
            setTarget(row, *value);
            ++filled;
        } else {
            missing.append(servoName(row));
        }
    }
    if (missing.isEmpty())
        setMessage(tr("Targets set to the present positions of %1 servos.").arg(filled),
                   Tone::Success);
    else
        setMessage(tr("Targets set for %1 servos. No position is known yet for %2: read the "
                      "positions first.")
                       .arg(filled)
                       .arg(missing.join(tr(", "))),
                   Tone::Warning);
    return filled;
}

void JointTable::onCaptureClicked()
{
    capturePositions();
}
