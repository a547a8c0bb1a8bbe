// The robot template editor: base chooser, name, rate, joints table, settings from a servo,
// live validation through robotTemplateFromJson, saving with an overwrite question.
#include "robottemplatedialog.h"

#include "busclient.h"
#include "modeltable.h"
#include "palette.h"
#include "registertable.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace {

// "p_gain=16, d_gain=32": the joint's settings as one editable cell.
QString settingsText(const QMap<QString, qint32> &settings)
{
    QStringList parts;
    for (auto it = settings.cbegin(); it != settings.cend(); ++it)
        parts.append(QStringLiteral("%1=%2").arg(it.key()).arg(it.value()));
    return parts.join(QStringLiteral(", "));
}

// A file name from a template name: characters no file system takes become "-".
QString fileNameFor(const QString &name)
{
    QString file = name.trimmed();
    for (QChar &c : file) {
        if (QStringView(u"/\\:*?\"<>|").contains(c) || c.unicode() < 32)
            c = u'-';
    }
    return file + QStringLiteral(".json");
}

} // namespace

RobotTemplateDialog::RobotTemplateDialog(feetech::BusClient *client, QWidget *parent)
    : QDialog(parent)
    , m_client(client)
    , m_askOverwrite([this](const QString &path) {
        return QMessageBox::question(
                   this, tr("Replace the template?"),
                   tr("%1 exists already. Replace it?").arg(QDir::toNativeSeparators(path)))
            == QMessageBox::Yes;
    })
{
    setObjectName(QStringLiteral("robotTemplateDialog"));
    setWindowTitle(tr("Save as robot template"));
    QStringList problems;
    m_templates = feetech::availableRobotTemplates(&problems);

    m_base = new QComboBox(this);
    m_base->setObjectName(QStringLiteral("templateBase"));
    for (const feetech::RobotTemplate &robot : std::as_const(m_templates))
        m_base->addItem(tr("Template: %1").arg(robot.name));
    if (m_client->servos()->count() > 0)
        m_base->addItem(tr("The %n servo(s) the scan found", nullptr, m_client->servos()->count()));
    m_name = new QLineEdit(this);
    m_name->setObjectName(QStringLiteral("templateName"));
    m_baud = new QComboBox(this);
    m_baud->setObjectName(QStringLiteral("templateBaud"));
    for (const qint32 rate : feetech::baudRates())
        m_baud->addItem(feetech::baudText(rate), rate);

    m_joints = new QTableWidget(0, ColumnCount, this);
    m_joints->setObjectName(QStringLiteral("templateJoints"));
    m_joints->setHorizontalHeaderLabels({tr("Joint name"), tr("ID"), tr("Model"), tr("Full turn"),
                                         tr("Settings (register units)")});
    m_joints->horizontalHeaderItem(SettingsColumn)
        ->setToolTip(tr("Registers set-up writes to this joint: key=value, separated by commas"));
    m_joints->horizontalHeaderItem(FullTurnColumn)
        ->setToolTip(tr("Turns without end stops (a wrist roll): calibrated over 0-4095"));
    m_joints->verticalHeader()->hide();
    m_joints->horizontalHeader()->setStretchLastSection(true);
    m_joints->setSelectionBehavior(QAbstractItemView::SelectRows);
    auto *add = new QPushButton(tr("Add joint"), this);
    auto *remove = new QPushButton(tr("Remove joint"), this);
    remove->setObjectName(QStringLiteral("removeJoint"));
    m_servo = new QComboBox(this);
    m_servo->setObjectName(QStringLiteral("settingsServo"));
    for (int i = 0; i < m_client->servos()->count(); ++i) {
        const feetech::ServoInfo &info = m_client->servos()->at(i).info;
        m_servo->addItem(tr("ID %1 (%2)").arg(info.id).arg(info.model.name), i);
    }
    auto *take = new QPushButton(tr("Take settings from servo"), this);
    take->setObjectName(QStringLiteral("takeSettings"));
    take->setToolTip(tr("The selected joint's settings get the chosen servo's present values "
                        "of the same registers"));
    take->setEnabled(m_servo->count() > 0);

    m_error = new QLabel(this);
    m_error->setObjectName(QStringLiteral("templateError"));
    m_error->setWordWrap(true);
    QPalette warning = m_error->palette();
    warning.setColor(QPalette::WindowText,
                     palette::toneColor(palette::Tone::Error, m_error->palette()));
    m_error->setPalette(warning);
    m_path = new QLabel(this);
    m_path->setWordWrap(true);
    m_path->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this);
    m_save = buttons->button(QDialogButtonBox::Save);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_save, &QPushButton::clicked, this, [this] {
        QString error;
        if (save(&error)) {
            accept();
            return;
        }
        if (!error.isEmpty())
            m_error->setText(error);
    });

    auto *form = new QFormLayout;
    form->addRow(tr("Start from:"), m_base);
    form->addRow(tr("Name:"), m_name);
    form->addRow(tr("Baud rate after set-up:"), m_baud);
    auto *jointButtons = new QHBoxLayout;
    jointButtons->addWidget(add);
    jointButtons->addWidget(remove);
    jointButtons->addStretch(1);
    jointButtons->addWidget(m_servo);
    jointButtons->addWidget(take);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_joints, 1);
    layout->addLayout(jointButtons);
    if (!problems.isEmpty())
        layout->addWidget(
            new QLabel(tr("Not offered (unreadable): %1").arg(problems.join(u' ')), this));
    layout->addWidget(m_error);
    layout->addWidget(m_path);
    layout->addWidget(buttons);

    connect(m_base, &QComboBox::currentIndexChanged, this, &RobotTemplateDialog::startFrom);
    connect(m_name, &QLineEdit::textChanged, this, &RobotTemplateDialog::validate);
    connect(m_baud, &QComboBox::currentIndexChanged, this, &RobotTemplateDialog::validate);
    connect(m_joints, &QTableWidget::itemChanged, this, &RobotTemplateDialog::validate);
    connect(add, &QPushButton::clicked, this, [this] {
        feetech::RobotJoint joint;
        joint.name = QStringLiteral("joint_%1").arg(m_joints->rowCount() + 1);
        joint.id = m_joints->rowCount() + 1;
        joint.model = QStringLiteral("STS3215");
        addJointRow(joint);
        validate();
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        const int row = m_joints->currentRow();
        if (row >= 0)
            m_joints->removeRow(row);
        validate();
    });
    connect(take, &QPushButton::clicked, this, &RobotTemplateDialog::takeSettingsFromServo);

    const int em = fontMetrics().horizontalAdvance(u'm');
    m_joints->setColumnWidth(NameColumn, em * 10);
    m_joints->setColumnWidth(IdColumn, em * 3);
    m_joints->setColumnWidth(ModelColumn, em * 7);
    m_joints->setColumnWidth(FullTurnColumn, em * 5);
    resize(em * 72, em * 42);
    startFrom(0);
}

