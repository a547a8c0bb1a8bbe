// The Monitor page: stream controls, the live plot, readouts refreshed on a timer rather than per
// sample, and CSV recording through a buffered stream flushed twice a second.
#include "feetechgui/monitorpage.h"

#include "common/widgethelpers.h"
#include "feetech/busclient.h"
#include "feetechgui/telemetryplot.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QStandardPaths>
#include <QStyle>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

using widgethelpers::actionButton;

namespace {

constexpr int kIdRole = Qt::UserRole + 1;
constexpr int kBaudRole = Qt::UserRole + 2;
constexpr int kIndexRole = Qt::UserRole + 3;

constexpr double kRates[] = {1, 5, 10, 20, 50, 100, 200};
constexpr double kDefaultRate = 50;
constexpr int kWindows[] = {5, 10, 30, 60, 120};
constexpr int kDefaultWindow = 10;
constexpr int kControlsWidth = 250;
// Per-servo samples per second are counted over this span.
constexpr qint64 kRateSpanUs = 1000000;

const QColor kProblemColour(0xc0, 0x1c, 0x1c);

// Decimals worth showing for each quantity, in its unit.
int decimals(feetech::Quantity quantity)
{
    switch (quantity) {
    case feetech::Quantity::Load:
    case feetech::Quantity::Voltage:
        return 1;
    default:
        return 0;
    }
}

} // namespace

