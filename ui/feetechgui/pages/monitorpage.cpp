// The Monitor page: stream controls, the live plot, readouts refreshed on a timer rather than per
// sample, and the recording group the ticked servos' samples are written through.
#include "monitorpage.h"

#include "busclient.h"
#include "monitorreadouts.h"
#include "monitorrecording.h"
#include "monitorservolist.h"
#include "monitorstatusline.h"
#include "recentfiles.h"
#include "telemetryplot.h"
#include "widgethelpers.h"
#include "widgetmemory.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScopedValueRollback>
#include <QScrollArea>
#include <QSplitter>
#include <QStandardPaths>
#include <QStyle>
#include <QTabBar>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

using widgethelpers::actionButton;

namespace {

constexpr double kRates[] = {1, 5, 10, 20, 50, 100, 200};
constexpr double kDefaultRate = 50;
constexpr int kWindows[] = {5, 10, 30, 60, 120};
constexpr int kControlsWidth = 250;

} // namespace

MonitorPage::MonitorPage(feetech::BusClient *client, QWidget *parent)
    : QWidget(parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("monitorPage"));
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);

    layout->addWidget(buildControls());

    // ---- right: plots over readouts, the stream's health below
    auto *right = new QWidget(this);
    auto *rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(6, 0, 0, 0);
    auto *splitter = new QSplitter(Qt::Vertical, right);
    splitter->setChildrenCollapsible(false);
    // The plot, and over it, when not every quantity ticked has room for a readable pane, a
    // tab a quantity: one pane at a time then.
    m_plotBox = new QWidget(splitter);
    auto *plotLayout = new QVBoxLayout(m_plotBox);
    plotLayout->setContentsMargins(0, 0, 0, 0);
    plotLayout->setSpacing(0);
    m_quantityTabs = new QTabBar(m_plotBox);
    m_quantityTabs->setObjectName(QStringLiteral("monitorQuantityTabs"));
    m_quantityTabs->setDocumentMode(true);
    m_quantityTabs->setExpanding(false);
    m_quantityTabs->hide();
    connect(m_quantityTabs, &QTabBar::currentChanged, this, [this] {
        if (!m_fittingPanes)
            fitPanes();
    });
    plotLayout->addWidget(m_quantityTabs);
    m_plot = new TelemetryPlot(m_plotBox);
    m_plot->setWindowSeconds(m_windowCombo->currentData().toDouble()); // as last chosen
    connect(m_plot, &TelemetryPlot::pausedChanged, this, &MonitorPage::updateControls);
    connect(m_plot, &TelemetryPlot::zoomedChanged, this, &MonitorPage::updateControls);
    plotLayout->addWidget(m_plot, 1);
    m_plotBox->installEventFilter(this);
    splitter->addWidget(m_plotBox);

    m_readouts = new MonitorReadouts(m_client, splitter);
    splitter->addWidget(m_readouts);
    splitter->setStretchFactor(0, 4);
    splitter->setStretchFactor(1, 1);
    rightLayout->addWidget(splitter, 1);

    m_statusLine = new MonitorStatusLine(right);
    m_statusLine->setObjectName(QStringLiteral("monitorStatus"));
    rightLayout->addWidget(m_statusLine);
    layout->addWidget(right, 1);

    m_readoutTimer = new QTimer(this);
    m_readoutTimer->setInterval(kReadoutIntervalMs);
    connect(m_readoutTimer, &QTimer::timeout, this, [this] {
        if (m_readoutsDirty || isRunning())
            updateReadouts(); // samples/s falls when a servo stops answering: recount
    });
    connect(m_recording, &MonitorRecording::reported, this, &MonitorPage::showMessage);
    connect(m_recording, &MonitorRecording::problem, this, [this](const QString &message) {
        emit problem(message);
        updateControls();
    });

    if (m_client) {
        connect(m_client->servos(), &feetech::ServoList::servosChanged, this,
                &MonitorPage::rebuildServoList);
        connect(m_client->telemetry(), &feetech::TelemetryHub::samplesReceived, this,
                &MonitorPage::addSamples);
        connect(m_client->telemetry(), &feetech::TelemetryHub::statsChanged, this,
                &MonitorPage::onStatsChanged);
        connect(m_client->telemetry(), &feetech::TelemetryHub::streamingChanged, this,
                &MonitorPage::onMonitoringChanged);
        connect(m_client, &feetech::BusClient::statusChanged, this, &MonitorPage::onStatusChanged);
        connect(m_client, &feetech::BusClient::scanFinished, this, [this] {
            if (m_resumeWhenListed && m_client->servos()->count() == 0) {
                m_resumeWhenListed = false;
                showMessage(tr("The scan found no servo: monitoring stays stopped."), false);
            }
            resumeAfterScan();
        });
        connect(m_client->share(), &feetech::ShareService::stateChanged, this,
                &MonitorPage::updateStatusLine);
    }
    onQuantityToggled();
    rebuildServoList();
}

