// Tests Feetech register values as the user reads and types them: parsing text in register or
// real units, status bit names, and values shown with their choices and units.
#include "registerlookup.h"
#include "servoparameters.h"
#include "telemetry.h"

#include <QtTest>

#include <limits>

using feetech::Family;
using feetech::RegisterTable;
using registerlookup::reg;
using registerlookup::scs;
using registerlookup::sts;

Q_DECLARE_METATYPE(feetech::Family)

namespace {

constexpr qint64 kRefused = std::numeric_limits<qint64>::min();

// What parseValue makes of `text`, or kRefused.
qint64 parsed(const feetech::Register &target, const QString &text)
{
    const auto value = feetech::parseValue(target, text, nullptr);
    return value ? qint64(*value) : kRefused;
}

} // namespace

class TestServoValues : public QObject
{
    Q_OBJECT

private slots:
    // ---- parseValue

    void parseValueTakesTheBaudRateInBitsPerSecond_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("code");
        QTest::newRow("1 Mbps") << QStringLiteral("1000000") << 0;
        QTest::newRow("500000") << QStringLiteral("500000") << 1;
        QTest::newRow("128000") << QStringLiteral("128000") << 3;
        QTest::newRow("115200 with spaces") << QStringLiteral(" 115200 ") << 4;
        QTest::newRow("76800") << QStringLiteral("76800") << 5;
        QTest::newRow("38400") << QStringLiteral("38400") << 7;
        QTest::newRow("choice label") << QStringLiteral("57600 bps") << 6;
        QTest::newRow("choice label, any case") << QStringLiteral("250000 BPS") << 2;
    }

    void parseValueTakesTheBaudRateInBitsPerSecond()
    {
        QFETCH(QString, text);
        QFETCH(int, code);
        QString error;
        const auto value = feetech::parseValue(reg(sts(), "baud_rate"), text, &error);
        QVERIFY2(value, qPrintable(error));
        QCOMPARE(*value, code);
    }

    void parseValueRefusesRatesFeetechDoesNotUse_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("9600 (index-only code 10)") << QStringLiteral("9600");
        QTest::newRow("19200 (LeRobot's code 7)") << QStringLiteral("19200");
        QTest::newRow("2 Mbps") << QStringLiteral("2000000");
        QTest::newRow("a code, not a rate") << QStringLiteral("4");
        QTest::newRow("zero") << QStringLiteral("0");
        QTest::newRow("negative") << QStringLiteral("-1000000");
        // 2^32 + 1000000: must not wrap round to 1 Mbps.
        QTest::newRow("wraps to 1 Mbps in 32 bits") << QStringLiteral("4295967296");
    }

    void parseValueRefusesRatesFeetechDoesNotUse()
    {
        QFETCH(QString, text);
        QString error;
        QVERIFY(!feetech::parseValue(reg(sts(), "baud_rate"), text, &error));
        QVERIFY2(error.contains(QStringLiteral("baud_rate")), qPrintable(error));
    }

    void parseValueInRealUnitsScalesByTheRegisterAndReadsTheLocale()
    {
        const feetech::Register &voltage = reg(sts(), "max_voltage"); // 0.1 V per step
        QString error;
        const auto real = feetech::ValueUnits::Real;
        QCOMPARE(feetech::parseValue(voltage, QStringLiteral("8.4"), &error, real),
                 std::optional<qint32>(84));
        QLocale::setDefault(QLocale(QLocale::German));
        QCOMPARE(feetech::parseValue(voltage, QStringLiteral("8,4"), &error, real),
                 std::optional<qint32>(84));
        QLocale::setDefault(QLocale::c());
        // The same text in register units is a whole number of steps, or nothing.
        QCOMPARE(feetech::parseValue(voltage, QStringLiteral("84"), &error),
                 std::optional<qint32>(84));
        QVERIFY(!feetech::parseValue(voltage, QStringLiteral("8.4"), &error));
        // Labels and the baud rate in bps are read the same way in both.
        QCOMPARE(
            feetech::parseValue(reg(sts(), "baud_rate"), QStringLiteral("115200"), &error, real),
            std::optional<qint32>(4));
        QVERIFY(!feetech::parseValue(voltage, QStringLiteral("high"), &error, real));
        QVERIFY2(error.contains(QStringLiteral("not a number")), qPrintable(error));
        QVERIFY(!feetech::parseValue(voltage, QStringLiteral("1e30"), &error, real));
    }

    void aRealValueBetweenTwoStepsBecomesTheNearestAndSaysSo()
    {
        const feetech::Register &acceleration = reg(sts(), "acceleration"); // 100 step/s² a step
        const auto real = feetech::ValueUnits::Real;
        QString error;
        QString adjusted = QStringLiteral("stale");
        QCOMPARE(feetech::parseValue(acceleration, QStringLiteral("50"), &error, real, &adjusted),
                 std::optional<qint32>(1));
        QVERIFY2(adjusted.contains(QStringLiteral("50 step/s²")), qPrintable(adjusted));
        QVERIFY2(adjusted.contains(QStringLiteral("100 step/s²")), qPrintable(adjusted));
        // A whole number of steps, with its unit as the table shows it, is taken as it is.
        QCOMPARE(feetech::parseValue(acceleration, QStringLiteral("5000 step/s²"), &error, real,
                                     &adjusted),
                 std::optional<qint32>(50));
        QVERIFY2(adjusted.isEmpty(), qPrintable(adjusted));
        // A decimal scale leaves no false note: 7.4 V is 74 steps of 0.1 V.
        QCOMPARE(feetech::parseValue(reg(sts(), "max_voltage"), QStringLiteral("7.4"), &error, real,
                                     &adjusted),
                 std::optional<qint32>(74));
        QVERIFY2(adjusted.isEmpty(), qPrintable(adjusted));
        QCOMPARE(feetech::parseValue(reg(sts(), "max_voltage"), QStringLiteral("7.44"), &error,
                                     real, &adjusted),
                 std::optional<qint32>(74));
        QVERIFY2(adjusted.contains(QStringLiteral("7.4 V")), qPrintable(adjusted));
    }

    void aRegistersStepAndValueReadInItsOwnUnit()
    {
        const feetech::Register &acceleration = reg(sts(), "acceleration");
        QCOMPARE(feetech::resolutionText(acceleration), QStringLiteral("100 step/s²"));
        QCOMPARE(feetech::displayValue(acceleration, 50), QStringLiteral("5000 step/s²"));
        QCOMPARE(feetech::realNumber(acceleration, 50), QStringLiteral("5000"));
        QCOMPARE(feetech::resolutionText(reg(sts(), "max_voltage")), QStringLiteral("0.1 V"));
        // The Monitor's units are the tables' units.
        QCOMPARE(feetech::quantityUnit(feetech::Quantity::Position),
                 feetech::registerUnit(reg(sts(), "present_position")));
    }

    void parseValueAcceptsChoiceLabelsIgnoringCase()
    {
        QCOMPARE(parsed(reg(sts(), "mode"), QStringLiteral("Step")), 3);
        QCOMPARE(parsed(reg(sts(), "mode"), QStringLiteral("pwm open loop")), 2);
        QCOMPARE(parsed(reg(sts(), "torque_enable"), QStringLiteral("Calibrate middle (2048)")),
                 128);
        QCOMPARE(parsed(reg(scs(), "lock"), QStringLiteral("unlocked")), 0);
        // A number is a number even where there are choices.
        QCOMPARE(parsed(reg(sts(), "mode"), QStringLiteral("1")), 1);
        // SMS has no step mode, so "Step" is no label of its mode register.
        QCOMPARE(parsed(reg(RegisterTable::forFamily(Family::Sms), "mode"), QStringLiteral("Step")),
                 kRefused);
        // Nor does SCS know torque enable 128.
        QString error;
        QVERIFY(!feetech::parseValue(reg(scs(), "torque_enable"), QStringLiteral("128"), &error));
        QVERIFY2(error.contains(QStringLiteral("torque_enable")), qPrintable(error));
    }

    void parseValueRefusesWhatIsNotAWholeNumber_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("word") << QStringLiteral("hot");
        QTest::newRow("fraction") << QStringLiteral("1.5");
        QTest::newRow("with unit") << QStringLiteral("70 °C");
        QTest::newRow("empty") << QString();
        QTest::newRow("blank") << QStringLiteral("   ");
    }

    void parseValueRefusesWhatIsNotAWholeNumber()
    {
        QFETCH(QString, text);
        QString error;
        QVERIFY(!feetech::parseValue(reg(sts(), "max_temperature"), text, &error));
        QVERIFY2(error.contains(QStringLiteral("max_temperature")), qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral("not a whole number")), qPrintable(error));
    }

    void parseValueChecksTheRegisterRange_data()
    {
        QTest::addColumn<Family>("family");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("accepted");
        QTest::newRow("STS offset -2047")
            << Family::Sts << QStringLiteral("position_offset") << QStringLiteral("-2047") << true;
        QTest::newRow("STS offset -2048")
            << Family::Sts << QStringLiteral("position_offset") << QStringLiteral("-2048") << false;
        QTest::newRow("HLS offset -4095")
            << Family::Hls << QStringLiteral("position_offset") << QStringLiteral("-4095") << true;
        QTest::newRow("STS max temperature 100")
            << Family::Sts << QStringLiteral("max_temperature") << QStringLiteral("100") << true;
        QTest::newRow("STS max temperature 101")
            << Family::Sts << QStringLiteral("max_temperature") << QStringLiteral("101") << false;
        QTest::newRow("SCS goal position 1023")
            << Family::Scs << QStringLiteral("goal_position") << QStringLiteral("1023") << true;
        QTest::newRow("SCS goal position 4095")
            << Family::Scs << QStringLiteral("goal_position") << QStringLiteral("4095") << false;
        QTest::newRow("STS ID 253")
            << Family::Sts << QStringLiteral("id") << QStringLiteral("253") << true;
        QTest::newRow("STS ID 254")
            << Family::Sts << QStringLiteral("id") << QStringLiteral("254") << false;
        QTest::newRow("STS angular resolution 0")
            << Family::Sts << QStringLiteral("angular_resolution") << QStringLiteral("0") << false;
        QTest::newRow("STS max torque beyond 64 bits")
            << Family::Sts << QStringLiteral("max_torque") << QStringLiteral("99999999999999999999")
            << false;
    }

    void parseValueChecksTheRegisterRange()
    {
        QFETCH(Family, family);
        QFETCH(QString, key);
        QFETCH(QString, text);
        QFETCH(bool, accepted);
        QString error;
        const auto value = feetech::parseValue(
            reg(RegisterTable::forFamily(family), qPrintable(key)), text, &error);
        QCOMPARE(value.has_value(), accepted);
        if (accepted)
            QCOMPARE(*value, text.toInt());
        else
            QVERIFY2(error.contains(key), qPrintable(error));
    }

    // ---- bitNames and displayValue

    void bitNamesListsTheStatusBitsSet()
    {
        const feetech::Register &status = reg(sts(), "status");
        QCOMPARE(feetech::bitNames(status, 0), QStringLiteral("none"));
        QCOMPARE(feetech::bitNames(status, 0x01), QStringLiteral("Voltage"));
        QCOMPARE(feetech::bitNames(status, 0x25), QStringLiteral("Voltage, Temperature, Load"));
        QCOMPARE(feetech::bitNames(status, 0x2F),
                 QStringLiteral("Voltage, Encoder, Temperature, Current, Load"));
        // SCS has no encoder or current bits (spec §7.1).
        QCOMPARE(feetech::bitNames(reg(scs(), "status"), 0x21), QStringLiteral("Voltage, Load"));
    }

    void bitNamesNeverCallsAnAlarmNone()
    {
        // Bit 4 is undocumented on STS (the ST3215 sheet calls it "angle"): a status of 0x10 is
        // still an alarm and must not read as "none".
        const QString shown = feetech::bitNames(reg(sts(), "status"), 0x10);
        QVERIFY2(shown != QStringLiteral("none"), qPrintable(shown));
        QVERIFY2(shown.contains(QLatin1Char('4')), qPrintable(shown));
        QCOMPARE(feetech::bitNames(reg(sts(), "status"), 0x14),
                 feetech::bitNames(reg(sts(), "status"), 0x04) + QStringLiteral(", ")
                     + feetech::bitNames(reg(sts(), "status"), 0x10));
        QVERIFY(feetech::bitNames(reg(scs(), "status"), 0x02) != QStringLiteral("none"));
    }

    void displayValueShowsChoicesBitsAndScaledUnits_data()
    {
        QTest::addColumn<Family>("family");
        QTest::addColumn<QString>("key");
        QTest::addColumn<int>("value");
        QTest::addColumn<QString>("shown");
        QTest::newRow("baud code 4")
            << Family::Sts << QStringLiteral("baud_rate") << 4 << QStringLiteral("115200 bps");
        QTest::newRow("mode 1") << Family::Sts << QStringLiteral("mode") << 1
                                << QStringLiteral("Constant speed (wheel)");
        QTest::newRow("torque enable 128") << Family::Sts << QStringLiteral("torque_enable") << 128
                                           << QStringLiteral("Calibrate middle (2048)");
        QTest::newRow("SCS lock") << Family::Scs << QStringLiteral("lock") << 1
                                  << QStringLiteral("Locked");
        QTest::newRow("status bits") << Family::Sts << QStringLiteral("status") << 0x24
                                     << QStringLiteral("Temperature, Load");
        QTest::newRow("status clear")
            << Family::Sts << QStringLiteral("status") << 0 << QStringLiteral("none");
        QTest::newRow("return delay 250 × 2 µs")
            << Family::Sts << QStringLiteral("return_delay") << 250 << QStringLiteral("500 µs");
        QTest::newRow("voltage 74 × 0.1 V")
            << Family::Sts << QStringLiteral("present_voltage") << 74 << QStringLiteral("7.4 V");
        QTest::newRow("load -500 × 0.1 %")
            << Family::Sts << QStringLiteral("present_load") << -500 << QStringLiteral("-50 %");
        QTest::newRow("current 500 × 6.5 mA")
            << Family::Sts << QStringLiteral("present_current") << 500 << QStringLiteral("3250 mA");
        QTest::newRow("protection time 200 × 10 ms")
            << Family::Sts << QStringLiteral("protection_time") << 200 << QStringLiteral("2000 ms");
        QTest::newRow("temperature, scale 1")
            << Family::Sts << QStringLiteral("present_temperature") << 35
            << QStringLiteral("35 °C");
        QTest::newRow("position, scale 1") << Family::Sts << QStringLiteral("present_position")
                                           << -100 << QStringLiteral("-100 step");
        QTest::newRow("no unit") << Family::Sts << QStringLiteral("id") << 5 << QStringLiteral("5");
        QTest::newRow("SCS speed threshold × 50, no unit")
            << Family::Scs << QStringLiteral("moving_speed_threshold") << 2
            << QStringLiteral("100");
        QTest::newRow("SCS goal time in ms")
            << Family::Scs << QStringLiteral("goal_time") << 1000 << QStringLiteral("1000 ms");
    }

    void displayValueShowsChoicesBitsAndScaledUnits()
    {
        QFETCH(Family, family);
        QFETCH(QString, key);
        QFETCH(int, value);
        QFETCH(QString, shown);
        QCOMPARE(
            feetech::displayValue(reg(RegisterTable::forFamily(family), qPrintable(key)), value),
            shown);
    }

    void displayValueOfAValueNoChoiceNamesIsTheNumber()
    {
        // 3 is no torque-enable choice: shown as it is rather than hidden.
        QCOMPARE(feetech::displayValue(reg(sts(), "torque_enable"), 3), QStringLiteral("3"));
    }

    // ---- definitions
};

QTEST_APPLESS_MAIN(TestServoValues)
#include "tst_servovalues.moc"