MonitorPage::MonitorPage(feetech::BusClient *client, QWidget *parent)
    : QWidget(parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("monitorPage"));
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);

    // ---- left: what to stream and how to show it, in a scroll area for short windows
    auto *scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("monitorControls"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFixedWidth(kControlsWidth);
    auto *controls = new QWidget(scroll);
    auto *controlsLayout = new QVBoxLayout(controls);
    controlsLayout->setContentsMargins(0, 0, 6, 0);
    scroll->setWidget(controls);
    layout->addWidget(scroll);

    auto *servoGroup = new QGroupBox(tr("Servos"), controls);
    auto *servoLayout = new QVBoxLayout(servoGroup);
    m_servoList = new QListWidget(servoGroup);
    m_servoList->setObjectName(QStringLiteral("monitorServoList"));
    m_servoList->setToolTip(tr("The servos to stream; ticking or unticking one while streaming "
                               "restarts the stream"));
    m_servoList->setMinimumHeight(m_servoList->fontMetrics().height() * 6);
    connect(m_servoList, &QListWidget::itemChanged, this, &MonitorPage::onServoItemChanged);
    servoLayout->addWidget(m_servoList);
    controlsLayout->addWidget(servoGroup, 1);

    auto *quantityGroup = new QGroupBox(tr("Plot"), controls);
    auto *quantityLayout = new QGridLayout(quantityGroup);
    for (int q = 0; q < feetech::kQuantityCount; ++q) {
        const feetech::Quantity quantity = feetech::kAllQuantities[q];
        auto *check = new QCheckBox(feetech::quantityName(quantity), quantityGroup);
        check->setObjectName(QStringLiteral("plot_%1").arg(feetech::quantityKey(quantity)));
        check->setToolTip(
            tr("Plot the %1 in %2")
                .arg(feetech::quantityName(quantity).toLower(), feetech::quantityUnit(quantity)));
        check->setChecked(quantity == feetech::Quantity::Position
                          || quantity == feetech::Quantity::Speed
                          || quantity == feetech::Quantity::Load);
        connect(check, &QCheckBox::toggled, this, &MonitorPage::onQuantityToggled);
        quantityLayout->addWidget(check, q / 2, q % 2);
        m_quantityChecks.append(check);
    }
    controlsLayout->addWidget(quantityGroup);

    auto *streamGroup = new QGroupBox(tr("Stream"), controls);
    auto *streamLayout = new QFormLayout(streamGroup);
    m_rateCombo = new QComboBox(streamGroup);
    m_rateCombo->setObjectName(QStringLiteral("monitorRateCombo"));
    m_rateCombo->setToolTip(tr("Samples per second for each servo"));
    for (const double rate : kRates)
        m_rateCombo->addItem(tr("%1 Hz").arg(rate), rate);
    m_rateCombo->addItem(tr("As fast as the bus allows"), 0.0);
    m_rateCombo->setCurrentIndex(m_rateCombo->findData(kDefaultRate));
    connect(m_rateCombo, &QComboBox::activated, this, &MonitorPage::onRateChosen);
    streamLayout->addRow(tr("Rate:"), m_rateCombo);
    m_startButton =
        actionButton(tr("Start"), "monitorStartButton",
                     tr("Start or stop streaming the ticked servos' feedback"), streamGroup);
    QFont bold = m_startButton->font();
    bold.setBold(true);
    m_startButton->setFont(bold);
    connect(m_startButton, &QPushButton::clicked, this, &MonitorPage::toggleStream);
    streamLayout->addRow(m_startButton);
    controlsLayout->addWidget(streamGroup);

    auto *viewGroup = new QGroupBox(tr("View"), controls);
    auto *viewLayout = new QFormLayout(viewGroup);
    m_windowCombo = new QComboBox(viewGroup);
    m_windowCombo->setObjectName(QStringLiteral("monitorWindowCombo"));
    m_windowCombo->setToolTip(tr("How many seconds of history the plot shows"));
    for (const int seconds : kWindows)
        m_windowCombo->addItem(tr("%1 s").arg(seconds), seconds);
    m_windowCombo->setCurrentIndex(m_windowCombo->findData(kDefaultWindow));
    connect(m_windowCombo, &QComboBox::activated, this, &MonitorPage::onWindowChosen);
    viewLayout->addRow(tr("Window:"), m_windowCombo);
    m_pauseButton =
        actionButton(tr("Pause"), "monitorPauseButton",
                     tr("Freeze the plot; samples are still received and recorded"), viewGroup);
    m_pauseButton->setIcon(style()->standardIcon(QStyle::SP_MediaPause));
    connect(m_pauseButton, &QPushButton::clicked, this, &MonitorPage::togglePause);
    m_resetZoomButton = actionButton(tr("Reset zoom"), "monitorResetZoomButton",
                                     tr("Back to the live view over the whole window"), viewGroup);
    connect(m_resetZoomButton, &QPushButton::clicked, this, [this] { m_plot->resetZoom(); });
    auto *viewButtons = new QHBoxLayout;
    viewButtons->addWidget(m_pauseButton);
    viewButtons->addWidget(m_resetZoomButton);
    viewLayout->addRow(viewButtons);
    m_exportButton =
        actionButton(tr("Export PNG…"), "monitorExportButton",
                     tr("Save the charts as they are shown as one PNG image"), viewGroup);
    connect(m_exportButton, &QPushButton::clicked, this, &MonitorPage::chooseExportFile);
    viewLayout->addRow(m_exportButton);
    controlsLayout->addWidget(viewGroup);

    auto *recordGroup = new QGroupBox(tr("Recording"), controls);
    auto *recordLayout = new QVBoxLayout(recordGroup);
    m_recordButton =
        actionButton(tr("Record CSV…"), "monitorRecordButton",
                     tr("Write every sample of the ticked servos to a CSV file"), recordGroup);
    connect(m_recordButton, &QPushButton::clicked, this, &MonitorPage::toggleRecording);
    recordLayout->addWidget(m_recordButton);
    m_recordingLabel = new QLabel(recordGroup);
    m_recordingLabel->setObjectName(QStringLiteral("monitorRecordingLabel"));
    m_recordingLabel->setWordWrap(true);
    m_recordingLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    recordLayout->addWidget(m_recordingLabel);
    controlsLayout->addWidget(recordGroup);

    m_message = new QLabel(controls);
    m_message->setObjectName(QStringLiteral("monitorMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message->hide();
    controlsLayout->addWidget(m_message);

    // ---- right: plots over readouts, the stream's health below
    auto *right = new QWidget(this);
    auto *rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(6, 0, 0, 0);
    auto *splitter = new QSplitter(Qt::Vertical, right);
    splitter->setChildrenCollapsible(false);
    m_plot = new TelemetryPlot(splitter);
    m_plot->setWindowSeconds(kDefaultWindow);
    connect(m_plot, &TelemetryPlot::pausedChanged, this, &MonitorPage::updateControls);
    connect(m_plot, &TelemetryPlot::zoomedChanged, this, &MonitorPage::updateControls);
    splitter->addWidget(m_plot);

    m_readouts = new QTableWidget(0, ReadoutColumns, splitter);
    m_readouts->setObjectName(QStringLiteral("monitorReadouts"));
    QStringList headers {tr("Servo")};
    for (const feetech::Quantity quantity : feetech::kAllQuantities) {
        headers.append(
            tr("%1 (%2)").arg(feetech::quantityName(quantity), feetech::quantityUnit(quantity)));
    }
    headers << tr("Moving") << tr("Status") << tr("Samples/s") << tr("Missed") << tr("State");
    m_readouts->setHorizontalHeaderLabels(headers);
    m_readouts->horizontalHeaderItem(StatusColumn)
        ->setToolTip(tr("The servo's protection bits that tripped (register 65)"));
    m_readouts->horizontalHeaderItem(MissedColumn)
        ->setToolTip(tr("Cycles in which the servo was asked and did not answer"));
    m_readouts->verticalHeader()->hide();
    m_readouts->verticalHeader()->setDefaultSectionSize(m_readouts->fontMetrics().height() + 6);
    m_readouts->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_readouts->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_readouts->setAlternatingRowColors(true);
    m_readouts->setWordWrap(false);
    m_readouts->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_readouts->horizontalHeader()->setSectionResizeMode(StatusColumn, QHeaderView::Stretch);
    splitter->addWidget(m_readouts);
    splitter->setStretchFactor(0, 4);
    splitter->setStretchFactor(1, 1);
    rightLayout->addWidget(splitter, 1);

    m_statusLine = new QLabel(right);
    m_statusLine->setObjectName(QStringLiteral("monitorStatus"));
    m_statusLine->setTextInteractionFlags(Qt::TextSelectableByMouse);
    rightLayout->addWidget(m_statusLine);
    layout->addWidget(right, 1);

    m_readoutTimer = new QTimer(this);
    m_readoutTimer->setInterval(kReadoutIntervalMs);
    connect(m_readoutTimer, &QTimer::timeout, this, [this] {
        if (m_readoutsDirty || isRunning())
            updateReadouts(); // samples/s falls when a servo stops answering: recount
    });
    m_recorder = new feetech::TelemetryRecorder(this);
    m_recorder->setFlushInterval(kFlushIntervalMs);
    connect(m_recorder, &feetech::TelemetryRecorder::flushed, this,
            &MonitorPage::updateRecordingLabel);
    connect(m_recorder, &feetech::TelemetryRecorder::failed, this, &MonitorPage::failRecording);

    if (m_client) {
        connect(m_client, &feetech::BusClient::servosChanged, this, &MonitorPage::rebuildServoList);
        connect(m_client, &feetech::BusClient::telemetryReceived, this, &MonitorPage::addSamples);
        connect(m_client, &feetech::BusClient::telemetryStatsChanged, this,
                &MonitorPage::onStatsChanged);
        connect(m_client, &feetech::BusClient::monitoringChanged, this,
                &MonitorPage::onMonitoringChanged);
        connect(m_client, &feetech::BusClient::statusChanged, this, &MonitorPage::onStatusChanged);
    }
    onQuantityToggled();
    rebuildServoList();
    updateRecordingLabel();
}

MonitorPage::~MonitorPage()
{
    stopRecording(); // what was buffered reaches the disk
}

void MonitorPage::setSelectedServos(const QVector<int> &indexes)
{
    m_updatingList = true;
    for (int row = 0; row < m_servoList->count(); ++row) {
        QListWidgetItem *item = m_servoList->item(row);
        if (item->flags() & Qt::ItemIsUserCheckable) {
            item->setCheckState(indexes.contains(item->data(kIndexRole).toInt()) ? Qt::Checked
                                                                                 : Qt::Unchecked);
        }
    }
    m_updatingList = false;
    onServoItemChanged();
}

QVector<int> MonitorPage::selectedServos() const
{
    QVector<int> indexes;
    for (int row = 0; row < m_servoList->count(); ++row) {
        const QListWidgetItem *item = m_servoList->item(row);
        if (item->checkState() == Qt::Checked)
            indexes.append(item->data(kIndexRole).toInt());
    }
    return indexes;
}

void MonitorPage::setQuantities(const QVector<feetech::Quantity> &quantities)
{
    for (int q = 0; q < feetech::kQuantityCount; ++q) {
        const QSignalBlocker blocker(m_quantityChecks.at(q));
        m_quantityChecks.at(q)->setChecked(quantities.contains(feetech::kAllQuantities[q]));
    }
    onQuantityToggled();
}

QVector<feetech::Quantity> MonitorPage::quantities() const
{
    QVector<feetech::Quantity> chosen;
    for (int q = 0; q < feetech::kQuantityCount; ++q) {
        if (m_quantityChecks.at(q)->isChecked())
            chosen.append(feetech::kAllQuantities[q]);
    }
    return chosen;
}

void MonitorPage::setRate(double rateHz)
{
    // The closest rate offered: the combo box shows what is asked of the bus.
    int best = 0;
    for (int i = 1; i < m_rateCombo->count(); ++i) {
        if (std::abs(m_rateCombo->itemData(i).toDouble() - rateHz)
            < std::abs(m_rateCombo->itemData(best).toDouble() - rateHz))
            best = i;
    }
    if (best == m_rateCombo->currentIndex())
        return;
    m_rateCombo->setCurrentIndex(best);
    onRateChosen();
}

double MonitorPage::rate() const
{
    return m_rateCombo->currentData().toDouble();
}

void MonitorPage::setWindowSeconds(double seconds)
{
    int best = 0;
    for (int i = 1; i < m_windowCombo->count(); ++i) {
        if (std::abs(m_windowCombo->itemData(i).toDouble() - seconds)
            < std::abs(m_windowCombo->itemData(best).toDouble() - seconds))
            best = i;
    }
    m_windowCombo->setCurrentIndex(best);
    onWindowChosen();
}

bool MonitorPage::start(QString *error)
{
    QString why;
    if (!m_client) {
        why = tr("There is no bus to monitor.");
    } else if (selectedServos().isEmpty()) {
        why = tr("Tick at least one servo to monitor.");
    } else {
        const bool fresh = !m_client->isMonitoring();
        if (m_client->startMonitor(selectedServos(), rate(), &why)) {
            if (fresh) {
                // A new run starts a new time line (its samples come later, queued); a
                // restart keeps the present one going.
                m_plot->clear();
                m_latest.clear();
                m_unlisted.clear();
                m_stats = {};
                m_readoutsDirty = true;
            }
            showMessage({}, false);
            updatePlotServos();
            updateControls();
            updateStatusLine();
            return true;
        }
    }
    if (error)
        *error = why;
    showMessage(tr("Monitoring did not start: %1").arg(why), true);
    emit problem(why);
    updateControls();
    return false;
}

void MonitorPage::stop()
{
    stopRecording();
    if (m_client && m_client->isMonitoring())
        m_client->stopMonitor();
    updateControls();
    updateStatusLine();
}

bool MonitorPage::isRunning() const
{
    return m_client && m_client->isMonitoring();
}

bool MonitorPage::startRecording(const QString &path, QString *error)
{
    stopRecording();
    // A header that could not be written goes through failRecording(), which says why; a file
    // that could not be opened is said here.
    bool reported = false;
    const QMetaObject::Connection watch = connect(m_recorder, &feetech::TelemetryRecorder::failed,
                                                  this, [&reported] { reported = true; });
    QString why;
    const bool opened = m_recorder->open(path, &why);
    disconnect(watch);
    if (!opened) {
        if (reported)
            why = m_message->text();
        else
            showMessage(why, true);
        if (error)
            *error = why;
        return false;
    }
    showMessage({}, false);
    updateRecordingLabel();
    updateControls();
    emit recordingChanged(true);
    return true;
}

void MonitorPage::stopRecording()
{
    if (!isRecording())
        return;
    if (!m_recorder->finish())
        return; // failRecording() has said why and closed it
    const QString path = m_recorder->fileName();
    m_recordingLabel->setText(tr("%Ln row(s) saved to %1.", nullptr, int(recordedRows()))
                                  .arg(QFileInfo(path).fileName()));
    m_recordingLabel->setToolTip(QDir::toNativeSeparators(path));
    updateControls();
    emit recordingChanged(false);
}

bool MonitorPage::exportPng(const QString &path, QString *error)
{
    QString why;
    if (m_plot->exportPng(path, &why)) {
        showMessage(tr("Plot saved to %1.").arg(QDir::toNativeSeparators(path)), false);
        return true;
    }
    if (error)
        *error = why;
    showMessage(why, true);
    return false;
}

void MonitorPage::addSamples(const QVector<feetech::FeedbackSample> &samples)
{
    // Ticked or not, for each servo the list names.
    QHash<Key, bool> listed;
    for (int row = 0; row < m_servoList->count(); ++row) {
        const QListWidgetItem *item = m_servoList->item(row);
        if (item->flags() & Qt::ItemIsUserCheckable) {
            listed.insert(Key {quint8(item->data(kIdRole).toInt()), item->data(kBaudRole).toInt()},
                          item->checkState() == Qt::Checked);
        }
    }
    QVector<feetech::FeedbackSample> kept;
    kept.reserve(samples.size());
    for (const feetech::FeedbackSample &sample : samples) {
        const Key key {sample.id, sample.baud};
        // A batch still in flight when a servo was unticked is not shown or recorded; a servo
        // the list does not name (samples fed from elsewhere) is.
        const auto entry = listed.constFind(key);
        if (entry != listed.constEnd() && !entry.value())
            continue;
        if (entry == listed.constEnd() && !m_unlisted.contains(key))
            m_unlisted.append(key);
        Latest &latest = m_latest[key];
        if (sample.steadyUs >= latest.sample.steadyUs)
            latest.sample = sample;
        latest.recent.push_back(sample.steadyUs);
        while (!latest.recent.empty() && latest.recent.front() <= sample.steadyUs - kRateSpanUs)
            latest.recent.pop_front();
        kept.append(sample);
        m_recorder->write(sample); // from its start on
    }
    if (kept.isEmpty())
        return;
    m_plot->addSamples(kept);
    m_readoutsDirty = true;
}

void MonitorPage::updateReadouts()
{
    m_readoutsDirty = false;
    const QVector<Key> keys = readoutKeys();
    if (m_readouts->rowCount() != keys.size())
        m_readouts->setRowCount(int(keys.size()));
    const qint64 now = feetech::steadyMicroseconds();
    const QLocale locale;
    const QString none = tr("—");
    for (int row = 0; row < keys.size(); ++row) {
        const Key &key = keys.at(row);
        const auto latest = m_latest.find(key);
        const feetech::FeedbackSample *sample =
            latest != m_latest.end() && latest->sample.steadyUs != 0 ? &latest->sample : nullptr;
        const feetech::ServoTelemetry *health = nullptr;
        for (const feetech::ServoTelemetry &servo : std::as_const(m_stats.servos)) {
            if (servo.id == key.id && servo.baud == key.baud)
                health = &servo;
        }

        QStringList cells(ReadoutColumns);
        cells[ServoColumn] = tr("ID %1").arg(key.id);
        for (int q = 0; q < feetech::kQuantityCount; ++q) {
            const auto value = sample ? sample->values.at(std::size_t(q)) : std::nullopt;
            cells[PositionColumn + q] =
                value ? locale.toString(*value, 'f', decimals(feetech::kAllQuantities[q])) : none;
        }
        cells[MovingColumn] = sample ? (sample->moving ? tr("yes") : tr("no")) : none;
        cells[StatusColumn] = sample ? statusText(key, sample->servoStatus) : none;
        if (latest != m_latest.end() && isRunning()) {
            while (!latest->recent.empty() && latest->recent.front() <= now - kRateSpanUs)
                latest->recent.pop_front();
            cells[RateColumn] = locale.toString(qint64(latest->recent.size()));
        } else {
            cells[RateColumn] = none;
        }
        cells[MissedColumn] = health ? locale.toString(health->missed) : none;
        bool missing = false;
        if (health && health->missing) {
            cells[StateColumn] = tr("Not answering");
            missing = true;
        } else if (!isRunning()) {
            cells[StateColumn] = sample ? tr("Stopped") : none;
        } else if (!sample) {
            cells[StateColumn] = tr("Waiting");
        } else {
            cells[StateColumn] = tr("OK");
        }

        for (int column = 0; column < ReadoutColumns; ++column) {
            QTableWidgetItem *item = m_readouts->item(row, column);
            if (!item) {
                item = new QTableWidgetItem;
                const bool text = column == ServoColumn || column == StatusColumn
                    || column == StateColumn || column == MovingColumn;
                item->setTextAlignment(Qt::Alignment(text ? Qt::AlignLeft : Qt::AlignRight)
                                       | Qt::AlignVCenter);
                m_readouts->setItem(row, column, item);
            }
            if (item->text() != cells.at(column))
                item->setText(cells.at(column));
        }
        // A tripped protection bit or a servo that stopped answering must catch the eye.
        const bool tripped = sample && sample->servoStatus != 0;
        QTableWidgetItem *status = m_readouts->item(row, StatusColumn);
        status->setForeground(tripped ? QBrush(kProblemColour) : QBrush());
        QTableWidgetItem *state = m_readouts->item(row, StateColumn);
        state->setForeground(missing ? QBrush(kProblemColour) : QBrush());
        QFont font = state->font();
        font.setBold(missing);
        state->setFont(font);
        QTableWidgetItem *servo = m_readouts->item(row, ServoColumn);
        servo->setForeground(m_plot->servoColor(key.id, key.baud).isValid()
                                 ? QBrush(m_plot->servoColor(key.id, key.baud))
                                 : QBrush());
        servo->setBackground(missing ? QBrush(QColor(0xfd, 0xe2, 0xe2)) : QBrush());
        servo->setToolTip(tr("ID %1 at %2").arg(key.id).arg(feetech::baudText(key.baud)));
    }
    updateStatusLine();
}

void MonitorPage::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    m_readoutTimer->start();
    updateReadouts();
}

void MonitorPage::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    m_readoutTimer->stop();
}

