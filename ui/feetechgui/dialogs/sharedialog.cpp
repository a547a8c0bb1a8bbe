// Link > Share this bus…: a form over the client's ShareService, and its live figures.
#include "sharedialog.h"

#include "busclient.h"
#include "recentfiles.h"

#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QTime>
#include <QVBoxLayout>

using feetech::ShareService;

ShareDialog::ShareDialog(feetech::BusClient *client, QWidget *parent)
    : QDialog(parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("shareDialog"));
    setWindowTitle(tr("Share this bus"));
    setModal(false);
    auto *intro = new QLabel(
        tr("ServoBench keeps the port and gives another program (LeRobot, a script) a port of "
           "its own: open the path below in it. Every byte passes both ways unchanged. Its "
           "traffic shows in the packet log, its servos in the servo tree, its reads of "
           "position, load, voltage and temperature in the Monitor, without a read of "
           "ServoBench's own. ServoBench's operations wait for the gaps between its "
           "transactions; a scan or a new baud rate waits until sharing stops; All torque off "
           "always goes."),
        this);
    intro->setWordWrap(true);

    m_path = new QLineEdit(ShareService::defaultLinkPath(), this);
    m_path->setObjectName(QStringLiteral("sharePath"));
    m_path->setToolTip(tr("The path the other program opens as its serial port"));
    m_copy = new QPushButton(tr("&Copy path"), this);
    m_copy->setObjectName(QStringLiteral("copySharePath"));
    auto *pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(m_copy);

    m_record = new QLineEdit(this);
    m_record->setObjectName(QStringLiteral("shareRecording"));
    m_record->setPlaceholderText(tr("No recording"));
    m_record->setToolTip(tr("Every frame with its time and direction; the packet log's Open "
                            "recording… shows it"));
    m_chooseRecord = new QPushButton(tr("C&hoose…"), this);
    m_chooseRecord->setObjectName(QStringLiteral("chooseShareRecording"));
    auto *recordRow = new QHBoxLayout;
    recordRow->addWidget(m_record, 1);
    recordRow->addWidget(m_chooseRecord);

    m_watch = new QCheckBox(tr("&Watch: read the program's servos in its idle gaps"), this);
    m_watch->setObjectName(QStringLiteral("shareWatch"));
    m_watch->setToolTip(tr("One READ at a time, only while the program leaves the bus quiet, so "
                           "alerts also cover what the program does not read itself"));

    auto *form = new QFormLayout;
    form->addRow(tr("Path for the other program:"), pathRow);
    form->addRow(tr("Recording file:"), recordRow);
    form->addRow(QString(), m_watch);

    m_startStop = new QPushButton(this);
    m_startStop->setObjectName(QStringLiteral("shareStartStop"));
    m_state = new QLabel(this);
    m_state->setObjectName(QStringLiteral("shareState"));
    m_state->setWordWrap(true);
    m_state->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_note = new QLabel(this);
    m_note->setObjectName(QStringLiteral("shareNote"));
    m_note->setWordWrap(true);
    m_counters = new QLabel(this);
    m_counters->setObjectName(QStringLiteral("shareCounters"));
    m_counters->setWordWrap(true);
    m_alerts = new QListWidget(this);
    m_alerts->setObjectName(QStringLiteral("shareAlerts"));
    m_alerts->setWordWrap(true);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_startStop, 0, Qt::AlignLeft);
    layout->addWidget(m_state);
    layout->addWidget(m_note);
    layout->addWidget(m_counters);
    layout->addWidget(new QLabel(tr("Alerts:"), this));
    layout->addWidget(m_alerts, 1);
    layout->addWidget(buttons);
    resize(560, 520);

    ShareService *service = client->share();
    connect(m_startStop, &QPushButton::clicked, this, &ShareDialog::startOrStop);
    connect(m_copy, &QPushButton::clicked, this, &ShareDialog::copyPath);
    connect(m_chooseRecord, &QPushButton::clicked, this, &ShareDialog::chooseRecording);
    connect(m_watch, &QCheckBox::toggled, this, [service](bool on) {
        if (service->isActive())
            service->setWatch(on);
    });
    connect(service, &ShareService::stateChanged, this, &ShareDialog::showState);
    connect(service, &ShareService::startFailed, this, &ShareDialog::showProblem);
    connect(service, &ShareService::countersChanged, this, &ShareDialog::showCounters);
    connect(service, &ShareService::alertRaised, this, &ShareDialog::addAlert);
    connect(service, &ShareService::noted, m_note, &QLabel::setText);
    connect(client, &feetech::BusClient::statusChanged, this, &ShareDialog::showState);
    m_watch->setChecked(service->isWatching());
    for (const share::ShareAlert &alert : service->alerts())
        addAlert(alert);
    showState();
    showCounters();
}

