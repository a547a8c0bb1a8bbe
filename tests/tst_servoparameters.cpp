// Tests Feetech register values as parameters: decoding read blocks, encoding checked writes, the
// definitions built from the tables, and servo identity (parsing and showing values:
// tst_servovalues).
#include "feetechsession.h"
#include "registerlookup.h"
#include "servoparameters.h"

#include <QtTest>

using feetech::Family;
using feetech::MiddleCalibration;
using feetech::RegisterTable;
using registerlookup::reg;
using registerlookup::scs;
using registerlookup::sts;

Q_DECLARE_METATYPE(feetech::Family)
Q_DECLARE_METATYPE(feetech::MiddleCalibration)

namespace {

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(text);
}

// Decoded values by key.
QHash<QString, qint32> decode(const RegisterTable &table, int address, const QByteArray &bytes)
{
    QHash<QString, qint32> values;
    for (const feetech::DecodedRegister &item : feetech::decodeRegisters(table, address, bytes))
        values.insert(item.reg->key, item.value);
    return values;
}

// Addresses 0-8 as a servo answers the identity READ.
QByteArray identity(int firmwareMajor, int firmwareMinor, int endFlag, int modelMajor,
                    int modelMinor)
{
    QByteArray bytes(9, '\0');
    bytes[0] = char(firmwareMajor);
    bytes[1] = char(firmwareMinor);
    bytes[2] = char(endFlag);
    bytes[3] = char(modelMajor);
    bytes[4] = char(modelMinor);
    bytes[5] = char(1); // ID
    bytes[6] = char(0); // baud code: 1 Mbps
    bytes[7] = char(0); // return delay
    bytes[8] = char(1); // response level
    return bytes;
}

void addFamilyRows()
{
    QTest::addColumn<Family>("family");
    QTest::newRow("scs") << Family::Scs;
    QTest::newRow("sts") << Family::Sts;
    QTest::newRow("sms") << Family::Sms;
    QTest::newRow("hls") << Family::Hls;
}

} // namespace

class TestServoParameters : public QObject
{
    Q_OBJECT

private slots:
    // ---- decodeRegisters

    void stsFeedbackBlockDecodesSignMagnitudeValues()
    {
        // The SDK's FeedBack read: 15 bytes at 56 (spec §5.1), little-endian.
        const QByteArray block = hex("0008" // 56 present_position 2048
                                     "6480" // 58 present_speed -100 (sign bit 15)
                                     "c804" // 60 present_load -200 (direction bit 10)
                                     "4a" // 62 present_voltage 7.4 V
                                     "23" // 63 present_temperature 35
                                     "00" // 64 async_write_flag
                                     "24" // 65 status: temperature, load
                                     "01" // 66 moving
                                     "0008" // 67 current_goal_position 2048
                                     "0a80"); // 69 present_current -10
        const auto values = decode(sts(), 56, block);
        QCOMPARE(values.size(), 10);
        QCOMPARE(values.value(QStringLiteral("present_position")), 2048);
        QCOMPARE(values.value(QStringLiteral("present_speed")), -100);
        QCOMPARE(values.value(QStringLiteral("present_load")), -200);
        QCOMPARE(values.value(QStringLiteral("present_voltage")), 74);
        QCOMPARE(values.value(QStringLiteral("present_temperature")), 35);
        QCOMPARE(values.value(QStringLiteral("status")), 0x24);
        QCOMPARE(values.value(QStringLiteral("moving")), 1);
        QCOMPARE(values.value(QStringLiteral("current_goal_position")), 2048);
        QCOMPARE(values.value(QStringLiteral("present_current")), -10);
    }

    void stsPositionOffsetUsesSignBitEleven()
    {
        const auto items = feetech::decodeRegisters(sts(), 31, hex("0508"));
        QCOMPARE(items.size(), 1);
        QCOMPARE(items.first().reg->key, QStringLiteral("position_offset"));
        QCOMPARE(items.first().value, -5);
        QCOMPARE(items.first().raw, quint16(0x0805));
        // Bit 15 is not the sign here: 0x8005 is a magnitude of 5 with bits above 11 ignored.
        QCOMPARE(decode(sts(), 31, hex("0580")).value(QStringLiteral("position_offset")), 5);
        QCOMPARE(decode(sts(), 31, hex("ff0f")).value(QStringLiteral("position_offset")), -2047);
    }