void MonitorPage::rebuildServoList()
{
    // Ticks survive a rescan by ID and baud rate; servos new to the list come ticked.
    QHash<Key, bool> previous;
    for (int row = 0; row < m_servoList->count(); ++row) {
        const QListWidgetItem *item = m_servoList->item(row);
        previous.insert(Key {quint8(item->data(kIdRole).toInt()), item->data(kBaudRole).toInt()},
                        item->checkState() == Qt::Checked);
    }
    m_updatingList = true;
    m_servoList->clear();
    const int count = m_client ? m_client->servoCount() : 0;
    for (int index = 0; index < count; ++index) {
        const feetech::ServoInfo &info = m_client->servo(index).info;
        const QString model = info.model.name.isEmpty() ? tr("unknown model") : info.model.name;
        auto *item = new QListWidgetItem(
            tr("ID %1 · %2 · %3").arg(info.id).arg(model, feetech::baudText(info.baud)),
            m_servoList);
        item->setData(kIdRole, info.id);
        item->setData(kBaudRole, info.baud);
        item->setData(kIndexRole, index);
        if (info.hasTable()) {
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
            item->setCheckState(previous.value(Key {info.id, info.baud}, true) ? Qt::Checked
                                                                               : Qt::Unchecked);
        } else {
            // Without the family's table the feedback block cannot be decoded.
            item->setFlags(Qt::ItemIsUserCheckable);
            item->setCheckState(Qt::Unchecked);
            item->setToolTip(tr("Unknown model: its feedback cannot be decoded"));
        }
    }
    m_updatingList = false;
    if (m_servoList->count() == 0) {
        auto *item = new QListWidgetItem(tr("Scan the bus to find servos."), m_servoList);
        item->setFlags(Qt::NoItemFlags);
    }
    m_unlisted.erase(std::remove_if(m_unlisted.begin(), m_unlisted.end(),
                                    [this](const Key &key) { return isListed(key); }),
                     m_unlisted.end());
    onServoItemChanged();
}

