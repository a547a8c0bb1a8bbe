// Tests pose files: round trips, every refusal with its reason, atomic saves.
#include "pose.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using feetech::Pose;
using feetech::PoseEntry;
using Code = util::FileError::Code;
Q_DECLARE_METATYPE(util::FileError::Code)

namespace {

constexpr qint32 k1M = 1000000;

Pose armPose()
{
    Pose pose;
    pose.name = QStringLiteral("Arm folded");
    pose.servos = {{1, k1M, 2048}, {2, k1M, 1024}, {3, k1M, 512}, {1, 115200, -300}};
    return pose;
}

QJsonObject entry(int id, qint32 baud, const QJsonValue &position)
{
    QJsonObject object;
    object.insert(QStringLiteral("id"), id);
    object.insert(QStringLiteral("baud"), baud);
    object.insert(QStringLiteral("position"), position);
    return object;
}

// A minimal valid pose document, to be spoiled one part at a time.
QJsonObject validRoot()
{
    QJsonObject root;
    root.insert(QStringLiteral("format"), QStringLiteral("servobench-pose"));
    root.insert(QStringLiteral("version"), 1);
    root.insert(QStringLiteral("name"), QStringLiteral("home"));
    root.insert(QStringLiteral("servos"), QJsonArray {entry(1, k1M, 2048), entry(2, k1M, 100)});
    return root;
}

QJsonObject with(QJsonObject root, const QString &key, const QJsonValue &value)
{
    root.insert(key, value);
    return root;
}

QJsonObject without(QJsonObject root, const QString &key)
{
    root.remove(key);
    return root;
}

// The valid document with its second servo entry replaced.
QJsonObject withSecondEntry(const QJsonValue &second)
{
    return with(validRoot(), QStringLiteral("servos"), QJsonArray {entry(1, k1M, 2048), second});
}

QJsonObject entryWithout(const QString &key)
{
    QJsonObject object = entry(2, k1M, 100);
    object.remove(key);
    return object;
}

QByteArray bytes(const QJsonObject &root)
{
    return QJsonDocument(root).toJson();
}

QByteArray readFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

class TestPose : public QObject
{
    Q_OBJECT

private slots:
    void jsonRoundTripKeepsNameAndEveryEntryInOrder()
    {
        const Pose pose = armPose();
        util::FileError error;
        const std::optional<Pose> back = feetech::poseFromJson(feetech::poseToJson(pose), &error);
        QVERIFY2(back, qPrintable(error.describe()));
        QCOMPARE(back->name, pose.name);
        QCOMPARE(back->servos.size(), 4);
        QVERIFY(*back == pose);
    }

    void documentHasTheFormatMarkerAndVersion()
    {
        const QJsonObject root = QJsonDocument::fromJson(feetech::poseToJson(armPose())).object();
        QCOMPARE(root.value(QStringLiteral("format")).toString(),
                 QStringLiteral("servobench-pose"));
        QCOMPARE(root.value(QStringLiteral("version")).toInt(), 1);
        const QJsonObject first = root.value(QStringLiteral("servos")).toArray().at(0).toObject();
        QCOMPARE(first.value(QStringLiteral("id")).toInt(), 1);
        QCOMPARE(first.value(QStringLiteral("baud")).toInt(), k1M);
        QCOMPARE(first.value(QStringLiteral("position")).toInt(), 2048);
    }

    void nameIsOptional()
    {
        Pose pose = armPose();
        pose.name.clear();
        QVERIFY(!QJsonDocument::fromJson(feetech::poseToJson(pose))
                     .object()
                     .contains(QStringLiteral("name")));
        const std::optional<Pose> back = feetech::poseFromJson(feetech::poseToJson(pose));
        QVERIFY(back);
        QVERIFY(back->name.isEmpty());
        QVERIFY(*back == pose);
    }

    void sameIdAtAnotherBaudIsAnotherServo()
    {
        const std::optional<Pose> pose = feetech::poseFromJson(feetech::poseToJson(armPose()));
        QVERIFY(pose);
        QCOMPARE(pose->find({1, k1M})->position, 2048);
        QCOMPARE(pose->find({1, 115200})->position, -300);
        QVERIFY(!pose->find({4, k1M}));
    }

