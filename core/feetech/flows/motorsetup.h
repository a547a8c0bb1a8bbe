// Setting up one motor of a robot: find the one servo on the bus, give it its ID, rate, settings.
#pragma once

#include "applyflow.h"
#include "busexchange.h"
#include "bustypes.h"
#include "guidedflows.h"
#include "jointcheck.h"
#include "motorfinder.h"

#include <QMap>
#include <QMetaType>
#include <QObject>
#include <QStringList>
#include <QVector>

#include <functional>
#include <memory>
#include <optional>

namespace feetech {

// What a motor is to become: its ID, rate and settings, and the model it must be.
struct MotorTarget
{
    QString joint; // for messages ("shoulder_lift"); may be empty
    int id = 1;
    qint32 baud = 1000000;
    QString model; // as the model table names it; empty: any model with a register table
    QMap<QString, qint32> settings; // register units by key, written and verified
    // Bits to clear in registers by key (a mask each), the other bits kept as the servo holds
    // them: read, cleared, written when they were set, verified.
    QMap<QString, quint32> clearedBits;
};

// A find or a set-up: what was found, what it became, and each step done.
struct MotorSetupResult
{
    bool ok = false;
    bool setUp = false; // a set-up (false: only a find)
    bool stopped = false; // cancelled between two steps
    OperationFailure failure = OperationFailure::None; // why it did not succeed
    MotorSearch search;
    ServoInfo from; // where the servo was found
    ServoInfo to; // where it answers afterwards
    QMap<QString, qint32> verified; // the settings as read back
    QStringList steps; // what was done, one line each
    QString message;
};

// Finds the one servo on the bus (MotorFinder) and sets it up, from the steps of the exchange,
// the guided flows and the apply flow; checks which joints of a robot already answer where they
// should. Nothing is written unless exactly one servo of the right model answers. Lives in the
// session's thread; the session runs each call as one operation.
class MotorSetup : public QObject
{
    Q_OBJECT

public:
    using SearchDone = MotorFinder::SearchDone;
    using SetupDone = std::function<void(const MotorSetupResult &result)>;
    using CheckDone = std::function<void(const QVector<JointCheck> &joints)>;

    MotorSetup(BusExchange &bus, GuidedFlows &flows, ApplyFlow &apply, QObject *parent = nullptr);

    // A broadcast PING at every rate, then the one servo's identity and a few reads of its
    // feedback (two servos at one ID garble those), then its model against target.model.
    void find(const MotorTarget &target, SearchDone done);
    // find, then (only for exactly one servo of the right model) the ID, the rate, the
    // settings written with the EEPROM unlocked and locked again, every one read back.
    void setUp(const MotorTarget &target, SetupDone done);
    // Asks each joint's ID at `baud` who answers there, and reads its EEPROM settings.
    void check(qint32 baud, const QVector<JointCheck> &joints, CheckDone done);
    // Stops before the next step (a step under way ends first, so the EEPROM is locked).
    void cancel() { m_cancelled = true; }
    // Called when find, setUp or check is queued (not when it starts), so a Stop pressed
    // while it waits in the queue still stops it.
    void clearCancel() { m_cancelled = false; }

signals:
    // Step `step` of `steps` has begun: `text` says what it does.
    void progress(int step, int steps, const QString &text);

private:
    struct Run;
    void changeId(std::shared_ptr<Run> run);
    void changeBaud(std::shared_ptr<Run> run);
    void writeSettings(std::shared_ptr<Run> run);
    void verifySettings(std::shared_ptr<Run> run);
    // Reads the registers `keys` of the servo into *values (register units by key).
    void readSettings(const ServoInfo &servo, const QStringList &keys,
                      std::shared_ptr<QMap<QString, qint32>> values, StepDone next);
    bool stoppedBefore(std::shared_ptr<Run> run, const QString &step);
    // Succeeds when `failure` is None.
    void finish(std::shared_ptr<Run> run, OperationFailure failure, const QString &message);

    void checkNext(qint32 baud, std::shared_ptr<QVector<JointCheck>> joints, int index,
                   CheckDone done);
    void compareSettings(JointCheck &joint, std::function<void()> then);

    BusExchange &m_bus;
    GuidedFlows &m_flows;
    ApplyFlow &m_apply;
    bool m_cancelled = false;
    MotorFinder m_finder;
    QMetaObject::Connection m_reading; // collects what readSettings reads
};

} // namespace feetech

Q_DECLARE_METATYPE(feetech::MotorTarget)
Q_DECLARE_METATYPE(feetech::MotorSetupResult)
