// Tests the simulator's data file: built-in firmware and defaults, and malformed files refused.
#include "simulatordata.h"

#include <QtTest>

using feetech::Family;
using sim::SimulatorData;

namespace {

const char kValid[] = R"({
  "format": 1,
  "defaults": {"max_temperature": 70},
  "families": {
    "scs": {"firmware": {"major": 1, "minor": 0}, "defaults": {"max_voltage": 90}},
    "sts": {"firmware": {"major": 3, "minor": 10}},
    "sms": {"firmware": {"major": 2, "minor": 54}},
    "hls": {"firmware": {"major": 3, "minor": 45}, "note": "both forms of 0x0B"}
  }
})";

QString refusal(const QByteArray &json)
{
    QString error;
    const auto data = SimulatorData::parse(json, QStringLiteral("simulator.json"), &error);
    return data ? QString() : error;
}

QByteArray replaced(const char *from, const char *to)
{
    QByteArray json(kValid);
    Q_ASSERT(json.contains(from));
    return json.replace(from, to);
}

} // namespace

class TestSimulatorData : public QObject
{
    Q_OBJECT

private slots:
    void theBuiltInFileGivesEachFamilyItsFirmware()
    {
        const SimulatorData &data = SimulatorData::builtIn();
        QCOMPARE(data.firmware(Family::Sts).major, 3);
        QCOMPARE(data.firmware(Family::Sts).minor, 10);
        QCOMPARE(data.firmware(Family::Hls).minor, 45);
        QCOMPARE(data.firmware(Family::Sms).major, 2);
        QCOMPARE(data.firmware(Family::Scs).major, 1);
    }

    void familyDefaultsAddToTheCommonOnes()
    {
        const auto data = SimulatorData::parse(kValid, QStringLiteral("simulator.json"), nullptr);
        QVERIFY(data);
        QCOMPARE(data->fallbackDefault(Family::Scs, u"max_voltage"), std::optional<qint32>(90));
        QCOMPARE(data->fallbackDefault(Family::Sts, u"max_voltage"), std::nullopt);
        QCOMPARE(data->fallbackDefault(Family::Hls, u"max_temperature"), std::optional<qint32>(70));
        QCOMPARE(SimulatorData::builtIn().fallbackDefault(Family::Sts, u"max_torque"),
                 std::optional<qint32>(1000));
    }

    void malformedFilesAreRefusedNamingTheFileAndField_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("field");
        QTest::newRow("not json") << QByteArray("{") << QString();
        QTest::newRow("wrong format")
            << replaced("\"format\": 1", "\"format\": 2") << QStringLiteral("format");
        QTest::newRow("unknown root field")
            << replaced("\"format\": 1,", "\"format\": 1, \"firmware\": 3,")
            << QStringLiteral("firmware");
        QTest::newRow("missing family")
            << replaced("\"sms\": {\"firmware\": {\"major\": 2, \"minor\": 54}},", "")
            << QStringLiteral("families.sms");
        QTest::newRow("unknown family") << replaced("\"families\": {", "\"families\": {\"xl\": {},")
                                        << QStringLiteral("families.xl");
        QTest::newRow("firmware not a number") << replaced("\"minor\": 10", "\"minor\": \"10\"")
                                               << QStringLiteral("families.sts.firmware.minor");
        QTest::newRow("firmware out of range") << replaced("\"major\": 2", "\"major\": 256")
                                               << QStringLiteral("families.sms.firmware.major");
        QTest::newRow("missing firmware")
            << replaced("\"firmware\": {\"major\": 3, \"minor\": 45}, ", "")
            << QStringLiteral("families.hls.firmware");
        QTest::newRow("default not whole")
            << replaced("\"max_voltage\": 90", "\"max_voltage\": 9.5")
            << QStringLiteral("families.scs.defaults.max_voltage");
        QTest::newRow("common default not a number")
            << replaced("\"max_temperature\": 70", "\"max_temperature\": null")
            << QStringLiteral("defaults.max_temperature");
    }

    void malformedFilesAreRefusedNamingTheFileAndField()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, field);
        const QString error = refusal(json);
        QVERIFY2(error.startsWith(QStringLiteral("simulator.json: ")), qPrintable(error));
        if (!field.isEmpty())
            QVERIFY2(error.contains(QStringLiteral(": ") + field + u' '), qPrintable(error));
    }
};

QTEST_APPLESS_MAIN(TestSimulatorData)
#include "tst_simulatordata.moc"