void MonitorPage::onServoItemChanged()
{
    if (m_updatingList)
        return;
    updatePlotServos();
    m_readoutsDirty = true;
    updateReadouts();
    restartIfRunning();
    updateControls();
}

void MonitorPage::onQuantityToggled()
{
    m_plot->setQuantities(quantities());
    m_exportButton->setEnabled(!quantities().isEmpty());
}

void MonitorPage::onRateChosen()
{
    restartIfRunning();
}

void MonitorPage::onWindowChosen()
{
    m_plot->setWindowSeconds(m_windowCombo->currentData().toDouble());
}

void MonitorPage::onMonitoringChanged(bool monitoring)
{
    if (!monitoring)
        stopRecording(); // the stream ended (Stop, a lost link): the recording with it
    updateControls();
    m_readoutsDirty = true;
    updateReadouts();
}

void MonitorPage::onStatsChanged(const feetech::TelemetryStats &stats)
{
    m_stats = stats;
    m_readoutsDirty = true;
    updateStatusLine();
}

void MonitorPage::onStatusChanged()
{
    if (m_client && !m_client->isConnected() && isRecording()) {
        stopRecording();
        showMessage(tr("Recording stopped: the bus was disconnected."), true);
    }
    updateControls();
}

void MonitorPage::toggleStream()
{
    if (isRunning())
        stop();
    else
        start();
}

