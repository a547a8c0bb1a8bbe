// The guard settings dialog: one row of editors per servo, defaults from its registers.
#include "guardsettingsdialog.h"

#include "busclient.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace {

QDoubleSpinBox *figureBox(double minimum, double maximum, const QString &suffix, QWidget *parent)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setRange(minimum, maximum);
    box->setDecimals(1);
    box->setSuffix(suffix);
    return box;
}

} // namespace

GuardSettingsDialog::GuardSettingsDialog(feetech::BusClient *client, QWidget *parent)
    : QDialog(parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("guardSettingsDialog"));
    setWindowTitle(tr("Overload and thermal guard"));
    auto *intro = new QLabel(
        tr("While a servo is driven (torque on, a goal, a test, an identify), the guard watches "
           "its load and temperature. When the load stays above its limit for the hold time, or "
           "the temperature comes within the margin of its maximum, it warns and then holds the "
           "servo where it stands (or switches its torque off). It never moves a servo. The "
           "defaults come from each servo's overload torque, protection time and maximum "
           "temperature registers."),
        this);
    intro->setWordWrap(true);
    m_enabled = new QCheckBox(tr("Guard the servos of this bus (recommended)"), this);
    m_enabled->setObjectName(QStringLiteral("guardEnabled"));
    m_enabled->setChecked(client->guard()->settings().enabled);

    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setObjectName(QStringLiteral("guardTable"));
    m_table->setHorizontalHeaderLabels({tr("Servo"), tr("Guarded"), tr("Load limit"),
                                        tr("Hold time"), tr("Max temperature"), tr("Acts within"),
                                        tr("Action")});
    m_table->verticalHeader()->hide();
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    for (int index = 0; index < client->servos()->count(); ++index) {
        const feetech::ServoInfo &info = client->servos()->at(index).info;
        if (!info.hasTable())
            continue;
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        m_indexes.append(index);
        auto *name = new QTableWidgetItem(tr("ID %1 (%2)").arg(info.id).arg(info.model.name));
        name->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, ServoColumn, name);
        auto *on = new QCheckBox(m_table);
        auto *load = figureBox(1.0, 100.0, tr(" %"), m_table);
        auto *hold = new QSpinBox(m_table);
        hold->setRange(100, 10000);
        hold->setSingleStep(100);
        hold->setSuffix(tr(" ms"));
        auto *maxTemperature = figureBox(20.0, 120.0, tr(" °C"), m_table);
        auto *margin = figureBox(0.0, 30.0, tr(" °C"), m_table);
        auto *action = new QComboBox(m_table);
        for (const auto kind : {feetech::GuardAction::Hold, feetech::GuardAction::TorqueOff})
            action->addItem(feetech::guardActionName(kind), int(kind));
        m_table->setCellWidget(row, OnColumn, on);
        m_table->setCellWidget(row, LoadColumn, load);
        m_table->setCellWidget(row, HoldColumn, hold);
        m_table->setCellWidget(row, MaxTemperatureColumn, maxTemperature);
        m_table->setCellWidget(row, MarginColumn, margin);
        m_table->setCellWidget(row, ActionColumn, action);
        fillRow(row, client->guard()->limits(index));
    }
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    QPushButton *defaults = buttons->addButton(tr("Restore defaults"), QDialogButtonBox::ResetRole);
    defaults->setObjectName(QStringLiteral("guardDefaultsButton"));
    connect(defaults, &QPushButton::clicked, this, &GuardSettingsDialog::restoreDefaults);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        m_client->guard()->setSettings(settings());
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(m_enabled);
    layout->addWidget(m_table, 1);
    layout->addWidget(buttons);
    const int em = fontMetrics().horizontalAdvance(u'm');
    resize(em * 70, em * 30);
}

void GuardSettingsDialog::fillRow(int row, const feetech::GuardLimits &limits)
{
    qobject_cast<QCheckBox *>(m_table->cellWidget(row, OnColumn))->setChecked(limits.enabled);
    qobject_cast<QDoubleSpinBox *>(m_table->cellWidget(row, LoadColumn))
        ->setValue(limits.loadPercent);
    qobject_cast<QSpinBox *>(m_table->cellWidget(row, HoldColumn))
        ->setValue(int(limits.holdTime.count()));
    qobject_cast<QDoubleSpinBox *>(m_table->cellWidget(row, MaxTemperatureColumn))
        ->setValue(limits.maxTemperature);
    qobject_cast<QDoubleSpinBox *>(m_table->cellWidget(row, MarginColumn))
        ->setValue(limits.temperatureMargin);
    auto *action = qobject_cast<QComboBox *>(m_table->cellWidget(row, ActionColumn));
    action->setCurrentIndex(action->findData(int(limits.action)));
}

feetech::GuardLimits GuardSettingsDialog::rowLimits(int row) const
{
    // What the dialog does not show (the current limit, the warn margin) stays as it was.
    feetech::GuardLimits limits = m_client->guard()->limits(m_indexes.at(row));
    limits.enabled = qobject_cast<QCheckBox *>(m_table->cellWidget(row, OnColumn))->isChecked();
    limits.loadPercent =
        qobject_cast<QDoubleSpinBox *>(m_table->cellWidget(row, LoadColumn))->value();
    limits.holdTime = std::chrono::milliseconds(
        qobject_cast<QSpinBox *>(m_table->cellWidget(row, HoldColumn))->value());
    limits.maxTemperature =
        qobject_cast<QDoubleSpinBox *>(m_table->cellWidget(row, MaxTemperatureColumn))->value();
    limits.temperatureMargin =
        qobject_cast<QDoubleSpinBox *>(m_table->cellWidget(row, MarginColumn))->value();
    limits.temperatureWarnMargin = std::max(limits.temperatureWarnMargin, limits.temperatureMargin);
    limits.action = feetech::GuardAction(
        qobject_cast<QComboBox *>(m_table->cellWidget(row, ActionColumn))->currentData().toInt());
    return limits;
}

feetech::GuardSettings GuardSettingsDialog::settings() const
{
    feetech::GuardSettings settings;
    settings.enabled = m_enabled->isChecked();
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const int index = m_indexes.at(row);
        const feetech::GuardLimits limits = rowLimits(row);
        if (limits != m_client->guard()->defaults(index)) {
            const feetech::ServoInfo &info = m_client->servos()->at(index).info;
            settings.servos.insert({info.id, info.baud}, limits);
        }
    }
    return settings;
}

void GuardSettingsDialog::restoreDefaults()
{
    m_enabled->setChecked(true);
    for (int row = 0; row < m_table->rowCount(); ++row)
        fillRow(row, m_client->guard()->defaults(m_indexes.at(row)));
}
