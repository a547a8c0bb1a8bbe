// Tests of util::FileError: the sentence each code gives, and the codes real loaders return.
#include "fileerror.h"
#include "lerobotcalibration.h"
#include "pose.h"
#include "profile.h"
#include "ptkparameters.h"
#include "robottemplate.h"
#include "testfiles.h"

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

#include <functional>

using util::FileError;
using Code = FileError::Code;
Q_DECLARE_METATYPE(util::FileError)
Q_DECLARE_METATYPE(util::FileError::Code)

// A loader of one kind of file: true when it accepted the file at `path`.
using Load = std::function<bool(const QString &path, FileError *error)>;
Q_DECLARE_METATYPE(Load)

class TestFileError : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    QString write(const QString &name, const QByteArray &contents)
    {
        return testsupport::writeTestFile(m_dir, name, contents);
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void noErrorIsASuccessWithoutASentence()
    {
        const FileError none;
        QVERIFY(!none);
        QCOMPARE(none.code(), Code::None);
        QVERIFY(none.describe().isEmpty());
        QVERIFY(FileError(Code::CannotRead, QStringLiteral("gone")));
    }

    void eachCodeGivesItsSentence_data()
    {
        QTest::addColumn<FileError>("error");
        QTest::addColumn<QString>("reason");
        const QString detail = QStringLiteral("the sentence of the kind of file");
        const auto withDetail = [&](Code code) {
            return FileError(code, detail);
        };
        QTest::newRow("cannot read") << FileError(Code::CannotRead, QStringLiteral("No such file"))
                                     << QStringLiteral("No such file");
        QTest::newRow("too large") << withDetail(Code::TooLarge) << detail;
        QTest::newRow("cannot write")
            << FileError(Code::CannotWrite, QStringLiteral("Permission denied"))
            << QStringLiteral("Permission denied");
        QTest::newRow("not JSON") << FileError(Code::NotJson, QStringLiteral("unterminated object"))
                                         .withValue(QStringLiteral("3"))
                                  << QStringLiteral(
                                         "not valid JSON: unterminated object at offset 3");
        QTest::newRow("not an object") << withDetail(Code::NotAnObject) << detail;
        QTest::newRow("wrong format") << withDetail(Code::WrongFormat) << detail;
        QTest::newRow("bad version")
            << FileError(Code::BadVersion)
            << QStringLiteral("the format version is missing or not a whole number");
        QTest::newRow("newer version") << withDetail(Code::NewerVersion) << detail;
        QTest::newRow("unknown version")
            << FileError(Code::UnknownVersion).withValue(QStringLiteral("0"))
            << QStringLiteral("unknown format version 0");
        QTest::newRow("unknown key")
            << FileError(Code::UnknownKey).withField(QStringLiteral("speed"))
            << QStringLiteral("unknown entry \"speed\"");
        QTest::newRow("unknown key in the kind's words")
            << FileError(Code::UnknownKey, QStringLiteral("unknown parameter \"gian\""))
                   .withField(QStringLiteral("gian"))
            << QStringLiteral("unknown parameter \"gian\"");
        QTest::newRow("missing field") << withDetail(Code::MissingField) << detail;
        QTest::newRow("wrong type") << withDetail(Code::WrongType) << detail;
        QTest::newRow("bad value") << withDetail(Code::BadValue) << detail;
        QTest::newRow("duplicate") << withDetail(Code::Duplicate) << detail;
        QTest::newRow("wrong servos") << withDetail(Code::WrongServos) << detail;
        QTest::newRow("nothing to save") << withDetail(Code::NothingToSave) << detail;
        QTest::newRow("no file name") << withDetail(Code::NoFileName) << detail;
    }

    void eachCodeGivesItsSentence()
    {
        QFETCH(FileError, error);
        QFETCH(QString, reason);
        QVERIFY(error);
        QCOMPARE(error.reason(), reason);
        // Without a file the sentence is the reason alone.
        QCOMPARE(error.describe(), reason);
        const QString path = QStringLiteral("/tmp/arm.json");
        const QString shown = QDir::toNativeSeparators(path);
        FileError read = error;
        QCOMPARE(read.inFile(path).describe(), shown + QStringLiteral(": ") + reason);
        FileError saved = error;
        QCOMPARE(saved.inFile(path, FileError::Action::Saving).describe(),
                 shown + QStringLiteral(" was not saved: ") + reason);
        FileError checked = error;
        QCOMPARE(checked.inFile(path, FileError::Action::CheckingSave).describe(),
                 shown + QStringLiteral(": ") + reason + QStringLiteral("; it was not saved"));
        FileError recorded = error;
        QCOMPARE(recorded.inFile(path, FileError::Action::Recording).describe(),
                 QStringLiteral("Could not open ") + shown + QStringLiteral(" for writing: ")
                     + reason + u'.');
    }

    void loadersSayWhatKindOfFailureItWas_data()
    {
        QTest::addColumn<Load>("load");
        QTest::addColumn<QByteArray>("contents"); // none: the file does not exist
        QTest::addColumn<Code>("code");
        QTest::addColumn<QString>("field");

        const Load pose = [](const QString &path, FileError *error) {
            return feetech::loadPose(path, error).has_value();
        };
        const Load profile = [](const QString &path, FileError *error) {
            return profile::load(path, QStringLiteral("ptk"), ptk::modelDefinitions(), error)
                .has_value();
        };
        const Load robot = [](const QString &path, FileError *error) {
            return feetech::loadRobotTemplate(path, error).has_value();
        };
        const Load calibration = [](const QString &path, FileError *error) {
            return feetech::loadLeRobotCalibration(path, error).has_value();
        };
        const struct
        {
            const char *kind;
            Load load;
            QByteArray missingField;
            QString field;
            QByteArray badValue;
        } kinds[] = {
            {"pose", pose, R"({"format": "servobench-pose", "version": 1})",
             QStringLiteral("servos"),
             R"({"format": "servobench-pose", "version": 1,
                 "servos": [{"id": 254, "baud": 1000000, "position": 0}]})"},
            {"profile", profile,
             R"({"format": "servobench-profile", "version": 1, "parameters": {}})",
             QStringLiteral("family"),
             R"({"format": "servobench-profile", "version": 1, "family": "ptk",
                 "parameters": {"gain": 31}})"},
            {"robot template", robot, R"({"format": "servobench-robot", "version": 1})",
             QStringLiteral("name"),
             R"({"format": "servobench-robot", "version": 1, "name": "Arm", "baud": 1234,
                 "joints": []})"},
            {"calibration", calibration, R"({"pan": {"id": 1}})", QStringLiteral("drive_mode"),
             R"({"pan": {"id": 300, "drive_mode": 0, "homing_offset": 0, "range_min": 0,
                         "range_max": 10}})"},
        };
        for (const auto &kind : kinds) {
            const QString name = QString::fromLatin1(kind.kind);
            QTest::newRow(qPrintable(name + QStringLiteral(", missing file")))
                << kind.load << QByteArray() << Code::CannotRead << QString();
            QTest::newRow(qPrintable(name + QStringLiteral(", not JSON")))
                << kind.load << QByteArray("{\"format\": ") << Code::NotJson << QString();
            QTest::newRow(qPrintable(name + QStringLiteral(", missing field")))
                << kind.load << kind.missingField << Code::MissingField << kind.field;
            QTest::newRow(qPrintable(name + QStringLiteral(", bad value")))
                << kind.load << kind.badValue << Code::BadValue << QString();
        }
    }

    void loadersSayWhatKindOfFailureItWas()
    {
        QFETCH(Load, load);
        QFETCH(QByteArray, contents);
        QFETCH(Code, code);
        QFETCH(QString, field);
        static int files = 0;
        const QString name = QStringLiteral("file-%1.json").arg(++files);
        const QString path = contents.isNull() ? m_dir.filePath(name) : write(name, contents);
        FileError error;
        QVERIFY(!load(path, &error));
        QCOMPARE(error.code(), code);
        if (!field.isEmpty())
            QCOMPARE(error.field(), field);
        QCOMPARE(QDir::toNativeSeparators(error.path()), QDir::toNativeSeparators(path));
        QVERIFY2(error.describe().startsWith(QDir::toNativeSeparators(path) + QStringLiteral(": ")),
                 qPrintable(error.describe()));
    }
};

QTEST_GUILESS_MAIN(TestFileError)
#include "tst_fileerror.moc"
