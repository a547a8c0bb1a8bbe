// Joint table: rows kept in step with the bus client and the monitor; the cells of a row are
// drawn in jointtablecells.cpp, Move all, torque and reads are in jointtableactions.cpp, poses in
// jointtableposes.cpp.
#include "jointtable.h"

#include "busclient.h"
#include "palette.h"
#include "registerkeys.h"
#include "servoparameters.h"
#include "targetdelegate.h"
#include "widgethelpers.h"

#include <QDir>
#include <QHBoxLayout>
#include <QHash>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSet>
#include <QShowEvent>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

using namespace feetech::registerkeys;
using widgethelpers::actionButton;

namespace {

quint64 servoKey(quint8 id, qint32 baud)
{
    return (quint64(quint32(baud)) << 8) | id;
}

} // namespace

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
    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setObjectName(QStringLiteral("jointTableView"));
    m_table->setHorizontalHeaderLabels(
        {tr("ID"), tr("Model"), tr("Baud rate"), tr("Position (steps)"), tr("Target (steps)"),
         tr("Target range"), tr("Torque"), tr("Motion"), tr("Identify")});
    const auto headerTip = [this](int column, const QString &tip) {
        m_table->horizontalHeaderItem(column)->setToolTip(tip);
    };
    headerTip(PositionColumn,
              tr("Present position: live while the monitor watches the servo, otherwise the "
                 "last value read (grey)"));
    headerTip(TargetColumn,
              tr("Where Move all sends the servo: double-click or type to change it"));
    headerTip(RangeColumn,
              tr("The servo's angle limits, or the goal register's range when the limits are "
                 "unknown or both 0"));
    headerTip(TorqueColumn, tr("Tick to switch torque on, untick to switch it off"));
    headerTip(MovingColumn, tr("Whether the servo reports that it is moving"));
    headerTip(IdentifyColumn,
              tr("Wiggle the servo slowly with little torque, then put it back as it was: see "
                 "which servo of the arm it is"));
    m_table->setItemDelegateForColumn(TargetColumn, new TargetDelegate(m_table));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                             | QAbstractItemView::AnyKeyPressed);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->setWordWrap(false);
    QHeaderView *header = m_table->horizontalHeader();
    header->setHighlightSections(false);
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->setStretchLastSection(true);
    // In character widths, so every column fits beside the servo tree at any font size.
    const int ems[ColumnCount] = {3, 7, 7, 10, 9, 9, 8, 6, 6};
    const int em = m_table->fontMetrics().horizontalAdvance(u'm');
    for (int column = 0; column < ColumnCount; ++column)
        m_table->setColumnWidth(column, ems[column] * em);
    layout->addWidget(m_table, 1);

    // ---- actions
    auto *actions = new QHBoxLayout;
    m_capture = actionButton(tr("Targets from present positions"), "captureButton",
                             tr("Copy every servo's present position into its target"), this);
    m_load =
        actionButton(tr("Load pose…"), "loadPoseButton",
                     tr("Fill the targets from a pose file; nothing moves until Move all"), this);
    m_save = actionButton(tr("Save pose…"), "savePoseButton", tr("Save the targets as a pose file"),
                          this);
    m_poseLabel = new QLabel(this);
    m_poseLabel->setObjectName(QStringLiteral("poseLabel"));
    m_poseLabel->setForegroundRole(QPalette::PlaceholderText);
    m_moveAll = actionButton(tr("Move all"), "moveAllButton",
                             tr("Send every target at once: one SYNC WRITE per baud rate"), this);
    m_moveAll->setMinimumWidth(140);
    QFont bold = m_moveAll->font();
    bold.setBold(true);
    m_moveAll->setFont(bold);
    actions->addWidget(m_capture);
    actions->addWidget(m_load);
    actions->addWidget(m_save);
    actions->addSpacing(12);
    actions->addWidget(m_poseLabel);
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
    connect(m_load, &QPushButton::clicked, this, &JointTable::onLoadClicked);
    connect(m_save, &QPushButton::clicked, this, &JointTable::onSaveClicked);
    connect(m_moveAll, &QPushButton::clicked, this, &JointTable::onMoveAllClicked);
    connect(m_table, &QTableWidget::itemChanged, this, &JointTable::onItemChanged);

    connect(m_client, &feetech::BusClient::servosChanged, this, &JointTable::rebuild);
    connect(m_client, &feetech::BusClient::servoUpdated, this, [this](int index) {
        if (index < 0 || index >= m_client->servoCount())
            return;
        const feetech::ServoInfo &info = m_client->servo(index).info;
        const int row = rowOf(info.id, info.baud);
        if (row < 0)
            return;
        const qint64 readMs = m_client->parameters(index)->lastReadMs(kPresentPosition);
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
        if (!m_client->isConnected())
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

int JointTable::rowOf(quint8 id, qint32 baud) const
{
    for (int row = 0; row < rowCount(); ++row) {
        if (m_rows.at(row).id == id && m_rows.at(row).baud == baud)
            return row;
    }
    return -1;
}

int JointTable::servoIndex(int row) const
{
    if (row < 0 || row >= rowCount())
        return -1;
    return m_client->indexOf(m_rows.at(row).id, m_rows.at(row).baud);
}

std::optional<qint64> JointTable::deviceValue(int row, const QString &key) const
{
    const int index = servoIndex(row);
    if (index < 0)
        return std::nullopt;
    return m_client->parameters(index)->deviceValue(key);
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
        if (servo.id == entry.id && servo.baud == entry.baud)
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
        return tr("ID %1").arg(m_rows.at(row).id);
    return tr("ID %1 (%2)").arg(m_rows.at(row).id).arg(m_client->servo(index).info.model.name);
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
    QHash<quint64, qint32> targets;
    for (const Row &row : std::as_const(m_rows)) {
        if (row.target)
            targets.insert(servoKey(row.id, row.baud), *row.target);
    }
    m_rows.clear();
    const QSignalBlocker blocker(m_table);
    m_table->setRowCount(0);
    for (int index = 0; index < m_client->servoCount(); ++index) {
        const feetech::ServoInfo &info = m_client->servo(index).info;
        Row row;
        row.id = info.id;
        row.baud = info.baud;
        const quint64 key = servoKey(info.id, info.baud);
        if (targets.contains(key))
            row.target = targets.value(key);
        row.modelReadMs = m_client->parameters(index)->lastReadMs(kPresentPosition);
        m_rows.append(row);
    }
    m_table->setRowCount(rowCount());
    for (int row = 0; row < rowCount(); ++row) {
        for (int column = 0; column < ColumnCount; ++column) {
            auto *item = new QTableWidgetItem;
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
            if (column == PositionColumn || column == TargetColumn)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(row, column, item);
        }
        auto *identify = new QPushButton(tr("Identify"), m_table);
        identify->setObjectName(QStringLiteral("identifyButton"));
        connect(identify, &QPushButton::clicked, this,
                [this, id = m_rows.at(row).id, baud = m_rows.at(row).baud] {
                    QString error;
                    if (!this->identify(rowOf(id, baud), &error))
                        setMessage(error, Tone::Error);
                });
        m_table->setCellWidget(row, IdentifyColumn, identify);
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
    if (!isVisible() || !m_client->isConnected())
        return;
    int asked = 0;
    for (int row = 0; row < rowCount(); ++row) {
        const int index = servoIndex(row);
        const quint64 key = servoKey(m_rows.at(row).id, m_rows.at(row).baud);
        if (index < 0 || (!all && (m_client->servo(index).read || m_readAsked.contains(key))))
            continue;
        m_readAsked.insert(key);
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
    const bool connected = m_client->isConnected();
    const bool rows = rowCount() > 0;
    bool anyTarget = false;
    for (const Row &row : std::as_const(m_rows))
        anyTarget = anyTarget || row.target.has_value();
    m_read->setEnabled(connected && rows);
    m_capture->setEnabled(rows);
    m_load->setEnabled(rows);
    m_save->setEnabled(anyTarget);
    m_moveAll->setEnabled(connected && anyTarget);
    m_poseLabel->setText(m_poseName.isEmpty() ? QString() : tr("Pose: %1").arg(m_poseName));
    refreshIdentifyButtons();
}

void JointTable::onTelemetry(const QVector<feetech::FeedbackSample> &samples)
{
    QSet<int> rows;
    for (const feetech::FeedbackSample &sample : samples) {
        const int row = rowOf(sample.id, sample.baud);
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

void JointTable::onTorqueWritten(quint8 id, qint32 baud, const feetech::OperationResult &result)
{
    const int row = rowOf(id, baud);
    if (row < 0 || !m_rows.at(row).torqueRequested)
        return;
    const bool requestedOn = *m_rows.at(row).torqueRequested == feetech::TorqueMode::On;
    m_rows[row].torqueRequested.reset();
    if (!result.ok)
        setMessage(tr("%1: torque was not switched %2: %3")
                       .arg(servoName(row), requestedOn ? tr("on") : tr("off"), result.message),
                   Tone::Error);
    refreshRow(row);
}

void JointTable::onItemChanged(QTableWidgetItem *item)
{
    if (m_updating)
        return;
    const int row = item->row();
    if (row < 0 || row >= rowCount())
        return;
    if (item->column() == TargetColumn) {
        const QVariant value = item->data(Qt::EditRole);
        if (value.isValid())
            setTarget(row, value.toInt());
        return;
    }
    if (item->column() == TorqueColumn) {
        // A damping servo (partly ticked) ticked again means "on".
        const bool on = item->checkState() != Qt::Unchecked;
        QString error;
        if (!setTorque(row, on, &error)) {
            setMessage(error, Tone::Error);
            refreshRow(row); // the tick goes back to what the servo reports
        }
    }
}
