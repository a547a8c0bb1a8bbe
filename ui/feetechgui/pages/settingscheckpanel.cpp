// The settings check's section of the Health page: check, findings, Fix and Fix all.
#include "settingscheckpanel.h"

#include "busclient.h"
#include "palette.h"
#include "widgethelpers.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

using feetech::SettingsFinding;
using feetech::SettingsFixOutcome;

namespace {

bool sameFinding(const SettingsFinding &a, const SettingsFinding &b)
{
    return a.servo.address() == b.servo.address() && a.key == b.key && a.code == b.code;
}

} // namespace

SettingsCheckPanel::SettingsCheckPanel(feetech::BusClient *client, QWidget *parent)
    : QWidget(parent)
    , m_client(client)
    , m_templates(feetech::availableRobotTemplates())
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *intro = new QLabel(
        tr("Finds the settings that stop a servo moving or make it misbehave: multi-turn phase "
           "bit, torque limits at 0, a mode other than position, angle limits, a slow return "
           "delay, an unlocked EEPROM, mixed firmware, voltage limits the supply breaks, and "
           "what differs from the robot template. It only reads; Fix writes the expected value "
           "and reads it back (limits, offset, mode, torque limit and phase only with torque "
           "off)."),
        this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto *buttons = new QHBoxLayout;
    m_template = new QComboBox(this);
    m_template->setObjectName(QStringLiteral("settingsTemplate"));
    m_template->setToolTip(tr("Also compare the servos with this robot template's settings"));
    m_template->addItem(tr("No robot template"));
    for (const feetech::RobotTemplate &robot : std::as_const(m_templates))
        m_template->addItem(feetech::robotDisplayName(robot.name), robot.name);
    m_check = widgethelpers::actionButton(tr("Check settings"), "settingsCheck",
                                          tr("Read the settings of every servo found"), this);
    m_fixAll = widgethelpers::actionButton(
        tr("Fix all"), "settingsFixAll",
        tr("Write the expected value of every finding that a write fixes, each read back"), this);
    buttons->addWidget(new QLabel(tr("Robot:"), this));
    buttons->addWidget(m_template);
    buttons->addWidget(m_check);
    buttons->addWidget(m_fixAll);
    buttons->addStretch(1);
    layout->addLayout(buttons);

    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setObjectName(QStringLiteral("settingsTable"));
    m_table->setHorizontalHeaderLabels(
        {tr("ID"), tr("Setting"), tr("Value"), tr("Expected"), tr("Why"), tr("Fix"), tr("Result")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->verticalHeader()->hide();
    for (const Column column : {IdColumn, SettingColumn, ValueColumn, ExpectedColumn, FixColumn})
        m_table->horizontalHeader()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
    // The reasons and the results are sentences: they share what room is left.
    m_table->horizontalHeader()->setSectionResizeMode(WhyColumn, QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(ResultColumn, QHeaderView::Stretch);
    m_table->setFocusPolicy(Qt::NoFocus); // nothing to select; the Fix buttons take the focus
    m_table->setWordWrap(true);
    layout->addWidget(m_table, 1);
    m_state = new QLabel(this);
    m_state->setObjectName(QStringLiteral("settingsState"));
    m_state->setWordWrap(true);
    layout->addWidget(m_state);

    connect(m_check, &QPushButton::clicked, this, [this] { check(); });
    connect(m_fixAll, &QPushButton::clicked, this, [this] { fixAll(); });
    connect(m_client, &feetech::BusClient::busyChanged, this, &SettingsCheckPanel::updateActions);
    connect(m_client, &feetech::BusClient::statusChanged, this, &SettingsCheckPanel::updateActions);
    connect(m_client->servos(), &feetech::ServoList::servosChanged, this, [this] {
        showFindings({}); // of servos that may no longer be there
        showState({}, false);
    });
    feetech::SettingsCheckService *service = m_client->settingsCheck();
    connect(service, &feetech::SettingsCheckService::checked, this,
            [this](const QVector<SettingsFinding> &found, bool completed, const QString &text) {
                showFindings(found);
                if (!completed)
                    showState(text, true);
                else if (found.isEmpty())
                    showState(tr("No problem found in the settings."), false);
                else
                    showState(tr("%n finding(s).", nullptr, int(found.size())), false);
            });
    connect(service, &feetech::SettingsCheckService::fixed, this,
            &SettingsCheckPanel::showOutcomes);
    updateActions();
}

QPushButton *SettingsCheckPanel::fixButton(int row) const
{
    return qobject_cast<QPushButton *>(m_table->cellWidget(row, FixColumn));
}

void SettingsCheckPanel::chooseTemplate(const QString &name)
{
    const int index = name.isEmpty() ? 0 : m_template->findData(name);
    if (index >= 0)
        m_template->setCurrentIndex(index);
}

feetech::SettingsExpectations SettingsCheckPanel::expectations() const
{
    const int chosen = m_template->currentIndex() - 1;
    if (chosen < 0 || chosen >= m_templates.size())
        return {};
    return feetech::settingsExpectations(m_templates.at(chosen));
}

bool SettingsCheckPanel::check(QString *error)
{
    QVector<int> indexes;
    for (int i = 0; i < m_client->servos()->count(); ++i)
        indexes.append(i);
    feetech::Refusal refusal;
    if (!m_client->settingsCheck()->check(indexes, expectations(), &refusal)) {
        const QString why = refusal.describe();
        showState(why, true);
        if (error)
            *error = why;
        return false;
    }
    showFindings({});
    showState(tr("Reading the settings of %n servo(s)…", nullptr, int(indexes.size())), false);
    updateActions();
    return true;
}

bool SettingsCheckPanel::fix(int row, QString *error)
{
    if (row < 0 || row >= m_findings.size()) {
        if (error)
            *error = tr("There is no finding in row %1.").arg(row + 1);
        return false;
    }
    return startFix({m_findings.at(row)}, error);
}

bool SettingsCheckPanel::fixAll(QString *error)
{
    QVector<SettingsFinding> pending;
    for (int row = 0; row < m_findings.size(); ++row) {
        if (!m_fixed.value(row))
            pending.append(m_findings.at(row));
    }
    return startFix(pending, error);
}

bool SettingsCheckPanel::startFix(const QVector<SettingsFinding> &findings, QString *error)
{
    feetech::Refusal refusal;
    if (!m_client->settingsCheck()->fix(findings, &refusal)) {
        const QString why = refusal.describe();
        showState(why, true);
        if (error)
            *error = why;
        return false;
    }
    showState(tr("Writing and reading back…"), false);
    updateActions();
    return true;
}

void SettingsCheckPanel::showFindings(const QVector<SettingsFinding> &findings)
{
    m_findings = findings;
    m_fixed = QVector<bool>(findings.size(), false);
    m_table->setRowCount(0);
    m_table->setRowCount(int(findings.size()));
    for (int row = 0; row < findings.size(); ++row) {
        const SettingsFinding &finding = findings.at(row);
        const auto cell = [this, row](int column, const QString &text) {
            m_table->setItem(row, column, new QTableWidgetItem(text));
        };
        cell(IdColumn, QString::number(finding.servo.id));
        cell(SettingColumn, finding.key.isEmpty() ? finding.code : finding.key);
        cell(ValueColumn,
             !finding.valueText.isEmpty()
                 ? finding.valueText
                 : (finding.value ? QString::number(*finding.value) : QString()));
        cell(ExpectedColumn, finding.expected ? QString::number(*finding.expected) : QString());
        cell(WhyColumn, finding.why);
        cell(ResultColumn, finding.fixable() ? QString() : tr("Nothing to write fixes this"));
        if (finding.fixable()) {
            auto *button = new QPushButton(tr("Fix"), m_table);
            button->setObjectName(QStringLiteral("settingsFix%1").arg(row));
            button->setToolTip(tr("Write %1 = %2 to servo %3 and read it back")
                                   .arg(finding.key)
                                   .arg(*finding.expected)
                                   .arg(finding.servo.id));
            connect(button, &QPushButton::clicked, this, [this, row] { fix(row); });
            m_table->setCellWidget(row, FixColumn, button);
        }
    }
    m_table->resizeRowsToContents();
    updateActions();
}

void SettingsCheckPanel::showOutcomes(const QVector<SettingsFixOutcome> &outcomes,
                                      const QString &text)
{
    bool allVerified = !outcomes.isEmpty();
    for (const SettingsFixOutcome &outcome : outcomes) {
        allVerified = allVerified && outcome.verified();
        for (int row = 0; row < m_findings.size(); ++row) {
            if (!sameFinding(m_findings.at(row), outcome.finding))
                continue;
            auto *item = new QTableWidgetItem(
                outcome.verified() ? tr("Fixed, verified") : feetech::fixOutcomeText(outcome));
            item->setForeground(palette::toneColor(
                outcome.verified() ? palette::Tone::Good : palette::Tone::Error, palette()));
            m_table->setItem(row, ResultColumn, item);
            if (outcome.verified()) {
                m_fixed[row] = true;
                if (QPushButton *button = fixButton(row))
                    button->setEnabled(false);
            }
        }
    }
    m_table->resizeRowsToContents();
    showState(allVerified ? tr("%1 Check again to see the servos as they are now.").arg(text)
                          : text,
              !allVerified);
    updateActions();
}

void SettingsCheckPanel::updateActions()
{
    const feetech::SettingsCheckService *service = m_client->settingsCheck();
    const bool idle = m_client->link()->isConnected() && !m_client->isBusy()
        && !service->isChecking() && !service->isFixing();
    m_check->setEnabled(idle && m_client->servos()->count() > 0);
    m_template->setEnabled(!service->isChecking());
    bool anyToFix = false;
    for (int row = 0; row < m_findings.size(); ++row) {
        const bool open = m_findings.at(row).fixable() && !m_fixed.value(row);
        anyToFix = anyToFix || open;
        if (QPushButton *button = fixButton(row))
            button->setEnabled(idle && open);
    }
    m_fixAll->setEnabled(idle && anyToFix);
}

void SettingsCheckPanel::showState(const QString &text, bool error)
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
