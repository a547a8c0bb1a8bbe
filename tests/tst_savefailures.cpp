// Every file ServoBench writes, into a folder it may not write and onto a full disk: each save
// fails with a message naming why, and leaves no file (or partial file) behind.
#include "packetlogentries.h"
#include "samplefiles.h"

#include "healthreport.h"
#include "packetlogmodel.h"
#include "robottemplate.h"
#include "telemetryrecorder.h"
#include "virtualfeetechbus.h"

#include <QtTest>

#include <csignal>
#include <sys/resource.h>
#include <unistd.h>

// One kind of file: saves to `path`, false and *error when it cannot.
using Save = std::function<bool(const QString &path, QString *error)>;
Q_DECLARE_METATYPE(Save)

namespace {

// A disk with no room left, for this process: every write to a regular file fails (EFBIG, as
// ENOSPC does on a full disk). /dev/full cannot stand in for a file that is saved by renaming
// a finished copy over it. Restored when it goes.
class FullDisk
{
public:
    // `room`: the size no file may grow past (0: no write at all succeeds).
    explicit FullDisk(rlim_t room = 0)
    {
        m_signal = std::signal(SIGXFSZ, SIG_IGN);
        getrlimit(RLIMIT_FSIZE, &m_saved);
        rlimit none = m_saved;
        none.rlim_cur = room;
        setrlimit(RLIMIT_FSIZE, &none);
    }
    ~FullDisk()
    {
        setrlimit(RLIMIT_FSIZE, &m_saved);
        std::signal(SIGXFSZ, m_signal);
    }

private:
    rlimit m_saved {};
    void (*m_signal)(int) = SIG_DFL;
};

// A kind of file that says why through util::FileError, as a Save: *error is the error's
// sentence, and stays empty unless the file system refused the file (CannotWrite).
Save fileSaver(const std::function<bool(const QString &path, util::FileError *error)> &save)
{
    return [save](const QString &path, QString *error) {
        util::FileError why;
        const bool saved = save(path, &why);
        *error = why.code() == util::FileError::Code::CannotWrite ? why.describe() : QString();
        return saved;
    };
}

feetech::HealthReport healthReport()
{
    feetech::HealthReport report;
    report.port = QStringLiteral("/dev/ttyUSB0");
    report.checkedAt = QDateTime::currentDateTime();
    return report;
}

bool recordTelemetry(const QString &path, QString *error)
{
    feetech::TelemetryRecorder recorder;
    recorder.setFlushInterval(0);
    util::FileError notOpened;
    if (!recorder.open(path, &notOpened)) {
        *error = notOpened.code() == util::FileError::Code::CannotWrite ? notOpened.describe()
                                                                        : QString();
        return false;
    }
    feetech::FeedbackSample sample;
    sample.id = 1;
    sample.steadyUs = recorder.startUs();
    recorder.write(sample);
    if (recorder.finish())
        return true;
    *error = recorder.errorString();
    return false;
}

// A folder this process cannot write into, or empty when there is none (root ignores the
// permissions of an ordinary folder; /sys is read-only for root too where it is mounted so).
QString readOnlyFolder(const QTemporaryDir &dir)
{
    if (geteuid() != 0) {
        const QString folder = dir.filePath(QStringLiteral("read-only"));
        QDir().mkpath(folder);
        QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::ExeOwner);
        return folder;
    }
    const QString sys = QStringLiteral("/sys");
    QFile probe(sys + QStringLiteral("/servobench-probe"));
    if (QFileInfo(sys).isDir() && !probe.open(QIODevice::WriteOnly))
        return sys;
    probe.remove();
    return {};
}

} // namespace