    void stsPresentLoadUsesDirectionBitTen()
    {
        QCOMPARE(decode(sts(), 60, hex("e803")).value(QStringLiteral("present_load")), 1000);
        QCOMPARE(decode(sts(), 60, hex("e807")).value(QStringLiteral("present_load")), -1000);
    }

    void scsTwoByteValuesAreHighByteFirst()
    {
        const QByteArray block = hex("01f4" // 56 present_position 500 (unsigned on SCS)
                                     "800a" // 58 present_speed -10
                                     "0464"); // 60 present_load -100
        const auto values = decode(scs(), 56, block);
        QCOMPARE(values.value(QStringLiteral("present_position")), 500);
        QCOMPARE(values.value(QStringLiteral("present_speed")), -10);
        QCOMPARE(values.value(QStringLiteral("present_load")), -100);
        // SCS positions carry no sign: bit 15 set is simply a large number.
        QCOMPARE(decode(scs(), 56, hex("8001")).value(QStringLiteral("present_position")), 32769);
        // The same bytes read little-endian on STS.
        QCOMPARE(decode(sts(), 56, hex("01f4")).value(QStringLiteral("present_position")),
                 -(0x7401 & 0x7FFF));
    }

    void onlyRegistersWhollyInsideTheBlockAreDecoded()
    {
        // 56-68: present_current (69-70) lies outside; starting at 57 cuts present_position.
        const auto cut = decode(sts(), 57,
                                hex("00"
                                    "6480"
                                    "c804"
                                    "4a"
                                    "23"
                                    "00"
                                    "24"
                                    "01"
                                    "0008"
                                    "0a"));
        QVERIFY(!cut.contains(QStringLiteral("present_position")));
        QVERIFY(!cut.contains(QStringLiteral("present_current")));
        QCOMPARE(cut.value(QStringLiteral("present_speed")), -100);
        QCOMPARE(cut.value(QStringLiteral("current_goal_position")), 2048);
        // One byte of a two-byte register is no value at all.
        QVERIFY(feetech::decodeRegisters(sts(), 56, hex("00")).isEmpty());
        // A gap in the table (50-54) decodes to nothing.
        QVERIFY(feetech::decodeRegisters(sts(), 50, hex("0000000000")).isEmpty());
        QVERIFY(feetech::decodeRegisters(sts(), 56, QByteArray()).isEmpty());
    }

    void decodedRegistersComeInAddressOrder()
    {
        const auto items = feetech::decodeRegisters(sts(), 0, QByteArray(50, '\0'));
        QVERIFY(!items.isEmpty());
        QCOMPARE(items.first().reg->key, QStringLiteral("firmware_major"));
        QCOMPARE(items.last().reg->key, QStringLiteral("torque_limit"));
        for (int i = 1; i < items.size(); ++i)
            QVERIFY(items.at(i - 1).reg->address < items.at(i).reg->address);
    }

    // ---- encodeWrites