    void invalidDocumentIsRefusedWithItsReason_data()
    {
        QTest::addColumn<Code>("code");
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("reason");

        QTest::newRow("not JSON") << Code::NotJson << QByteArray("{\"format\": ")
                                  << QStringLiteral("not valid JSON");
        QTest::newRow("not an object")
            << Code::NotAnObject << QByteArray("[1, 2]") << QStringLiteral("not a JSON object");
        QTest::newRow("no format")
            << Code::WrongFormat << bytes(without(validRoot(), QStringLiteral("format")))
            << QStringLiteral("not a ServoBench pose");
        QTest::newRow("a profile") << Code::WrongFormat
                                   << bytes(with(validRoot(), QStringLiteral("format"),
                                                 QStringLiteral("servobench-profile")))
                                   << QStringLiteral("not a ServoBench pose");
        QTest::newRow("no version")
            << Code::BadVersion << bytes(without(validRoot(), QStringLiteral("version")))
            << QStringLiteral("format version is missing");
        QTest::newRow("fractional version")
            << Code::BadVersion << bytes(with(validRoot(), QStringLiteral("version"), 1.5))
            << QStringLiteral("format version is missing or not a whole number");
        QTest::newRow("newer version")
            << Code::NewerVersion << bytes(with(validRoot(), QStringLiteral("version"), 2))
            << QStringLiteral("written by a newer ServoBench");
        QTest::newRow("version 0")
            << Code::UnknownVersion << bytes(with(validRoot(), QStringLiteral("version"), 0))
            << QStringLiteral("unknown format version 0");
        QTest::newRow("unknown entry")
            << Code::UnknownKey << bytes(with(validRoot(), QStringLiteral("speed"), 3))
            << QStringLiteral("unknown entry \"speed\"");
        QTest::newRow("name not text")
            << Code::WrongType << bytes(with(validRoot(), QStringLiteral("name"), 7))
            << QStringLiteral("\"name\" must be text");
        QTest::newRow("no servos")
            << Code::MissingField << bytes(without(validRoot(), QStringLiteral("servos")))
            << QStringLiteral("no \"servos\" list");
        QTest::newRow("servos not a list")
            << Code::MissingField
            << bytes(with(validRoot(), QStringLiteral("servos"), QJsonObject()))
            << QStringLiteral("no \"servos\" list");
        QTest::newRow("entry not an object") << Code::WrongType << bytes(withSecondEntry(5))
                                             << QStringLiteral("servo entry 2: not a JSON object");
        QTest::newRow("id missing")
            << Code::MissingField << bytes(withSecondEntry(entryWithout(QStringLiteral("id"))))
            << QStringLiteral("servo entry 2: \"id\" is missing");
        QTest::newRow("baud missing")
            << Code::MissingField << bytes(withSecondEntry(entryWithout(QStringLiteral("baud"))))
            << QStringLiteral("servo entry 2: \"baud\" is missing");
        QTest::newRow("position missing")
            << Code::MissingField
            << bytes(withSecondEntry(entryWithout(QStringLiteral("position"))))
            << QStringLiteral("servo entry 2: \"position\" is missing");
        QTest::newRow("unknown key in entry")
            << Code::UnknownKey
            << bytes(withSecondEntry(with(entry(2, k1M, 100), QStringLiteral("speed"), 1)))
            << QStringLiteral("servo entry 2: unknown entry \"speed\"");
        QTest::newRow("broadcast id")
            << Code::BadValue << bytes(withSecondEntry(entry(254, k1M, 100)))
            << QStringLiteral("254 is not a servo ID (0 to 253)");
        QTest::newRow("id as text")
            << Code::BadValue
            << bytes(withSecondEntry(
                   with(entry(2, k1M, 100), QStringLiteral("id"), QStringLiteral("2"))))
            << QStringLiteral("\"2\" is not a servo ID");
        QTest::newRow("baud not a rate")
            << Code::BadValue << bytes(withSecondEntry(entry(2, 9600, 100)))
            << QStringLiteral("9600 is not a Feetech baud rate");
        QTest::newRow("position fractional")
            << Code::BadValue << bytes(withSecondEntry(entry(2, k1M, 100.5)))
            << QStringLiteral("100.5 is not an integer");
        QTest::newRow("position as text")
            << Code::BadValue << bytes(withSecondEntry(entry(2, k1M, QStringLiteral("100"))))
            << QStringLiteral("\"100\" is not an integer");
        QTest::newRow("position boolean")
            << Code::BadValue << bytes(withSecondEntry(entry(2, k1M, true)))
            << QStringLiteral("true is not an integer");
        QTest::newRow("position too large")
            << Code::BadValue << bytes(withSecondEntry(entry(2, k1M, 40000)))
            << QStringLiteral("40000 is out of range (-32767 to 32767)");
        QTest::newRow("duplicate id and baud")
            << Code::Duplicate << bytes(withSecondEntry(entry(1, k1M, 100)))
            << QStringLiteral("servo entry 2: ID 1 at 1000000 bps is already in the pose");
    }

