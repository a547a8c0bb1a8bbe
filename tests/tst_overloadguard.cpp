// Tests of the overload and thermal guard's decisions: load threshold and hold time, warn then
// act, the thermal margin, the latched-overload bit, and limits per servo from the table.
#include "feedbacksample.h"

#include "modeltable.h"
#include "overloadguard.h"
#include "registertable.h"

#include <QtTest>

using feetech::FeedbackSample;
using feetech::GuardCause;
using feetech::GuardDecision;
using feetech::GuardLimits;
using feetech::GuardStage;
using feetech::OverloadGuard;
using feetech::Quantity;

namespace {

constexpr qint64 kMs = 1000; // microseconds

feetech::ServoInfo sts(quint8 id)
{
    feetech::ServoInfo servo;
    servo.id = id;
    servo.baud = 1000000;
    servo.modelMajor = 9;
    servo.modelMinor = 3;
    servo.model = feetech::ModelTable::builtIn().identify(9, 3);
    return servo;
}

// A sample of servo `id` at `ms` with `load` (%) and `temperature` (°C).
FeedbackSample sample(quint8 id, qint64 ms, double load, double temperature = 35.0,
                      quint8 status = 0)
{
    FeedbackSample s = testsupport::feedbackSample(id, ms * kMs, 2048.0);
    s.values.at(int(Quantity::Load)) = load;
    s.values.at(int(Quantity::Temperature)) = temperature;
    s.servoStatus = status;
    return s;
}

QVector<GuardStage> stages(const QVector<GuardDecision> &decisions, GuardCause cause)
{
    QVector<GuardStage> out;
    for (const GuardDecision &decision : decisions) {
        if (decision.cause == cause)
            out.append(decision.stage);
    }
    return out;
}

// Feeds samples of `load` every 100 ms from `fromMs` to `toMs`: every decision, in order.
QVector<GuardDecision> feed(OverloadGuard &guard, const feetech::ServoInfo &servo, qint64 fromMs,
                            qint64 toMs, double load, double temperature = 35.0)
{
    QVector<GuardDecision> all;
    for (qint64 ms = fromMs; ms <= toMs; ms += 100)
        all += guard.observe(servo, sample(servo.id, ms, load, temperature));
    return all;
}

} // namespace

// A guard whose servos all have a 1 s hold time, as the tests below count on.
OverloadGuard oneSecondGuard()
{
    OverloadGuard guard;
    feetech::GuardSettings settings;
    for (const quint8 id : {quint8(1), quint8(2), quint8(3)}) {
        GuardLimits limits =
            feetech::defaultGuardLimits(feetech::RegisterTable::forFamily(feetech::Family::Sts));
        limits.holdTime = std::chrono::milliseconds(1000);
        settings.servos.insert({id, 1000000}, limits);
    }
    guard.setSettings(settings);
    return guard;
}

class TestOverloadGuard : public QObject
{
    Q_OBJECT

private slots:
    void defaultsComeFromTheRegisterTable()
    {
        const auto &table = feetech::RegisterTable::forFamily(feetech::Family::Sts);
        const GuardLimits limits = feetech::defaultGuardLimits(table);
        QCOMPARE(limits.loadPercent, 80.0); // overload torque, factory value
        QCOMPARE(limits.maxTemperature, 70.0); // max temperature, factory value
        QCOMPARE(limits.holdTime, std::chrono::milliseconds(500)); // a quarter of 2 s protection
        QVERIFY(!limits.currentMilliamps); // the load is compared with the overload torque
        QVERIFY(limits.enabled);
        QCOMPARE(limits.action, feetech::GuardAction::Hold);
    }

    void defaultsFollowTheServosOwnRegisterValues()
    {
        const auto &table = feetech::RegisterTable::forFamily(feetech::Family::Sts);
        const GuardLimits limits =
            feetech::defaultGuardLimits(table, [](QStringView key) -> std::optional<qint32> {
                if (key == u"overload_torque")
                    return 50;
                if (key == u"max_temperature")
                    return 60;
                if (key == u"protection_time")
                    return 120; // 1.2 s
                return std::nullopt;
            });
        QCOMPARE(limits.loadPercent, 50.0);
        QCOMPARE(limits.maxTemperature, 60.0);
        QCOMPARE(limits.holdTime, std::chrono::milliseconds(300));
    }

