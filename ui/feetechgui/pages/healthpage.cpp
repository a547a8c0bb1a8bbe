// The Health page: a check of every servo found, its verdicts in a table, the move test and the
// report.
#include "healthpage.h"

#include "busclient.h"
#include "healthmovetest.h"
#include "jointnames.h"
#include "palette.h"
#include "recentfiles.h"
#include "robottemplate.h"
#include "settingscheckpanel.h"
#include "widgethelpers.h"

#include <QDir>
#include <QFileDialog>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QStackedWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

using feetech::ServoHealth;
using feetech::Verdict;

namespace {

QString measured(const std::optional<double> &value, int decimals, const QString &unit)
{
    return value ? QLocale().toString(*value, 'f', decimals) + QLatin1Char(' ') + unit : QString();
}

palette::Tone verdictTone(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Ok:
        return palette::Tone::Good;
    case Verdict::Warning:
        return palette::Tone::Warning;
    case Verdict::Fault:
        return palette::Tone::Error;
    }
    return palette::Tone::Accent;
}

} // namespace

HealthPage::HealthPage(feetech::BusClient *client, QWidget *parent)
    : QWidget(parent)
    , m_client(client)
{
    m_confirm = [this](const QString &question) {
        return QMessageBox::question(this, tr("Move test"), question,
                                     QMessageBox::Yes | QMessageBox::No, QMessageBox::No)
            == QMessageBox::Yes;
    };
    // The page scrolls in a short window rather than make it taller than a 1366x768 screen.
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto *scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("healthScrollArea"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    outer->addWidget(scroll);
    auto *body = new QWidget(scroll);
    auto *layout = new QVBoxLayout(body);
    auto *intro = new QLabel(
        tr("Checks each servo: firmware, voltage and temperature against its own limits, status "
           "bits, load, %1 reads for communication quality, position against its angle limits. "
           "It only reads; the move test moves a servo 100 steps and back, once you confirm.")
            .arg(feetech::kDefaultHealthReads),
        this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto *buttons = new QHBoxLayout;
    m_check = widgethelpers::actionButton(
        tr("Check"), "healthCheck", tr("Read every servo found and give each a verdict"), this);
    m_cancel = widgethelpers::actionButton(tr("Cancel"), "healthCancel",
                                           tr("Stop the check before the next servo"), this);
    m_move = widgethelpers::actionButton(
        tr("Move test…"), "healthMoveTest",
        tr("Move the selected servo a little and back, and measure how it follows"), this);
    m_save = widgethelpers::actionButton(tr("Save report…"), "healthSave",
                                         tr("Save the verdicts as an HTML page or as JSON"), this);
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("healthProgress"));
    m_progress->setVisible(false);
    for (QWidget *widget : {static_cast<QWidget *>(m_check), static_cast<QWidget *>(m_cancel),
                            static_cast<QWidget *>(m_move), static_cast<QWidget *>(m_save)})
        buttons->addWidget(widget);
    buttons->addWidget(m_progress, 1);
    layout->addLayout(buttons);

    m_stack = new QStackedWidget(this);
    m_empty = new QLabel(tr("No servos scanned yet: scan the bus, then check their health here."),
                         m_stack);
    m_empty->setObjectName(QStringLiteral("healthEmpty"));
    m_empty->setAlignment(Qt::AlignCenter);
    m_empty->setWordWrap(true);
    m_table = new QTableWidget(0, ColumnCount, m_stack);
    m_table->setObjectName(QStringLiteral("healthTable"));
    m_table->setHorizontalHeaderLabels({tr("ID"), tr("Model"), tr("Firmware"), tr("Verdict"),
                                        tr("Reasons"), tr("Voltage"), tr("Temperature"), tr("Load"),
                                        tr("Communication"), tr("Move test")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setTextElideMode(Qt::ElideNone);
    m_table->setWordWrap(true);
    m_stack->addWidget(m_empty);
    m_stack->addWidget(m_table);
    layout->addWidget(m_stack, 1);
    m_state = new QLabel(this);
    m_state->setObjectName(QStringLiteral("healthState"));
    m_state->setWordWrap(true);
    layout->addWidget(m_state);

    auto *settings = new QGroupBox(tr("Settings"), this);
    settings->setObjectName(QStringLiteral("healthSettings"));
    auto *settingsLayout = new QVBoxLayout(settings);
    m_settings = new SettingsCheckPanel(m_client, settings);
    settingsLayout->addWidget(m_settings);
    layout->addWidget(settings, 1);
    scroll->setWidget(body);
    connect(m_settings, &SettingsCheckPanel::message, this, &HealthPage::message);

    connect(m_check, &QPushButton::clicked, this, [this] { check(); });
    connect(m_cancel, &QPushButton::clicked, this, &HealthPage::cancel);
    connect(m_move, &QPushButton::clicked, this, [this] { moveTest(); });
    connect(m_save, &QPushButton::clicked, this, &HealthPage::chooseReportFile);
    connect(m_table, &QTableWidget::itemSelectionChanged, this, &HealthPage::updateActions);
    connect(m_client->servos(), &feetech::ServoList::servosChanged, this,
            &HealthPage::forgetResults);
    connect(m_client, &feetech::BusClient::busyChanged, this, &HealthPage::updateActions);
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        // Unplugged, the verdicts say nothing of the servos any more.
        if (!m_client->link()->isConnected() && (!m_readings.isEmpty() || !m_moves.isEmpty()))
            forgetResults();
        updateActions();
    });
    connect(m_client->health(), &feetech::HealthService::reading, this,
            [this](const feetech::HealthReading &reading, int done, int total) {
                m_readings.insert({reading.servo.id, reading.servo.baud}, reading);
                reassess();
                if (!m_checking)
                    return;
                m_progress->setRange(0, total);
                m_progress->setValue(done);
            });
    connect(m_client->health(), &feetech::HealthService::checkFinished, this,
            [this](bool completed, const QString &text) {
                m_checking = false;
                m_progress->setVisible(false);
                m_checkedAt = QDateTime::currentDateTime();
                // Servos of the arm that are not on the bus are a finding too, not silence.
                const QString missing = missingJoints();
                showState(missing.isEmpty() ? text : text + u' ' + missing,
                          !completed || !missing.isEmpty());
                updateActions();
            });
    connect(m_client->health(), &feetech::HealthService::moveTested, this,
            [this](const feetech::MoveTestResult &result) {
                if (!m_moving)
                    return;
                m_moving = false;
                m_moves.insert({result.id, result.baud}, result);
                reassess();
                showState(result.message, !result.ok);
                updateActions();
            });
    reassess();
}

bool HealthPage::check(QString *error)
{
    QVector<int> indexes;
    for (int i = 0; i < m_client->servos()->count(); ++i)
        indexes.append(i);
    feetech::Refusal refusal;
    if (!m_client->health()->check(indexes, feetech::kDefaultHealthReads, &refusal)) {
        const QString why = refusal.describe();
        showState(why, true);
        if (error)
            *error = why;
        return false;
    }
    m_checking = true;
    m_readings.clear();
    m_moves.clear();
    reassess();
    m_progress->setRange(0, int(indexes.size()));
    m_progress->setValue(0);
    m_progress->setVisible(true);
    showState(tr("Checking %n servo(s)…", nullptr, int(indexes.size())), false);
    updateActions();
    return true;
}

void HealthPage::cancel()
{
    if (m_checking)
        m_client->health()->cancel();
}

bool HealthPage::moveTest(QString *error)
{
    int index = selectedServo();
    QString why = index < 0 ? tr("Select the servo to move in the table first.")
                            : m_client->health()->moveTestBlocker(index).describe();
    if (why.isEmpty()) {
        // The question runs its own event loop: by its answer the servo list may have changed,
        // so the servo confirmed is looked up again by its address.
        const feetech::ServoInfo info = m_client->servos()->at(index).info;
        const QString question =
            tr("%1 (%2) will move %3 steps from where it stands and back, with its torque "
               "on meanwhile. Make sure nothing is in the way. Move it?")
                .arg(feetech::JointNames::of(*m_client).label(info.address()))
                .arg(info.model.name)
                .arg(feetech::HealthMoveTest::kAmplitude);
        const bool confirmed = m_confirm(question);
        index = m_client->servos()->indexOf(info.address());
        if (!confirmed)
            why = tr("The move test was not confirmed: nothing moved.");
        else if (index < 0)
            why = tr("Servo %1 is no longer on the bus: nothing moved.").arg(info.id);
        else if (feetech::Refusal refusal; m_client->health()->moveTest(index, true, &refusal))
            m_moving = true;
        else
            why = refusal.describe();
    }
    if (!m_moving) {
        showState(why, true);
        if (error)
            *error = why;
        return false;
    }
    showState(tr("Moving servo %1…").arg(m_client->servos()->at(index).info.id), false);
    updateActions();
    return true;
}

bool HealthPage::saveReport(const QString &path, QString *error)
{
    QString why;
    const auto format = feetech::reportFormatFor(path);
    feetech::HealthReport report;
    report.port = m_client->link()->status().portName;
    report.checkedAt = m_checkedAt.isValid() ? m_checkedAt : QDateTime::currentDateTime();
    report.servos = results();
    if (!format)
        why = tr("Save the report as .html or .json: %1 is neither.").arg(path);
    else if (feetech::saveHealthReport(path, *format, report, &why))
        showState(tr("Report saved to %1.").arg(QDir::toNativeSeparators(path)), false);
    if (!why.isEmpty()) {
        showState(why, true);
        emit problem(why);
        if (error)
            *error = why;
        return false;
    }
    return true;
}

void HealthPage::chooseReportFile()
{
    QString filter;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save health report"),
        recentfiles::suggestedPath(recentfiles::Kind::HealthReport,
                                   QStringLiteral("servo-health.html")),
        tr("HTML page (*.html);;JSON (*.json)"), &filter);
    if (path.isEmpty())
        return;
    QString chosen = path;
    if (!feetech::reportFormatFor(chosen))
        chosen += filter.contains(QLatin1String("json")) ? QStringLiteral(".json")
                                                         : QStringLiteral(".html");
    if (saveReport(chosen))
        recentfiles::add(recentfiles::Kind::HealthReport, chosen);
}

