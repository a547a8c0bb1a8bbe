// The settings check's rules on readings made by hand: what each rule finds, what it expects,
// which need torque off, the template's differences and the firmware mismatch.
#include "settingscheck.h"

#include <QtTest>

using feetech::SettingsFinding;
using feetech::SettingsReading;

namespace {

// An STS3215 at `id` as its identity (addresses 0-8) says, with firmware 3.`minor`.
feetech::ServoInfo sts3215(quint8 id, quint8 minor = 10)
{
    const QByteArray identity {"\x03\x00\x00\x09\x03\x01\x00\x00\x01", 9};
    QByteArray bytes = identity;
    bytes[1] = char(minor);
    bytes[5] = char(id);
    return *feetech::servoInfoFromIdentity(id, 1000000, bytes);
}

// A servo whose settings let it move as a joint, at 7.4 V.
SettingsReading healthy(quint8 id, quint8 minor = 10)
{
    SettingsReading reading;
    reading.servo = sts3215(id, minor);
    reading.values = {
        {QStringLiteral("phase"), 12},           {QStringLiteral("torque_limit"), 1000},
        {QStringLiteral("max_torque"), 1000},    {QStringLiteral("mode"), 0},
        {QStringLiteral("min_angle_limit"), 0},  {QStringLiteral("max_angle_limit"), 4095},
        {QStringLiteral("return_delay"), 0},     {QStringLiteral("lock"), 1},
        {QStringLiteral("min_voltage"), 40},     {QStringLiteral("max_voltage"), 80},
        {QStringLiteral("present_voltage"), 74}, {QStringLiteral("p_gain"), 16}};
    return reading;
}

QStringList codes(const QVector<SettingsFinding> &findings)
{
    QStringList found;
    for (const SettingsFinding &finding : findings)
        found.append(finding.code);
    return found;
}

} // namespace

class TestSettingsCheck : public QObject
{
    Q_OBJECT

private slots:
    void aServoSetUpAsAJointHasNoFinding()
    {
        QVERIFY(feetech::checkSettings({healthy(1), healthy(2)}).isEmpty());
    }