    void encodeWritesUsesTheFamilyByteOrderAndSignBit_data()
    {
        QTest::addColumn<Family>("family");
        QTest::addColumn<QString>("key");
        QTest::addColumn<qint64>("value");
        QTest::addColumn<int>("address");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<bool>("eeprom");
        QTest::newRow("STS goal position 1304, low byte first")
            << Family::Sts << QStringLiteral("goal_position") << qint64(1304) << 42 << hex("1805")
            << false;
        QTest::newRow("SCS goal position 1000, high byte first")
            << Family::Scs << QStringLiteral("goal_position") << qint64(1000) << 42 << hex("03e8")
            << false;
        QTest::newRow("SCS max torque 1000") << Family::Scs << QStringLiteral("max_torque")
                                             << qint64(1000) << 16 << hex("03e8") << true;
        QTest::newRow("STS offset -5: sign bit 11")
            << Family::Sts << QStringLiteral("position_offset") << qint64(-5) << 31 << hex("0508")
            << true;
        QTest::newRow("STS offset -2047") << Family::Sts << QStringLiteral("position_offset")
                                          << qint64(-2047) << 31 << hex("ff0f") << true;
        QTest::newRow("HLS offset -5: sign bit 15")
            << Family::Hls << QStringLiteral("position_offset") << qint64(-5) << 31 << hex("0580")
            << true;
        QTest::newRow("STS goal speed -100") << Family::Sts << QStringLiteral("goal_speed")
                                             << qint64(-100) << 46 << hex("6480") << false;
        QTest::newRow("STS torque enable 128 (calibrate)")
            << Family::Sts << QStringLiteral("torque_enable") << qint64(128) << 40 << hex("80")
            << false;
        QTest::newRow("SCS lock at 48")
            << Family::Scs << QStringLiteral("lock") << qint64(0) << 48 << hex("00") << false;
        QTest::newRow("STS lock at 55")
            << Family::Sts << QStringLiteral("lock") << qint64(1) << 55 << hex("01") << false;
    }

    void encodeWritesUsesTheFamilyByteOrderAndSignBit()
    {
        QFETCH(Family, family);
        QFETCH(QString, key);
        QFETCH(qint64, value);
        QFETCH(int, address);
        QFETCH(QByteArray, bytes);
        QFETCH(bool, eeprom);
        QString error;
        const auto writes =
            feetech::encodeWrites(RegisterTable::forFamily(family), {{key, value}}, &error);
        QVERIFY2(writes, qPrintable(error));
        QCOMPARE(writes->size(), 1);
        QCOMPARE(writes->first().address, address);
        QCOMPARE(writes->first().bytes.toHex(), bytes.toHex());
        QCOMPARE(writes->first().eeprom, eeprom);
        // And back: what was written decodes to what was asked.
        QCOMPARE(decode(RegisterTable::forFamily(family), address, bytes).value(key),
                 qint32(value));
    }

    void encodeWritesKeepsTheOrderOfTheEdits()
    {
        const auto writes = feetech::encodeWrites(sts(),
                                                  {{QStringLiteral("max_temperature"), 65},
                                                   {QStringLiteral("goal_position"), 2048},
                                                   {QStringLiteral("min_voltage"), 45}},
                                                  nullptr);
        QVERIFY(writes);
        QCOMPARE(writes->size(), 3);
        QCOMPARE(writes->at(0).address, 13);
        QCOMPARE(writes->at(0).bytes, hex("41"));
        QCOMPARE(writes->at(1).address, 42);
        QCOMPARE(writes->at(1).bytes, hex("0008"));
        QCOMPARE(writes->at(2).address, 15);
    }

    void encodeWritesRefusesOutOfRangeValuesNamingTheKey_data()
    {
        QTest::addColumn<Family>("family");
        QTest::addColumn<QString>("key");
        QTest::addColumn<qint64>("value");
        QTest::newRow("STS offset 2048")
            << Family::Sts << QStringLiteral("position_offset") << qint64(2048);
        QTest::newRow("STS offset -2048")
            << Family::Sts << QStringLiteral("position_offset") << qint64(-2048);
        QTest::newRow("STS max temperature 101")
            << Family::Sts << QStringLiteral("max_temperature") << qint64(101);
        QTest::newRow("STS ID 254 (broadcast)")
            << Family::Sts << QStringLiteral("id") << qint64(254);
        QTest::newRow("SCS goal position 1024")
            << Family::Scs << QStringLiteral("goal_position") << qint64(1024);
        QTest::newRow("SCS goal position -1")
            << Family::Scs << QStringLiteral("goal_position") << qint64(-1);
        QTest::newRow("SMS mode 3 (no step mode)")
            << Family::Sms << QStringLiteral("mode") << qint64(3);
        QTest::newRow("beyond 32 bits")
            << Family::Sts << QStringLiteral("max_torque") << (qint64(1) << 32);
    }

