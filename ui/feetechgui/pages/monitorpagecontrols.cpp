// The Monitor page's left column: the servos, quantities, stream, view and recording groups.
#include "monitorpage.h"

#include "telemetryplot.h"
#include "widgethelpers.h"
#include "widgetmemory.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QStyle>
#include <QVBoxLayout>

using widgethelpers::actionButton;

namespace {

constexpr double kRates[] = {1, 5, 10, 20, 50, 100, 200};
constexpr double kDefaultRate = 50;
constexpr int kWindows[] = {5, 10, 30, 60, 120};
constexpr int kControlsWidth = 250;

} // namespace

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
    return scroll;
}
