// The GUI thread's side of motor set-up: find the one servo on the bus, set it up, check joints.
#pragma once

#include "busoperation.h"
#include "motorsetup.h"
#include "refusal.h"

#include <QObject>
#include <QVector>

#include <optional>

namespace feetech {

class BusClient;
class OperationReply;

// Belongs to a BusClient (BusClient::motorSetup()). No scan is needed: each servo is found
// alone. Each find or set-up ends with finished, each check with jointsChecked, also when the
// link went down meanwhile; a servo of the list that was set up is moved to where it answers.
class MotorSetupService : public QObject
{
    Q_OBJECT

public:
    explicit MotorSetupService(BusClient *client);

    // Looks for the one servo on the bus at every rate. Nullptr and *refusal (NotConnected,
    // Busy) when not started; the same for the others.
    OperationReply *find(const MotorTarget &target, Refusal *refusal = nullptr);
    // Finds the one servo again and gives it the target's ID, rate and settings, verified.
    OperationReply *setUp(const MotorTarget &target, Refusal *refusal = nullptr);
    // Which of `joints` already answer at their ID at `baud`, as their model.
    OperationReply *checkJoints(qint32 baud, const QVector<JointCheck> &joints,
                                Refusal *refusal = nullptr);
    // Stops a find, set-up or check before its next step.
    void cancel();

signals:
    void progress(int step, int steps, const QString &text);
    void finished(const feetech::MotorSetupResult &result);
    void jointsChecked(const QVector<feetech::JointCheck> &joints, bool ok, const QString &message);

private:
    void followCheck(const QVector<JointCheck> &joints);
    OperationReply *start(const BusOperation &operation, Refusal *refusal);
    void onWorkFinished(const OperationResult &result);

    BusClient *m_client;
    qint32 m_checkBaud = 0; // the rate of the check under way
};

} // namespace feetech