QVector<ServoHealth> HealthPage::results() const
{
    QVector<ServoHealth> checked;
    for (int i = 0; i < m_client->servos()->count(); ++i) {
        const feetech::ServoInfo &info = m_client->servos()->at(i).info;
        const auto found = m_health.constFind({info.id, info.baud});
        if (found != m_health.constEnd())
            checked.append(*found);
    }
    return checked;
}

QString HealthPage::missingJoints() const
{
    const feetech::JointNames names = feetech::JointNames::of(*m_client);
    if (names.isEmpty())
        return {};
    for (const feetech::RobotTemplate &robot : feetech::availableRobotTemplates()) {
        if (robot.name != names.robot())
            continue;
        QStringList missing;
        for (const feetech::RobotJoint &joint : robot.joints) {
            if (m_client->servos()->indexOf({quint8(joint.id), robot.baud}) < 0)
                missing.append(
                    tr("%1 (ID %2)").arg(feetech::jointDisplayName(joint.name)).arg(joint.id));
        }
        if (missing.isEmpty())
            return {};
        return tr("Of the %1, %n joint(s) did not answer the scan: %2. Check their cables and "
                  "scan again.",
                  nullptr, int(missing.size()))
            .arg(feetech::robotDisplayName(robot.name), QLocale().createSeparatedList(missing));
    }
    return {};
}