void ShareDialog::startOrStop()
{
    ShareService *service = m_client->share();
    if (service->isActive()) {
        service->stop();
        return;
    }
    share::ShareOptions options;
    options.linkPath = QDir::fromNativeSeparators(m_path->text().trimmed());
    options.recordPath = m_record->text().trimmed();
    options.watch = m_watch->isChecked();
    feetech::Refusal refusal;
    if (!service->start(options, &refusal)) {
        showProblem(refusal.describe());
        return;
    }
    m_alerts->clear();
}

void ShareDialog::copyPath()
{
    const ShareService *service = m_client->share();
    const QString path = service->state() == ShareService::State::Sharing
        ? service->linkPath()
        : m_path->text().trimmed();
    QApplication::clipboard()->setText(path);
    m_note->setText(tr("Copied %1: paste it as the other program's port.").arg(path));
}

void ShareDialog::chooseRecording()
{
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Record the shared bus to"),
        m_record->text().isEmpty() ? recentfiles::suggestedPath(recentfiles::Kind::ShareRecording,
                                                                QStringLiteral("shared-bus.txt"))
                                   : m_record->text(),
        tr("Share recordings (*.txt);;All files (*)"));
    if (!path.isEmpty())
        m_record->setText(QDir::toNativeSeparators(path));
}

void ShareDialog::showState()
{
    const ShareService *service = m_client->share();
    const bool connected = m_client->link()->isConnected();
    const ShareService::State state = service->state();
    // What a running share was started with stays as it is until it stops.
    m_path->setEnabled(state == ShareService::State::Off);
    m_record->setEnabled(state == ShareService::State::Off);
    m_chooseRecord->setEnabled(state == ShareService::State::Off);
    switch (state) {
    case ShareService::State::Off:
        m_startStop->setText(tr("&Start sharing"));
        m_startStop->setEnabled(connected);
        m_state->setText(connected ? tr("Not sharing.") : tr("Connect to a Feetech bus first."));
        break;
    case ShareService::State::Starting:
        m_startStop->setText(tr("&Stop sharing"));
        m_startStop->setEnabled(true);
        m_state->setText(tr("Starting…"));
        break;
    case ShareService::State::Sharing:
        m_startStop->setText(tr("&Stop sharing"));
        m_startStop->setEnabled(true);
        m_path->setText(QDir::toNativeSeparators(service->linkPath()));
        m_state->setText(
            tr("Sharing at %1 baud: give the other program %2 (the pseudo-terminal %3).")
                .arg(service->portBaud())
                .arg(QDir::toNativeSeparators(service->linkPath()),
                     QDir::toNativeSeparators(service->terminalPath())));
        break;
    }
}

void ShareDialog::showCounters()
{
    const ShareService *service = m_client->share();
    const share::ShareCounters &count = service->counters();
    m_counters->setText(
        tr("From the program: %1 frame(s). Back to it: %2 frame(s). Unanswered: %3. "
           "Garbled bytes: %4. Alerts: %5. Watch reads: %6.")
            .arg(count.framesFromProgram)
            .arg(count.framesToProgram)
            .arg(count.unanswered)
            .arg(count.garbledBytes)
            .arg(service->alerts().size())
            .arg(service->watchReads()));
}

void ShareDialog::addAlert(const share::ShareAlert &alert)
{
    m_alerts->addItem(tr("%1  ID %2: %3")
                          .arg(QTime::currentTime().toString(QStringLiteral("hh:mm:ss")))
                          .arg(alert.id)
                          .arg(alert.message));
    m_alerts->scrollToBottom();
    showCounters();
}

void ShareDialog::showProblem(const QString &text)
{
    m_state->setText(text);
}
