// The GUI thread's side of the health check of the servos found, and of its confirmed move test.
#pragma once

#include "refusal.h"
#include "servohealth.h"

#include <QObject>
#include <QVector>

#include <optional>

namespace feetech {

class BusClient;
class OperationReply;

// Belongs to a BusClient (BusClient::health()). Reads only, except the move test, which runs
// only once the user confirmed it.
class HealthService : public QObject
{
    Q_OBJECT

public:
    explicit HealthService(BusClient *client);

    // Reads each of servos `indexes` in turn (its limits and `reads` feedback blocks); a
    // reading per servo, then checkFinished. Nullptr and *refusal
    // when nothing was started.
    OperationReply *check(const QVector<int> &indexes, int reads = kDefaultHealthReads,
                          Refusal *refusal = nullptr);
    // The running check stops before its next servo.
    void cancel();
    bool isChecking() const { return m_checking; }
    // Why servo `index` cannot take the move test now (none when it can).
    Refusal moveTestBlocker(int index) const;
    // The move test moves the horn: it runs only when `confirmed` says the user agreed to it;
    // otherwise (NotConfirmed), as when blocked, nullptr and *refusal, and nothing is sent.
    // Ends with moveTested.
    OperationReply *moveTest(int index, bool confirmed, Refusal *refusal = nullptr);

signals:
    // Each servo's reading as it comes, the `done`-th of `total`.
    void reading(const feetech::HealthReading &reading, int done, int total);
    void checkFinished(bool completed, const QString &message);
    // Also when the link went down meanwhile (then not ok).
    void moveTested(const feetech::MoveTestResult &result);

private:
    void onWorkFinished(const OperationResult &result);

    BusClient *m_client;
    bool m_checking = false;
};

} // namespace feetech