void HealthPage::forgetResults()
{
    m_readings.clear();
    m_moves.clear();
    // The verdicts go with the servos they were about, and so does what was said of them
    // ("4 servo(s) checked."); a check under way says its own words when it ends.
    if (!m_checking && !m_moving) {
        m_checkedAt = {};
        showState({}, false);
    }
    reassess();
}

void HealthPage::reassess()
{
    QVector<ServoHealth> verdicts;
    for (int i = 0; i < m_client->servos()->count(); ++i) {
        const feetech::ServoInfo &info = m_client->servos()->at(i).info;
        const auto reading = m_readings.constFind({info.id, info.baud});
        if (reading == m_readings.constEnd())
            continue;
        ServoHealth health = feetech::assessHealth(*reading);
        const auto move = m_moves.constFind({info.id, info.baud});
        if (move != m_moves.constEnd())
            feetech::addMoveTest(health, *move);
        verdicts.append(health);
    }
    feetech::flagFirmwareMismatches(verdicts);
    m_health.clear();
    for (const ServoHealth &health : std::as_const(verdicts))
        m_health.insert({health.id, health.baud}, health);
    rebuildRows();
}

void HealthPage::rebuildRows()
{
    const int selected = m_table->currentRow();
    m_table->setRowCount(m_client->servos()->count());
    // Read once a table (the templates come from disk), not once a row.
    const feetech::JointNames joints = feetech::JointNames::of(*m_client);
    for (int row = 0; row < m_client->servos()->count(); ++row) {
        const feetech::ServoInfo &info = m_client->servos()->at(row).info;
        ServoHealth health;
        const auto found = m_health.constFind({info.id, info.baud});
        if (found != m_health.constEnd())
            health = *found;
        if (found == m_health.constEnd()) { // as the scan found it
            health.id = info.id;
            health.baud = info.baud;
            health.model = info.model.name;
            health.firmware = info.firmware();
        }
        fillRow(row, health, joints);
        if (found == m_health.constEnd()) {
            m_table->item(row, VerdictColumn)->setText(tr("not checked"));
            m_table->item(row, VerdictColumn)->setForeground(palette().color(QPalette::Text));
        }
    }
    m_table->resizeColumnsToContents();
    // The reasons wrap rather than push the measurements out of sight.
    m_table->setColumnWidth(ReasonsColumn, std::min(m_table->columnWidth(ReasonsColumn), 420));
    m_table->resizeRowsToContents();
    if (selected >= 0 && selected < m_table->rowCount())
        m_table->selectRow(selected);
    m_stack->setCurrentWidget(m_client->servos()->count() == 0 ? static_cast<QWidget *>(m_empty)
                                                               : m_table);
    updateActions();
}

