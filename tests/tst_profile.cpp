// Tests JSON profiles: round trips in user units, strict validation, atomic saves, device diff.
#include "profile.h"
#include "ptkparameters.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using profile::Profile;
using Code = util::FileError::Code;
Q_DECLARE_METATYPE(util::FileError::Code)
using profile::ProfileValue;

namespace {

const QString kPtk = QStringLiteral("ptk");

// The seed document's sample servo as a profile: wire values, in definition order.
Profile seedProfile(bool softStart)
{
    const ptk::ParameterSet sample = ptk::ParameterSet::seedSample(softStart);
    Profile result;
    result.family = kPtk;
    for (const ptk::ParameterInfo &meta : ptk::parameterInfos())
        result.values.append({QLatin1String(meta.key), *sample.value(meta.parameter)});
    return result;
}

// A minimal valid profile document, to be spoiled one part at a time.
QJsonObject validRoot()
{
    QJsonObject parameters;
    parameters.insert(QStringLiteral("gain"), 29);
    parameters.insert(QStringLiteral("inversion"), true);
    QJsonObject root;
    root.insert(QStringLiteral("format"), QStringLiteral("servobench-profile"));
    root.insert(QStringLiteral("version"), 1);
    root.insert(QStringLiteral("family"), kPtk);
    root.insert(QStringLiteral("model"), QString());
    root.insert(QStringLiteral("parameters"), parameters);
    return root;
}

QJsonObject withParameter(QJsonObject root, const QString &key, const QJsonValue &value)
{
    QJsonObject parameters = root.value(QStringLiteral("parameters")).toObject();
    parameters.insert(key, value);
    root.insert(QStringLiteral("parameters"), parameters);
    return root;
}

QByteArray bytes(const QJsonObject &root)
{
    return QJsonDocument(root).toJson();
}

QVector<model::Definition> definitionsWithReadOnly()
{
    QVector<model::Definition> definitions = ptk::modelDefinitions();
    model::Definition voltage;
    voltage.key = QStringLiteral("present_voltage");
    voltage.label = QStringLiteral("Present voltage");
    voltage.unit = QStringLiteral("V");
    voltage.scale = 0.1;
    voltage.maximum = 255;
    voltage.access = model::Access::ReadOnly;
    definitions.append(voltage);
    return definitions;
}

QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

class TestProfile : public QObject
{
    Q_OBJECT

private slots:
    void savedProfileLoadsBackUnchanged()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("sample.json"));
        Profile original = seedProfile(true);
        original.model = QStringLiteral("PTK 7308");
        original.note = QStringLiteral("bench sample, soft start on");
        original.saved = QDateTime(QDate(2024, 5, 17), QTime(14, 3, 9), Qt::UTC);