void RobotTemplateDialog::setOverwriteQuestion(std::function<bool(const QString &path)> ask)
{
    m_askOverwrite = std::move(ask);
}

void RobotTemplateDialog::startFrom(int at)
{
    if (at < 0)
        return;
    if (at < m_templates.size()) {
        feetech::RobotTemplate robot = m_templates.at(at);
        // A built-in template keeps its name; the copy needs one of its own.
        if (at < feetech::builtInRobotTemplates().size())
            robot.name = tr("My %1").arg(robot.name);
        fill(robot);
        return;
    }
    // The servos the scan found: one joint each, named after its ID, no settings yet.
    feetech::RobotTemplate robot;
    robot.name = tr("My arm");
    for (int i = 0; i < m_client->servos()->count(); ++i) {
        const feetech::ServoInfo &info = m_client->servos()->at(i).info;
        if (i == 0)
            robot.baud = info.baud;
        feetech::RobotJoint joint;
        joint.name = QStringLiteral("joint_%1").arg(info.id);
        joint.id = info.id;
        joint.model = info.model.name.section(u'/', 0, 0);
        robot.joints.append(joint);
    }
    fill(robot);
}

void RobotTemplateDialog::fill(const feetech::RobotTemplate &robot)
{
    m_filling = true;
    m_name->setText(robot.name);
    m_baud->setCurrentIndex(std::max(0, m_baud->findData(robot.baud)));
    m_joints->setRowCount(0);
    for (const feetech::RobotJoint &joint : robot.joints)
        addJointRow(joint);
    m_filling = false;
    validate();
}

