// The GUI thread's side of the settings check of the servos found, and of its verified fixes.
#pragma once

#include "refusal.h"
#include "settingscheck.h"

#include <QObject>
#include <QVector>

namespace feetech {

class BusClient;
class OperationReply;

// Belongs to a BusClient (BusClient::settingsCheck()). The check reads only; a fix writes only
// the findings it is given, each read back.
class SettingsCheckService : public QObject
{
    Q_OBJECT

public:
    explicit SettingsCheckService(BusClient *client);

    // Reads servos `indexes` in turn and judges them, against `expected` where it names them
    // (checkSettings); ends with checked. Nullptr and *refusal when nothing was started.
    OperationReply *check(const QVector<int> &indexes, const SettingsExpectations &expected = {},
                          Refusal *refusal = nullptr);
    // Writes the expected value of each of `findings` and reads it back (fixSettings in
    // busoperations.h); ends with fixed. Refused (NothingToWrite) when none is fixable.
    OperationReply *fix(const QVector<SettingsFinding> &findings, Refusal *refusal = nullptr);
    bool isChecking() const { return m_checking; }
    bool isFixing() const { return m_fixing; }

signals:
    // Also when the check did not complete (then `completed` is false and the findings are
    // those of the servos read before it ended).
    void checked(const QVector<feetech::SettingsFinding> &findings, bool completed,
                 const QString &message);
    // One outcome per finding fixed, in their order; empty when the fix did not run to its end
    // (the link went down), with `message` saying why.
    void fixed(const QVector<feetech::SettingsFixOutcome> &outcomes, const QString &message);

private:
    Refusal blocker() const;

    BusClient *m_client;
    bool m_checking = false;
    bool m_fixing = false;
    QVector<SettingsReading> m_readings; // of the check running
    SettingsExpectations m_expected; // of the check running
};

} // namespace feetech
