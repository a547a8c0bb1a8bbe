// Tests the Feetech register tables and model table: built-in data and the JSON validator.
#include "modeltable.h"
#include "registertable.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using feetech::ByteOrder;
using feetech::Family;
using feetech::ModelTable;
using feetech::RegisterTable;

Q_DECLARE_METATYPE(feetech::Family)
Q_DECLARE_METATYPE(feetech::ByteOrder)

namespace {

const QString kSource = QStringLiteral("test-table.json");

QJsonObject registerObject(int address, int size, const QString &key, int minimum, int maximum)
{
    return QJsonObject {
        {QStringLiteral("address"), address},
        {QStringLiteral("size"), size},
        {QStringLiteral("key"), key},
        {QStringLiteral("label"), key.toUpper()},
        {QStringLiteral("storage"), QStringLiteral("ram")},
        {QStringLiteral("access"), QStringLiteral("rw")},
        {QStringLiteral("min"), minimum},
        {QStringLiteral("max"), maximum},
    };
}

QJsonObject with(QJsonObject object, const QString &field, const QJsonValue &value)
{
    object.insert(field, value);
    return object;
}

QByteArray tableJson(const QJsonArray &registers, const QString &family = QStringLiteral("sts"))
{
    const QJsonObject root {
        {QStringLiteral("format"), 1},
        {QStringLiteral("family"), family},
        {QStringLiteral("title"), QStringLiteral("Test table")},
        {QStringLiteral("byte_order"), QStringLiteral("little")},
        {QStringLiteral("registers"), registers},
    };
    return QJsonDocument(root).toJson();
}

QByteArray modelsJson(const QJsonArray &models,
                      const QJsonObject &majors = {{QStringLiteral("9"), QStringLiteral("sts")}})
{
    const QJsonObject root {
        {QStringLiteral("format"), 1},
        {QStringLiteral("baud_rates"), QJsonArray {1000000, 500000, 115200}},
        {QStringLiteral("families_by_major"), majors},
        {QStringLiteral("models"), models},
    };
    return QJsonDocument(root).toJson();
}

QJsonObject model(int major, int minor, const QString &name, const QJsonValue &family)
{
    return QJsonObject {{QStringLiteral("major"), major},
                        {QStringLiteral("minor"), minor},
                        {QStringLiteral("name"), name},
                        {QStringLiteral("family"), family}};
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

class TestRegisterTable : public QObject
{
    Q_OBJECT

private slots:
    void builtInTableLoadsWithTheFamilyByteOrderAndLock_data()
    {
        QTest::addColumn<Family>("family");
        QTest::addColumn<ByteOrder>("order");
        QTest::addColumn<int>("lockAddress");
        QTest::newRow("scs") << Family::Scs << ByteOrder::Big << 48;
        QTest::newRow("sts") << Family::Sts << ByteOrder::Little << 55;
        QTest::newRow("sms") << Family::Sms << ByteOrder::Little << 55;
        QTest::newRow("hls") << Family::Hls << ByteOrder::Little << 55;
    }

    void builtInTableLoadsWithTheFamilyByteOrderAndLock()
    {
        QFETCH(Family, family);
        QFETCH(ByteOrder, order);
        QFETCH(int, lockAddress);
        const RegisterTable &table = RegisterTable::forFamily(family);
        QCOMPARE(table.family(), family);
        QCOMPARE(table.byteOrder(), order);
        const feetech::Register *lock = table.find(u"lock");
        QVERIFY(lock);
        QCOMPARE(lock->address, lockAddress);
        QCOMPARE(lock->size, 1);
        QVERIFY(lock->writable());
        QCOMPARE(table.at(lockAddress), lock);
        QCOMPARE(table.format(*lock).order, order);
    }

    void builtInTableHasEveryKeyTheCodeReliesOn_data() { addFamilyRows(); }

    void builtInTableHasEveryKeyTheCodeReliesOn()
    {
        QFETCH(Family, family);
        const RegisterTable &table = RegisterTable::forFamily(family);
        const char *const required[] = {
            "id",
            "baud_rate",
            "min_angle_limit",
            "max_angle_limit",
            "torque_enable",
            "goal_position",
            "goal_speed",
            "lock",
            "present_position",
            "present_speed",
            "present_load",
            "present_voltage",
            "present_temperature",
            "status",
            "moving",
        };
        for (const char *key : required)
            QVERIFY2(table.find(QString::fromLatin1(key)), key);
        // SCS has neither an offset nor a mode register (spec §4.1).
        const bool scs = family == Family::Scs;
        QCOMPARE(table.find(u"position_offset") != nullptr, !scs);
        QCOMPARE(table.find(u"mode") != nullptr, !scs);
    }

    void builtInSignBitsFollowTheSpec_data()
    {
        QTest::addColumn<Family>("family");
        QTest::addColumn<int>("positionSignBit"); // -1: unsigned
        QTest::addColumn<int>("loadSignBit");
        QTest::addColumn<int>("offsetSignBit"); // -1: no such register
        // SCS positions are unsigned (LeRobot, C++ SCSCL); STS offset bit 11, HLS bit 15.
        QTest::newRow("scs") << Family::Scs << -1 << 10 << -1;
        QTest::newRow("sts") << Family::Sts << 15 << 10 << 11;
        QTest::newRow("sms") << Family::Sms << 15 << 10 << 11;
        QTest::newRow("hls") << Family::Hls << 15 << 10 << 15;
    }

    void builtInSignBitsFollowTheSpec()
    {
        QFETCH(Family, family);
        QFETCH(int, positionSignBit);
        QFETCH(int, loadSignBit);
        QFETCH(int, offsetSignBit);
        const RegisterTable &table = RegisterTable::forFamily(family);
        const auto signBit = [&](QStringView key) {
            const feetech::Register *reg = table.find(key);
            return reg && reg->signBit ? *reg->signBit : -1;
        };
        QCOMPARE(signBit(u"present_position"), positionSignBit);
        QCOMPARE(signBit(u"present_load"), loadSignBit);
        QCOMPARE(signBit(u"position_offset"), offsetSignBit);
        QCOMPARE(table.find(u"present_position")->address, 56);
        QCOMPARE(table.find(u"present_load")->address, 60);
        if (offsetSignBit >= 0)
            QCOMPARE(table.find(u"position_offset")->address, 31);
    }

    void blocksAreContiguousRunsCoveringEveryRegisterOnce_data() { addFamilyRows(); }

    void blocksAreContiguousRunsCoveringEveryRegisterOnce()
    {
        QFETCH(Family, family);
        const RegisterTable &table = RegisterTable::forFamily(family);
        const QVector<feetech::Block> blocks = table.blocks();
        QVERIFY(!blocks.isEmpty());
        for (int i = 1; i < blocks.size(); ++i) {
            // Blocks ascend and never touch: touching blocks would have been one run.
            QVERIFY(blocks.at(i).address > blocks.at(i - 1).address + blocks.at(i - 1).size);
        }
        // Walk the registers: each starts where the previous one ended, or at a block start.
        int block = -1;
        int expected = -1;
        int covered = 0;
        for (const feetech::Register &reg : table.registers()) {
            if (reg.address != expected) {
                ++block;
                QVERIFY(block < blocks.size());
                QCOMPARE(reg.address, blocks.at(block).address);
            }
            QVERIFY(reg.end() <= blocks.at(block).address + blocks.at(block).size);
            expected = reg.end();
            covered += reg.size;
        }
        QCOMPARE(block, blocks.size() - 1);
        int blockBytes = 0;
        for (const feetech::Block &each : blocks)
            blockBytes += each.size;
        QCOMPARE(blockBytes, covered);
    }

    void ramBlocksCoverEveryRamRegisterAndNothingElse_data() { addFamilyRows(); }

    void ramBlocksCoverEveryRamRegisterAndNothingElse()
    {
        QFETCH(Family, family);
        const RegisterTable &table = RegisterTable::forFamily(family);
        QSet<int> inBlocks;
        for (const feetech::Block &block : table.ramBlocks()) {
            for (int address = block.address; address < block.address + block.size; ++address) {
                QVERIFY(!inBlocks.contains(address));
                inBlocks.insert(address);
            }
        }
        QSet<int> ram;
        for (const feetech::Register &reg : table.registers()) {
            for (int address = reg.address; address < reg.end(); ++address) {
                if (reg.storage == feetech::Storage::Ram)
                    ram.insert(address);
            }
        }
        QCOMPARE(inBlocks, ram);
    }

    void tablesGiveTheirTorqueValuesAndFeedbackBlock()
    {
        const RegisterTable &sts = RegisterTable::forFamily(Family::Sts);
        QCOMPARE(sts.torqueValue(feetech::TorqueMode::Off), std::optional<qint32>(0));
        QCOMPARE(sts.torqueValue(feetech::TorqueMode::CalibrateMiddle), std::optional<qint32>(128));
        QVERIFY(!RegisterTable::forFamily(Family::Scs)
                     .torqueValue(feetech::TorqueMode::CalibrateMiddle)
                     .has_value());
        QVERIFY(!RegisterTable::forFamily(Family::Sms)
                     .torqueValue(feetech::TorqueMode::Damping)
                     .has_value());
        for (const Family family : feetech::kAllFamilies) {
            const feetech::Block block = RegisterTable::forFamily(family).feedbackBlock();
            QCOMPARE(block.address, 56);
            QCOMPARE(block.size, 15);
        }
        QCOMPARE(feetech::baudRates().size(), 8);
        QCOMPARE(feetech::baudForCode(4), 115200);
        QCOMPARE(feetech::defaultBaud(Family::Sms), 115200);
        QCOMPARE(feetech::defaultBaud(Family::Hls), 1000000);
    }

    void tableFactsThatContradictTheRegistersAreRefused()
    {
        QJsonArray registers {
            with(registerObject(40, 1, QStringLiteral("torque_enable"), 0, 1),
                 QStringLiteral("choices"),
                 QJsonArray {QJsonObject {{QStringLiteral("value"), 0},
                                          {QStringLiteral("label"), QStringLiteral("Off")}},
                             QJsonObject {{QStringLiteral("value"), 1},
                                          {QStringLiteral("label"), QStringLiteral("On")}}}),
        };
        QJsonObject root = QJsonDocument::fromJson(tableJson(registers)).object();
        QString error;
        // Torque enable without its values.
        QVERIFY(!RegisterTable::fromJson(QJsonDocument(root).toJson(), kSource, &error));
        QVERIFY2(error.contains(QStringLiteral("torque_enable_values")), qPrintable(error));
        // A value that is not one of its choices.
        root.insert(QStringLiteral("torque_enable_values"),
                    QJsonObject {{QStringLiteral("off"), 0},
                                 {QStringLiteral("on"), 1},
                                 {QStringLiteral("damping"), 2}});
        QVERIFY(!RegisterTable::fromJson(QJsonDocument(root).toJson(), kSource, &error));
        QVERIFY2(error.startsWith(kSource) && error.contains(QStringLiteral("damping")),
                 qPrintable(error));
        root.insert(QStringLiteral("torque_enable_values"),
                    QJsonObject {{QStringLiteral("off"), 0}, {QStringLiteral("on"), 1}});
        QVERIFY2(RegisterTable::fromJson(QJsonDocument(root).toJson(), kSource, &error),
                 qPrintable(error));
        // The model table's baud codes: a rate listed twice.
        QVERIFY(!ModelTable::fromJson(
            QJsonDocument(
                QJsonObject {{QStringLiteral("format"), 1},
                             {QStringLiteral("baud_rates"), QJsonArray {1000000, 1000000}},
                             {QStringLiteral("models"), QJsonArray {}}})
                .toJson(),
            kSource, &error));
        QVERIFY2(error.contains(QStringLiteral("baud_rates")), qPrintable(error));
    }

    void aFeedbackBlockAtTheTopOfTheIntegerRangeIsRefused()
    {
        // Found by fuzzing: the block's end was added up in int before the address was checked,
        // an overflow the sanitizer build stops on.
        QFile file(QStringLiteral(":/feetech/registers-sts.json"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
        for (const auto &[address, size] : {std::pair {2147483647, 1}, std::pair {56, 2147483647},
                                            std::pair {-2147483647 - 1, -1}}) {
            root.insert(
                QStringLiteral("feedback_block"),
                QJsonObject {{QStringLiteral("address"), address}, {QStringLiteral("size"), size}});
            QString error;
            QVERIFY(!RegisterTable::fromJson(QJsonDocument(root).toJson(), kSource, &error));
            QVERIFY2(error.contains(QStringLiteral("feedback_block")), qPrintable(error));
        }
    }

    void stsTableReadsInThreeBlocks()
    {
        // Checked by hand against registers-sts.json: 0-49 (up to torque limit at 48), 55-70
        // (lock to present current), 80-86 (factory area).
        const QVector<feetech::Block> blocks = RegisterTable::forFamily(Family::Sts).blocks();
        QCOMPARE(blocks.size(), 3);
        QCOMPARE(blocks.at(0).address, 0);
        QCOMPARE(blocks.at(0).size, 50);
        QCOMPARE(blocks.at(1).address, 55);
        QCOMPARE(blocks.at(1).size, 16);
        QCOMPARE(blocks.at(2).address, 80);
        QCOMPARE(blocks.at(2).size, 7);
    }

    void fromJsonAcceptsAMinimalTable()
    {
        const QJsonArray registers {
            with(with(registerObject(31, 2, QStringLiteral("position_offset"), -2047, 2047),
                      QStringLiteral("sign_bit"), 11),
                 QStringLiteral("default"), 0),
            registerObject(55, 1, QStringLiteral("lock"), 0, 1),
        };
        QString error;
        const auto table = RegisterTable::fromJson(tableJson(registers), kSource, &error);
        QVERIFY2(table.has_value(), qPrintable(error));
        QCOMPARE(table->family(), Family::Sts);
        QCOMPARE(table->title(), QStringLiteral("Test table"));
        QCOMPARE(table->byteOrder(), ByteOrder::Little);
        QCOMPARE(table->registers().size(), 2);
        const feetech::Register *offset = table->find(u"position_offset");
        QVERIFY(offset);
        QCOMPARE(offset->minimum, -2047);
        QCOMPARE(offset->signBit, std::optional<int>(11));
        QCOMPARE(offset->defaultValue, std::optional<qint32>(0));
        QCOMPARE(table->blocks().size(), 2);
    }

    void fromJsonRejectsABadTableNamingTheCulprit_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QStringList>("mentions");
        const QJsonObject position =
            registerObject(42, 2, QStringLiteral("goal_position"), 0, 4095);
        const QJsonObject lock = registerObject(55, 1, QStringLiteral("lock"), 0, 1);

        QTest::newRow("overlapping registers")
            << tableJson({position, registerObject(43, 1, QStringLiteral("squatter"), 0, 1)})
            << QStringList {QStringLiteral("goal_position"), QStringLiteral("squatter")};
        QTest::newRow("size 3") << tableJson(
            {registerObject(42, 3, QStringLiteral("wide"), 0, 1), lock})
                                << QStringList {QStringLiteral("wide")};
        QTest::newRow("duplicate key")
            << tableJson({lock, registerObject(60, 1, QStringLiteral("lock"), 0, 1)})
            << QStringList {QStringLiteral("lock")};
        QTest::newRow("max 300 on a 1-byte register")
            << tableJson({registerObject(13, 1, QStringLiteral("max_temperature"), 0, 300)})
            << QStringList {QStringLiteral("max_temperature")};
        QTest::newRow("70000 on a 2-byte register")
            << tableJson({registerObject(16, 2, QStringLiteral("max_torque"), 0, 70000)})
            << QStringList {QStringLiteral("max_torque")};
        QTest::newRow("+-4000 with sign bit 11") << tableJson(
            {with(registerObject(31, 2, QStringLiteral("position_offset"), -4000, 4000),
                  QStringLiteral("sign_bit"), 11)})
                                                 << QStringList {QStringLiteral("position_offset")};
        QTest::newRow("negative min without a sign bit")
            << tableJson({registerObject(42, 2, QStringLiteral("goal_position"), -1, 4095)})
            << QStringList {QStringLiteral("goal_position")};
        QTest::newRow("min above max")
            << tableJson({registerObject(33, 1, QStringLiteral("mode"), 3, 0)})
            << QStringList {QStringLiteral("mode")};
        QTest::newRow("unknown field")
            << tableJson({lock, with(position, QStringLiteral("colour"), QStringLiteral("red"))})
            << QStringList {QStringLiteral("goal_position"), QStringLiteral("colour")};
        QTest::newRow("bad JSON") << QByteArray(
            "{\"format\": 1, \"family\": \"sts\", \"registers\": [")
                                  << QStringList {QStringLiteral("JSON")};
        QTest::newRow("unknown family")
            << tableJson({lock}, QStringLiteral("dxl")) << QStringList {QStringLiteral("dxl")};
        QTest::newRow("default does not fit the register")
            << tableJson({with(lock, QStringLiteral("default"), 300)})
            << QStringList {QStringLiteral("lock"), QStringLiteral("default")};
        QTest::newRow("default outside min..max")
            << tableJson({position, with(lock, QStringLiteral("default"), 5)})
            << QStringList {QStringLiteral("lock"), QStringLiteral("default")};
        QTest::newRow("negative default without a sign bit")
            << tableJson({with(position, QStringLiteral("default"), -1)})
            << QStringList {QStringLiteral("goal_position"), QStringLiteral("default")};
    }

    void fromJsonRejectsABadTableNamingTheCulprit()
    {
        QFETCH(QByteArray, json);
        QFETCH(QStringList, mentions);
        QString error;
        QVERIFY(!RegisterTable::fromJson(json, kSource, &error).has_value());
        QVERIFY2(error.startsWith(kSource), qPrintable(error));
        for (const QString &mention : mentions)
            QVERIFY2(error.contains(mention), qPrintable(error));
    }

    void identifyNamesModelsAndTheirFamilies_data()
    {
        QTest::addColumn<int>("major");
        QTest::addColumn<int>("minor");
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("family"); // -1: no family
        QTest::newRow("STS3215") << 9 << 3 << QStringLiteral("STS3215") << int(Family::Sts);
        QTest::newRow("SCS15") << 5 << 15 << QStringLiteral("SCS15") << int(Family::Scs);
        QTest::newRow("STS3032") << 9 << 2 << QStringLiteral("STS3032") << int(Family::Sts);
        QTest::newRow("SM-CL, known but no table") << 6 << 0 << QStringLiteral("SMxx-360M") << -1;
        QTest::newRow("SCS-named major 9, no table") << 9 << 15 << QStringLiteral("SCS15-2") << -1;
    }

    void identifyNamesModelsAndTheirFamilies()
    {
        QFETCH(int, major);
        QFETCH(int, minor);
        QFETCH(QString, name);
        QFETCH(int, family);
        const feetech::ModelInfo info =
            ModelTable::builtIn().identify(quint8(major), quint8(minor));
        QCOMPARE(info.name, name);
        QCOMPARE(info.major, major);
        QCOMPARE(info.minor, minor);
        QCOMPARE(info.family.has_value(), family >= 0);
        if (family >= 0)
            QCOMPARE(int(*info.family), family);
    }

    void unlistedMinorOfAKnownMajorIsNamedAfterTheFamily()
    {
        const feetech::ModelInfo info = ModelTable::builtIn().identify(10, 44);
        QCOMPARE(info.family, std::optional<Family>(Family::Hls));
        QVERIFY2(info.name.contains(QLatin1String("HLS")), qPrintable(info.name));
        QVERIFY2(info.name.contains(QLatin1String("10/44")), qPrintable(info.name));
    }

    void unknownMajorHasNoFamilyAndSaysUnknown()
    {
        const feetech::ModelInfo info = ModelTable::builtIn().identify(200, 1);
        QVERIFY(!info.family.has_value());
        QVERIFY2(info.name.contains(QLatin1String("unknown"), Qt::CaseInsensitive),
                 qPrintable(info.name));
        QVERIFY2(info.name.contains(QLatin1String("200/1")), qPrintable(info.name));
    }

    void modelNumberReadsAddressesThreeAndFourInTheFamilyOrder()
    {
        QCOMPARE(feetech::modelNumber(9, 3, ByteOrder::Little), quint16(777));
        QCOMPARE(feetech::modelNumber(5, 4, ByteOrder::Big), quint16(1284));
        QCOMPARE(feetech::modelNumber(9, 11, ByteOrder::Little), quint16(2825));
    }

    void findByNameIgnoresCase()
    {
        for (const QString &name :
             {QStringLiteral("sts3215"), QStringLiteral("STS3215"), QStringLiteral("Sts3215")}) {
            const auto info = ModelTable::builtIn().findByName(name);
            QVERIFY2(info.has_value(), qPrintable(name));
            QCOMPARE(info->name, QStringLiteral("STS3215"));
            QCOMPARE(info->major, 9);
            QCOMPARE(info->minor, 3);
        }
        QVERIFY(!ModelTable::builtIn().findByName(u"sts9999").has_value());
    }

    void findByNameAcceptsEitherAliasOfASlashedName()
    {
        const auto info = ModelTable::builtIn().findByName(u"scs0009");
        QVERIFY(info.has_value());
        QCOMPARE(info->major, 5);
        QCOMPARE(info->minor, 4);
        QVERIFY(ModelTable::builtIn().findByName(u"SCS009").has_value());
        QVERIFY(!ModelTable::builtIn().findByName(u"SCS009/").has_value());
    }

    void modelTableFromJsonAcceptsAMinimalTable()
    {
        QString error;
        const auto table = ModelTable::fromJson(
            modelsJson({model(9, 3, QStringLiteral("STS3215"), QStringLiteral("sts")),
                        model(6, 0, QStringLiteral("SMxx-360M"), QJsonValue::Null)}),
            kSource, &error);
        QVERIFY2(table.has_value(), qPrintable(error));
        QCOMPARE(table->models().size(), 2);
        QCOMPARE(table->identify(9, 3).family, std::optional<Family>(Family::Sts));
        QVERIFY(!table->identify(6, 0).family.has_value());
        QCOMPARE(table->identify(9, 77).family, std::optional<Family>(Family::Sts));
    }

    void modelTableFromJsonRejectsDuplicatesAndUnknownFamilies_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("mention");
        QTest::newRow("duplicate model")
            << modelsJson({model(9, 3, QStringLiteral("STS3215"), QStringLiteral("sts")),
                           model(9, 3, QStringLiteral("STS3215 again"), QStringLiteral("sts"))})
            << QStringLiteral("9/3");
        QTest::newRow("unknown model family")
            << modelsJson({model(9, 3, QStringLiteral("STS3215"), QStringLiteral("xl"))})
            << QStringLiteral("STS3215");
        QTest::newRow("unknown family for a major")
            << modelsJson({}, {{QStringLiteral("7"), QStringLiteral("xl")}}) << QStringLiteral("7");
    }

    void modelTableFromJsonRejectsDuplicatesAndUnknownFamilies()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, mention);
        QString error;
        QVERIFY(!ModelTable::fromJson(json, kSource, &error).has_value());
        QVERIFY2(error.startsWith(kSource), qPrintable(error));
        QVERIFY2(error.contains(mention), qPrintable(error));
    }
};

QTEST_APPLESS_MAIN(TestRegisterTable)
#include "tst_registertable.moc"