void MonitorPage::togglePause()
{
    m_plot->setPaused(!m_plot->isPaused());
}

void MonitorPage::chooseExportFile()
{
    const QString directory = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export plot"), QDir(directory).filePath(QStringLiteral("servobench-monitor.png")),
        tr("PNG images (*.png)"));
    if (!path.isEmpty())
        exportPng(path);
}

void MonitorPage::toggleRecording()
{
    if (isRecording()) {
        stopRecording();
        return;
    }
    const QString directory = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Record telemetry"),
        QDir(directory).filePath(QStringLiteral("servobench-telemetry.csv")),
        tr("CSV files (*.csv)"));
    if (!path.isEmpty())
        startRecording(path);
}

void MonitorPage::restartIfRunning()
{
    if (!isRunning())
        return;
    if (selectedServos().isEmpty()) {
        stop();
        showMessage(tr("Monitoring stopped: no servo is ticked."), false);
        return;
    }
    start();
}

void MonitorPage::updatePlotServos()
{
    QVector<TelemetryPlot::Servo> servos;
    for (const Key &key : checkedKeys())
        servos.append({key.id, key.baud});
    for (const Key &key : std::as_const(m_unlisted))
        servos.append({key.id, key.baud});
    m_plot->setServos(servos);
}

void MonitorPage::updateControls()
{
    const bool running = isRunning();
    const bool connected = m_client && m_client->isConnected();
    m_startButton->setText(running ? tr("Stop") : tr("Start"));
    m_startButton->setIcon(
        style()->standardIcon(running ? QStyle::SP_MediaStop : QStyle::SP_MediaPlay));
    m_startButton->setEnabled(running || (connected && !selectedServos().isEmpty()));
    const bool paused = m_plot->isPaused();
    m_pauseButton->setText(paused ? tr("Resume") : tr("Pause"));
    m_pauseButton->setIcon(
        style()->standardIcon(paused ? QStyle::SP_MediaPlay : QStyle::SP_MediaPause));
    m_resetZoomButton->setEnabled(m_plot->isZoomed());
    m_recordButton->setText(isRecording() ? tr("Stop recording") : tr("Record CSV…"));
    updateStatusLine();
}