    void encodeWritesRefusesOutOfRangeValuesNamingTheKey()
    {
        QFETCH(Family, family);
        QFETCH(QString, key);
        QFETCH(qint64, value);
        QString error;
        // A valid edit next to the bad one: nothing at all is written.
        const auto writes = feetech::encodeWrites(
            RegisterTable::forFamily(family), {{QStringLiteral("lock"), 0}, {key, value}}, &error);
        QVERIFY(!writes);
        QVERIFY2(error.contains(key), qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral("out of range")), qPrintable(error));
    }

    void encodeWritesRefusesReadOnlyAndUnknownKeys_data()
    {
        QTest::addColumn<Family>("family");
        QTest::addColumn<QString>("key");
        QTest::newRow("STS present position") << Family::Sts << QStringLiteral("present_position");
        QTest::newRow("STS model major") << Family::Sts << QStringLiteral("model_major");
        QTest::newRow("STS factory max speed") << Family::Sts << QStringLiteral("max_speed_limit");
        QTest::newRow("unknown key") << Family::Sts << QStringLiteral("no_such_register");
        QTest::newRow("SCS has no offset") << Family::Scs << QStringLiteral("position_offset");
        QTest::newRow("SCS has no mode") << Family::Scs << QStringLiteral("mode");
        QTest::newRow("HLS has no return delay") << Family::Hls << QStringLiteral("return_delay");
    }

    void encodeWritesRefusesReadOnlyAndUnknownKeys()
    {
        QFETCH(Family, family);
        QFETCH(QString, key);
        QString error;
        QVERIFY(!feetech::encodeWrites(RegisterTable::forFamily(family), {{key, 0}}, &error));
        QVERIFY2(error.contains(key), qPrintable(error));
        QVERIFY2(error.contains(feetech::familyName(family)), qPrintable(error));
    }

    void encodeWritesOfNothingIsAnEmptyPlan()
    {
        const auto writes = feetech::encodeWrites(sts(), {}, nullptr);
        QVERIFY(writes);
        QVERIFY(writes->isEmpty());
    }

    void modelDefinitionsMirrorTheTable_data() { addFamilyRows(); }

    void modelDefinitionsMirrorTheTable()
    {
        QFETCH(Family, family);
        const RegisterTable &table = RegisterTable::forFamily(family);
        const auto definitions = feetech::modelDefinitions(table);
        QCOMPARE(definitions.size(), table.registers().size());
        for (int i = 0; i < definitions.size(); ++i) {
            const model::Definition &definition = definitions.at(i);
            const feetech::Register &source = table.registers().at(i);
            QCOMPARE(definition.key, source.key);
            QVERIFY(table.find(definition.key) == &source);
            QCOMPARE(definition.minimum, qint64(source.minimum));
            QCOMPARE(definition.maximum, qint64(source.maximum));
            QCOMPARE(definition.scale, source.scale);
            QCOMPARE(definition.unit, source.unit);
            QCOMPARE(definition.access == model::Access::ReadWrite, source.writable());
            QCOMPARE(definition.storage == model::Storage::Eeprom,
                     source.storage == feetech::Storage::Eeprom);
            QCOMPARE(definition.choices.size(), source.choices.size());
            QVERIFY(!definition.label.isEmpty());
            QVERIFY(!definition.group.isEmpty());
        }
    }

    void settingsGroupsNameOnlyKeysSomeTableHas()
    {
        for (const feetech::SettingsGroup &group : feetech::settingsGroups()) {
            QVERIFY(!group.title.isEmpty());
            for (const QString &key : group.keys) {
                bool known = false;
                for (const Family family : feetech::kAllFamilies)
                    known = known || RegisterTable::forFamily(family).find(key);
                QVERIFY2(known, qPrintable(key));
            }
        }
    }

    void profileHoldsWritableEepromSettingsExceptIdAndBaud_data() { addFamilyRows(); }

    void profileHoldsWritableEepromSettingsExceptIdAndBaud()
    {
        QFETCH(Family, family);
        const RegisterTable &table = RegisterTable::forFamily(family);
        const auto definitions = feetech::profileDefinitions(table);
        QStringList keys;
        for (const model::Definition &definition : definitions) {
            const feetech::Register *source = table.find(definition.key);
            QVERIFY2(source, qPrintable(definition.key));
            QVERIFY2(source->writable(), qPrintable(definition.key));
            QCOMPARE(source->storage, feetech::Storage::Eeprom);
            QCOMPARE(definition.access, model::Access::ReadWrite);
            QCOMPARE(definition.storage, model::Storage::Eeprom);
            keys.append(definition.key);
        }
        QVERIFY(!keys.contains(QStringLiteral("id")));
        QVERIFY(!keys.contains(QStringLiteral("baud_rate")));
        QVERIFY(!keys.contains(QStringLiteral("secondary_id"))); // HLS: also an address
        // Read-only EEPROM and RAM registers stay out.
        QVERIFY(!keys.contains(QStringLiteral("firmware_major")));
        QVERIFY(!keys.contains(QStringLiteral("model_minor")));
        QVERIFY(!keys.contains(QStringLiteral("torque_enable")));
        QVERIFY(!keys.contains(QStringLiteral("lock")));
        QVERIFY(!keys.contains(QStringLiteral("goal_position")));
        QVERIFY(!keys.contains(QStringLiteral("present_position")));
        QVERIFY(!keys.contains(QStringLiteral("dts")));
        // Everything else that is writable EEPROM is in, in address order.
        int expected = 0;
        for (const feetech::Register &source : table.registers()) {
            if (source.storage == feetech::Storage::Eeprom && source.writable()
                && source.key != u"id" && source.key != u"baud_rate"
                && source.key != u"secondary_id")
                QCOMPARE(keys.value(expected++), source.key);
        }
        QCOMPARE(keys.size(), expected);
        QVERIFY(keys.contains(QStringLiteral("max_temperature")));
        QVERIFY(keys.contains(QStringLiteral("response_level")));
    }

    void stsProfileKeepsTheOffsetAndScsHasNone()
    {
        const auto has = [](const RegisterTable &table, const QString &key) {
            for (const model::Definition &definition : feetech::profileDefinitions(table)) {
                if (definition.key == key)
                    return true;
            }
            return false;
        };
        QVERIFY(has(sts(), QStringLiteral("position_offset")));
        QVERIFY(has(sts(), QStringLiteral("mode")));
        QVERIFY(!has(scs(), QStringLiteral("position_offset")));
        QVERIFY(has(scs(), QStringLiteral("holding_torque")));
    }

    // ---- identity

    void sts3215IdentityGivesItsModelAndTable()
    {
        const auto info = feetech::servoInfoFromIdentity(1, 1000000, identity(3, 10, 0, 9, 3));
        QVERIFY(info);
        QCOMPARE(info->id, quint8(1));
        QCOMPARE(info->baud, 1000000);
        QCOMPARE(info->modelNumber(), quint16(777));
        QCOMPARE(info->model.name, QStringLiteral("STS3215"));
        QVERIFY(info->hasTable());
        QCOMPARE(*info->model.family, Family::Sts);
        QCOMPARE(info->table().family(), Family::Sts);
        QVERIFY(!info->table().isRaw());
        QCOMPARE(info->firmware(), QStringLiteral("3.10"));
        QCOMPARE(info->baudCode, quint8(0));
        QVERIFY(info->repliesToWrites());
    }

    void scs15IdentityIsReadBigEndian()
    {
        const auto info = feetech::servoInfoFromIdentity(3, 1000000, identity(1, 2, 1, 5, 15));
        QVERIFY(info);
        QCOMPARE(info->model.name, QStringLiteral("SCS15"));
        QCOMPARE(*info->model.family, Family::Scs);
        QCOMPARE(info->modelNumber(), quint16(0x050F));
        QCOMPARE(info->table().byteOrder(), feetech::ByteOrder::Big);
        QCOMPARE(info->firmware(), QStringLiteral("1.02"));
    }

    void responseLevelZeroMeansNoRepliesToWrites()
    {
        QByteArray bytes = identity(3, 10, 0, 9, 3);
        bytes[8] = 0;
        const auto info = feetech::servoInfoFromIdentity(1, 1000000, bytes);
        QVERIFY(info);
        QVERIFY(!info->repliesToWrites());
    }

    void tooFewIdentityBytesAreNoIdentity()
    {
        QVERIFY(!feetech::servoInfoFromIdentity(1, 1000000, identity(3, 10, 0, 9, 3).left(8)));
        QVERIFY(!feetech::servoInfoFromIdentity(1, 1000000, QByteArray()));
    }

    void endFlagContradictingTheFamilyLeavesNoTable_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("STS3215 claiming big-endian") << identity(3, 10, 1, 9, 3);
        QTest::newRow("SCS15 claiming little-endian") << identity(1, 2, 0, 5, 15);
        QTest::newRow("HLS claiming big-endian") << identity(3, 43, 1, 10, 0);
        QTest::newRow("STS3215 with END 2") << identity(3, 10, 2, 9, 3);
    }

    void endFlagContradictingTheFamilyLeavesNoTable()
    {
        QFETCH(QByteArray, bytes);
        const auto info = feetech::servoInfoFromIdentity(1, 1000000, bytes);
        QVERIFY(info);
        QVERIFY(!info->model.family);
        QVERIFY(!info->hasTable());
        QVERIFY(info->table().isRaw());
        QCOMPARE(feetech::middleCalibration(*info), MiddleCalibration::Unsupported);
    }

    void unknownMajorHasNoFamily()
    {
        // The model 1540 (4/6) the FTServo_Python README shows is in no list (spec §4.2).
        const auto info = feetech::servoInfoFromIdentity(1, 1000000, identity(3, 0, 0, 4, 6));
        QVERIFY(info);
        QVERIFY(!info->model.family);
        QVERIFY(!info->hasTable());
        QVERIFY(info->table().isRaw());
        QCOMPARE(info->modelNumber(), quint16(1540));
        QVERIFY2(info->model.name.contains(QStringLiteral("4/6")), qPrintable(info->model.name));
    }

    void unlistedMinorOfAKnownMajorKeepsTheFamilyTable()
    {
        const auto info = feetech::servoInfoFromIdentity(1, 1000000, identity(3, 10, 0, 9, 42));
        QVERIFY(info);
        QCOMPARE(*info->model.family, Family::Sts);
        QVERIFY(info->hasTable());
    }

    // ---- middle calibration

    void middleCalibrationFollowsFamilyAndFirmware_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<MiddleCalibration>("method");
        QTest::newRow("STS fw 3.10: instruction 0x0B")
            << identity(3, 10, 0, 9, 3) << MiddleCalibration::Instruction;
        QTest::newRow("STS fw 3.9: torque enable 128")
            << identity(3, 9, 0, 9, 3) << MiddleCalibration::TorqueEnable128;
        QTest::newRow("STS fw 3.7 (ST3215 sheet default)")
            << identity(3, 7, 0, 9, 3) << MiddleCalibration::TorqueEnable128;
        QTest::newRow("STS fw 4.0") << identity(4, 0, 0, 9, 3) << MiddleCalibration::Instruction;
        QTest::newRow("SMS: torque enable 128")
            << identity(2, 54, 0, 8, 0) << MiddleCalibration::TorqueEnable128;
        QTest::newRow("SMS with new firmware: still torque enable 128")
            << identity(3, 20, 0, 8, 44) << MiddleCalibration::TorqueEnable128;
        QTest::newRow("HLS: instruction 0x0B")
            << identity(3, 43, 0, 10, 0) << MiddleCalibration::Instruction;
        QTest::newRow("SCS: no offset register")
            << identity(1, 2, 1, 5, 15) << MiddleCalibration::Unsupported;
        QTest::newRow("unknown model")
            << identity(3, 10, 0, 4, 6) << MiddleCalibration::Unsupported;
        QTest::newRow("listed model without a table (SM30-360M)")
            << identity(3, 10, 0, 6, 3) << MiddleCalibration::Unsupported;
    }

    void middleCalibrationFollowsFamilyAndFirmware()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(MiddleCalibration, method);
        const auto info = feetech::servoInfoFromIdentity(1, 1000000, bytes);
        QVERIFY(info);
        QCOMPARE(feetech::middleCalibration(*info), method);
    }
};

QTEST_APPLESS_MAIN(TestServoParameters)
#include "tst_servoparameters.moc"
