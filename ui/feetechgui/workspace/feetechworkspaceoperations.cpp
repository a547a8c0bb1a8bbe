// The Feetech workspace's operations: the scan dialog and the scan, Apply with its
// confirmations, the guided flows (change ID and baud, calibrate middle, factory reset) and
// profiles of the servo shown.
#include "feetechworkspace.h"

#include "busclient.h"
#include "profileactions.h"
#include "scandialog.h"
#include "scanmemory.h"
#include "servoparameters.h"

#include <QDateTime>
#include <QDir>
#include <QInputDialog>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>

#include <algorithm>

void FeetechWorkspace::openScanDialog()
{
    ScanDialog dialog(m_scanOptions, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    scanmemory::rememberScanOptions(dialog.options());
    startScan(dialog.options());
}

void FeetechWorkspace::startScan(const feetech::ScanOptions &options)
{
    if (!m_client->isConnected()) {
        emit problem(tr("Connect to the bus before scanning."));
        return;
    }
    m_scanOptions = options;
    m_current.reset();
    m_scan->hide();
    m_cancelScan->show();
    m_scanProgress->setValue(0);
    m_scanProgress->show();
    m_client->scan(options);
    showServo();
}

void FeetechWorkspace::apply()
{
    const int index = currentIndex();
    model::ParameterModel *parameters = m_client->parameters(index);
    if (!parameters)
        return;
    const auto newId = parameters->pendingValue(QStringLiteral("id"));
    const auto newBaud = parameters->pendingValue(QStringLiteral("baud_rate"));
    const feetech::ServoInfo info = m_client->servo(index).info;
    if (newId || newBaud) {
        QStringList changes;
        if (newId)
            changes.append(tr("its ID from %1 to %2").arg(info.id).arg(*newId));
        if (newBaud)
            changes.append(tr("its baud rate from %1 to %2")
                               .arg(feetech::baudText(info.baud),
                                    feetech::baudText(feetech::baudForCode(int(*newBaud)))));
        const auto answer = QMessageBox::question(
            this, tr("Change how the servo is reached?"),
            tr("This changes %1.<br><br>ServoBench writes it to EEPROM with the lock opened "
               "and closed again, then finds the servo at its new address and confirms it "
               "there. Other programs and robot code must use the new address afterwards.")
                .arg(changes.join(tr(" and "))),
            QMessageBox::Ok | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Ok)
            return;
    }
    QString error;
    if (!m_client->applyAll(index, &error))
        emit problem(tr("Nothing was written: %1").arg(error));
}

void FeetechWorkspace::run(feetech::OperationReply *(feetech::BusClient::*operation)(int,
                                                                                     QString *),
                           const QString &what)
{
    QString error;
    if (!(m_client->*operation)(currentIndex(), &error))
        emit problem(error);
    else
        emit message(what);
}

void FeetechWorkspace::changeId()
{
    const int index = currentIndex();
    if (index < 0)
        return;
    const feetech::ServoInfo info = m_client->servo(index).info;
    QStringList used;
    for (const int id : m_client->idsInUse())
        used.append(QString::number(id));
    bool ok = false;
    const int newId = QInputDialog::getInt(
        this, tr("Change ID"),
        tr("New ID for %1 (IDs found on this bus: %2).\nAn ID in use is refused.")
            .arg(servoTitle(), used.join(QStringLiteral(", "))),
        info.id, 0, feetech::kMaxServoId, 1, &ok);
    if (!ok || newId == info.id)
        return;
    if (m_client->idsInUse().contains(newId)) {
        emit problem(tr("ID %1 is already in use on this bus; nothing was written.").arg(newId));
        return;
    }
    QString error;
    if (!m_client->changeId(index, newId, &error))
        emit problem(error);
}

void FeetechWorkspace::changeBaud()
{
    const int index = currentIndex();
    if (index < 0)
        return;
    const feetech::ServoInfo info = m_client->servo(index).info;
    QStringList rates;
    for (const qint32 rate : feetech::baudRates())
        rates.append(QString::number(rate));
    bool ok = false;
    const QString chosen = QInputDialog::getItem(
        this, tr("Change baud rate"),
        tr("New baud rate for %1 (now %2). ServoBench follows the servo to the new rate and "
           "confirms it there.")
            .arg(servoTitle(), feetech::baudText(info.baud)),
        rates, int(rates.indexOf(QString::number(info.baud))), false, &ok);
    if (!ok || chosen.toInt() == info.baud)
        return;
    QString error;
    if (!m_client->changeBaud(index, chosen.toInt(), &error))
        emit problem(error);
}

void FeetechWorkspace::calibrateMiddle()
{
    const auto answer = QMessageBox::question(
        this, tr("Calibrate middle"),
        tr("The horn's present position becomes the middle (2048) of %1. Turn the horn to "
           "where the middle should be first; the new offset is stored in EEPROM.")
            .arg(servoTitle()),
        QMessageBox::Ok | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer == QMessageBox::Ok)
        run(&feetech::BusClient::calibrateMiddle, tr("Calibrating the middle…"));
}

void FeetechWorkspace::factoryReset()
{
    const int index = currentIndex();
    if (index < 0)
        return;
    const feetech::ServoInfo info = m_client->servo(index).info;
    // A backup first, always: a factory reset cannot be undone any other way.
    const QString suggested =
        QStringLiteral("servo-%1-backup-%2.json")
            .arg(info.id)
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss")));
    QMessageBox::information(this, tr("Factory reset"),
                             tr("First save a backup profile of %1; the reset only starts once "
                                "it is saved.")
                                 .arg(servoTitle()));
    const QString path = profileactions::chooseSavePath(this, suggested);
    if (path.isEmpty())
        return;
    if (!saveProfile(path, false)) // what the servo holds, not what is being edited
        return;
    const auto answer = QMessageBox::warning(
        this, tr("Factory reset"),
        tr("Backup saved to %1.<br><br>Restore the factory values of %2? Everything but the ID "
           "returns to what the servo left the factory with, possibly including its baud "
           "rate; ServoBench looks for it at every rate afterwards.")
            .arg(QDir::toNativeSeparators(path).toHtmlEscaped(), servoTitle()),
        QMessageBox::Reset | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer == QMessageBox::Reset)
        run(&feetech::BusClient::factoryReset, tr("Restoring factory values…"));
}

void FeetechWorkspace::onOperationFinished(const feetech::OperationResult &result)
{
    using feetech::Operation;
    if (result.control) {
        // Goal and torque writes come many a second: the pages show them; only a failure is
        // worth the status bar, and the servo list has not changed.
        if (!result.ok)
            emit problem(result.message);
        return;
    }
    if (result.ok && m_current
        && (result.operation == Operation::ChangeId || result.operation == Operation::ChangeBaud
            || result.operation == Operation::FactoryReset))
        m_current = std::make_pair(result.servo.id, result.servo.baud);
    if (result.ok)
        emit message(result.message);
    else
        emit problem(result.message);
    rebuildTree();
    showServo();
}

void FeetechWorkspace::chooseProfileToSave()
{
    const int index = currentIndex();
    if (index < 0) {
        emit problem(tr("Choose a servo first."));
        return;
    }
    const QString path = profileactions::chooseSavePath(
        this, QStringLiteral("servo-%1.json").arg(m_client->servo(index).info.id));
    if (!path.isEmpty() && saveProfile(path))
        emit message(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
}

bool FeetechWorkspace::saveProfile(const QString &path, bool withEdits)
{
    const int index = currentIndex();
    if (index < 0 || !m_client->servo(index).info.hasTable()) {
        emit problem(tr("Only a servo of a known model can be saved as a profile."));
        return false;
    }
    const feetech::ServoInfo &info = m_client->servo(index).info;
    QString error;
    if (!profileactions::save(path, *m_client->parameters(index),
                              feetech::familyKey(*info.model.family), info.model.name,
                              feetech::profileDefinitions(info.table()), withEdits, &error)) {
        emit problem(error);
        return false;
    }
    return true;
}

void FeetechWorkspace::chooseProfileToLoad()
{
    const QString path = profileactions::chooseLoadPath(this);
    if (!path.isEmpty())
        loadProfile(path);
}

void FeetechWorkspace::loadProfile(const QString &path)
{
    const int index = currentIndex();
    if (index < 0 || !m_client->servo(index).info.hasTable()) {
        emit problem(tr("Choose a servo of a known model first."));
        return;
    }
    if (m_client->isBusy()) {
        emit problem(tr("Wait for the running operation to finish before loading a profile."));
        return;
    }
    const feetech::ServoInfo &info = m_client->servo(index).info;
    QString error;
    const profileactions::LoadOutcome outcome = profileactions::loadAsEdits(
        this, path, feetech::familyKey(*info.model.family),
        feetech::profileDefinitions(info.table()), *m_client->parameters(index), &error);
    if (outcome == profileactions::LoadOutcome::Failed)
        emit problem(error);
    else if (const QString note = profileactions::outcomeMessage(outcome); !note.isEmpty())
        emit message(note);
}