void MonitorPage::updateStatusLine()
{
    const QLocale locale;
    QString text;
    if (isRunning()) {
        text = tr("Streaming · %1 cycles/s · %2 samples/s · %3 missed")
                   .arg(locale.toString(m_stats.cyclesPerSecond, 'f', 0),
                        locale.toString(m_stats.samplesPerSecond, 'f', 0),
                        locale.toString(m_stats.missed));
    } else {
        text = tr("Stopped");
    }
    if (m_plot->isPaused())
        text += tr(" · plot paused (samples are still received)");
    if (m_statusLine->text() != text)
        m_statusLine->setText(text);
}

void MonitorPage::updateRecordingLabel()
{
    if (!isRecording()) {
        if (m_recordingLabel->text().isEmpty())
            m_recordingLabel->setText(tr("Not recording."));
        return;
    }
    const QString path = m_recorder->fileName();
    m_recordingLabel->setText(tr("Recording to %1: %Ln row(s).", nullptr, int(recordedRows()))
                                  .arg(QFileInfo(path).fileName()));
    m_recordingLabel->setToolTip(QDir::toNativeSeparators(path));
}

void MonitorPage::failRecording(const QString &why)
{
    const QString path = QDir::toNativeSeparators(m_recorder->fileName());
    const QString message =
        tr("Recording to %1 failed after %Ln row(s): %2", nullptr, int(recordedRows()))
            .arg(path, why);
    m_recordingLabel->setText(tr("Recording failed."));
    showMessage(message, true);
    emit problem(message);
    updateControls();
    emit recordingChanged(false);
}

