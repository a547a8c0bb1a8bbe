// End-to-end tests of the Feetech session against a simulated mixed bus on a pty.
#include "busoperations.h"
#include "feetechbus.h"
#include "feetechsession.h"
#include "servoparameters.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <chrono>

using feetech::OperationFailure;
using feetech::OperationResult;
using feetech::ReadSource;
using feetech::ServoInfo;
using feetech::Session;

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k115k = 115200;

// STS3215 ×2, SCS15 (big-endian), HLS at 1 Mbps; an SMS at 115200.
QVector<sim::FeetechServoSpec> mixedServos()
{
    auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"SCS15", u"HLS"});
    servos.append({5, QStringLiteral("SMS"), k115k});
    return servos;
}

// The session's values for one servo, decoded as the GUI and CLI decode them.
struct Memory
{
    QHash<QString, qint32> values;
    quint8 status = 0;
};

} // namespace

class TestFeetechSession : public testsupport::FeetechSessionTest
{
    Q_OBJECT

private:
    void startBus(const sim::SimulatorOptions &options)
    {
        QString error;
        QVERIFY2(startSession(options, &error), qPrintable(error));
        QCOMPARE(m_session->status().state, seriallink::ConnectionState::Connected);
    }

    bool scan(const feetech::ScanOptions &options)
    {
        m_found.clear();
        QSignalSpy finished(m_session.get(), &Session::scanFinished);
        m_session->submit(feetech::operations::scan(options));
        return (!finished.isEmpty() || finished.wait(30000)) && finished.first().at(0).toBool();
    }

    Memory readAll(const ServoInfo &servo)
    {
        Memory memory;
        auto connection = connect(m_session.get(), &Session::memoryRead, this,
                                  [&](quint8 id, qint32, int address, const QByteArray &bytes,
                                      ReadSource, quint8 status) {
                                      if (id != servo.id || address < 0)
                                          return;
                                      memory.status = status;
                                      for (const auto &item :
                                           feetech::decodeRegisters(servo.table(), address, bytes))
                                          memory.values.insert(item.reg->key, item.value);
                                  });
        const OperationResult result =
            run([&] { m_session->submit(feetech::operations::read(servo, {}, ReadSource::Read)); });
        disconnect(connection);
        if (!result.ok)
            memory.values.clear();
        return memory;
    }

    // Scans IDs 0-2 at 1 Mbps only.
    bool scanIdsUpTo2At1M()
    {
        feetech::ScanOptions options;
        options.lastId = 2;
        options.bauds = {k1M};
        return scan(options);
    }

    std::optional<ServoInfo> found(quint8 id) const
    {
        for (const ServoInfo &servo : m_found) {
            if (servo.id == id)
                return servo;
        }
        return std::nullopt;
    }

    QStringList framesReceived() const
    {
        return testsupport::logLinesStartingWith(logPath(), QStringLiteral("in "));
    }

private slots:
    void init()
    {
        m_found.clear();
        startBus(busOptions(mixedServos()));
    }

    void cleanup() { stopSession(); }

    void scanFindsEveryServoAtItsBaud()
    {
        feetech::ScanOptions options;
        options.bauds = feetech::baudRates();
        QVERIFY(scan(options));
        QCOMPARE(m_found.size(), 5);
        const struct
        {
            quint8 id;
            qint32 baud;
            const char *model;
            feetech::Family family;
            quint16 modelNumber;
        } expected[] = {{1, k1M, "STS3215", feetech::Family::Sts, 777},
                        {2, k1M, "STS3215", feetech::Family::Sts, 777},
                        {3, k1M, "SCS15", feetech::Family::Scs, 0x050F},
                        {4, k1M, "HLS", feetech::Family::Hls, 0},
                        {5, k115k, "SMS", feetech::Family::Sms, 0}};
        for (const auto &servo : expected) {
            const auto info = found(servo.id);
            QVERIFY2(info, qPrintable(QStringLiteral("servo %1 not found").arg(servo.id)));
            QCOMPARE(info->baud, servo.baud);
            QVERIFY(info->model.family);
            QCOMPARE(*info->model.family, servo.family);
            if (servo.modelNumber)
                QCOMPARE(info->modelNumber(), servo.modelNumber);
            if (QByteArray(servo.model) != "HLS" && QByteArray(servo.model) != "SMS")
                QCOMPARE(info->model.name, QString::fromLatin1(servo.model));
        }
        // The adaptive timeout learned this link's answer time.
        QVERIFY(m_session->measuredLatency().has_value());
        QVERIFY(m_session->scanAllowance() < std::chrono::milliseconds(20));
        // Empty IDs and colliding probe answers are what a scan expects, not link trouble.
        QCOMPARE(m_session->counters().timeouts, 0);
        QCOMPARE(m_session->counters().checksumErrors, 0);
        QCOMPARE(m_session->counters().failures, 0);
    }

