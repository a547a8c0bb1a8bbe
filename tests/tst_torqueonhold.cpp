// Tests that switching torque on never moves the horn: the goal is set to the present position
// first, unless the same write sets a goal or torque is on already (simulated STS3215 and SCS15);
// and the checks before and after a test that moves a servo and puts it back.
#include "feetechbus.h"

#include "busclient.h"
#include "operationlog.h"
#include "servoparameters.h"
#include "torqueonhold.h"

#include <QSignalSpy>
#include <QtTest>

using feetech::BusClient;
using feetech::OperationResult;

namespace {

constexpr qint32 k1M = 1000000;
const QString kTorque = QStringLiteral("torque_enable");
const QString kGoal = QStringLiteral("goal_position");

} // namespace

class TestTorqueOnHold : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<BusClient> m_client;

    // Writes `values` to the servo at `index` and waits for the result.
    OperationResult write(int index, const QVector<model::WriteItem> &values)
    {
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        feetech::Refusal refusal;
        if (!m_client->writeValues(index, values, &refusal)) {
            qWarning("refused: %s", qPrintable(refusal.describe()));
            return {};
        }
        if (!finished.wait(10000))
            return {};
        return finished.takeFirst().at(0).value<OperationResult>();
    }

private slots:
    void init()
    {
        QString error;
        const auto servos = testsupport::servosAt(k1M, {u"STS3215", u"SCS15"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_client = std::make_unique<BusClient>(testsupport::patientTiming());
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 2));
        QCOMPARE(m_client->servos()->count(), 2);
    }

    void cleanup()
    {
        m_client.reset();
        m_simulator.reset();
    }

    void torqueOnSetsTheGoalToWhereTheHornStandsFirst_data()
    {
        QTest::addColumn<int>("id");
        QTest::newRow("STS3215") << 1;
        QTest::newRow("SCS15") << 2;
    }

    void torqueOnSetsTheGoalToWhereTheHornStandsFirst()
    {
        QFETCH(int, id);
        const int index = m_client->servos()->indexOf({quint8(id), k1M});
        // Torque off, with a goal far from the horn left over from earlier work.
        setSimulatorValue(id, u"torque_enable", 0);
        const qint32 present = simulatorValue(id, u"present_position");
        setSimulatorValue(id, u"goal_position", present > 400 ? present - 300 : present + 300);
        const OperationResult result = write(index, {{kTorque, 1}});
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(simulatorValue(id, u"torque_enable"), 1);
        QCOMPARE(simulatorValue(id, u"goal_position"), present);
        QCOMPARE(simulatorValue(id, u"present_position"), present);
        // What the client shows is what the servo now holds.
        QCOMPARE(m_client->servos()->parameters(index)->deviceValue(kGoal),
                 std::optional<qint64>(present));
    }

    void aGoalWrittenWithTheTorqueIsKept()
    {
        const int index = m_client->servos()->indexOf({1, k1M});
        setSimulatorValue(1, u"torque_enable", 0);
        const qint32 present = simulatorValue(1, u"present_position");
        const qint32 wanted = present > 400 ? present - 200 : present + 200;
        const OperationResult result = write(index, {{kGoal, wanted}, {kTorque, 1}});
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(simulatorValue(1, u"goal_position"), wanted);
    }

    void torqueAlreadyOnLeavesTheGoalAlone()
    {
        const int index = m_client->servos()->indexOf({1, k1M});
        setSimulatorValue(1, u"torque_enable", 1);
        const qint32 goal = simulatorValue(1, u"goal_position");
        const OperationResult result = write(index, {{kTorque, 1}});
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(simulatorValue(1, u"goal_position"), goal);
    }

    void onlyTorqueOnNeedsTheHold()
    {
        const feetech::ServoInfo &servo =
            m_client->servos()->at(m_client->servos()->indexOf({1, k1M})).info;
        const auto encoded = [&servo](const QVector<model::WriteItem> &items) {
            QString error;
            return *feetech::encodeWrites(servo.table(), items, &error);
        };
        QVERIFY(feetech::needsHoldBeforeTorqueOn(servo, encoded({{kTorque, 1}})));
        QVERIFY(!feetech::needsHoldBeforeTorqueOn(servo, encoded({{kTorque, 0}})));
        QVERIFY(!feetech::needsHoldBeforeTorqueOn(servo, encoded({{kTorque, 2}}))); // damping
        QVERIFY(!feetech::needsHoldBeforeTorqueOn(servo, encoded({{kGoal, 100}, {kTorque, 1}})));
        QVERIFY(
            !feetech::needsHoldBeforeTorqueOn(servo, encoded({{QStringLiteral("p_gain"), 30}})));
    }

    // The checks of the tests that move a servo and put it back (health, joint identification).
    void aMoveTestLeavesAServoAloneOutsidePositionModeOrWithAnOddTorque()
    {
        const feetech::ServoInfo &servo = m_client->servos()->at(0).info;
        const QString mode = QStringLiteral("mode");
        bool torqueWasOn = false;
        QVERIFY(feetech::whyNotToMove(servo, {{mode, 0}, {kTorque, 1}}, &torqueWasOn).isEmpty());
        QVERIFY(torqueWasOn);
        QVERIFY(feetech::whyNotToMove(servo, {{mode, 0}, {kTorque, 0}}, &torqueWasOn).isEmpty());
        QVERIFY(!torqueWasOn);
        const QString wheel = feetech::whyNotToMove(servo, {{mode, 1}, {kTorque, 0}}, &torqueWasOn);
        QVERIFY2(wheel.contains(QLatin1String("not in position mode (mode 1)")), qPrintable(wheel));
        const QString odd = feetech::whyNotToMove(servo, {{mode, 0}, {kTorque, 7}}, &torqueWasOn);
        QVERIFY2(odd.contains(QLatin1String("torque enable 7, neither on nor off")),
                 qPrintable(odd));
    }

    void aMoveTestSaysWhatItDidNotPutBack()
    {
        const QHash<QString, qint32> before {{kTorque, 0}, {kGoal, 2048}};
        QVERIFY(feetech::notRestoredAsItWas({kTorque, kGoal}, before, before).isEmpty());
        QCOMPARE(
            feetech::notRestoredAsItWas({kTorque, kGoal}, before, {{kTorque, 0}, {kGoal, 2100}}),
            QStringLiteral("it was not restored as it was: goal_position reads 2100, not 2048."));
    }
};

QTEST_GUILESS_MAIN(TestTorqueOnHold)
#include "tst_torqueonhold.moc"
