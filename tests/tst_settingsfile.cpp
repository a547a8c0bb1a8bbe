// Tests feetech::SettingsFile's reading: a profile or a robot template from a file or from its
// text gives the same values, and text that is neither is refused naming its source; a
// template's bits to clear become writes only where they are set; what torque refuses.
#include "modeltable.h"
#include "registertable.h"
#include "settingsfile.h"
#include "testfiles.h"

#include <QTemporaryDir>
#include <QtTest>

namespace {

const QByteArray kProfile = R"({"format": "servobench-profile", "version": 1, "family": "sts",
                                "parameters": {"p_gain": 22, "max_angle_limit": 4000}})";
const QByteArray kTemplate = R"({"format": "servobench-robot", "version": 1, "name": "Arm",
                                 "baud": 1000000, "settings": {"p_gain": 16},
                                 "joints": [{"name": "base", "id": 1, "model": "STS3215"}]})";

feetech::ServoInfo sts3215(quint8 id)
{
    feetech::ServoInfo servo;
    servo.id = id;
    servo.baud = 1000000;
    servo.model = *feetech::ModelTable::builtIn().findByName(u"STS3215");
    servo.modelMajor = quint8(servo.model.major);
    servo.modelMinor = quint8(servo.model.minor);
    return servo;
}

QVector<std::pair<QString, qint64>> valuesOf(const feetech::SettingsFile &file)
{
    QString error;
    const auto values = file.valuesFor(sts3215(1), &error);
    if (!values)
        qFatal("no values: %s", qPrintable(error));
    QVector<std::pair<QString, qint64>> pairs;
    for (const model::WriteItem &item : *values)
        pairs.append({item.key, item.value});
    return pairs;
}

} // namespace

class TestSettingsFile : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    QString write(const QString &name, const QByteArray &contents)
    {
        return testsupport::writeTestFile(m_dir, name, contents);
    }

private slots:
    void aTemplatesBitsToClearAreWrittenOnlyWhereSetKeepingTheOtherBits()
    {
        const QByteArray text = R"({"format": "servobench-robot", "version": 1, "name": "Arm",
                                    "clear_bits": {"phase": [4]},
                                    "joints": [{"name": "base", "id": 1, "model": "STS3215"}]})";
        util::FileError error;
        const auto file = feetech::SettingsFile::fromJson(text, QStringLiteral("arm.json"), &error);
        QVERIFY2(file, qPrintable(error.describe()));
        const auto cleared = file->clearedBitsFor(sts3215(1));
        QCOMPARE(cleared.value(QStringLiteral("phase")), 0x10u);
        QVERIFY(file->clearedBitsFor(sts3215(2)).isEmpty()); // no joint with that ID
        const auto phaseIs = [](qint64 phase) {
            return [phase](const QString &key) -> std::optional<qint64> {
                return key == QLatin1String("phase") ? std::optional<qint64>(phase) : std::nullopt;
            };
        };
        const auto set = feetech::changedValues({}, phaseIs(0x9c), cleared);
        QCOMPARE(set.size(), 1);
        QCOMPARE(set.first().key, QStringLiteral("phase"));
        QCOMPARE(set.first().value, 0x8c);
        QVERIFY(feetech::changedValues({}, phaseIs(0x0c), cleared).isEmpty());
        // Under torque a new phase is refused as a new offset is: the position would read anew.
        QVERIFY(!feetech::torqueRefusal(sts3215(1), set, 1).isEmpty());
        QVERIFY(feetech::torqueRefusal(sts3215(1), set, 0).isEmpty());
    }

    void aProfileReadFromTextIsTheProfileReadFromItsFile()
    {
        util::FileError error;
        const auto fromFile =
            feetech::SettingsFile::load(write(QStringLiteral("gains.json"), kProfile), &error);
        QVERIFY2(fromFile, qPrintable(error.describe()));
        const auto fromText =
            feetech::SettingsFile::fromJson(kProfile, QStringLiteral("gains.json"), &error);
        QVERIFY2(fromText, qPrintable(error.describe()));
        QVERIFY(!fromText->isTemplate());
        QCOMPARE(valuesOf(*fromText), valuesOf(*fromFile));
        const QVector<std::pair<QString, qint64>> expected {
            {QStringLiteral("max_angle_limit"), 4000}, {QStringLiteral("p_gain"), 22}};
        auto values = valuesOf(*fromText);
        std::sort(values.begin(), values.end());
        QCOMPARE(values, expected);
    }

    void aTemplateIsRecognisedInTextByItsFormat()
    {
        util::FileError error;
        const auto fromFile =
            feetech::SettingsFile::load(write(QStringLiteral("arm.json"), kTemplate), &error);
        QVERIFY2(fromFile, qPrintable(error.describe()));
        const auto fromText =
            feetech::SettingsFile::fromJson(kTemplate, QStringLiteral("arm.json"), &error);
        QVERIFY2(fromText, qPrintable(error.describe()));
        QVERIFY(fromText->isTemplate());
        QCOMPARE(fromText->robot()->name, QStringLiteral("Arm"));
        QCOMPARE(valuesOf(*fromText), valuesOf(*fromFile));
    }

    void textThatIsNeitherIsRefusedWithTheSameMessageAsItsFile()
    {
        const QByteArray broken = R"({"format": "servobench-profile", "version": 1,
                                      "family": "sts", "parameters": {"p_gain": "high"}})";
        const QString path = write(QStringLiteral("broken.json"), broken);
        util::FileError fileError;
        QVERIFY(!feetech::SettingsFile::load(path, &fileError));
        util::FileError textError;
        QVERIFY(
            !feetech::SettingsFile::fromJson(broken, QDir::toNativeSeparators(path), &textError));
        QCOMPARE(textError.code(), util::FileError::Code::WrongType);
        QCOMPARE(textError.field(), QStringLiteral("p_gain"));
        QCOMPARE(fileError.code(), textError.code());
        const QString sentence = textError.describe();
        QCOMPARE(sentence, fileError.describe());
        QVERIFY2(sentence.startsWith(QDir::toNativeSeparators(path) + QStringLiteral(": ")),
                 qPrintable(sentence));
        QVERIFY2(sentence.contains(QStringLiteral("p_gain")), qPrintable(sentence));
    }
};

QTEST_GUILESS_MAIN(TestSettingsFile)
#include "tst_settingsfile.moc"