class TestSaveFailures : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void eachFormat_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<Save>("save");
        QTest::newRow("profile") << QStringLiteral("servo.sbprofile")
                                 << fileSaver([](const QString &path, util::FileError *error) {
                                        return profile::save(path, testsupport::samplePtkProfile(),
                                                             ptk::modelDefinitions(), error);
                                    });
        QTest::newRow("pose") << QStringLiteral(
            "arm.sbpose") << fileSaver([](const QString &path, util::FileError *error) {
            return feetech::savePose(path, testsupport::samplePose(), error);
        });
        QTest::newRow("robot template")
            << QStringLiteral("arm.sbrobot")
            << fileSaver([](const QString &path, util::FileError *error) {
                   return feetech::saveRobotTemplate(feetech::builtInRobotTemplates().first(), path,
                                                     error);
               });
        QTest::newRow("calibration") << QStringLiteral(
            "arm.json") << fileSaver([](const QString &path, util::FileError *error) {
            return feetech::saveLeRobotCalibration(testsupport::sampleCalibration(), path, error);
        });
        QTest::newRow("health report json")
            << QStringLiteral("health.json") << Save([](const QString &path, QString *error) {
                   return feetech::saveHealthReport(path, feetech::ReportFormat::Json,
                                                    healthReport(), error);
               });
        QTest::newRow("health report html")
            << QStringLiteral("health.html") << Save([](const QString &path, QString *error) {
                   return feetech::saveHealthReport(path, feetech::ReportFormat::Html,
                                                    healthReport(), error);
               });
        QTest::newRow("packet log")
            << QStringLiteral("packets.tsv") << Save([](const QString &path, QString *error) {
                   seriallink::PacketLogModel log;
                   log.append(testsupport::logEntry(0));
                   return log.exportToFile(path, error);
               });
        QTest::newRow("simulator state")
            << QStringLiteral("bus.json") << Save([](const QString &path, QString *error) {
                   sim::VirtualFeetechBus bus({{1, QStringLiteral("STS3215"), 0}});
                   sim::SimRefusal why;
                   if (bus.saveState(path, &why))
                       return true;
                   *error = why.describe();
                   return false;
               });
        QTest::newRow("telemetry recording") << QStringLiteral("run.csv") << Save(recordTelemetry);
    }

    void eachFormat()
    {
        QFETCH(QString, name);
        QFETCH(Save, save);
        QString error;

        // It can be written at all.
        const QString written = m_dir.filePath(QStringLiteral("ok-") + name);
        QVERIFY2(save(written, &error), qPrintable(error));
        QVERIFY(QFileInfo(written).size() > 0);

        // A full disk: a message, and no file under the name or beside it.
        const QString folder = m_dir.filePath(QStringLiteral("full-") + name);
        QVERIFY(QDir().mkpath(folder));
        const QString onFullDisk = folder + u'/' + name;
        error.clear();
        bool saved = true;
        {
            const FullDisk full;
            saved = save(onFullDisk, &error);
        }
        QVERIFY(!saved);
        QVERIFY(!error.isEmpty());
        QVERIFY2(QDir(folder).isEmpty(), qPrintable(QDir(folder).entryList().join(u' ')));

        // An old file under the name is left whole when the new one cannot be written.
        QVERIFY(QFile::copy(written, onFullDisk));
        {
            const FullDisk full;
            saved = save(onFullDisk, &error);
        }
        QVERIFY(!saved);
        if (name != QLatin1String("run.csv")) { // a recording streams into its file
            QFile old(written);
            QFile kept(onFullDisk);
            QVERIFY(old.open(QIODevice::ReadOnly) && kept.open(QIODevice::ReadOnly));
            QCOMPARE(kept.readAll(), old.readAll());
        }
        QCOMPARE(QDir(folder).entryList(QDir::Files | QDir::Hidden).size(),
                 name == QLatin1String("run.csv") ? 0 : 1);

        // A folder it may not write into.
        const QString readOnly = readOnlyFolder(m_dir);
        if (readOnly.isEmpty())
            QSKIP("no folder here is read-only for this user");
        error.clear();
        QVERIFY(!save(readOnly + u'/' + name, &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(!QFile::exists(readOnly + u'/' + name));
    }

    void aDeviceNamedAsTheTargetStaysADevice()
    {
        // Saved to /dev/full (through a link of its own, so that a regression replaces the
        // link, never the machine's device), a file fails for want of room; the device is
        // written directly, not replaced by a finished copy renamed over it (as root could).
        if (!QFileInfo::exists(QStringLiteral("/dev/full")))
            QSKIP("needs /dev/full");
        const QString link = m_dir.filePath(QStringLiteral("full-device"));
        QVERIFY(QFile::link(QStringLiteral("/dev/full"), link));
        util::FileError error;
        QVERIFY(!feetech::savePose(link, testsupport::samplePose(), &error));
        QCOMPARE(error.code(), util::FileError::Code::CannotWrite);
        QVERIFY(!error.describe().isEmpty());
        const QFileInfo device(link);
        QVERIFY(device.isSymLink());
        QVERIFY(device.exists() && !device.isFile());
    }

    void aRecordingCutShortByAFullDiskKeepsItsWholeRows()
    {
        const QString path = m_dir.filePath(QStringLiteral("cut-short.csv"));
        feetech::TelemetryRecorder recorder;
        recorder.setFlushInterval(0);
        QVERIFY(recorder.open(path));
        feetech::FeedbackSample sample;
        sample.id = 1;
        sample.steadyUs = recorder.startUs();
        for (int row = 0; row < 3; ++row)
            recorder.write(sample);
        QVERIFY(recorder.flush());
        const qint64 whole = QFileInfo(path).size();
        for (int row = 0; row < 500; ++row) // far more than the room left
            recorder.write(sample);
        bool finished = true;
        {
            const FullDisk full(rlim_t(whole + 40)); // room for part of a row
            finished = recorder.finish();
        }
        QVERIFY(!finished);
        QVERIFY2(recorder.errorString().contains(QStringLiteral("3 row")),
                 qPrintable(recorder.errorString()));
        QCOMPARE(QFileInfo(path).size(), whole);
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll().count('\n'), 1 + 3); // the header and three whole rows
    }

private:
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestSaveFailures)
#include "tst_savefailures.moc"