    void aModelWithoutOverloadTorqueIsWatchedByItsProtectionCurrent()
    {
        const auto &table = feetech::RegisterTable::forFamily(feetech::Family::Hls);
        const GuardLimits limits =
            feetech::defaultGuardLimits(table, [](QStringView key) -> std::optional<qint32> {
                return key == u"protection_current" ? std::optional<qint32>(200) : std::nullopt;
            });
        QVERIFY(limits.currentMilliamps);
        QCOMPARE(*limits.currentMilliamps, 200 * 6.5);
        QCOMPARE(limits.loadPercent, 80.0); // the fallback
        QCOMPARE(limits.maxTemperature, 70.0); // the HLS table has no factory value: fallback
    }

    void aShortLoadPeakIsNeitherWarnedNorActedOn()
    {
        OverloadGuard guard = oneSecondGuard();
        const auto servo = sts(1);
        auto decisions = feed(guard, servo, 0, 300, 95.0); // 300 ms < half the hold time
        decisions += feed(guard, servo, 400, 3000, 20.0);
        QVERIFY(decisions.isEmpty());
    }

    void aLoadAboveTheThresholdWarnsAtHalfTheHoldTimeThenActsOnce()
    {
        OverloadGuard guard = oneSecondGuard();
        const auto servo = sts(1);
        QVERIFY(feed(guard, servo, 0, 400, -95.0).isEmpty()); // the sign does not matter
        const auto warned = feed(guard, servo, 500, 500, -95.0);
        QCOMPARE(stages(warned, GuardCause::Overload), QVector<GuardStage> {GuardStage::Warning});
        QCOMPARE(warned.first().value, -95.0);
        QCOMPARE(warned.first().limit, 80.0);
        QVERIFY(feed(guard, servo, 600, 900, -95.0).isEmpty());
        const auto acted = feed(guard, servo, 1000, 1000, -95.0);
        QCOMPARE(stages(acted, GuardCause::Overload), QVector<GuardStage> {GuardStage::Acted});
    }

    void aLoadThatStaysAfterTheHoldIsReportedOnceAndNotActedOnAgain()
    {
        OverloadGuard guard = oneSecondGuard();
        const auto servo = sts(1);
        const auto decisions = feed(guard, servo, 0, 5000, 95.0);
        QCOMPARE(stages(decisions, GuardCause::Overload),
                 (QVector<GuardStage> {GuardStage::Warning, GuardStage::Acted,
                                       GuardStage::StillLoaded}));
    }

    void aNewGoalAfterTheActionStartsANewEpisode()
    {
        OverloadGuard guard = oneSecondGuard();
        const auto servo = sts(1);
        feed(guard, servo, 0, 1000, 95.0);
        guard.rearm(servo.id, servo.baud);
        const auto again = feed(guard, servo, 1100, 2200, 95.0);
        QCOMPARE(stages(again, GuardCause::Overload),
                 (QVector<GuardStage> {GuardStage::Warning, GuardStage::Acted}));
    }

    void aNewGoalBeforeTheActionDoesNotResetTheHoldTime()
    {
        OverloadGuard guard = oneSecondGuard();
        const auto servo = sts(1);
        feed(guard, servo, 0, 700, 95.0);
        guard.rearm(servo.id, servo.baud); // a slider dragged against the block
        const auto acted = feed(guard, servo, 800, 1000, 95.0);
        QCOMPARE(stages(acted, GuardCause::Overload), QVector<GuardStage> {GuardStage::Acted});
    }

    void aLongGapBetweenSamplesStillWarnsBeforeActing()
    {
        OverloadGuard guard = oneSecondGuard();
        const auto servo = sts(1);
        guard.observe(servo, sample(1, 0, 95.0));
        const auto decisions = guard.observe(servo, sample(1, 1500, 95.0));
        QCOMPARE(stages(decisions, GuardCause::Overload),
                 (QVector<GuardStage> {GuardStage::Warning, GuardStage::Acted}));
    }

    void temperatureWarnsWithinTheWarnMarginAndActsWithinTheMargin()
    {
        OverloadGuard guard = oneSecondGuard();
        const auto servo = sts(1);
        QVERIFY(feed(guard, servo, 0, 100, 0.0, 59.0).isEmpty()); // 11 °C below 70
        QCOMPARE(stages(feed(guard, servo, 200, 300, 0.0, 61.0), GuardCause::Heat),
                 QVector<GuardStage> {GuardStage::Warning});
        const auto acted = feed(guard, servo, 400, 600, 0.0, 65.0);
        QCOMPARE(stages(acted, GuardCause::Heat), QVector<GuardStage> {GuardStage::Acted});
        QCOMPARE(acted.first().value, 65.0);
        QCOMPARE(acted.first().limit, 70.0);
    }

