// Every file ServoBench reads, made bad every way (empty, truncated, garbled, of the wrong type,
// NaN, infinite or huge numbers, deeply nested, 100 MB long): each reader refuses it with a
// message, and nothing crashes.
#include "hostilefiles.h"
#include "samplefiles.h"

#include "processmemory.h"
#include "robottemplate.h"
#include "settingsfile.h"
#include "virtualfeetechbus.h"

#include <QtTest>

// A reader: true when it accepted the file at `path`; *error says why not.
using Read = std::function<bool(const QString &path, QString *error)>;
Q_DECLARE_METATYPE(Read)

namespace {

// A reader of a kind of file that says why through util::FileError, as a Read: *error is the
// error's sentence, and a refusal must carry a code.
Read fileReader(const std::function<bool(const QString &path, util::FileError *error)> &read)
{
    return [read](const QString &path, QString *error) {
        util::FileError why;
        const bool accepted = read(path, &why);
        *error = accepted || why ? why.describe() : QString();
        return accepted;
    };
}

// The simulator's bus, as `servosim --state` reads it.
sim::VirtualFeetechBus simulatedBus()
{
    return sim::VirtualFeetechBus({{1, QStringLiteral("STS3215"), 0}});
}

} // namespace

class TestBadFiles : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    // Saves the good file with `save`, then writes its bad variants; one row per variant.
    void addRows(const QString &format, const QString &name,
                 const std::function<bool(const QString &)> &save, const Read &read)
    {
        const QString good = m_dir.filePath(QStringLiteral("good-") + name);
        QVERIFY2(save(good), qPrintable(format));
        QString error;
        QVERIFY2(read(good, &error), qPrintable(format + QStringLiteral(": ") + error));
        QFile file(good);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString folder = m_dir.filePath(format).replace(u' ', u'-');
        for (const testsupport::HostileFile &bad :
             testsupport::writeHostileFiles(folder, name, file.readAll())) {
            QTest::newRow(qPrintable(format + QStringLiteral(", ") + bad.kind)) << bad.path << read;
        }
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void eachReaderRefusesEachBadFile_data()
    {
        QTest::addColumn<QString>("path");
        QTest::addColumn<Read>("read");
        addRows(
            QStringLiteral("PTK profile"), QStringLiteral("servo.json"),
            [](const QString &path) {
                return profile::save(path, testsupport::samplePtkProfile(),
                                     ptk::modelDefinitions());
            },
            fileReader([](const QString &path, util::FileError *error) {
                return profile::load(path, QStringLiteral("ptk"), ptk::modelDefinitions(), error)
                    .has_value();
            }));
        addRows(
            QStringLiteral("pose"), QStringLiteral("arm.json"),
            [](const QString &path) { return feetech::savePose(path, testsupport::samplePose()); },
            fileReader([](const QString &path, util::FileError *error) {
                return feetech::loadPose(path, error).has_value();
            }));
        const auto saveTemplate = [](const QString &path) {
            return feetech::saveRobotTemplate(feetech::builtInRobotTemplates().first(), path,
                                              nullptr);
        };
        addRows(QStringLiteral("robot template"), QStringLiteral("robot.json"), saveTemplate,
                fileReader([](const QString &path, util::FileError *error) {
                    return feetech::loadRobotTemplate(path, error).has_value();
                }));
        addRows(QStringLiteral("settings file"), QStringLiteral("settings.json"), saveTemplate,
                fileReader([](const QString &path, util::FileError *error) {
                    return feetech::SettingsFile::load(path, error).has_value();
                }));
        addRows(
            QStringLiteral("calibration"), QStringLiteral("so101.json"),
            [](const QString &path) {
                return feetech::saveLeRobotCalibration(testsupport::sampleCalibration(), path,
                                                       nullptr);
            },
            fileReader([](const QString &path, util::FileError *error) {
                return feetech::loadLeRobotCalibration(path, error).has_value();
            }));
        addRows(
            QStringLiteral("simulator state"), QStringLiteral("state.json"),
            [](const QString &path) { return simulatedBus().saveState(path, nullptr); },
            [](const QString &path, QString *error) {
                sim::SimRefusal why;
                if (simulatedBus().loadState(path, &why))
                    return true;
                *error = why.describe();
                return false;
            });
    }

    void eachReaderRefusesEachBadFile()
    {
        QFETCH(QString, path);
        QFETCH(Read, read);
        const auto before = util::processMemory();
        QString error;
        QVERIFY(!read(path, &error));
        QVERIFY(!error.trimmed().isEmpty());
        // A 100 MB file is refused by its size, not read whole first.
        const auto after = util::processMemory();
        if (QFileInfo(path).size() >= testsupport::kHugeFileBytes && before && after) {
            const double grownMb = after->peakResidentMb - before->peakResidentMb;
            QVERIFY2(grownMb < 50, qPrintable(QStringLiteral("%1 MB more").arg(grownMb)));
        }
    }
};

QTEST_GUILESS_MAIN(TestBadFiles)
#include "tst_badfiles.moc"