void HealthPage::fillRow(int row, const ServoHealth &health, const feetech::JointNames &joints)
{
    QStringList reasons;
    for (const feetech::HealthFinding &finding : health.findings)
        reasons.append(finding.message);
    // The servo by joint where the arm matches a template, as the tree names it.
    const feetech::ServoAddress address {health.id, health.baud};
    const QString servo =
        joints.joint(address).isEmpty() ? QString::number(health.id) : joints.label(address);
    const QStringList cells {servo,
                             health.model,
                             health.firmware,
                             feetech::verdictName(health.verdict),
                             reasons.join(QLatin1Char('\n')),
                             measured(health.voltage, 1, QStringLiteral("V")),
                             measured(health.temperature, 0, QStringLiteral("°C")),
                             measured(health.load, 1, QStringLiteral("%")),
                             health.comm.reads > 0 ? feetech::commText(health.comm) : QString(),
                             health.move ? feetech::moveText(*health.move) : QString()};
    for (int column = 0; column < ColumnCount; ++column) {
        auto *item = new QTableWidgetItem(cells.at(column));
        if (column == ReasonsColumn && !health.findings.isEmpty()) {
            QStringList codes;
            for (const feetech::HealthFinding &finding : health.findings)
                codes.append(finding.code);
            item->setToolTip(codes.join(QStringLiteral(", ")));
        }
        m_table->setItem(row, column, item);
    }
    QTableWidgetItem *verdict = m_table->item(row, VerdictColumn);
    verdict->setForeground(palette::toneColor(verdictTone(health.verdict), palette()));
    QFont bold = verdict->font();
    bold.setBold(true);
    verdict->setFont(bold);
}

void HealthPage::updateActions()
{
    const bool idle = m_client->link()->isConnected() && !m_client->isBusy();
    m_check->setEnabled(idle && m_client->servos()->count() > 0 && !m_checking);
    m_cancel->setEnabled(m_checking);
    const int index = selectedServo();
    m_move->setEnabled(!m_checking && !m_moving && index >= 0
                       && !m_client->health()->moveTestBlocker(index));
    m_save->setEnabled(!m_health.isEmpty() && !m_checking);
}

void HealthPage::showState(const QString &text, bool error)
{
    m_state->setText(text);
    QPalette colours = m_state->palette();
    colours.setColor(QPalette::WindowText,
                     error ? palette::toneColor(palette::Tone::Error, palette())
                           : palette().color(QPalette::WindowText));
    m_state->setPalette(colours);
    if (!error && !text.isEmpty())
        emit message(text);
}

int HealthPage::selectedServo() const
{
    const int row = m_table->currentRow();
    return row >= 0 && row < m_client->servos()->count()
            && m_table->selectionModel()->hasSelection()
        ? row
        : -1;
}
