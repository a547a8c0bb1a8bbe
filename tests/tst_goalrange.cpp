// Tests feetech::goalRange against a scanned simulated bus (STS3215 and SCS15 at 1 Mbps): the
// goal register's range until angle limits are known, the limits once they are, and the cases
// in which limits bound nothing.
#include "feetechbus.h"
#include "goalrange.h"
#include "registerkeys.h"

#include <QtTest>

#include <memory>

using feetech::goalRange;
using feetech::PositionRange;
using namespace feetech::registerkeys;

namespace {
constexpr qint32 k1M = 1000000;
} // namespace

class TestGoalRange : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;

    // The scanned servo with ID `id`; -1 when the scan did not find it.
    int scanned(quint8 id)
    {
        if (!testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 3))
            return -1;
        return m_client->servos()->indexOf({id, k1M});
    }

    const feetech::Register *goalRegister(int index) const
    {
        return m_client->servos()->at(index).info.table().find(kGoalPosition);
    }

    // As if the servo had reported these limits (no read needed).
    void setLimits(int index, qint64 low, qint64 high)
    {
        m_client->servos()->parameters(index)->setDeviceValue(kMinAngleLimit, low);
        m_client->servos()->parameters(index)->setDeviceValue(kMaxAngleLimit, high);
    }

private slots:
    void init()
    {
        QString error;
        const auto servos = testsupport::servosAt(k1M, {u"STS3215", u"SCS15"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>();
    }

    void cleanup()
    {
        m_client.reset();
        m_simulator.reset();
    }

    void aServoTheClientDoesNotHaveHasNoRange()
    {
        QVERIFY(!goalRange(*m_client, 0)); // nothing scanned yet
        const int index = scanned(1);
        QVERIFY(index >= 0);
        QVERIFY(!goalRange(*m_client, -1));
        QVERIFY(!goalRange(*m_client, m_client->servos()->count()));
    }

    void limitsNotReadYetLeaveTheGoalRegistersRange()
    {
        const int index = scanned(1);
        QVERIFY(index >= 0);
        const feetech::Register *goal = goalRegister(index);
        QVERIFY(goal);
        const auto range = goalRange(*m_client, index);
        QVERIFY(range);
        QCOMPARE(range->minimum, goal->minimum);
        QCOMPARE(range->maximum, goal->maximum);
        QVERIFY(!range->fromAngleLimits);
    }

    void reportedAngleLimitsBoundTheGoals()
    {
        const int index = scanned(1);
        QVERIFY(index >= 0);
        setLimits(index, 1000, 3000);
        const auto range = goalRange(*m_client, index);
        QVERIFY(range);
        QCOMPARE(range->minimum, 1000);
        QCOMPARE(range->maximum, 3000);
        QVERIFY(range->fromAngleLimits);
        QVERIFY(!range->contains(999));
        QVERIFY(range->contains(1000));
        QVERIFY(range->contains(3000));
        QVERIFY(!range->contains(3001));
    }

    void bothLimitsZeroMeanMultiTurnAndBoundNothing()
    {
        const int index = scanned(1);
        QVERIFY(index >= 0);
        setLimits(index, 0, 0);
        const auto range = goalRange(*m_client, index);
        QVERIFY(range);
        QCOMPARE(range->minimum, goalRegister(index)->minimum);
        QCOMPARE(range->maximum, goalRegister(index)->maximum);
        QVERIFY(!range->fromAngleLimits);
    }

    void limitsBeyondTheRegisterCannotWidenIt()
    {
        const int index = scanned(1);
        QVERIFY(index >= 0);
        const feetech::Register *goal = goalRegister(index);
        setLimits(index, qint64(goal->minimum) - 100, qint64(goal->maximum) + 100);
        const auto range = goalRange(*m_client, index);
        QVERIFY(range);
        QCOMPARE(range->minimum, goal->minimum);
        QCOMPARE(range->maximum, goal->maximum);
        QVERIFY(range->fromAngleLimits);
    }

    void crossedLimitsAreNotTrusted()
    {
        const int index = scanned(1);
        QVERIFY(index >= 0);
        setLimits(index, 3000, 1000);
        const auto range = goalRange(*m_client, index);
        QVERIFY(range);
        QCOMPARE(range->minimum, goalRegister(index)->minimum);
        QCOMPARE(range->maximum, goalRegister(index)->maximum);
        QVERIFY(!range->fromAngleLimits);
    }

    void eachFamilyUsesItsOwnGoalRegister()
    {
        const int sts = scanned(1);
        QVERIFY(sts >= 0);
        const int scs = m_client->servos()->indexOf({2, k1M});
        QVERIFY(scs >= 0);
        const auto stsRange = goalRange(*m_client, sts);
        const auto scsRange = goalRange(*m_client, scs);
        QVERIFY(stsRange && scsRange);
        QCOMPARE(scsRange->minimum, goalRegister(scs)->minimum);
        QCOMPARE(scsRange->maximum, goalRegister(scs)->maximum);
        QCOMPARE(stsRange->maximum, goalRegister(sts)->maximum);
        QVERIFY(stsRange->maximum != scsRange->maximum); // the tables differ
    }
};

QTEST_GUILESS_MAIN(TestGoalRange)
#include "tst_goalrange.moc"