    void scanFindsServosThatAnswerLate()
    {
        // Replies up to 6 ms late: the wait follows the measured answers, and an answer that
        // still comes too late names its servo, which is asked again with time to spare.
        sim::SimulatorOptions options = busOptions(mixedServos());
        options.faults.delayMs = 6;
        options.seed = 7;
        cleanup();
        startBus(options);
        feetech::ScanOptions scanOptions;
        scanOptions.lastId = 20;
        QVERIFY(scan(scanOptions));
        QVERIFY(found(1) && found(2) && found(3) && found(4));
    }

    void scanSkipsSilentBaudRates()
    {
        feetech::ScanOptions options;
        options.bauds = {500000};
        QVERIFY(scan(options));
        QVERIFY(m_found.isEmpty());
        // Only the broadcast probe went out at a rate where nothing answers, and, as nobody
        // was found, its second, more patient look.
        QCOMPARE(framesReceived().size(), 2);
    }

    void cancelStopsTheScan()
    {
        feetech::ScanOptions options;
        options.skipSilentRates = false;
        options.bauds = {250000};
        QSignalSpy finished(m_session.get(), &Session::scanFinished);
        QSignalSpy progress(m_session.get(), &Session::scanProgress);
        m_session->submit(feetech::operations::scan(options));
        QVERIFY(progress.wait(5000));
        QTRY_VERIFY(progress.size() > 3);
        m_session->cancel(feetech::Operation::Scan);
        QVERIFY(finished.wait(5000));
        QCOMPARE(finished.first().at(0).toBool(), false);
        QVERIFY(progress.last().at(0).toInt() < 254);
    }

    void tableReadsDecodeSignedAndBigEndianValues()
    {
        feetech::ScanOptions options;
        options.lastId = 5;
        options.bauds = {k1M};
        QVERIFY(scan(options));
        const QString readOfServo1 = QStringLiteral("FF FF 01 04 02");
        const qsizetype scanReads = framesReceived().filter(readOfServo1).size();
        m_simulator->call([](sim::Simulator &simulator) {
            sim::VirtualFeetechBus *bus = simulator.feetechBus();
            bus->findServo(1)->setValue(u"position_offset", -100);
            bus->findServo(1)->setValue(u"goal_speed", -250);
            bus->findServo(3)->setValue(u"max_angle_limit", 1000); // 0x03E8, high byte first
            bus->findServo(3)->setValue(u"goal_position", 300);
        });
        const Memory sts = readAll(*found(1));
        QCOMPARE(sts.values.value(QStringLiteral("position_offset")), -100);
        QCOMPARE(sts.values.value(QStringLiteral("goal_speed")), -250);
        QCOMPARE(sts.values.value(QStringLiteral("model_major")), 9);
        const Memory scs = readAll(*found(3));
        QCOMPARE(scs.values.value(QStringLiteral("max_angle_limit")), 1000);
        QCOMPARE(scs.values.value(QStringLiteral("goal_position")), 300);
        // One READ for the STS table (its blocks are a few bytes apart), not one per register.
        const QStringList reads = framesReceived().filter(readOfServo1);
        QCOMPARE(reads.size(), scanReads + 1);
        QVERIFY(reads.last().contains(QStringLiteral("FF FF 01 04 02 00 57"))); // 0-86
    }

