// Tests feetech::BatchProgram on a simulated bus (STS3215 ×3 at 1 Mbps): a servo unplugged after
// the scan fails alone while the others are written and verified, a servo with edits of its own
// is left alone, a servo with torque on gets no offset or limit change, a profile never copies
// its position offset, and nothing starts on a bus that is not connected.
#include "batchprogram.h"
#include "feetechbus.h"

#include <QtTest>

#include <memory>

namespace {

constexpr qint32 k1M = 1000000;

} // namespace

class TestBatchProgram : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;
    std::unique_ptr<feetech::BatchProgram> m_batch;

    feetech::SettingsFile gains() const
    {
        util::FileError error;
        const auto file = feetech::SettingsFile::load(
            writeTestFile(QStringLiteral("gains.json"),
                          R"({"format": "servobench-profile", "version": 1, "family": "sts",
                              "parameters": {"p_gain": 22}})"),
            &error);
        if (!file)
            qFatal("the test profile is invalid: %s", qPrintable(error.describe()));
        return *file;
    }

    // A profile saved from one servo of an arm: its offset and limits as well as its gains.
    feetech::SettingsFile calibratedProfile() const
    {
        util::FileError error;
        const auto file = feetech::SettingsFile::load(
            writeTestFile(QStringLiteral("calibrated.json"),
                          R"({"format": "servobench-profile", "version": 1, "family": "sts",
                              "parameters": {"p_gain": 22, "position_offset": 300,
                                             "max_angle_limit": 4000}})"),
            &error);
        if (!file)
            qFatal("the test profile is invalid: %s", qPrintable(error.describe()));
        return *file;
    }

    QVector<feetech::ProgramOutcome> runOnAll() { return runOnAll(gains()); }

    QVector<feetech::ProgramOutcome> runOnAll(const feetech::SettingsFile &file)
    {
        QSignalSpy finished(m_batch.get(), &feetech::BatchProgram::finished);
        QString error;
        if (!m_batch->start({0, 1, 2}, file, &error)) {
            qWarning("refused: %s", qPrintable(error));
            return {};
        }
        if (!finished.wait(30000))
            return {};
        return finished.first().first().value<QVector<feetech::ProgramOutcome>>();
    }

private slots:
    void init()
    {
        QString error;
        const auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"STS3215"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>(testsupport::patientTiming());
        m_batch = std::make_unique<feetech::BatchProgram>(m_client.get());
    }

    void cleanup()
    {
        m_batch.reset();
        m_client.reset();
        m_simulator.reset();
    }

    void nothingStartsOnABusThatIsNotConnected()
    {
        QString error;
        QVERIFY(!m_batch->start({0}, gains(), &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(!m_batch->isRunning());
    }

    void aServoUnpluggedAfterTheScanFailsAloneAndTheOthersAreVerified()
    {
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 4));
        QCOMPARE(m_client->servos()->count(), 3);
        m_simulator->call([](sim::Simulator &simulator) { simulator.feetechBus()->unplug(1); });
        const QVector<feetech::ProgramOutcome> outcomes = runOnAll();
        QCOMPARE(outcomes.size(), 3);
        QCOMPARE(outcomes.at(0).status, feetech::ProgramOutcome::Status::Ok);
        QCOMPARE(outcomes.at(0).changed, QStringList {QStringLiteral("p_gain")});
        QCOMPARE(outcomes.at(1).id, quint8(2));
        QCOMPARE(outcomes.at(1).status, feetech::ProgramOutcome::Status::Failed);
        QVERIFY(!outcomes.at(1).error.isEmpty());
        QCOMPARE(outcomes.at(2).status, feetech::ProgramOutcome::Status::Ok);
        QCOMPARE(simulatorValue(1, u"p_gain"), 22);
        QCOMPARE(simulatorValue(3, u"p_gain"), 22);
        QVERIFY(!m_batch->isRunning());
        QVERIFY(!m_client->isBusy());
    }

    void aProfileKeepsEachOffsetAndATorquedServoGetsNoLimitChange()
    {
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 4));
        setSimulatorValue(2, u"torque_enable", 1);
        const qint32 gain = simulatorValue(2, u"p_gain");
        const qint32 limit = simulatorValue(2, u"max_angle_limit");
        const qint32 offset = simulatorValue(1, u"position_offset");
        const QVector<feetech::ProgramOutcome> outcomes = runOnAll(calibratedProfile());
        QCOMPARE(outcomes.size(), 3);
        const QStringList written {QStringLiteral("p_gain"), QStringLiteral("max_angle_limit")};
        for (const int i : {0, 2}) {
            QCOMPARE(outcomes.at(i).status, feetech::ProgramOutcome::Status::Ok);
            QCOMPARE(QSet<QString>(outcomes.at(i).changed.cbegin(), outcomes.at(i).changed.cend()),
                     QSet<QString>(written.cbegin(), written.cend()));
            QCOMPARE(outcomes.at(i).leftOut, QStringList {QStringLiteral("position_offset")});
        }
        QCOMPARE(simulatorValue(1, u"position_offset"), offset);
        QCOMPARE(simulatorValue(3, u"max_angle_limit"), 4000);
        QVERIFY(feetech::leftOutNote(outcomes).contains(QLatin1String("position_offset")));
        // Torque on: refused whole, nothing written to it.
        QCOMPARE(outcomes.at(1).status, feetech::ProgramOutcome::Status::Failed);
        QVERIFY2(outcomes.at(1).error.contains(QLatin1String("torque is on")),
                 qPrintable(outcomes.at(1).error));
        QCOMPARE(simulatorValue(2, u"p_gain"), gain);
        QCOMPARE(simulatorValue(2, u"max_angle_limit"), limit);
        QCOMPARE(simulatorValue(2, u"position_offset"), offset);
    }

    void aServoWithEditsOfItsOwnIsLeftAlone()
    {
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 4));
        const int index = m_client->servos()->indexOf({2, k1M});
        QVERIFY(m_client->servos()->parameters(index)->edit(QStringLiteral("d_gain"), 5));
        const qint32 gain = simulatorValue(2, u"p_gain");
        const QVector<feetech::ProgramOutcome> outcomes = runOnAll();
        QCOMPARE(outcomes.size(), 3);
        QCOMPARE(outcomes.at(1).status, feetech::ProgramOutcome::Status::Failed);
        QVERIFY(outcomes.at(1).error.contains(QStringLiteral("edits")));
        QCOMPARE(simulatorValue(2, u"p_gain"), gain);
        QCOMPARE(m_client->servos()->parameters(index)->pendingValue(QStringLiteral("d_gain")),
                 std::optional<qint64>(5));
        QCOMPARE(outcomes.at(2).status, feetech::ProgramOutcome::Status::Ok);

        // Once they are applied, a second run finds servos 1 and 3 unchanged.
        m_client->servos()->parameters(index)->revertAll();
        const QVector<feetech::ProgramOutcome> again = runOnAll();
        QCOMPARE(again.at(0).status, feetech::ProgramOutcome::Status::Unchanged);
        QCOMPARE(again.at(1).status, feetech::ProgramOutcome::Status::Ok);
        QCOMPARE(again.at(2).status, feetech::ProgramOutcome::Status::Unchanged);
    }
};

QTEST_GUILESS_MAIN(TestBatchProgram)
#include "tst_batchprogram.moc"
