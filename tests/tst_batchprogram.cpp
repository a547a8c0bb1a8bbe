// Tests feetech::BatchProgram on a simulated bus (STS3215 ×3 at 1 Mbps): a servo unplugged after
// the scan fails alone while the others are written and verified, a servo with edits of its own
// is left alone, and nothing starts on a bus that is not connected.
#include "feetech/batchprogram.h"
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
        QString error;
        const auto file = feetech::SettingsFile::load(
            writeTestFile(QStringLiteral("gains.json"),
                          R"({"format": "servobench-profile", "version": 1, "family": "sts",
                              "parameters": {"p_gain": 22}})"),
            &error);
        if (!file)
            qFatal("the test profile is invalid: %s", qPrintable(error));
        return *file;
    }

    QVector<feetech::ProgramOutcome> runOnAll()
    {
        QSignalSpy finished(m_batch.get(), &feetech::BatchProgram::finished);
        QString error;
        if (!m_batch->start({0, 1, 2}, gains(), &error)) {
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
        QCOMPARE(m_client->servoCount(), 3);
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

    void aServoWithEditsOfItsOwnIsLeftAlone()
    {
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 4));
        const int index = m_client->indexOf(2, k1M);
        QVERIFY(m_client->parameters(index)->edit(QStringLiteral("d_gain"), 5));
        const qint32 gain = simulatorValue(2, u"p_gain");
        const QVector<feetech::ProgramOutcome> outcomes = runOnAll();
        QCOMPARE(outcomes.size(), 3);
        QCOMPARE(outcomes.at(1).status, feetech::ProgramOutcome::Status::Failed);
        QVERIFY(outcomes.at(1).error.contains(QStringLiteral("edits")));
        QCOMPARE(simulatorValue(2, u"p_gain"), gain);
        QCOMPARE(m_client->parameters(index)->pendingValue(QStringLiteral("d_gain")),
                 std::optional<qint64>(5));
        QCOMPARE(outcomes.at(2).status, feetech::ProgramOutcome::Status::Ok);

        // Once they are applied, a second run finds servos 1 and 3 unchanged.
        m_client->parameters(index)->revertAll();
        const QVector<feetech::ProgramOutcome> again = runOnAll();
        QCOMPARE(again.at(0).status, feetech::ProgramOutcome::Status::Unchanged);
        QCOMPARE(again.at(1).status, feetech::ProgramOutcome::Status::Ok);
        QCOMPARE(again.at(2).status, feetech::ProgramOutcome::Status::Unchanged);
    }
};

QTEST_GUILESS_MAIN(TestBatchProgram)
#include "tst_batchprogram.moc"