void RobotTemplateDialog::addJointRow(const feetech::RobotJoint &joint)
{
    const bool filling = m_filling;
    m_filling = true;
    const int row = m_joints->rowCount();
    m_joints->insertRow(row);
    m_joints->setItem(row, NameColumn, new QTableWidgetItem(joint.name));
    m_joints->setItem(row, IdColumn, new QTableWidgetItem(QString::number(joint.id)));
    m_joints->setItem(row, ModelColumn, new QTableWidgetItem(joint.model));
    auto *fullTurn = new QTableWidgetItem;
    fullTurn->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsSelectable);
    fullTurn->setCheckState(joint.fullTurn ? Qt::Checked : Qt::Unchecked);
    m_joints->setItem(row, FullTurnColumn, fullTurn);
    auto *settings = new QTableWidgetItem(settingsText(joint.settings));
    settings->setToolTip(settings->text());
    m_joints->setItem(row, SettingsColumn, settings);
    m_filling = filling;
}

std::optional<feetech::RobotTemplate> RobotTemplateDialog::edited(QString *error) const
{
    feetech::RobotTemplate robot;
    robot.name = m_name->text().trimmed();
    robot.baud = m_baud->currentData().toInt();
    for (int row = 0; row < m_joints->rowCount(); ++row) {
        const auto text = [this, row](int column) {
            const QTableWidgetItem *item = m_joints->item(row, column);
            return item ? item->text().trimmed() : QString();
        };
        feetech::RobotJoint joint;
        joint.name = text(NameColumn);
        bool ok = false;
        joint.id = text(IdColumn).toInt(&ok);
        if (!ok) {
            *error = tr("joint %1: the ID \"%2\" is not a number").arg(row + 1).arg(text(IdColumn));
            return std::nullopt;
        }
        joint.model = text(ModelColumn);
        joint.fullTurn = m_joints->item(row, FullTurnColumn)->checkState() == Qt::Checked;
        for (const QString &part : text(SettingsColumn).split(u',', Qt::SkipEmptyParts)) {
            const QString key = part.section(u'=', 0, 0).trimmed();
            const qint32 value = part.section(u'=', 1).trimmed().toInt(&ok);
            if (!ok || key.isEmpty()) {
                *error = tr("joint %1: \"%2\" is not key=value (a register and a whole number)")
                             .arg(row + 1)
                             .arg(part.trimmed());
                return std::nullopt;
            }
            joint.settings.insert(key, value);
        }
        robot.joints.append(joint);
    }
    for (const feetech::RobotTemplate &builtIn : feetech::builtInRobotTemplates()) {
        if (builtIn.name.compare(robot.name, Qt::CaseInsensitive) == 0) {
            *error = tr("\"%1\" is the name of a built-in template: choose another, so the "
                        "wizards can tell them apart")
                         .arg(robot.name);
            return std::nullopt;
        }
    }
    // Exactly the checks loading makes, on exactly the bytes that would be written.
    util::FileError why;
    auto checked = feetech::robotTemplateFromJson(feetech::robotTemplateToJson(robot),
                                                  QDir::toNativeSeparators(targetPath()), &why);
    if (!checked)
        *error = why.describe();
    return checked;
}