    void invalidDocumentIsRefusedWithItsReason()
    {
        QFETCH(Code, code);
        QFETCH(QByteArray, json);
        QFETCH(QString, reason);
        util::FileError error;
        QVERIFY(!feetech::poseFromJson(json, &error));
        QCOMPARE(error.code(), code);
        QVERIFY2(error.describe().contains(reason), qPrintable(error.describe()));
    }

    void validDocumentIsAccepted()
    {
        // The base of the refusal cases must itself be fine, or they prove nothing.
        util::FileError error;
        const std::optional<Pose> pose = feetech::poseFromJson(bytes(validRoot()), &error);
        QVERIFY2(pose, qPrintable(error.describe()));
        QCOMPARE(pose->name, QStringLiteral("home"));
        QCOMPARE(pose->servos.size(), 2);
        QVERIFY(pose->servos.at(1) == (PoseEntry {2, k1M, 100}));
    }

    void fileRoundTrip()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("arm.pose.json"));
        util::FileError error;
        QVERIFY2(feetech::savePose(path, armPose(), &error), qPrintable(error.describe()));
        const std::optional<Pose> back = feetech::loadPose(path, &error);
        QVERIFY2(back, qPrintable(error.describe()));
        QVERIFY(*back == armPose());
    }

    void saveRefusesWhatLoadWouldRefuseAndKeepsTheOldFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("arm.pose.json"));
        QVERIFY(feetech::savePose(path, armPose()));
        const QByteArray before = readFile(path);

        Pose twice = armPose();
        twice.servos.append({2, k1M, 0});
        util::FileError error;
        QVERIFY(!feetech::savePose(path, twice, &error));
        QCOMPARE(error.code(), Code::Duplicate);
        QCOMPARE(error.action(), util::FileError::Action::Saving);
        QVERIFY2(error.describe().contains(QStringLiteral("was not saved")),
                 qPrintable(error.describe()));
        QVERIFY2(error.describe().contains(QStringLiteral("ID 2 at 1000000 bps")),
                 qPrintable(error.describe()));
        QCOMPARE(readFile(path), before);

        Pose tooFar = armPose();
        tooFar.servos[0].position = 40000;
        QVERIFY(!feetech::savePose(path, tooFar, &error));
        QCOMPARE(error.code(), Code::BadValue);
        QCOMPARE(error.field(), QStringLiteral("position"));
        QVERIFY2(error.describe().contains(QStringLiteral("out of range")),
                 qPrintable(error.describe()));
        QCOMPARE(readFile(path), before);
    }

    void saveIntoMissingFolderSaysSoAndNamesTheFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("no/such/folder/arm.pose.json"));
        util::FileError error;
        QVERIFY(!feetech::savePose(path, armPose(), &error));
        QCOMPARE(error.code(), Code::CannotWrite);
        QVERIFY2(error.describe().contains(QDir::toNativeSeparators(path)),
                 qPrintable(error.describe()));
    }

    void loadNamesTheFileInItsError()
    {
        QTemporaryDir dir;
        const QString missing = dir.filePath(QStringLiteral("missing.json"));
        util::FileError error;
        QVERIFY(!feetech::loadPose(missing, &error));
        QCOMPARE(error.code(), Code::CannotRead);
        QVERIFY2(error.describe().startsWith(QDir::toNativeSeparators(missing)),
                 qPrintable(error.describe()));

        const QString wrong = dir.filePath(QStringLiteral("wrong.json"));
        QFile file(wrong);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(bytes(with(validRoot(), QStringLiteral("version"), 2)));
        file.close();
        QVERIFY(!feetech::loadPose(wrong, &error));
        QCOMPARE(error.code(), Code::NewerVersion);
        QVERIFY2(error.describe().startsWith(QDir::toNativeSeparators(wrong)),
                 qPrintable(error.describe()));
        QVERIFY2(error.describe().contains(QStringLiteral("newer ServoBench")),
                 qPrintable(error.describe()));
    }

    void loadRefusesAHugeFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("huge.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray(2 * 1024 * 1024, ' '));
        file.close();
        util::FileError error;
        QVERIFY(!feetech::loadPose(path, &error));
        QCOMPARE(error.code(), Code::TooLarge);
        QVERIFY2(error.describe().contains(QStringLiteral("too large")),
                 qPrintable(error.describe()));
    }
};

QTEST_GUILESS_MAIN(TestPose)
#include "tst_pose.moc"
