// Tests of the Feetech bus client's own bookkeeping: its servo list, edits, work and busy state.
#include "feetechbus.h"

#include "busclient.h"
#include "feetechpacket.h"
#include "operationlog.h"

#include <QSignalSpy>
#include <QtTest>

using feetech::BusClient;
using feetech::Instruction;
using feetech::OperationResult;
using model::State;

namespace {

constexpr qint32 k1M = 1000000;

const QString kMaxTemperature = QStringLiteral("max_temperature");
const QString kAcceleration = QStringLiteral("acceleration");

} // namespace

class TestBusClient : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<BusClient> m_client;

    model::ParameterModel &parameters(int index) { return *m_client->servos()->parameters(index); }

    // The address of register `key` in servo `index`'s table.
    int addressOf(int index, const QString &key) const
    {
        return m_client->servos()->at(index).info.table().find(key)->address;
    }

    // Waits for the next result the operation log reports; it, or an empty one after 10 s.
    OperationResult nextResult(QSignalSpy &finished)
    {
        if (finished.isEmpty() && !finished.wait(10000))
            return {};
        return finished.takeFirst().at(0).value<OperationResult>();
    }

private slots:
    void init()
    {
        QString error;
        const auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"SCS15"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_client = std::make_unique<BusClient>(testsupport::patientTiming());
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 5));
        QCOMPARE(m_client->servos()->count(), 3);
    }

    void cleanup()
    {
        m_client.reset();
        m_simulator.reset();
    }

    void scanFillsTheServoListWithAParameterModelPerServo()
    {
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(m_client->servos()->at(i).info.id, quint8(i + 1));
            QCOMPARE(m_client->servos()->indexOf({quint8(i + 1), k1M}), i);
            QVERIFY(!m_client->servos()->at(i).read);
        }
        QCOMPARE(m_client->servos()->indexOf({2, 500000}), -1);
        QCOMPARE(m_client->servos()->idsInUse(), (QVector<int> {1, 2, 3}));
        // The list is a table model too, one row per servo in the tree's order.
        feetech::ServoList &list = *m_client->servos();
        QCOMPARE(list.rowCount(), 3);
        QCOMPARE(list.columnCount(), int(feetech::ServoList::ColumnCount));
        QCOMPARE(list.data(list.index(2, feetech::ServoList::IdColumn)).toInt(), 3);
        QCOMPARE(list.data(list.index(0, feetech::ServoList::BaudColumn)).toInt(), 1000000);
        QCOMPARE(list.data(list.index(0, feetech::ServoList::FamilyColumn)).toString(),
                 QStringLiteral("STS"));
        QCOMPARE(list.data(list.index(2, feetech::ServoList::ModelColumn)).toString(),
                 m_client->servos()->at(2).info.model.name);
        QVERIFY(!list.data(list.index(3, 0)).isValid());
        QCOMPARE(list.headerData(feetech::ServoList::FirmwareColumn, Qt::Horizontal).toString(),
                 QStringLiteral("Firmware"));
        QSignalSpy reset(&list, &QAbstractItemModel::modelReset);
        // Each model follows its servo's table: the SCS has no offset register.
        QVERIFY(parameters(0).definition(QStringLiteral("position_offset")));
        QVERIFY(!parameters(2).definition(QStringLiteral("position_offset")));
        QVERIFY(parameters(2).definition(kMaxTemperature));
        // A new scan starts from an empty list.
        QSignalSpy changed(m_client->servos(), &feetech::ServoList::servosChanged);
        QSignalSpy finished(m_client.get(), &BusClient::scanFinished);
        feetech::ScanOptions options;
        options.lastId = 2;
        m_client->scan(options);
        QCOMPARE(m_client->servos()->count(), 0);
        QCOMPARE(changed.size(), 1);
        QVERIFY(finished.wait(20000));
        QCOMPARE(m_client->servos()->count(), 2);
        QCOMPARE(changed.size(), 3);
        QCOMPARE(reset.size(), 3); // emptied, then each servo found
    }

    void aServoAddressNamesAServoByItsIdAndRate()
    {
        const feetech::ServoAddress first = m_client->servos()->at(0).info.address();
        QCOMPARE(first, (feetech::ServoAddress {1, k1M}));
        QVERIFY(first != (feetech::ServoAddress {1, 500000})); // the same ID at another rate
        QVERIFY(first != (feetech::ServoAddress {2, k1M}));
        QHash<feetech::ServoAddress, int> byAddress;
        for (int i = 0; i < m_client->servos()->count(); ++i)
            byAddress.insert(m_client->servos()->at(i).info.address(), i);
        QCOMPARE(byAddress.size(), 3);
        QCOMPARE(byAddress.value({3, k1M}, -1), 2);
        QCOMPARE(byAddress.value({3, 500000}, -1), -1);
    }

    void applyWritesTheEditsAndLeavesAnIdEditPending()
    {
        QVERIFY(parameters(0).edit(kMaxTemperature, 66));
        QVERIFY(parameters(0).edit(QStringLiteral("id"), 9));
        feetech::Refusal refusal;
        QVERIFY2(m_client->apply(0, &refusal), qPrintable(refusal.describe()));
        QCOMPARE(parameters(0).state(kMaxTemperature), State::Writing);
        QTRY_COMPARE_WITH_TIMEOUT(parameters(0).state(kMaxTemperature), State::Verified, 10000);
        QCOMPARE(simulatorValue(1, kMaxTemperature), 66);
        QCOMPARE(*parameters(0).deviceValue(kMaxTemperature), 66);
        // The ID has its own flow: the edit waits, nothing was written there.
        QCOMPARE(parameters(0).state(QStringLiteral("id")), State::Edited);
        QCOMPARE(*parameters(0).pendingValue(QStringLiteral("id")), 9);
        QCOMPARE(simulatorValue(1, u"id"), 1);
    }

    void applyAllWritesTheRegistersAndThenChangesTheId()
    {
        QVERIFY(parameters(0).edit(kMaxTemperature, 66));
        QVERIFY(parameters(0).edit(QStringLiteral("id"), 9));
        const int temperatureAddress = addressOf(0, kMaxTemperature);
        const int idAddress = addressOf(0, QStringLiteral("id"));
        QSignalSpy busy(m_client.get(), &BusClient::busyChanged);
        feetech::Refusal refusal;
        QVERIFY2(m_client->applyAll(0, &refusal), qPrintable(refusal.describe()));
        QTRY_VERIFY_WITH_TIMEOUT(m_client->servos()->indexOf({9, k1M}) >= 0, 10000);
        QCOMPARE(m_client->servos()->indexOf({1, k1M}), -1);
        QCOMPARE(simulatorValue(9, kMaxTemperature), 66);
        // Register first, at the old ID; then the ID.
        int temperatureWrite = -1;
        int idWrite = -1;
        const auto writes = testsupport::feetechRequestsReceived(logPath(), Instruction::Write, 1);
        for (int i = 0; i < writes.size(); ++i) {
            const quint8 address = quint8(writes.at(i).parameters.at(0));
            if (address == temperatureAddress && temperatureWrite < 0)
                temperatureWrite = i;
            if (address == idAddress && idWrite < 0)
                idWrite = i;
        }
        QVERIFY(temperatureWrite >= 0 && temperatureWrite < idWrite);
        const int moved = m_client->servos()->indexOf({9, k1M});
        QVERIFY(!parameters(moved).pendingValue(QStringLiteral("id")));
        QTRY_VERIFY_WITH_TIMEOUT(!m_client->isBusy(), 10000);
        QCOMPARE(busy.first().at(0).toBool(), true);
        QCOMPARE(busy.last().at(0).toBool(), false);
    }

    void allTorqueOffRunsBetweenTheStepsOfAnApplyChain()
    {
        QVERIFY(parameters(0).edit(kMaxTemperature, 66));
        QVERIFY(parameters(0).edit(QStringLiteral("id"), 9));
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        feetech::Refusal refusal;
        QVERIFY2(m_client->applyAll(0, &refusal), qPrintable(refusal.describe()));
        // Asked while the register write runs: it must not wait for the ID change after it.
        m_client->allTorqueOff();
        QVector<OperationResult> results; // the reads after a flow aside
        for (int waited = 0; waited < 6 && results.size() < 3; ++waited) {
            const OperationResult result = nextResult(finished);
            if (result.operation != feetech::Operation::Read)
                results.append(result);
        }
        QCOMPARE(results.size(), 3);
        QCOMPARE(results.at(0).operation, feetech::Operation::Write);
        QVERIFY(results.at(0).ok);
        QVERIFY(!results.at(0).final);
        QCOMPARE(results.at(1).operation, feetech::Operation::TorqueOff);
        QCOMPARE(results.at(2).operation, feetech::Operation::ChangeId);
        QVERIFY2(results.at(2).ok, qPrintable(results.at(2).message));
        QVERIFY(results.at(2).final);
        QTRY_VERIFY_WITH_TIMEOUT(m_client->servos()->indexOf({9, k1M}) >= 0, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(!m_client->isBusy(), 10000);
    }

    void monitorNotesReachTheLinksPacketLog()
    {
        QSignalSpy logged(m_client->link(), &seriallink::LinkMirror::packetLogged);
        feetech::Refusal refusal;
        QVERIFY2(m_client->telemetry()->subscribe(this, {0, 1}, 50, &refusal),
                 qPrintable(refusal.describe()));
        // Servo 2 goes silent: the note that says so is in the log every view shows.
        setSimulatorValue(2, u"id", 20);
        const auto noted = [&logged] {
            return std::any_of(logged.begin(), logged.end(), [](const QVariantList &arguments) {
                return arguments.first().value<seriallink::PacketLogEntry>().summary.contains(
                    QLatin1String("stopped answering"));
            });
        };
        QTRY_VERIFY_WITH_TIMEOUT(noted(), 10000);
        m_client->telemetry()->unsubscribe(this);
    }

    void aStreamTakesASilentServoOutOnlyAfterTheMissesItWasGiven_data()
    {
        QTest::addColumn<int>("misses");
        QTest::newRow("default") << feetech::kDefaultMissesBeforeMissing;
        QTest::newRow("calibration recording") << 10;
    }

    void aStreamTakesASilentServoOutOnlyAfterTheMissesItWasGiven()
    {
        QFETCH(int, misses);
        feetech::Refusal refusal;
        setSimulatorValue(2, u"id", 22); // servo 2 goes silent before the stream starts
        QVERIFY2(m_client->telemetry()->subscribe(this, {0, 1}, 50, &refusal, misses),
                 qPrintable(refusal.describe()));
        const auto silent = [this]() -> std::optional<feetech::ServoTelemetry> {
            for (const feetech::ServoTelemetry &servo : m_client->telemetry()->stats().servos) {
                if (servo.id == 2 && servo.missing)
                    return servo;
            }
            return std::nullopt;
        };
        QTRY_VERIFY_WITH_TIMEOUT(silent().has_value(), 10000);
        QVERIFY2(silent()->missed >= misses, qPrintable(QString::number(silent()->missed)));
        QVERIFY2(silent()->missed < misses + 5, qPrintable(QString::number(silent()->missed)));
        m_client->telemetry()->unsubscribe(this);
    }

    void anEepromWriteWhoseUnlockGoesUnansweredIsFailedAndKeepsTheEdit()
    {
        setSimulatorValue(2, u"id", 30); // servo 2 is no longer there
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        QVERIFY(parameters(1).edit(kMaxTemperature, 66));
        QVERIFY(m_client->apply(1));
        const OperationResult result = nextResult(finished);
        QCOMPARE(result.operation, feetech::Operation::Write);
        QVERIFY(!result.ok);
        QVERIFY(!result.writesSent); // the register write never went out
        QCOMPARE(parameters(1).state(kMaxTemperature), State::Failed);
        QCOMPARE(*parameters(1).pendingValue(kMaxTemperature), 66);
        QVERIFY(!m_client->isBusy());
    }

    void anEepromLeftOpenByALostAnswerIsSaidAndLockedOnceTheServoAnswers()
    {
        // Every answer is lost: the unlock lands unconfirmed and no relock is confirmed.
        m_simulator->call([](sim::Simulator &simulator) {
            sim::FaultSettings faults;
            faults.drop = 1.0;
            simulator.setFaults(faults, 5);
        });
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        QVERIFY(parameters(0).edit(kMaxTemperature, 68));
        QVERIFY(m_client->apply(0));
        const OperationResult result = nextResult(finished);
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, feetech::OperationFailure::NoAnswer);
        QVERIFY2(result.message.contains(QLatin1String("may be left open")),
                 qPrintable(result.message));
        m_simulator->call([](sim::Simulator &simulator) { simulator.setFaults({}, 1); });
        // The next apply of that servo opens and closes it again, confirmed.
        QVERIFY(m_client->apply(0));
        const OperationResult again = nextResult(finished);
        QVERIFY2(again.ok, qPrintable(again.message));
        QCOMPARE(simulatorValue(1, u"lock"), 1);
        QCOMPARE(simulatorValue(1, kMaxTemperature), 68);
    }

    void aRamWriteThatGoesUnansweredIsUnknownUntilAReadSettlesIt()
    {
        setSimulatorValue(2, u"id", 30); // servo 2 is no longer there
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        QVERIFY(parameters(1).edit(kAcceleration, 40));
        QVERIFY(m_client->apply(1));
        const OperationResult result = nextResult(finished);
        QVERIFY(!result.ok);
        QVERIFY(result.writesSent);
        // It went out and nothing answered: whether it landed is not known.
        QCOMPARE(parameters(1).state(kAcceleration), State::Unknown);
        QCOMPARE(*parameters(1).pendingValue(kAcceleration), 40);
        // Back at its ID, the servo is read: it never got the write.
        setSimulatorValue(30, u"id", 2);
        m_client->readServo(1);
        QTRY_COMPARE_WITH_TIMEOUT(parameters(1).state(kAcceleration), State::Failed, 10000);
        QCOMPARE(*parameters(1).pendingValue(kAcceleration), 40);
    }

    void aWriteWhoseAnswersAreLostButThatLandedIsSettledVerifiedByARead()
    {
        m_simulator->call([](sim::Simulator &simulator) {
            sim::FaultSettings faults;
            faults.drop = 1.0; // every answer lost; the requests still arrive
            simulator.setFaults(faults, 3);
        });
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        QVERIFY(parameters(0).edit(kAcceleration, 41));
        QVERIFY(m_client->apply(0));
        const OperationResult result = nextResult(finished);
        QVERIFY(!result.ok);
        QVERIFY(result.writesSent);
        QCOMPARE(parameters(0).state(kAcceleration), State::Unknown);
        QCOMPARE(simulatorValue(1, kAcceleration), 41);
        m_simulator->call([](sim::Simulator &simulator) { simulator.setFaults({}, 1); });
        m_client->readServo(0);
        QTRY_COMPARE_WITH_TIMEOUT(parameters(0).state(kAcceleration), State::Verified, 10000);
        QVERIFY(!parameters(0).pendingValue(kAcceleration));
    }

    void writeValuesLeavesPendingEditsAlone()
    {
        QVERIFY(parameters(0).edit(kMaxTemperature, 66));
        QSignalSpy busy(m_client.get(), &BusClient::busyChanged);
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        feetech::Refusal refusal;
        QVERIFY2(m_client->writeValues(0, {{kMaxTemperature, 70}}, &refusal),
                 qPrintable(refusal.describe()));
        const OperationResult result = nextResult(finished);
        QVERIFY2(result.ok, qPrintable(result.message));
        QVERIFY(result.control);
        QCOMPARE(simulatorValue(1, kMaxTemperature), 70);
        QCOMPARE(*parameters(0).deviceValue(kMaxTemperature), 70);
        QCOMPARE(*parameters(0).pendingValue(kMaxTemperature), 66);
        QCOMPARE(parameters(0).state(kMaxTemperature), State::Edited);
        // A control write never makes the bus busy.
        QVERIFY(busy.isEmpty());
    }

    void busyChangedFollowsForegroundWorkAndBlocksWrites()
    {
        QSignalSpy busy(m_client.get(), &BusClient::busyChanged);
        m_client->readServo(0);
        QCOMPARE(busy.size(), 1);
        QCOMPARE(busy.first().at(0).toBool(), true);
        QVERIFY(m_client->isBusy());
        QVERIFY(parameters(1).edit(kMaxTemperature, 66));
        feetech::Refusal refusal;
        QVERIFY(!m_client->apply(1, &refusal));
        QCOMPARE(refusal, m_client->writeBlocker(1));
        QCOMPARE(refusal.code(), feetech::Refusal::Code::Busy);
        QCOMPARE(parameters(1).state(kMaxTemperature), State::Edited);
        QTRY_COMPARE_WITH_TIMEOUT(busy.size(), 2, 10000);
        QCOMPARE(busy.last().at(0).toBool(), false);
        QVERIFY(m_client->servos()->at(0).read);
        QVERIFY(!m_client->writeBlocker(1));
    }

    void eachRefusalComesWithItsCodeAndASentence()
    {
        using Code = feetech::Refusal::Code;
        // A shared ID and an unknown model, as a scan lists them.
        feetech::ServoInfo shared = m_client->servos()->at(0).info;
        shared.id = 7;
        shared.sharedId = true;
        m_client->servos()->add(shared);
        feetech::ServoInfo unknown;
        unknown.id = 8;
        unknown.baud = k1M;
        m_client->servos()->add(unknown);
        const int sharedIndex = m_client->servos()->indexOf({7, k1M});
        const int unknownIndex = m_client->servos()->indexOf({8, k1M});
        const int scsIndex = m_client->servos()->indexOf({3, k1M});
        QVERIFY(!m_client->writeBlocker(0));
        QVERIFY(m_client->writeBlocker(0).describe().isEmpty());

        feetech::Refusal refusal;
        QVERIFY(!m_client->changeId(sharedIndex, 9, &refusal));
        QCOMPARE(refusal.code(), Code::SharedId);
        QVERIFY2(refusal.describe().contains(QLatin1String("ID 7")),
                 qPrintable(refusal.describe()));
        QCOMPARE(m_client->commands()->blocker(sharedIndex).code(), Code::SharedId);
        QCOMPARE(m_client->identify()->blocker(sharedIndex).code(), Code::SharedId);

        QVERIFY(!m_client->apply(unknownIndex, &refusal));
        QCOMPARE(refusal.code(), Code::UnknownModel);
        QVERIFY(!refusal.describe().isEmpty());
        QVERIFY(!m_client->commands()->blocker(unknownIndex)); // an unknown model may be rebooted

        QVERIFY(!m_client->commands()->factoryReset(42, &refusal));
        QCOMPARE(refusal.code(), Code::NoServo);
        QVERIFY(!refusal.describe().isEmpty());
        QVERIFY(!m_client->commands()->lockEeprom(-1, &refusal));
        QCOMPARE(refusal.code(), Code::NoServo);

        QVERIFY(!m_client->changeId(0, 2, &refusal));
        QCOMPARE(refusal.code(), Code::IdInUse);
        QCOMPARE(refusal.value(), 2);
        QVERIFY2(refusal.describe().contains(QLatin1String("ID 2")),
                 qPrintable(refusal.describe()));

        QVERIFY(!m_client->commands()->calibrateMiddle(scsIndex, &refusal));
        QCOMPARE(refusal.code(), Code::NoMiddleCalibration);
        QVERIFY(!refusal.describe().isEmpty());

        QVERIFY(!m_client->apply(0, &refusal));
        QCOMPARE(refusal.code(), Code::NothingToWrite);
        QVERIFY(!m_client->writeValues(0, {}, &refusal));
        QCOMPARE(refusal.code(), Code::NothingToWrite);
        QVERIFY(!refusal.describe().isEmpty());
        QVERIFY(parameters(0).edit(QStringLiteral("id"), 2));
        QVERIFY(!m_client->apply(0, &refusal)); // the ID edit waits for its own flow
        QCOMPARE(refusal.code(), Code::NothingToWrite);
        QVERIFY(!m_client->applyAll(0, &refusal));
        QCOMPARE(refusal.code(), Code::IdInUse);
        QCOMPARE(refusal.value(), 2);
        parameters(0).revertAll();

        QVERIFY(!m_client->writeValues(0, {{kMaxTemperature, 100000}}, &refusal));
        QCOMPARE(refusal.code(), Code::BadValue);
        QVERIFY2(refusal.describe().contains(kMaxTemperature), qPrintable(refusal.describe()));

        QVERIFY(m_client->moveAll({}, &refusal).isEmpty());
        QCOMPARE(refusal.code(), Code::NothingToMove);
        QVERIFY(!refusal.describe().isEmpty());
        QVERIFY(m_client->moveAll({{unknownIndex, 100}}, &refusal).isEmpty());
        QCOMPARE(refusal.code(), Code::UnknownModel);
        QVERIFY2(refusal.describe().contains(QLatin1String("Servo 8")),
                 qPrintable(refusal.describe()));
        QVERIFY(m_client->moveAll({{0, 100000}}, &refusal).isEmpty());
        QCOMPARE(refusal.code(), Code::BadValue);
        QCOMPARE(refusal.servoId(), std::optional<quint8>(1));
        QVERIFY2(refusal.describe().startsWith(QLatin1String("Servo 1: ")),
                 qPrintable(refusal.describe()));

        QVERIFY(
            !m_client->commands()->sendPacket(QByteArray("\xff\xff\x01", 3), k1M, 1, 0, &refusal));
        QCOMPARE(refusal.code(), Code::NotAFrame);
        QVERIFY(!refusal.describe().isEmpty());
        QVERIFY(!m_client->commands()->sendPacket(feetech::ping(1), 12345, 1, 0, &refusal));
        QCOMPARE(refusal.code(), Code::NotAFeetechRate);
        QVERIFY2(refusal.describe().contains(QLatin1String("12345")),
                 qPrintable(refusal.describe()));

        m_client->identify()->hold(0, QStringLiteral("Held by a test."));
        refusal = m_client->identify()->blocker(0);
        QCOMPARE(refusal.code(), Code::ServoHeld);
        QCOMPARE(refusal.describe(), QStringLiteral("Held by a test."));
        m_client->identify()->release({1, k1M});
        QVERIFY(!m_client->identify()->blocker(0));

        // The services next to the client refuse the same way.
        QVERIFY(!m_client->health()->check({}, 1, &refusal));
        QCOMPARE(refusal.code(), Code::NoServoToCheck);
        QVERIFY(!refusal.describe().isEmpty());
        QVERIFY(!m_client->health()->check({0, 42}, 1, &refusal));
        QCOMPARE(refusal.code(), Code::NoServo);
        QVERIFY(!m_client->health()->moveTest(0, false, &refusal));
        QCOMPARE(refusal.code(), Code::NotConfirmed);
        QVERIFY2(refusal.describe().contains(QLatin1String("servo 1")),
                 qPrintable(refusal.describe()));
        QCOMPARE(m_client->health()->moveTestBlocker(sharedIndex).code(), Code::SharedId);
        QVERIFY(!m_client->guard()->recoverOverload(unknownIndex, true, &refusal));
        QCOMPARE(refusal.code(), Code::UnknownModel);
        QVERIFY(!m_client->telemetry()->subscribe(this, {0, unknownIndex}, 50, &refusal));
        QCOMPARE(refusal.code(), Code::UndecodableFeedback);
        QVERIFY2(refusal.describe().contains(QLatin1String("Servo 8")),
                 qPrintable(refusal.describe()));
        // Nothing of all this was sent.
        QVERIFY(testsupport::feetechRequestsReceived(logPath(), Instruction::Write).isEmpty());
    }

    void aBusyBusRefusesWithBusy()
    {
        using Code = feetech::Refusal::Code;
        QVERIFY(m_client->readServo(0));
        QVERIFY(m_client->isBusy());
        feetech::Refusal refusal;
        QVERIFY(!m_client->changeBaud(1, 500000, &refusal));
        QCOMPARE(refusal.code(), Code::Busy);
        QVERIFY(!refusal.describe().isEmpty());
        QCOMPARE(m_client->commands()->blocker(1).code(), Code::Busy);
        QCOMPARE(m_client->identify()->blocker(1).code(), Code::Busy);
        QVERIFY(!m_client->commands()->lockEeprom(1, &refusal));
        QCOMPARE(refusal.code(), Code::Busy);
        QVERIFY(!m_client->commands()->reboot(1, &refusal));
        QCOMPARE(refusal.code(), Code::Busy);
        QVERIFY(!m_client->health()->check({0, 1}, 1, &refusal));
        QCOMPARE(refusal.code(), Code::Busy);
        QVERIFY(!m_client->motorSetup()->find({}, &refusal));
        QCOMPARE(refusal.code(), Code::Busy);
        QVERIFY(!m_client->guard()->recoverOverload(1, true, &refusal));
        QCOMPARE(refusal.code(), Code::Busy);
        QTRY_VERIFY_WITH_TIMEOUT(!m_client->isBusy(), 10000);
    }

    void aDisconnectedClientRefusesWithNotConnected()
    {
        using Code = feetech::Refusal::Code;
        m_client->disconnectFrom();
        QTRY_COMPARE_WITH_TIMEOUT(m_client->link()->status().state,
                                  seriallink::ConnectionState::Disconnected, 10000);
        feetech::Refusal refusal;
        QCOMPARE(m_client->writeBlocker(0).code(), Code::NotConnected);
        QVERIFY(!m_client->writeBlocker(0).describe().isEmpty());
        QVERIFY(!m_client->apply(0, &refusal));
        QCOMPARE(refusal.code(), Code::NotConnected);
        QVERIFY(!m_client->writeValues(0, {{kMaxTemperature, 70}}, &refusal));
        QCOMPARE(refusal.code(), Code::NotConnected);
        QVERIFY(!m_client->commands()->reboot(0, &refusal));
        QCOMPARE(refusal.code(), Code::NotConnected);
        QVERIFY(m_client->moveAll({{0, 2048}}, &refusal).isEmpty());
        QCOMPARE(refusal.code(), Code::NotConnected);
        QVERIFY(!m_client->commands()->sendPacket(feetech::ping(1), k1M, 1, 0, &refusal));
        QCOMPARE(refusal.code(), Code::NotConnected);
        QVERIFY(!m_client->health()->check({0}, 1, &refusal));
        QCOMPARE(refusal.code(), Code::NotConnected);
        QVERIFY(!m_client->motorSetup()->checkJoints(k1M, {}, &refusal));
        QCOMPARE(refusal.code(), Code::NotConnected);
    }

    void disconnectForgetsWorkInProgress()
    {
        setSimulatorValue(1, u"id", 30); // the write will wait for answers that never come
        QVERIFY(parameters(0).edit(kMaxTemperature, 66));
        QSignalSpy busy(m_client.get(), &BusClient::busyChanged);
        QVERIFY(m_client->apply(0));
        QVERIFY(m_client->isBusy());
        m_client->disconnectFrom();
        QTRY_COMPARE_WITH_TIMEOUT(m_client->link()->status().state,
                                  seriallink::ConnectionState::Disconnected, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(!busy.isEmpty() && !busy.last().at(0).toBool(), 10000);
        QVERIFY(!m_client->isBusy());
        QCOMPARE(parameters(0).state(kMaxTemperature), State::Failed); // the unlock never answered
        QCOMPARE(*parameters(0).pendingValue(kMaxTemperature), 66);
        // Nothing of the old work is left to be matched with new results.
        setSimulatorValue(30, u"id", 1);
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 5));
        QVERIFY(parameters(0).edit(kMaxTemperature, 67));
        QVERIFY(m_client->apply(0));
        QTRY_COMPARE_WITH_TIMEOUT(parameters(0).state(kMaxTemperature), State::Verified, 10000);
        QVERIFY(!m_client->isBusy());
    }
};

QTEST_GUILESS_MAIN(TestBusClient)
#include "tst_busclient.moc"
