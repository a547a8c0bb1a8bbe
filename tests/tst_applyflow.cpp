// Tests the apply plan: which edits become register writes, and the ID and baud rate after them.
#include "applyflow.h"
#include "parametermodel.h"
#include "servoparameters.h"

#include <QtTest>

using namespace feetech;

namespace {

ServoInfo sts3215(quint8 id)
{
    ServoInfo servo;
    servo.id = id;
    servo.baud = 1000000;
    servo.model = ModelTable::builtIn().identify(9, 3);
    return servo;
}

std::unique_ptr<model::ParameterModel> parametersOf(const ServoInfo &servo)
{
    auto parameters = std::make_unique<model::ParameterModel>();
    parameters->setDefinitions(modelDefinitions(servo.table()));
    for (const model::Definition &definition : parameters->definitions())
        parameters->setDeviceValue(definition.key, definition.minimum);
    return parameters;
}

} // namespace

class TestApplyFlow : public QObject
{
    Q_OBJECT

private slots:
    void registersAreWrittenFirstAndTheIdAndBaudRateLast()
    {
        const ServoInfo servo = sts3215(3);
        auto parameters = parametersOf(servo);
        QVERIFY(parameters->edit(QStringLiteral("max_temperature"), 65));
        QVERIFY(parameters->edit(QStringLiteral("id"), 7));
        QVERIFY(parameters->edit(QStringLiteral("baud_rate"), 4)); // code 4: 115200
        ApplyRefusal refusal;
        const auto plan =
            planApply(servo, *parameters, {3, 5}, feetech::ApplyScope::Everything, &refusal);
        QVERIFY2(plan.has_value(), qPrintable(refusal.describe()));
        QVERIFY(!refusal);
        QCOMPARE(plan->writtenKeys, QStringList {QStringLiteral("max_temperature")});
        QCOMPARE(plan->writes.size(), 1);
        QCOMPARE(plan->writes.first().address, servo.table().find(u"max_temperature")->address);
        QVERIFY(plan->writes.first().eeprom);
        QCOMPARE(plan->newId, std::optional<int>(7));
        QCOMPARE(plan->newBaud, std::optional<qint32>(115200));
        QCOMPARE(plan->idsInUse, (QVector<int> {3, 5}));
        // Planning leaves the model alone: the edits are still there to take.
        QVERIFY(parameters->pendingValue(QStringLiteral("id")).has_value());
        QCOMPARE(parameters->state(QStringLiteral("max_temperature")), model::State::Edited);
    }

    void anIdInUseIsRefusedBeforeAnythingIsPlanned()
    {
        const ServoInfo servo = sts3215(3);
        auto parameters = parametersOf(servo);
        QVERIFY(parameters->edit(QStringLiteral("max_temperature"), 65));
        QVERIFY(parameters->edit(QStringLiteral("id"), 5));
        ApplyRefusal refusal;
        QVERIFY(!planApply(servo, *parameters, {3, 5}, feetech::ApplyScope::Everything, &refusal)
                     .has_value());
        QCOMPARE(refusal.code(), ApplyRefusal::Code::IdInUse);
        QCOMPARE(refusal.newId(), 5);
        QCOMPARE(refusal.describe(), QStringLiteral("ID 5 is already in use on this bus."));
    }

    void aRegistersOnlyPlanLeavesThePendingIdAndBaudRateAlone()
    {
        const ServoInfo servo = sts3215(3);
        auto parameters = parametersOf(servo);
        QVERIFY(parameters->edit(QStringLiteral("max_temperature"), 65));
        QVERIFY(parameters->edit(QStringLiteral("id"), 5)); // in use: not this plan's business
        QVERIFY(parameters->edit(QStringLiteral("baud_rate"), 4));
        ApplyRefusal refusal;
        const auto plan =
            planApply(servo, *parameters, {3, 5}, feetech::ApplyScope::Registers, &refusal);
        QVERIFY2(plan.has_value(), qPrintable(refusal.describe()));
        QCOMPARE(plan->writtenKeys, QStringList {QStringLiteral("max_temperature")});
        QVERIFY(!plan->newId);
        QVERIFY(!plan->newBaud);
        // With only the ID and baud pending there is nothing for it to write.
        QVERIFY(parameters->edit(QStringLiteral("max_temperature"), 70));
        parameters->revert(QStringLiteral("max_temperature"));
        QVERIFY(!planApply(servo, *parameters, {3, 5}, feetech::ApplyScope::Registers, &refusal));
        QCOMPARE(refusal.code(), ApplyRefusal::Code::NothingToWrite);
        QCOMPARE(refusal.describe(), QStringLiteral("Nothing to write."));
    }

    void nothingPendingIsNothingToWrite()
    {
        const ServoInfo servo = sts3215(1);
        auto parameters = parametersOf(servo);
        ApplyRefusal refusal;
        QVERIFY(!planApply(servo, *parameters, {1}, feetech::ApplyScope::Everything, &refusal)
                     .has_value());
        QCOMPARE(refusal.code(), ApplyRefusal::Code::NothingToWrite);
        QCOMPARE(refusal.describe(), QStringLiteral("Nothing to write."));
    }

    void aValueTheServoCannotTakeIsRefusedWithTheRegisterItNames()
    {
        const ServoInfo servo = sts3215(1);
        auto parameters = parametersOf(servo);
        // A parameter the servo's table does not have: no register to write it to.
        QVector<model::Definition> definitions = parameters->definitions();
        model::Definition stray;
        stray.key = QStringLiteral("not_a_register");
        stray.maximum = 10;
        definitions.append(stray);
        parameters->setDefinitions(definitions);
        parameters->setDeviceValue(stray.key, 0);
        QVERIFY(parameters->edit(stray.key, 3));
        ApplyRefusal refusal;
        QVERIFY(!planApply(servo, *parameters, {1}, feetech::ApplyScope::Registers, &refusal)
                     .has_value());
        QCOMPARE(refusal.code(), ApplyRefusal::Code::BadValue);
        QVERIFY2(refusal.detail().contains(stray.key), qPrintable(refusal.detail()));
        QCOMPARE(refusal.describe(), refusal.detail());
    }
};

QTEST_GUILESS_MAIN(TestApplyFlow)
#include "tst_applyflow.moc"