        util::FileError error;
        QVERIFY2(profile::save(path, original, ptk::modelDefinitions(), &error),
                 qPrintable(error.describe()));
        const std::optional<Profile> loaded =
            profile::load(path, kPtk, ptk::modelDefinitions(), &error);
        QVERIFY2(loaded, qPrintable(error.describe()));
        QCOMPARE(loaded->family, original.family);
        QCOMPARE(loaded->model, original.model);
        QCOMPARE(loaded->note, original.note);
        QCOMPARE(loaded->saved, original.saved);
        QCOMPARE(loaded->values, original.values);
    }

    void valuesAreWrittenInUserUnitsWithSwitchesAsBooleans()
    {
        const QJsonObject root =
            QJsonDocument::fromJson(profile::toJson(seedProfile(false), ptk::modelDefinitions()))
                .object();
        QCOMPARE(root.value(QStringLiteral("format")).toString(),
                 QStringLiteral("servobench-profile"));
        QCOMPARE(root.value(QStringLiteral("version")).toInt(), 1);
        QCOMPARE(root.value(QStringLiteral("family")).toString(), kPtk);
        const QJsonObject parameters = root.value(QStringLiteral("parameters")).toObject();
        QCOMPARE(parameters.size(), ptk::kParameterCount);
        // Pulse widths travel as µs × 4; the file holds µs.
        QCOMPARE(parameters.value(QStringLiteral("min_pulse_us")).toDouble(), 500.0);
        QCOMPARE(parameters.value(QStringLiteral("max_pulse_us")).toDouble(), 2500.0);
        QCOMPARE(parameters.value(QStringLiteral("gain")).toDouble(), 29.0);
        QCOMPARE(parameters.value(QStringLiteral("neutral")).toDouble(), 4096.0);
        QCOMPARE(parameters.value(QStringLiteral("overload_time_ms")).toDouble(), 2000.0);
        QVERIFY(parameters.value(QStringLiteral("inversion")).isBool());
        QCOMPARE(parameters.value(QStringLiteral("inversion")).toBool(), true);
        QVERIFY(parameters.value(QStringLiteral("soft_start")).isBool());
        QCOMPARE(parameters.value(QStringLiteral("soft_start")).toBool(), false);
        // Whole user values are written as integers, not as 500.0.
        QVERIFY(profile::toJson(seedProfile(false), ptk::modelDefinitions())
                    .contains("\"min_pulse_us\": 500,"));
    }

    void aProfileForAnotherFamilyIsRejected()
    {
        QJsonObject root = validRoot();
        root.insert(QStringLiteral("family"), QStringLiteral("sts"));
        util::FileError error;
        QVERIFY(!profile::parse(bytes(root), kPtk, ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), Code::WrongServos);
        QVERIFY2(error.describe().contains(QStringLiteral("\"sts\""))
                     && error.describe().contains(QStringLiteral("\"ptk\"")),
                 qPrintable(error.describe()));
    }

    void anUnknownParameterIsRejectedByName()
    {
        const QJsonObject root = withParameter(validRoot(), QStringLiteral("gian"), 3);
        util::FileError error;
        QVERIFY(!profile::parse(bytes(root), kPtk, ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), Code::UnknownKey);
        QCOMPARE(error.field(), QStringLiteral("gian"));
        QCOMPARE(error.describe(), QStringLiteral("unknown parameter \"gian\""));
    }

    void anOutOfRangeValueIsRejectedWithItsRange_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("message");
        QTest::newRow("pulse over")
            << QStringLiteral("min_pulse_us") << 3000.0
            << QStringLiteral("min_pulse_us: 3000 µs is out of range (500 to 1500 µs)");
        QTest::newRow("pulse under") << QStringLiteral("max_pulse_us") << 1499.75
                                     << QStringLiteral("max_pulse_us: 1499.75 µs is out of range "
                                                       "(1500 to 2500 µs)");
        QTest::newRow("gain") << QStringLiteral("gain") << 31.0
                              << QStringLiteral("gain: 31 is out of range (0 to 30)");
        QTest::newRow("negative") << QStringLiteral("damping") << -1.0
                                  << QStringLiteral("damping: -1 is out of range (0 to 255)");
        QTest::newRow("huge") << QStringLiteral("neutral") << 1e300
                              << QStringLiteral("neutral: 1e+300 is out of range (2000 to 6000)");
    }

    void anOutOfRangeValueIsRejectedWithItsRange()
    {
        QFETCH(QString, key);
        QFETCH(double, value);
        QFETCH(QString, message);
        util::FileError error;
        QVERIFY(!profile::parse(bytes(withParameter(validRoot(), key, value)), kPtk,
                                ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), Code::BadValue);
        QCOMPARE(error.field(), key);
        QCOMPARE(error.describe(), message);
    }

    void aValueOfTheWrongTypeIsRejected_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<QString>("message");
        QTest::addColumn<Code>("code");
        QTest::newRow("number as text")
            << QStringLiteral("gain") << QJsonValue(QStringLiteral("29"))
            << QStringLiteral("gain: expected a number") << Code::WrongType;
        QTest::newRow("number as boolean")
            << QStringLiteral("gain") << QJsonValue(true)
            << QStringLiteral("gain: expected a number") << Code::WrongType;
        QTest::newRow("null") << QStringLiteral("damping") << QJsonValue(QJsonValue::Null)
                              << QStringLiteral("damping: expected a number") << Code::WrongType;
        QTest::newRow("switch as number")
            << QStringLiteral("inversion") << QJsonValue(1)
            << QStringLiteral("inversion: expected true or false") << Code::WrongType;
        QTest::newRow("switch as text")
            << QStringLiteral("soft_start") << QJsonValue(QStringLiteral("on"))
            << QStringLiteral("soft_start: expected true or false") << Code::WrongType;
        QTest::newRow("fraction") << QStringLiteral("gain") << QJsonValue(2.5)
                                  << QStringLiteral("gain: 2.5 is not a whole number")
                                  << Code::BadValue;
        QTest::newRow("between raw steps")
            << QStringLiteral("min_pulse_us") << QJsonValue(500.1)
            << QStringLiteral("min_pulse_us: 500.1 µs is not a multiple of 0.25 µs")
            << Code::BadValue;
    }

    void aValueOfTheWrongTypeIsRejected()
    {
        QFETCH(QString, key);
        QFETCH(QJsonValue, value);
        QFETCH(QString, message);
        QFETCH(Code, code);
        util::FileError error;
        QVERIFY(!profile::parse(bytes(withParameter(validRoot(), key, value)), kPtk,
                                ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), code);
        QCOMPARE(error.describe(), message);
    }

    void aQuarterMicrosecondStepIsAccepted()
    {
        const QJsonObject root = withParameter(validRoot(), QStringLiteral("min_pulse_us"), 500.25);
        util::FileError error;
        const std::optional<Profile> loaded =
            profile::parse(bytes(root), kPtk, ptk::modelDefinitions(), &error);
        QVERIFY2(loaded, qPrintable(error.describe()));
        QCOMPARE(loaded->value(QStringLiteral("min_pulse_us")).value_or(-1), 2001);
    }

    void malformedJsonIsRejectedWithItsOffset()
    {
        util::FileError error;
        QVERIFY(!profile::parse("{\"format\": \"servobench-profile\",, \"version\": 1}", kPtk,
                                ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), Code::NotJson);
        QCOMPARE(error.value(), QStringLiteral("33"));
        QVERIFY2(error.describe().startsWith(QStringLiteral("not valid JSON")),
                 qPrintable(error.describe()));
        QVERIFY2(error.describe().contains(QStringLiteral("at offset 33")),
                 qPrintable(error.describe()));
        QVERIFY(!profile::parse(QByteArray(), kPtk, ptk::modelDefinitions(), &error));
        QVERIFY2(error.describe().startsWith(QStringLiteral("not valid JSON")),
                 qPrintable(error.describe()));
    }

    void aProfileFromANewerVersionIsRejected()
    {
        QJsonObject root = validRoot();
        root.insert(QStringLiteral("version"), 2);
        // A newer format may well bring entries this version does not know; the version is
        // what the user must hear about.
        root.insert(QStringLiteral("checksum"), QStringLiteral("abc"));
        util::FileError error;
        QVERIFY(!profile::parse(bytes(root), kPtk, ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), Code::NewerVersion);
        QCOMPARE(error.describe(),
                 QStringLiteral("the profile has format version 2 and was written by a newer "
                                "ServoBench; this version reads format version 1 and older"));
    }

    void aBrokenEnvelopeIsRejected_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("message");
        QTest::addColumn<Code>("code");
        const auto spoiled = [](const QString &key, const QJsonValue &value) {
            QJsonObject root = validRoot();
            if (value.isUndefined())
                root.remove(key);
            else
                root.insert(key, value);
            return bytes(root);
        };
        const QString notAProfile =
            QStringLiteral("not a ServoBench profile (\"format\" is not \"servobench-profile\")");
        QTest::newRow("array") << QByteArray("[1, 2]")
                               << QStringLiteral("not a ServoBench profile (the document is not "
                                                 "a JSON object)")
                               << Code::NotAnObject;
        QTest::newRow("no format") << spoiled(QStringLiteral("format"), QJsonValue::Undefined)
                                   << notAProfile << Code::WrongFormat;
        QTest::newRow("other format")
            << spoiled(QStringLiteral("format"), QStringLiteral("servobench-log")) << notAProfile
            << Code::WrongFormat;
        const QString badVersion =
            QStringLiteral("the format version is missing or not a whole number");
        QTest::newRow("no version") << spoiled(QStringLiteral("version"), QJsonValue::Undefined)
                                    << badVersion << Code::BadVersion;
        QTest::newRow("version as text") << spoiled(QStringLiteral("version"), QStringLiteral("1"))
                                         << badVersion << Code::BadVersion;
        QTest::newRow("fractional version")
            << spoiled(QStringLiteral("version"), 1.5) << badVersion << Code::BadVersion;
        QTest::newRow("version zero")
            << spoiled(QStringLiteral("version"), 0) << QStringLiteral("unknown format version 0")
            << Code::UnknownVersion;
        QTest::newRow("unknown entry")
            << spoiled(QStringLiteral("comment"), QStringLiteral("x"))
            << QStringLiteral("unknown entry \"comment\"") << Code::UnknownKey;
        QTest::newRow("no family")
            << spoiled(QStringLiteral("family"), QJsonValue::Undefined)
            << QStringLiteral("the profile names no servo family") << Code::MissingField;
        QTest::newRow("model as number")
            << spoiled(QStringLiteral("model"), 7308) << QStringLiteral("\"model\" must be text")
            << Code::WrongType;
        QTest::newRow("note as object")
            << spoiled(QStringLiteral("note"), QJsonObject())
            << QStringLiteral("\"note\" must be text") << Code::WrongType;
        QTest::newRow("bad time")
            << spoiled(QStringLiteral("saved"), QStringLiteral("yesterday"))
            << QStringLiteral("\"saved\": \"yesterday\" is not an ISO 8601 date and time")
            << Code::BadValue;
        QTest::newRow("no parameters")
            << spoiled(QStringLiteral("parameters"), QJsonValue::Undefined)
            << QStringLiteral("the profile has no \"parameters\" object") << Code::MissingField;
        QTest::newRow("parameters as array")
            << spoiled(QStringLiteral("parameters"), QJsonArray {29})
            << QStringLiteral("the profile has no \"parameters\" object") << Code::MissingField;
    }

    void aBrokenEnvelopeIsRejected()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, message);
        QFETCH(Code, code);
        util::FileError error;
        QVERIFY(!profile::parse(json, kPtk, ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), code);
        QCOMPARE(error.describe(), message);
    }

    void aPartialProfileLoadsOnlyWhatItHoldsInDefinitionOrder()
    {
        QJsonObject root = validRoot();
        QJsonObject parameters;
        // Alphabetically max_pulse_us comes first; in the definitions min_angle does.
        parameters.insert(QStringLiteral("max_pulse_us"), 2000);
        parameters.insert(QStringLiteral("min_angle"), 40);
        root.insert(QStringLiteral("parameters"), parameters);
        util::FileError error;
        const std::optional<Profile> loaded =
            profile::parse(bytes(root), kPtk, ptk::modelDefinitions(), &error);
        QVERIFY2(loaded, qPrintable(error.describe()));
        const QVector<ProfileValue> expected {{QStringLiteral("min_angle"), 40},
                                              {QStringLiteral("max_pulse_us"), 8000}};
        QCOMPARE(loaded->values, expected);
        QVERIFY(loaded->model.isEmpty());
        QVERIFY(!loaded->saved.isValid());
    }

    void readOnlyValuesInAFileAreIgnored()
    {
        // Out of range and of the wrong type: it would be refused if it were looked at.
        QJsonObject root =
            withParameter(validRoot(), QStringLiteral("present_voltage"), QStringLiteral("12 V"));
        util::FileError error;
        const std::optional<Profile> loaded =
            profile::parse(bytes(root), kPtk, definitionsWithReadOnly(), &error);
        QVERIFY2(loaded, qPrintable(error.describe()));
        QVERIFY(!loaded->value(QStringLiteral("present_voltage")));
        QCOMPARE(loaded->value(QStringLiteral("gain")).value_or(-1), 29);
        QCOMPARE(loaded->value(QStringLiteral("inversion")).value_or(-1), 1);
    }

    void aSaveIntoAMissingDirectoryFailsAndCreatesNothing()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString missing = dir.filePath(QStringLiteral("missing"));
        const QString path = missing + QStringLiteral("/sample.json");
        util::FileError error;
        QVERIFY(!profile::save(path, seedProfile(true), ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), Code::CannotWrite);
        QVERIFY2(error.describe().startsWith(QDir::toNativeSeparators(path)
                                             + QStringLiteral(" was not saved")),
                 qPrintable(error.describe()));
        QVERIFY(!QFileInfo::exists(missing));
        QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden),
                 QStringList());
    }

    void aRefusedSaveLeavesTheOldFileAsItWas()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("sample.json"));
        util::FileError error;
        QVERIFY2(profile::save(path, seedProfile(true), ptk::modelDefinitions(), &error),
                 qPrintable(error.describe()));
        const QByteArray before = readAll(path);

        Profile outOfRange = seedProfile(true);
        outOfRange.values[0].raw = 40; // gain
        QVERIFY(!profile::save(path, outOfRange, ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), Code::BadValue);
        QVERIFY2(error.describe().endsWith(QStringLiteral("gain: 40 is out of range (0 to 30)")),
                 qPrintable(error.describe()));
        Profile badSwitch = seedProfile(true);
        badSwitch.values[8].raw = 2; // inversion would come back as 1
        QVERIFY(!profile::save(path, badSwitch, ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), Code::BadValue);
        QVERIFY2(error.describe().contains(QStringLiteral("inversion")),
                 qPrintable(error.describe()));
        Profile unknown = seedProfile(true);
        unknown.values.append({QStringLiteral("torque"), 1});
        QVERIFY(!profile::save(path, unknown, ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), Code::UnknownKey);
        QVERIFY2(error.describe().contains(QStringLiteral("\"torque\"")),
                 qPrintable(error.describe()));

        QCOMPARE(readAll(path), before);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
                 QStringList {QStringLiteral("sample.json")});
    }

    void aLoadErrorNamesTheFile()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("other.json"));
        util::FileError error;
        QVERIFY(!profile::load(path, kPtk, ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), Code::CannotRead);
        QVERIFY2(error.describe().startsWith(QDir::toNativeSeparators(path) + QStringLiteral(": ")),
                 qPrintable(error.describe()));

        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(bytes(withParameter(validRoot(), QStringLiteral("gain"), 31)));
        file.close();
        QVERIFY(!profile::load(path, kPtk, ptk::modelDefinitions(), &error));
        QCOMPARE(error.code(), Code::BadValue);
        QCOMPARE(error.describe(),
                 QDir::toNativeSeparators(path)
                     + QStringLiteral(": gain: 31 is out of range (0 to 30)"));
    }

    void diffListsExactlyTheDifferingParameters()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitionsWithReadOnly());
        const Profile device = seedProfile(true);
        for (const ProfileValue &entry : device.values) {
            if (entry.key != QLatin1String("soft_start")) // never read
                parameters.setDeviceValue(entry.key, entry.raw);
        }
        parameters.setDeviceValue(QStringLiteral("present_voltage"), 74);
        // An edit in progress is no device value: the diff must not hide gain behind it.
        QVERIFY(parameters.edit(QStringLiteral("gain"), 20));

        Profile file = seedProfile(true);
        file.values[0].raw = 20; // gain: 29 on the device
        file.values[6].raw = 2400; // min_pulse_us: 2000 on the device
        file.values.append({QStringLiteral("present_voltage"), 80}); // read-only: not applied

        const QVector<profile::DiffRow> rows = profile::diff(file, parameters);
        QCOMPARE(rows.size(), 3);
        QCOMPARE(rows.at(0).key, QStringLiteral("gain"));
        QCOMPARE(rows.at(0).label, ptk::translatedLabel(ptk::Parameter::Gain));
        QCOMPARE(rows.at(0).device.value_or(-1), 29);
        QCOMPARE(rows.at(0).file, 20);
        QCOMPARE(rows.at(1).key, QStringLiteral("min_pulse_us"));
        QCOMPARE(rows.at(1).device.value_or(-1), 2000);
        QCOMPARE(rows.at(1).file, 2400);
        QCOMPARE(rows.at(2).key, QStringLiteral("soft_start"));
        QVERIFY(!rows.at(2).device);
        QCOMPARE(rows.at(2).file, 1);

        QVERIFY(profile::diff(seedProfile(true), parameters).size() == 1); // soft_start only
    }

    void fromModelTakesThePendingEditOnlyWhenAsked()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(ptk::modelDefinitions());
        parameters.setDeviceValue(QStringLiteral("gain"), 29);
        parameters.setDeviceValue(QStringLiteral("min_pulse_us"), 2000);
        QVERIFY(parameters.edit(QStringLiteral("gain"), 20));
        QVERIFY(parameters.edit(QStringLiteral("inversion"), 1)); // edited, never read

        const Profile pending = profile::fromModel(parameters, kPtk, QStringLiteral("X"), true);
        QCOMPARE(pending.family, kPtk);
        QCOMPARE(pending.model, QStringLiteral("X"));
        QVERIFY(pending.saved.isValid());
        const QVector<ProfileValue> withEdits {{QStringLiteral("gain"), 20},
                                               {QStringLiteral("min_pulse_us"), 2000},
                                               {QStringLiteral("inversion"), 1}};
        QCOMPARE(pending.values, withEdits);

        const Profile device = profile::fromModel(parameters, kPtk, QString(), false);
        const QVector<ProfileValue> deviceOnly {{QStringLiteral("gain"), 29},
                                                {QStringLiteral("min_pulse_us"), 2000}};
        QCOMPARE(device.values, deviceOnly);

        // What fromModel makes, save takes and load gives back, time stamp included.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("edits.json"));
        util::FileError error;
        QVERIFY2(profile::save(path, pending, ptk::modelDefinitions(), &error),
                 qPrintable(error.describe()));
        const std::optional<Profile> loaded =
            profile::load(path, kPtk, ptk::modelDefinitions(), &error);
        QVERIFY2(loaded, qPrintable(error.describe()));
        QCOMPARE(loaded->values, pending.values);
        QCOMPARE(loaded->saved, pending.saved);
    }
};

QTEST_GUILESS_MAIN(TestProfile)
#include "tst_profile.moc"