    void aTableReadInOneReadGivesTheValuesOfAReadPerBlock()
    {
        QVERIFY(scanIdsUpTo2At1M());
        const ServoInfo servo = *found(1);
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(1)->setValue(u"position_offset", -321);
        });
        const Memory whole = readAll(servo);
        QCOMPARE(framesReceived().filter(QStringLiteral("FF FF 01 04 02 00 57")).size(), 1);
        Memory perBlock;
        for (const feetech::Block &block : servo.table().blocks()) {
            QSignalSpy read(m_session.get(), &Session::memoryRead);
            QVERIFY(run([&] {
                        m_session->submit(
                            feetech::operations::read(servo, {block}, ReadSource::Read));
                    }).ok);
            QCOMPARE(read.size(), 1);
            for (const auto &item : feetech::decodeRegisters(servo.table(), block.address,
                                                             read.first().at(3).toByteArray()))
                perBlock.values.insert(item.reg->key, item.value);
        }
        QCOMPARE(whole.values.value(QStringLiteral("position_offset")), -321);
        QCOMPARE(whole.values.size(), int(servo.table().registers().size()));
        QCOMPARE(whole.values, perBlock.values);
    }

    void aServoRefusingLongReadsIsReadBlockByBlockFromThenOn()
    {
        QVERIFY(scanIdsUpTo2At1M());
        const ServoInfo servo = *found(1);
        const Memory answered = readAll(servo);
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(1)->setLongestRead(64); // the table spans 87
        });
        const auto readsOf = [this](const char *request) {
            return framesReceived().filter(QLatin1String(request)).size();
        };
        const int longReadsBefore = readsOf("FF FF 01 04 02 00 57");
        const Memory fallenBack = readAll(servo);
        QCOMPARE(fallenBack.values, answered.values);
        QVERIFY(readsOf("FF FF 01 04 02 00 57") > longReadsBefore);
        QCOMPARE(readsOf("FF FF 01 04 02 00 32"), 1); // addresses 0-49
        const int longReads = readsOf("FF FF 01 04 02 00 57");
        QCOMPARE(readAll(servo).values, answered.values);
        QCOMPARE(readsOf("FF FF 01 04 02 00 57"), longReads); // not asked again
        QCOMPARE(readsOf("FF FF 01 04 02 00 32"), 2);
    }

    void eepromChangeSurvivesPowerCycle()
    {
        feetech::ScanOptions options;
        options.lastId = 2;
        QVERIFY(scan(options));
        const ServoInfo servo = *found(1);
        QString error;
        const auto writes =
            feetech::encodeWrites(servo.table(), {{QStringLiteral("max_temperature"), 65}}, &error);
        QVERIFY2(writes, qPrintable(error));
        const OperationResult result =
            run([&] { m_session->submit(feetech::operations::write(servo, *writes)); });
        QVERIFY2(result.ok, qPrintable(result.message));
        // unlock (55 = 0), write, lock (55 = 1), read back: in that order.
        const QStringList frames = framesReceived();
        const int unlock =
            frames.indexOf(QRegularExpression(QStringLiteral(".*FF FF 01 04 03 37 00 .*")));
        const int write =
            frames.indexOf(QRegularExpression(QStringLiteral(".*FF FF 01 04 03 0D 41 .*")));
        const int lock =
            frames.indexOf(QRegularExpression(QStringLiteral(".*FF FF 01 04 03 37 01 .*")));
        QVERIFY(unlock >= 0 && unlock < write && write < lock);
        m_simulator->call([](sim::Simulator &simulator) { simulator.powerCycle(); });
        QCOMPARE(readAll(servo).values.value(QStringLiteral("max_temperature")), 65);
    }

    void changeToOccupiedIdIsRefused()
    {
        feetech::ScanOptions options;
        options.lastId = 5;
        QVERIFY(scan(options));
        const ServoInfo servo = *found(1);
        const int before = framesReceived().size();
        // Known from the scan: refused before anything is sent.
        OperationResult result = run([&] {
            m_session->submit(feetech::operations::changeId(servo, 2, {1, 2, 3, 4}));
        });
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, OperationFailure::IdInUse);
        QCOMPARE(framesReceived().size(), before);
        // Not known, but a servo answers there: refused after the PING, nothing written.
        result = run([&] { m_session->submit(feetech::operations::changeId(servo, 3, {})); });
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, OperationFailure::IdInUse);
        const QStringList after = framesReceived().mid(before);
        QVERIFY(!after.isEmpty());
        for (const QString &frame : after)
            QVERIFY2(!frame.contains(QLatin1String(" 03 "))
                         || frame.contains(QLatin1String("FF FF 03 02 01")),
                     qPrintable(frame));
        QCOMPARE(readAll(servo).values.value(QStringLiteral("id")), 1);
    }

    void changeIdMovesTheServo()
    {
        feetech::ScanOptions options;
        options.lastId = 2;
        QVERIFY(scan(options));
        const OperationResult result = run([&] {
            m_session->submit(feetech::operations::changeId(*found(2), 9, {1, 2}));
        });
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(result.servo.id, quint8(9));
        QVERIFY(scan(options));
        QVERIFY(!found(2));
        options.firstId = 9;
        options.lastId = 9;
        QVERIFY(scan(options));
        QVERIFY(found(9));
    }

    void baudChangeIsFollowed()
    {
        feetech::ScanOptions options;
        options.lastId = 2;
        QVERIFY(scan(options));
        const OperationResult result =
            run([&] { m_session->submit(feetech::operations::changeBaud(*found(2), 500000)); });
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(result.servo.baud, 500000);
        QCOMPARE(readAll(result.servo).values.value(QStringLiteral("baud_rate")), 1);
        // It stays there after a power cycle: the change went to EEPROM and was locked.
        m_simulator->call([](sim::Simulator &simulator) { simulator.powerCycle(); });
        const OperationResult ping =
            run([&] { m_session->submit(feetech::operations::ping(2, 500000)); });
        QVERIFY2(ping.ok, qPrintable(ping.message));
    }

    void unknownModelGetsRawView()
    {
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(1)->setValue(u"model_major", 77);
        });
        feetech::ScanOptions options;
        options.lastId = 1;
        QVERIFY(scan(options));
        const ServoInfo servo = *found(1);
        QVERIFY(!servo.hasTable());
        QVERIFY(servo.table().isRaw());
        const Memory memory = readAll(servo);
        QCOMPARE(memory.values.size(), feetech::RegisterTable::kRawViewSize);
        QCOMPARE(memory.values.value(QStringLiteral("byte_003")), 77);
        // Nothing is written to a servo nobody knows.
        const OperationResult result = run([&] {
            m_session->submit(
                feetech::operations::write(servo, {{40, QByteArray(1, char(1)), false}}));
        });
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, OperationFailure::Unsupported);
    }

    void calibrateMiddleByFirmware()
    {
        feetech::ScanOptions options;
        options.lastId = 4;
        QVERIFY(scan(options));
        QCOMPARE(feetech::middleCalibration(*found(1)), feetech::MiddleCalibration::Instruction);
        QCOMPARE(feetech::middleCalibration(*found(3)), feetech::MiddleCalibration::Unsupported);
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(1)->setPhysicalPosition(2548);
        });
        const OperationResult result =
            run([&] { m_session->submit(feetech::operations::calibrateMiddle(*found(1))); });
        QVERIFY2(result.ok, qPrintable(result.message));
        const Memory memory = readAll(*found(1));
        QVERIFY(qAbs(memory.values.value(QStringLiteral("present_position")) - 2048) <= 2);
        const OperationResult scs =
            run([&] { m_session->submit(feetech::operations::calibrateMiddle(*found(3))); });
        QVERIFY(!scs.ok);
        QCOMPARE(scs.failure, OperationFailure::Unsupported);
    }

    void aFailedOperationSaysWhyByItsKind()
    {
        QVERIFY(scanIdsUpTo2At1M());
        const ServoInfo servo = *found(1);
        ServoInfo missing = servo;
        missing.id = 9;
        const auto failureOf = [this](feetech::BusOperation operation) {
            const OperationResult result = run([&] { m_session->submit(std::move(operation)); });
            return result.ok ? OperationFailure::None : result.failure;
        };
        QCOMPARE(failureOf(feetech::operations::ping(9, k1M)), OperationFailure::NoAnswer);
        QCOMPARE(failureOf(feetech::operations::read(missing, {}, ReadSource::Read)),
                 OperationFailure::NoAnswer);
        QCOMPARE(failureOf(feetech::operations::clearStatus(missing)), OperationFailure::NoAnswer);
        QCOMPARE(failureOf(feetech::operations::changeId(servo, servo.id, {})),
                 OperationFailure::NothingToDo);
        QCOMPARE(failureOf(feetech::operations::changeId(servo, 300, {})),
                 OperationFailure::InvalidRequest);
        QCOMPARE(failureOf(feetech::operations::changeBaud(servo, k1M)),
                 OperationFailure::NothingToDo);
        QCOMPARE(failureOf(feetech::operations::changeBaud(servo, 12345)),
                 OperationFailure::InvalidRequest);
        QCOMPARE(failureOf(feetech::operations::apply(servo, {})), OperationFailure::NothingToDo);
        QCOMPARE(failureOf(feetech::operations::ping(1, k1M)), OperationFailure::None);
    }

    void anOperationWhoseTurnComesAfterTheLinkClosedIsNotConnected()
    {
        QVERIFY(scanIdsUpTo2At1M());
        QSignalSpy finished(m_session.get(), &Session::operationFinished);
        m_session->close();
        m_session->submit(feetech::operations::ping(1, k1M));
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        const auto result = finished.first().at(0).value<OperationResult>();
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, OperationFailure::NotConnected);
    }

    void rebootAndClearStatus()
    {
        feetech::ScanOptions options;
        options.lastId = 1;
        QVERIFY(scan(options));
        OperationResult result =
            run([&] { m_session->submit(feetech::operations::reboot(*found(1))); });
        QVERIFY2(result.ok, qPrintable(result.message));
        result = run([&] { m_session->submit(feetech::operations::clearStatus(*found(1))); });
        QVERIFY2(result.ok, qPrintable(result.message));
        QVERIFY(framesReceived().filter(QStringLiteral("FF FF 01 02 0A")).size() == 1);
    }

    void aLostLinkAfterAllTorqueOffInAnIdentifyPauseEndsTheIdentifyToo()
    {
        // A pause long enough that the link is lost while identify still waits in it.
        feetech::SessionTiming timing;
        timing.identifyPollInterval = std::chrono::seconds(60);
        m_session = std::make_unique<Session>(timing);
        connect(m_session.get(), &Session::servoFound, this,
                [this](const ServoInfo &servo) { m_found.append(servo); });
        m_session->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off);
        feetech::ScanOptions options;
        options.lastId = 1;
        QVERIFY(scan(options));
        const auto servo = found(1);
        QVERIFY(servo);
        QSignalSpy finished(m_session.get(), &Session::operationFinished);
        const auto ended = [&finished](feetech::Operation operation) {
            return std::any_of(finished.begin(), finished.end(), [operation](const auto &signal) {
                return signal.at(0).template value<OperationResult>().operation == operation;
            });
        };
        m_session->submit(feetech::operations::identifyJoint(*servo));
        QTRY_VERIFY_WITH_TIMEOUT(simulatorValue(1, u"torque_enable") == 1, 10000);
        m_session->submit(feetech::operations::torqueOffAll({k1M}, {*servo}));
        QTRY_VERIFY_WITH_TIMEOUT(ended(feetech::Operation::TorqueOff), 10000);
        QVERIFY(!ended(feetech::Operation::Identify));
        m_session->close();
        QTRY_VERIFY_WITH_TIMEOUT(ended(feetech::Operation::Identify), 10000);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        for (const QList<QVariant> &signal : std::as_const(finished)) {
            const auto result = signal.at(0).value<OperationResult>();
            if (result.operation == feetech::Operation::Identify)
                QCOMPARE(result.failure, OperationFailure::LinkLost);
        }
    }
};

QTEST_GUILESS_MAIN(TestFeetechSession)
#include "tst_feetechsession.moc"