void MonitorPage::showMessage(const QString &text, bool isError)
{
    m_message->setText(text);
    m_message->setStyleSheet(isError ? QStringLiteral("color: %1;").arg(kProblemColour.name())
                                     : QString());
    m_message->setVisible(!text.isEmpty());
}

QVector<MonitorPage::Key> MonitorPage::checkedKeys() const
{
    QVector<Key> keys;
    for (int row = 0; row < m_servoList->count(); ++row) {
        const QListWidgetItem *item = m_servoList->item(row);
        if (item->checkState() == Qt::Checked)
            keys.append({quint8(item->data(kIdRole).toInt()), item->data(kBaudRole).toInt()});
    }
    return keys;
}

bool MonitorPage::isListed(const Key &key) const
{
    for (int row = 0; row < m_servoList->count(); ++row) {
        const QListWidgetItem *item = m_servoList->item(row);
        if ((item->flags() & Qt::ItemIsUserCheckable) && item->data(kIdRole).toInt() == key.id
            && item->data(kBaudRole).toInt() == key.baud)
            return true;
    }
    return false;
}

QVector<MonitorPage::Key> MonitorPage::readoutKeys() const
{
    return checkedKeys() + m_unlisted;
}

QString MonitorPage::statusText(const Key &key, quint8 bits) const
{
    const int index = m_client ? m_client->indexOf(key.id, key.baud) : -1;
    if (index >= 0)
        return feetech::servoStatusText(m_client->servo(index).info.table(), bits);
    return bits == 0 ? tr("none") : QStringLiteral("0x%1").arg(bits, 2, 16, QLatin1Char('0'));
}