MonitorPage::~MonitorPage()
{
    // While the page can still show why the last rows could not be written.
    m_recording->stopRecording();
}

QWidget *MonitorPage::buildControls()
{
    // In a scroll area for short windows.
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

    auto *servoGroup = new QGroupBox(tr("Servos"), controls);
    auto *servoLayout = new QVBoxLayout(servoGroup);
    m_servoList = new MonitorServoList(servoGroup);
    connect(m_servoList, &MonitorServoList::ticksChanged, this, &MonitorPage::onTicksChanged);
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
        // Before the page listens: the plot does not exist yet (it is applied once it does).
        widgetmemory::remember(
            check, QStringLiteral("monitor/plot_%1").arg(feetech::quantityKey(quantity)));
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
    widgetmemory::remember(m_rateCombo, QStringLiteral("monitor/rate"));
    streamLayout->addRow(tr("Rate:"), m_rateCombo);
    m_startButton =
        actionButton(tr("Start"), "monitorStartButton",
                     tr("Start or stop streaming the ticked servos' feedback"), streamGroup);
    QFont bold = m_startButton->font();
    bold.setBold(true);
    m_startButton->setFont(bold);
    connect(m_startButton, &QPushButton::clicked, this, &MonitorPage::toggleStream);
    streamLayout->addRow(m_startButton);
    // First: Rate and Start stay in sight on a 1366x768 screen, above the servo list.
    controlsLayout->insertWidget(0, streamGroup);

    auto *viewGroup = new QGroupBox(tr("View"), controls);
    auto *viewLayout = new QFormLayout(viewGroup);
    m_windowCombo = new QComboBox(viewGroup);
    m_windowCombo->setObjectName(QStringLiteral("monitorWindowCombo"));
    m_windowCombo->setToolTip(tr("How many seconds of history the plot shows"));
    for (const int seconds : kWindows)
        m_windowCombo->addItem(tr("%1 s").arg(seconds), seconds);
    m_windowCombo->setCurrentIndex(m_windowCombo->findData(kDefaultWindowSeconds));
    connect(m_windowCombo, &QComboBox::activated, this, &MonitorPage::onWindowChosen);
    widgetmemory::remember(m_windowCombo, QStringLiteral("monitor/window"));
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

    m_recording = new MonitorRecording(controls);
    controlsLayout->addWidget(m_recording);

    m_message = new QLabel(controls);
    m_message->setObjectName(QStringLiteral("monitorMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message->hide();
    controlsLayout->addWidget(m_message);
    return scroll;
}

void MonitorPage::setSelectedServos(const QVector<int> &indexes)
{
    m_servoList->setSelectedServos(indexes);
}

QVector<int> MonitorPage::selectedServos() const
{
    return m_servoList->selectedServos();
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
        const bool fresh = !m_client->telemetry()->isSubscribed(this);
        feetech::Refusal refusal;
        if (m_client->telemetry()->subscribe(this, selectedServos(), rate(), &refusal)) {
            if (fresh) {
                // A new run starts a new time line (its samples come later, queued); a
                // restart keeps the present one going.
                m_plot->clear();
                m_readouts->clearSamples();
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
        why = refusal.describe();
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
    m_recording->stopRecording();
    if (m_client)
        m_client->telemetry()->unsubscribe(this);
    updateControls();
    updateStatusLine();
}

bool MonitorPage::isRunning() const
{
    return m_client && m_client->telemetry()->isSubscribed(this);
}

bool MonitorPage::exportPng(const QString &path, QString *error)
{
    QString why;
    // Every quantity ticked, at the file's own size, whatever the window shows.
    if (m_plot->exportPng(path, &why, quantities())) {
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
    const QHash<Key, bool> listed = m_servoList->ticks();
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
        m_readouts->addSample(sample);
        kept.append(sample);
        m_recording->recorder()->write(sample); // from its start on
    }
    if (kept.isEmpty())
        return;
    m_plot->addSamples(kept);
    m_readoutsDirty = true;
}

void MonitorPage::updateReadouts()
{
    m_readoutsDirty = false;
    QVector<MonitorReadouts::Row> rows;
    for (const Key &key : readoutKeys())
        rows.append(
            {key, m_plot->servoColor(key.id, key.baud), m_servoList->jointNames().label(key)});
    m_readouts->refresh(rows, m_stats, isRunning());
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
    m_servoList->rebuild(m_client);
    QHash<Key, QString> names;
    for (int index = 0; m_client && index < m_client->servos()->count(); ++index) {
        const Key key = m_client->servos()->at(index).info.address();
        if (!m_servoList->jointNames().joint(key).isEmpty())
            names.insert(key, m_servoList->jointNames().label(key));
    }
    m_plot->setServoNames(names);
    m_unlisted.erase(std::remove_if(m_unlisted.begin(), m_unlisted.end(),
                                    [this](const Key &key) { return m_servoList->isListed(key); }),
                     m_unlisted.end());
    onTicksChanged();
    resumeAfterScan();
}

void MonitorPage::resumeAfterScan()
{
    if (!m_resumeWhenListed || !m_client || m_client->isScanning()
        || m_client->servos()->count() == 0)
        return;
    m_resumeWhenListed = false;
    if (!m_client->link()->isConnected() || selectedServos().isEmpty())
        return;
    QString error;
    if (start(&error))
        showMessage(tr("Monitoring again, after the scan."), false);
    else
        showMessage(tr("The Monitor could not start again after the scan: %1").arg(error), true);
}

void MonitorPage::onTicksChanged()
{
    updatePlotServos();
    m_readoutsDirty = true;
    updateReadouts();
    restartIfRunning();
    updateControls();
}

void MonitorPage::onQuantityToggled()
{
    fitPanes();
    m_exportButton->setEnabled(!quantities().isEmpty());
}

void MonitorPage::fitPanes()
{
    const QVector<feetech::Quantity> ticked = quantities();
    const feetech::Quantity shown =
        m_quantityTabs->isVisible() && m_quantityTabs->currentIndex() >= 0
        ? feetech::Quantity(m_quantityTabs->tabData(m_quantityTabs->currentIndex()).toInt())
        : (ticked.isEmpty() ? feetech::Quantity::Position : ticked.first());
    const QScopedValueRollback<bool> fitting(m_fittingPanes, true);
    if (ticked.size() <= m_plot->readablePanesIn(m_plotBox->height())) {
        m_quantityTabs->hide();
        m_plot->setQuantities(ticked);
        return;
    }
    // One pane, its quantity chosen by a tab; the tabs keep the order of the ticks, and are
    // made again only when the ticks change (a resize keeps them).
    QVector<feetech::Quantity> tabbed;
    for (int tab = 0; tab < m_quantityTabs->count(); ++tab)
        tabbed.append(feetech::Quantity(m_quantityTabs->tabData(tab).toInt()));
    if (tabbed != ticked) {
        while (m_quantityTabs->count() > 0)
            m_quantityTabs->removeTab(0);
        for (const feetech::Quantity quantity : ticked) {
            const int tab = m_quantityTabs->addTab(feetech::quantityName(quantity));
            m_quantityTabs->setTabData(tab, int(quantity));
            if (quantity == shown)
                m_quantityTabs->setCurrentIndex(tab);
        }
    }
    m_quantityTabs->show();
    m_plot->setQuantities({feetech::Quantity(
        m_quantityTabs->tabData(std::max(0, m_quantityTabs->currentIndex())).toInt())});
}

bool MonitorPage::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_plotBox && event->type() == QEvent::Resize && !m_fittingPanes)
        QTimer::singleShot(0, this, &MonitorPage::fitPanes); // after the layout settles
    return QWidget::eventFilter(watched, event);
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
        m_recording->stopRecording(); // the stream ended (Stop, a lost link): the recording with it
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
    if (m_client && !m_client->link()->isConnected() && m_recording->isRecording()) {
        m_recording->stopRecording();
        showMessage(tr("Recording stopped: the bus was disconnected."), true);
    }
    updateControls();
}

void MonitorPage::toggleStream()
{
    m_resumeWhenListed = false; // the user's Start or Stop is the last word
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
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export plot"),
        recentfiles::suggestedPath(recentfiles::Kind::PlotImage,
                                   QStringLiteral("servobench-monitor.png")),
        tr("PNG images (*.png)"));
    if (!path.isEmpty() && exportPng(path))
        recentfiles::add(recentfiles::Kind::PlotImage, path);
}

void MonitorPage::restartIfRunning()
{
    if (!isRunning())
        return;
    if (selectedServos().isEmpty() && m_client && m_client->servos()->count() == 0) {
        // The list is scanned again (a re-scan of the Doctor, Scan): it goes on once it has
        // servos, and says so meanwhile rather than stopping unsaid.
        stop();
        m_resumeWhenListed = true;
        showMessage(tr("Monitoring paused while the bus is scanned; it starts again with the "
                       "servos found."),
                    false);
        return;
    }
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
    for (const Key &key : m_servoList->checkedKeys())
        servos.append({key.id, key.baud});
    for (const Key &key : std::as_const(m_unlisted))
        servos.append({key.id, key.baud});
    m_plot->setServos(servos);
}

void MonitorPage::updateControls()
{
    const bool running = isRunning();
    const bool connected = m_client && m_client->link()->isConnected();
    m_startButton->setText(running ? tr("Stop") : tr("Start"));
    m_startButton->setIcon(
        style()->standardIcon(running ? QStyle::SP_MediaStop : QStyle::SP_MediaPlay));
    m_startButton->setEnabled(running || (connected && !selectedServos().isEmpty()));
    const bool paused = m_plot->isPaused();
    m_pauseButton->setText(paused ? tr("Resume") : tr("Pause"));
    m_pauseButton->setIcon(
        style()->standardIcon(paused ? QStyle::SP_MediaPlay : QStyle::SP_MediaPause));
    m_resetZoomButton->setEnabled(m_plot->isZoomed());
    updateStatusLine();
}

void MonitorPage::updateStatusLine()
{
    const QLocale locale;
    QString text;
    if (isRunning() && m_client
        && m_client->share()->state() == feetech::ShareService::State::Sharing) {
        // The session's own cycles wait: what plots is what the other program reads.
        text = tr("Shared bus · showing the other program's reads, none of ServoBench's own");
    } else if (isRunning()) {
        text = tr("Streaming · %1 cycles/s · %2 samples/s · %3 missed · %4 late")
                   .arg(locale.toString(m_stats.cyclesPerSecond, 'f', 0),
                        locale.toString(m_stats.samplesPerSecond, 'f', 0),
                        locale.toString(m_stats.missed), locale.toString(m_stats.late));
    } else {
        text = tr("Stopped");
    }
    if (m_plot->isPaused())
        text += tr(" · plot paused (samples are still received)");
    if (m_statusLine->text() != text)
        m_statusLine->setText(text);
}

void MonitorPage::showMessage(const QString &text, bool isError)
{
    m_message->setText(text);
    m_message->setStyleSheet(
        isError ? QStringLiteral("color: %1;").arg(MonitorReadouts::kProblemColour.name())
                : QString());
    m_message->setVisible(!text.isEmpty());
}

QVector<MonitorPage::Key> MonitorPage::readoutKeys() const
{
    return m_servoList->checkedKeys() + m_unlisted;
}