    void eachRuleFindsItsProblemWithTheValueThatFixesIt_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<qint32>("value");
        QTest::addColumn<QString>("code");
        QTest::addColumn<qint32>("expected");
        QTest::addColumn<bool>("needsTorqueOff");
        QTest::newRow("phase bit 4") << "phase" << 28 << "multi-turn" << 12 << true;
        QTest::newRow("torque limit 0")
            << "torque_limit" << 0 << "torque-limit-zero" << 1000 << true;
        QTest::newRow("maximum torque 0")
            << "max_torque" << 0 << "max-torque-zero" << 1000 << false;
        QTest::newRow("wheel mode") << "mode" << 1 << "mode" << 0 << true;
        QTest::newRow("slow return delay") << "return_delay" << 250 << "return-delay" << 0 << false;
        QTest::newRow("open EEPROM") << "lock" << 0 << "unlocked" << 1 << false;
    }

    void eachRuleFindsItsProblemWithTheValueThatFixesIt()
    {
        QFETCH(QString, key);
        QFETCH(qint32, value);
        QFETCH(QString, code);
        QFETCH(qint32, expected);
        QFETCH(bool, needsTorqueOff);
        SettingsReading reading = healthy(3);
        reading.values[key] = value;
        const auto findings = feetech::checkSettings({reading});
        QCOMPARE(findings.size(), 1);
        const SettingsFinding &finding = findings.first();
        QCOMPARE(finding.code, code);
        QCOMPARE(finding.key, key);
        QCOMPARE(finding.servo.id, quint8(3));
        QCOMPARE(finding.value, std::optional<qint32>(value));
        QCOMPARE(finding.expected, std::optional<qint32>(expected));
        QCOMPARE(finding.needsTorqueOff, needsTorqueOff);
        QVERIFY(!finding.why.isEmpty());
    }

    void bit4OfAPhaseRegisterWithoutTheMultiTurnBitIsNoFinding()
    {
        // An SCS servo's phase register names no multi-turn bit.
        const QByteArray identity {"\x03\x00\x01\x05\x0f\x01\x00\x00\x01", 9};
        SettingsReading reading = healthy(1);
        reading.servo = *feetech::servoInfoFromIdentity(1, 1000000, identity);
        QCOMPARE(reading.servo.model.name, QStringLiteral("SCS15"));
        reading.values[QStringLiteral("phase")] = 0x10;
        const auto findings = feetech::checkSettings({reading});
        QVERIFY2(findings.isEmpty(), qPrintable(codes(findings).join(u' ')));
    }

    void aZeroTorqueLimitIsGivenBackTheMaximumTorque()
    {
        SettingsReading reading = healthy(1);
        reading.values[QStringLiteral("torque_limit")] = 0;
        reading.values[QStringLiteral("max_torque")] = 500;
        QCOMPARE(feetech::checkSettings({reading}).first().expected, std::optional<qint32>(500));
    }

    void angleLimitsBothZeroOrOutOfOrderAreFound()
    {
        SettingsReading zero = healthy(1);
        zero.values[QStringLiteral("max_angle_limit")] = 0;
        const auto zeroFindings = feetech::checkSettings({zero});
        QCOMPARE(codes(zeroFindings), QStringList {QStringLiteral("angle-limits-zero")});
        QCOMPARE(zeroFindings.first().key, QStringLiteral("max_angle_limit"));
        QCOMPARE(zeroFindings.first().expected, std::optional<qint32>(4095));
        QVERIFY(zeroFindings.first().needsTorqueOff);

        SettingsReading crossed = healthy(1);
        crossed.values[QStringLiteral("min_angle_limit")] = 3000;
        crossed.values[QStringLiteral("max_angle_limit")] = 3000;
        const auto crossedFindings = feetech::checkSettings({crossed});
        QCOMPARE(codes(crossedFindings),
                 (QStringList {QStringLiteral("angle-limits-order"),
                               QStringLiteral("angle-limits-order")}));
        QCOMPARE(crossedFindings.at(0).key, QStringLiteral("min_angle_limit"));
        QCOMPARE(crossedFindings.at(1).key, QStringLiteral("max_angle_limit"));
    }

    void aSupplyOutsideTheVoltageLimitsIsFoundWithNothingToWrite()
    {
        SettingsReading high = healthy(1);
        high.values[QStringLiteral("present_voltage")] = 121;
        const auto highFindings = feetech::checkSettings({high});
        QCOMPARE(codes(highFindings), QStringList {QStringLiteral("voltage-limit")});
        QCOMPARE(highFindings.first().key, QStringLiteral("max_voltage"));
        QVERIFY(!highFindings.first().fixable());
        QVERIFY(highFindings.first().why.contains(QStringLiteral("12.1 V")));

        SettingsReading low = healthy(1);
        low.values[QStringLiteral("present_voltage")] = 35;
        QCOMPARE(feetech::checkSettings({low}).first().key, QStringLiteral("min_voltage"));
    }

    void theTemplateAddsItsDifferencesAndGivesARuleItsValue()
    {
        SettingsReading reading = healthy(6);
        reading.values[QStringLiteral("p_gain")] = 32;
        reading.values[QStringLiteral("max_torque")] = 0;
        reading.values[QStringLiteral("return_delay")] = 250;
        feetech::SettingsExpectations expected;
        expected.source = QStringLiteral("SO-101 follower arm");
        expected.byId[6] = {{QStringLiteral("p_gain"), 16},
                            {QStringLiteral("max_torque"), 500},
                            {QStringLiteral("return_delay"), 0}};
        expected.byId[1] = {{QStringLiteral("p_gain"), 99}}; // not checked: no servo 1
        const auto findings = feetech::checkSettings({reading}, expected);
        // By address: return delay (7), max torque (16), P gain (21); one finding each.
        QCOMPARE(codes(findings),
                 (QStringList {QStringLiteral("return-delay"), QStringLiteral("max-torque-zero"),
                               QStringLiteral("template")}));
        QCOMPARE(findings.at(1).expected, std::optional<qint32>(500));
        QCOMPARE(findings.at(2).key, QStringLiteral("p_gain"));
        QCOMPARE(findings.at(2).expected, std::optional<qint32>(16));
        QVERIFY(findings.at(2).why.contains(expected.source));
    }

    void servosOfOneModelWithDifferentFirmwareEachGetAFinding()
    {
        const auto findings = feetech::checkSettings({healthy(1, 9), healthy(2, 10)});
        QCOMPARE(codes(findings),
                 (QStringList {QStringLiteral("firmware-mismatch"),
                               QStringLiteral("firmware-mismatch")}));
        QCOMPARE(findings.at(0).valueText, QStringLiteral("3.09"));
        QVERIFY(!findings.at(0).fixable());
        QVERIFY(findings.at(0).why.contains(QStringLiteral("servo 2 has 3.10")));
    }

    void anUnreadableServoIsAFindingWithItsReason()
    {
        SettingsReading reading;
        reading.servo.id = 4;
        reading.failure = QStringLiteral("no answer");
        const auto findings = feetech::checkSettings({reading, healthy(1)});
        QCOMPARE(codes(findings), QStringList {QStringLiteral("unreadable")});
        QVERIFY(findings.first().why.contains(QStringLiteral("no answer")));
    }

    void theJsonRowHasTheIdKeyValueExpectedAndWhy()
    {
        SettingsReading reading = healthy(2);
        reading.values[QStringLiteral("mode")] = 3;
        const QJsonObject row =
            feetech::settingsFindingJson(feetech::checkSettings({reading}).first());
        QCOMPARE(row[QStringLiteral("id")].toInt(), 2);
        QCOMPARE(row[QStringLiteral("key")].toString(), QStringLiteral("mode"));
        QCOMPARE(row[QStringLiteral("value")].toInt(), 3);
        QCOMPARE(row[QStringLiteral("expected")].toInt(), 0);
        QVERIFY(!row[QStringLiteral("why")].toString().isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestSettingsCheck)
#include "tst_settingscheck.moc"