    void aServoAlreadyHotWarnsThenActsAtOnce()
    {
        OverloadGuard guard = oneSecondGuard();
        const auto decisions = guard.observe(sts(1), sample(1, 0, 0.0, 68.0));
        QCOMPARE(stages(decisions, GuardCause::Heat),
                 (QVector<GuardStage> {GuardStage::Warning, GuardStage::Acted}));
    }

    void aServoThatCooledDownIsGuardedAfresh()
    {
        OverloadGuard guard = oneSecondGuard();
        const auto servo = sts(1);
        feed(guard, servo, 0, 100, 0.0, 68.0);
        feed(guard, servo, 200, 300, 0.0, 40.0);
        QCOMPARE(stages(feed(guard, servo, 400, 400, 0.0, 68.0), GuardCause::Heat),
                 (QVector<GuardStage> {GuardStage::Warning, GuardStage::Acted}));
    }

    void limitsSetForOneServoApplyToThatServoOnly()
    {
        OverloadGuard guard;
        feetech::GuardSettings settings;
        GuardLimits strict =
            feetech::defaultGuardLimits(feetech::RegisterTable::forFamily(feetech::Family::Sts));
        strict.loadPercent = 30.0;
        strict.holdTime = std::chrono::milliseconds(400);
        strict.action = feetech::GuardAction::TorqueOff;
        settings.servos.insert({2, 1000000}, strict);
        guard.setSettings(settings);
        QCOMPARE(guard.limitsFor(sts(2)).action, feetech::GuardAction::TorqueOff);
        QCOMPARE(guard.limitsFor(sts(1)).loadPercent, 80.0);
        QCOMPARE(stages(feed(guard, sts(2), 0, 400, 50.0), GuardCause::Overload),
                 (QVector<GuardStage> {GuardStage::Warning, GuardStage::Acted}));
        QVERIFY(feed(guard, sts(1), 0, 3000, 50.0).isEmpty());
    }

    void aServoSwitchedOffInTheGuardOrTheWholeGuardOffIsNotWatched()
    {
        OverloadGuard guard;
        feetech::GuardSettings settings;
        GuardLimits off;
        off.enabled = false;
        settings.servos.insert({1, 1000000}, off);
        guard.setSettings(settings);
        QVERIFY(feed(guard, sts(1), 0, 3000, 99.0, 69.0).isEmpty());
        QVERIFY(!feed(guard, sts(2), 0, 3000, 99.0).isEmpty());
        settings.enabled = false;
        guard.setSettings(settings);
        QVERIFY(feed(guard, sts(3), 0, 3000, 99.0, 69.0).isEmpty());
    }

    void theOverloadBitIsReportedOnceWhileSetAndWhenItClears()
    {
        OverloadGuard guard = oneSecondGuard();
        const auto servo = sts(1);
        QVector<GuardDecision> decisions;
        for (int i = 0; i < 5; ++i)
            decisions += guard.observe(servo, sample(1, i * 100, 0.0, 35.0, 0x20));
        decisions += guard.observe(servo, sample(1, 600, 0.0, 35.0, 0x00));
        QCOMPARE(stages(decisions, GuardCause::LatchedOverload),
                 (QVector<GuardStage> {GuardStage::Warning, GuardStage::Cleared}));
        QCOMPARE(
            feetech::overloadStatusBit(feetech::RegisterTable::forFamily(feetech::Family::Sts)),
            quint8(0x20));
    }

    void theActionMessageNamesTheServoTheFiguresAndWhatWasDone()
    {
        feetech::GuardEvent event;
        event.id = 3;
        event.stage = GuardStage::Acted;
        event.value = 97.0;
        event.limit = 80.0;
        event.heldAt = 2100;
        const QString text = feetech::guardEventText(event, GuardLimits {});
        QVERIFY2(text.contains(QLatin1String("ID 3")), qPrintable(text));
        QVERIFY2(text.contains(QLatin1String("97 %")), qPrintable(text));
        QVERIFY2(text.contains(QLatin1String("80 %")), qPrintable(text));
        QVERIFY2(text.contains(QLatin1String("2100")), qPrintable(text));
        event.action = feetech::GuardAction::TorqueOff;
        QVERIFY(feetech::guardEventText(event, GuardLimits {}).contains(QLatin1String("torque")));
    }

    void actionKeysReadBack()
    {
        for (const auto action : {feetech::GuardAction::Hold, feetech::GuardAction::TorqueOff})
            QCOMPARE(feetech::guardActionFromKey(feetech::guardActionKey(action)), action);
        QVERIFY(!feetech::guardActionFromKey(u"explode"));
    }
};

QTEST_GUILESS_MAIN(TestOverloadGuard)
#include "tst_overloadguard.moc"