QString RobotTemplateDialog::targetPath() const
{
    return QDir(feetech::userRobotTemplateFolder()).filePath(fileNameFor(m_name->text()));
}

void RobotTemplateDialog::validate()
{
    if (m_filling)
        return;
    QString error;
    const bool valid = edited(&error).has_value();
    m_error->setText(valid ? QString() : error);
    m_save->setEnabled(valid);
    m_path->setText(valid ? tr("Will be saved to %1, where the set-up wizards find it.")
                                .arg(QDir::toNativeSeparators(targetPath()))
                          : QString());
}

bool RobotTemplateDialog::save(QString *error)
{
    QString why;
    const auto robot = edited(&why);
    if (!robot) {
        if (error)
            *error = why;
        return false;
    }
    const QString path = targetPath();
    if (QFileInfo::exists(path) && !m_askOverwrite(path)) {
        if (error)
            error->clear(); // the user said no: nothing to report
        return false;
    }
    if (!QDir().mkpath(feetech::userRobotTemplateFolder())) {
        if (error)
            *error = tr("The folder %1 cannot be created.")
                         .arg(QDir::toNativeSeparators(feetech::userRobotTemplateFolder()));
        return false;
    }
    util::FileError notSaved;
    if (!feetech::saveRobotTemplate(*robot, path, &notSaved)) {
        if (error)
            *error = notSaved.describe();
        return false;
    }
    emit saved(path);
    return true;
}

void RobotTemplateDialog::takeSettingsFromServo()
{
    const int row = m_joints->currentRow();
    const int index = m_servo->currentData().toInt();
    if (row < 0 || index < 0 || index >= m_client->servos()->count()) {
        m_error->setText(tr("Select a joint and a servo first."));
        return;
    }
    if (m_client->servos()->at(index).read) {
        applyServoValues(row, index);
        return;
    }
    if (m_client->isBusy()) {
        m_error->setText(tr("The bus is busy: try again in a moment."));
        return;
    }
    const feetech::ServoInfo &info = m_client->servos()->at(index).info;
    m_pendingRead = std::pair(row, info.address());
    m_error->setText(tr("Reading servo ID %1…").arg(info.id));
    if (feetech::OperationReply *reply = m_client->readServo(index))
        connect(reply, &feetech::OperationReply::finished, this,
                &RobotTemplateDialog::onOperationFinished);
}

void RobotTemplateDialog::onOperationFinished(const feetech::OperationResult &result)
{
    if (!m_pendingRead || result.operation != feetech::Operation::Read
        || result.servo.address() != m_pendingRead->second)
        return;
    const int row = m_pendingRead->first;
    m_pendingRead.reset();
    if (!result.ok) {
        m_error->setText(result.message);
        return;
    }
    applyServoValues(row, m_client->servos()->indexOf(result.servo.address()));
}

void RobotTemplateDialog::applyServoValues(int row, int index)
{
    if (row >= m_joints->rowCount() || index < 0)
        return;
    QString error;
    const auto robot = edited(&error);
    if (!robot) {
        m_error->setText(tr("Fix the template first: %1").arg(error));
        return;
    }
    const model::ParameterModel *parameters = m_client->servos()->parameters(index);
    QMap<QString, qint32> settings = robot->joints.at(row).settings;
    if (settings.isEmpty()) {
        m_error->setText(tr("Joint %1 sets no registers yet: type their keys (key=value), then "
                            "take their values from a servo.")
                             .arg(robot->joints.at(row).name));
        return;
    }
    QStringList unknown;
    for (auto it = settings.begin(); it != settings.end(); ++it) {
        const auto value = parameters->deviceValue(it.key());
        if (value)
            it.value() = qint32(*value);
        else
            unknown.append(it.key());
    }
    m_joints->item(row, SettingsColumn)->setText(settingsText(settings));
    if (!unknown.isEmpty())
        m_error->setText(tr("The servo has no value for %1: kept as they were.")
                             .arg(unknown.join(QStringLiteral(", "))));
}
