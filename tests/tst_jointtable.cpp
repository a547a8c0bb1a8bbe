// GUI tests of the joint table against a simulated bus: rows, ranges, torque, Move all as one
// SYNC WRITE, live positions and pose files.
#include "feetechbus.h"
#include "jointtable.h"
#include "jointtableposes.h"
#include "jointtableview.h"
#include "namedchild.h"
#include "operationlog.h"
#include "pose.h"
#include "skippablequestion.h"

#include <QApplication>
#include <QCheckBox>
#include <QLabel>
#include <QMap>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include <cstdlib>
#include <functional>
#include <memory>

namespace {

constexpr qint32 k1M = 1000000;
constexpr quint8 kSyncWrite = 0x83;
constexpr int kGoalAddress = 42;

// One SYNC WRITE as the simulator received it: FF FF FE LEN 83 ADDR L (ID D1..DL)... CHK.
struct SyncWrite
{
    int address = 0;
    int length = 0;
    QMap<int, QByteArray> data; // by servo ID
};

std::optional<SyncWrite> decodeSyncWrite(const QByteArray &frame)
{
    if (frame.size() < 8 || quint8(frame.at(2)) != 0xFE || quint8(frame.at(4)) != kSyncWrite)
        return std::nullopt;
    SyncWrite write;
    write.address = quint8(frame.at(5));
    write.length = quint8(frame.at(6));
    const int entries = (quint8(frame.at(3)) - 4) / (write.length + 1);
    for (int i = 0; i < entries; ++i) {
        const int at = 7 + i * (write.length + 1);
        write.data.insert(quint8(frame.at(at)), frame.mid(at + 1, write.length));
    }
    return write;
}

// Every SYNC WRITE frame the simulator received, in order.
QVector<QByteArray> syncWritesReceived(const QString &logPath)
{
    QVector<QByteArray> frames;
    for (const QByteArray &frame : testsupport::feetechFramesReceived(logPath)) {
        if (frame.size() > 4 && quint8(frame.at(4)) == kSyncWrite)
            frames.append(frame);
    }
    return frames;
}

// A two-byte goal in the family's byte order: SCS big-endian, the others little-endian.
qint32 goalValue(const QByteArray &bytes, bool bigEndian)
{
    const int first = quint8(bytes.at(0));
    const int second = quint8(bytes.at(1));
    return bigEndian ? (first << 8) | second : first | (second << 8);
}

} // namespace

class TestJointTable : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;
    std::unique_ptr<JointTable> m_joints;

    template<typename T>
    T *child(const char *name) const
    {
        return testsupport::namedChild<T>(m_joints.get(), name);
    }

    // Answers the next question as it shows (its own event loop runs meanwhile).
    void answerQuestion(std::function<void(QMessageBox *)> answer)
    {
        QTimer::singleShot(0, this, [answer] {
            QTRY_VERIFY(qobject_cast<QMessageBox *>(QApplication::activeModalWidget()));
            answer(qobject_cast<QMessageBox *>(QApplication::activeModalWidget()));
        });
    }

    void connectAndScan()
    {
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 10));
        QCOMPARE(m_joints->rowCount(), 4);
    }

    // Reads every servo through the table's own button, as a user without the monitor would.
    void readAll()
    {
        auto *read = child<QPushButton>("readPositionsButton");
        QVERIFY(read->isVisible());
        QVERIFY(read->isEnabled());
        // Operations finish in the order they were asked for: once the four reads are done,
        // everything queued before them has been sent too.
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        read->click();
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() >= m_joints->rowCount(), 10000);
        for (int index = 0; index < m_client->servos()->count(); ++index)
            QVERIFY(m_client->servos()->at(index).read);
        for (int row = 0; row < m_joints->rowCount(); ++row)
            QVERIFY(m_joints->position(row).has_value());
    }

    void switchTorqueOnEverywhere()
    {
        // Ticked in the table, as a user would.
        for (int row = 0; row < m_joints->rowCount(); ++row)
            m_joints->table()->item(row, JointTableView::TorqueColumn)->setCheckState(Qt::Checked);
        for (int row = 0; row < m_joints->rowCount(); ++row) {
            QTRY_COMPARE_WITH_TIMEOUT(
                m_joints->table()->item(row, JointTableView::TorqueColumn)->text(),
                QStringLiteral("On"), 10000);
            QCOMPARE(simulatorValue(quint8(row + 1), QStringLiteral("torque_enable")), 1);
        }
    }

private slots:
    void init()
    {
        QString error;
        const auto servos =
            testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"STS3215", u"SCS15"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>();
        m_joints = std::make_unique<JointTable>(m_client.get());
        m_joints->resize(1180, 820);
        m_joints->show();
    }

    void cleanup()
    {
        m_joints.reset();
        m_client.reset();
        m_simulator.reset();
    }

    void identifyAsksBeforeItMovesAndCanBeToldNotToAskAgain()
    {
        SkippableQuestion::askAllAgain();
        connectAndScan();
        QPushButton *identify = m_joints->identifyButton(0);
        QTRY_VERIFY_WITH_TIMEOUT(identify->isEnabled(), 10000);

        // Cancel (the default): nothing is sent, nothing moves.
        QString asked;
        bool cancelWasDefault = false;
        answerQuestion([&](QMessageBox *box) {
            asked = box->text();
            cancelWasDefault = box->defaultButton() == box->button(QMessageBox::Cancel);
            box->button(QMessageBox::Cancel)->click();
        });
        identify->click(); // returns once the question is answered
        QVERIFY2(asked.contains(QStringLiteral("ID 1")), qPrintable(asked));
        QVERIFY(cancelWasDefault);
        QVERIFY(!m_client->identify()->isRunning(0));
        QVERIFY(!SkippableQuestion(QStringLiteral("identify"), {}, {}).isSkipped());

        // Go ahead, and do not ask again.
        answerQuestion([](QMessageBox *box) {
            box->findChild<QCheckBox *>(QStringLiteral("dontAskAgainBox"))->setChecked(true);
            box->findChild<QPushButton *>(QStringLiteral("goAheadButton"))->click();
        });
        identify->click();
        QVERIFY(m_client->identify()->isRunning(0));
        QTRY_VERIFY_WITH_TIMEOUT(!m_client->identify()->isRunning(0), 20000);

        // Asked no more: the click starts it at once.
        QTRY_VERIFY_WITH_TIMEOUT(identify->isEnabled(), 10000);
        identify->click();
        QVERIFY(!QApplication::activeModalWidget());
        QVERIFY(m_client->identify()->isRunning(0));
        QTRY_VERIFY_WITH_TIMEOUT(!m_client->identify()->isRunning(0), 20000);
        SkippableQuestion::askAllAgain();
    }

    void scanGivesOneRowPerServo()
    {
        QCOMPARE(m_joints->rowCount(), 0);
        QVERIFY(!child<QPushButton>("moveAllButton")->isEnabled());
        connectAndScan();
        QTableWidget *table = m_joints->table();
        for (int row = 0; row < 4; ++row) {
            QCOMPARE(table->item(row, JointTableView::IdColumn)->text(), QString::number(row + 1));
            QCOMPARE(table->item(row, JointTableView::BaudColumn)->text(),
                     QStringLiteral("1 Mbps"));
            QCOMPARE(m_joints->rowOf({quint8(row + 1), k1M}), row);
            QVERIFY(!m_joints->target(row));
        }
        QCOMPARE(table->item(0, JointTableView::ModelColumn)->text(), QStringLiteral("STS3215"));
        QCOMPARE(table->item(3, JointTableView::ModelColumn)->text(), QStringLiteral("SCS15"));
        // Without the monitor the table says its positions are not live and offers a read.
        QVERIFY(child<QLabel>("liveHint")->text().contains(QStringLiteral("not running")));
        QVERIFY(child<QPushButton>("readPositionsButton")->isVisible());
    }

    void targetRangeComesFromTheAngleLimitsOnceRead()
    {
        m_joints->hide(); // another tab is open: nothing is read for the joints
        connectAndScan();
        // Not read yet: the goal register's range.
        QCOMPARE(m_joints->targetRange(0)->minimum, -30719);
        QCOMPARE(m_joints->targetRange(0)->maximum, 30719);
        QVERIFY(!m_joints->targetRange(0)->fromAngleLimits);
        QCOMPARE(m_joints->targetRange(3)->maximum, 1023);
        QVERIFY(!m_joints->position(0));
        // Opening the tab reads every servo by itself: limits, positions and torque.
        m_joints->show();
        QTRY_VERIFY_WITH_TIMEOUT(m_joints->targetRange(0)->fromAngleLimits, 10000);
        for (int row = 0; row < m_joints->rowCount(); ++row) {
            QTRY_VERIFY(m_joints->position(row).has_value());
            QCOMPARE(m_joints->table()->item(row, JointTableView::TorqueColumn)->text(),
                     QStringLiteral("Off"));
        }
        QCOMPARE(m_joints->targetRange(0)->minimum, 0);
        QCOMPARE(m_joints->targetRange(0)->maximum, 4095);
        QCOMPARE(m_joints->targetRange(3)->minimum, 20);
        QCOMPARE(m_joints->targetRange(3)->maximum, 1003);
        QCOMPARE(m_joints->table()->item(3, JointTableView::RangeColumn)->text(),
                 QStringLiteral("20 to 1003"));

        // Both limits 0 (multi-turn mode) bound nothing: back to the register's range.
        m_client->servos()->parameters(1)->setDeviceValue(QStringLiteral("max_angle_limit"), 0);
        m_client->servos()->parameters(1)->setDeviceValue(QStringLiteral("min_angle_limit"), 0);
        QCOMPARE(m_joints->targetRange(1)->maximum, 30719);
        QVERIFY(!m_joints->targetRange(1)->fromAngleLimits);

        // The editor only goes as far as the servo may be sent.
        QTableWidget *table = m_joints->table();
        const QModelIndex cell = table->model()->index(3, JointTableView::TargetColumn);
        table->setCurrentIndex(cell);
        table->edit(cell);
        auto *editor = table->findChild<QSpinBox *>(QStringLiteral("targetEditor"));
        QVERIFY(editor);
        QCOMPARE(editor->minimum(), 20);
        QCOMPARE(editor->maximum(), 1003);
        editor->setValue(640);
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE(m_joints->target(3), std::optional<qint32>(640));
    }

    void moveAllSendsOneSyncWriteWithEveryTarget()
    {
        connectAndScan();
        readAll();
        switchTorqueOnEverywhere();
        const QVector<qint32> targets = {1000, 2500, 3000, 700};
        for (int row = 0; row < 4; ++row)
            m_joints->setTarget(row, targets.at(row));
        QVERIFY(syncWritesReceived(logPath()).isEmpty());

        auto *move = child<QPushButton>("moveAllButton");
        QVERIFY(move->isEnabled());
        move->click();
        QVERIFY2(m_joints->message().contains(QStringLiteral("one SYNC WRITE")),
                 qPrintable(m_joints->message()));
        QTRY_COMPARE_WITH_TIMEOUT(syncWritesReceived(logPath()).size(), 1, 5000);

        // Every servo's ID and target in the one frame, each in its family's byte order. All
        // four servos listen at 1 Mbps only, so the moves below also show the rate was right.
        const auto write = decodeSyncWrite(syncWritesReceived(logPath()).first());
        QVERIFY(write);
        QCOMPARE(write->address, kGoalAddress);
        QCOMPARE(write->length, 2);
        QCOMPARE(write->data.keys(), QList<int>({1, 2, 3, 4}));
        for (int id = 1; id <= 4; ++id)
            QCOMPARE(goalValue(write->data.value(id), id == 4), targets.at(id - 1));

        // The simulated horns travel to their targets.
        for (int id = 1; id <= 4; ++id) {
            QCOMPARE(simulatorValue(quint8(id), QStringLiteral("goal_position")),
                     targets.at(id - 1));
            QTRY_VERIFY_WITH_TIMEOUT(
                std::abs(simulatorValue(quint8(id), QStringLiteral("present_position"))
                         - targets.at(id - 1))
                    <= 2,
                10000);
        }
        QCOMPARE(syncWritesReceived(logPath()).size(), 1);

        // Read again, the table shows where they are now.
        readAll();
        for (int row = 0; row < 4; ++row)
            QTRY_VERIFY_WITH_TIMEOUT(std::abs(*m_joints->position(row) - targets.at(row)) <= 2,
                                     10000);
    }

    void targetOutOfRangeSendsNothing()
    {
        connectAndScan();
        readAll();
        QCOMPARE(m_joints->capturePositions(), 4);
        for (int row = 0; row < 4; ++row)
            QCOMPARE(m_joints->target(row), m_joints->position(row));
        const qint32 goalBefore = simulatorValue(4, QStringLiteral("goal_position"));

        // Inside the SCS register's range (0-1023) but beyond the servo's angle limit.
        m_joints->setTarget(3, 1010);
        QCOMPARE(m_joints->table()->item(3, JointTableView::TargetColumn)->data(Qt::DisplayRole),
                 QVariant(1010));
        QString error;
        QVERIFY(!m_joints->moveAll(&error));
        QVERIFY2(error.contains(QStringLiteral("ID 4 (SCS15)")), qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral("20 to 1003")), qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral("Nothing was sent")), qPrintable(error));

        // The button says the same where the user sees it.
        child<QPushButton>("moveAllButton")->click();
        QCOMPARE(m_joints->message(), error);

        m_joints->setTarget(3, 500);
        m_joints->setTarget(0, 5000);
        QVERIFY(!m_joints->moveAll(&error));
        QVERIFY2(error.contains(QStringLiteral("0 to 4095")), qPrintable(error));

        // A round trip through the bus proves nothing was queued before it.
        readAll();
        QVERIFY(syncWritesReceived(logPath()).isEmpty());
        QCOMPARE(simulatorValue(4, QStringLiteral("goal_position")), goalBefore);
    }

    void moveAllRefusesMissingTargetsAndAClosedBus()
    {
        connectAndScan();
        m_joints->setTarget(0, 100);
        QString error;
        QVERIFY(!m_joints->moveAll(&error));
        QVERIFY2(error.contains(QStringLiteral("ID 2 (STS3215) has no target")), qPrintable(error));

        for (int row = 1; row < 4; ++row)
            m_joints->setTarget(row, 100);
        m_client->disconnectFrom();
        QTRY_VERIFY(!m_client->link()->isConnected());
        QVERIFY(!m_joints->moveAll(&error));
        QVERIFY2(error.contains(QStringLiteral("not connected")), qPrintable(error));
        QVERIFY(!child<QPushButton>("moveAllButton")->isEnabled());
        QVERIFY(syncWritesReceived(logPath()).isEmpty());
    }

    void savedPoseLoadsBackTheTargets()
    {
        connectAndScan();
        const QVector<qint32> targets = {1111, 2222, 3333, 444};
        for (int row = 0; row < 4; ++row)
            m_joints->setTarget(row, targets.at(row));
        const QString path = m_dir.filePath(QStringLiteral("arm.json"));
        util::FileError error;
        QVERIFY2(m_joints->poses()->savePose(path, &error), qPrintable(error.describe()));

        const std::optional<feetech::Pose> saved = feetech::loadPose(path, &error);
        QVERIFY2(saved, qPrintable(error.describe()));
        QCOMPARE(saved->servos.size(), 4);
        QCOMPARE(saved->find({4, k1M})->position, 444);

        for (int row = 0; row < 4; ++row)
            m_joints->setTarget(row, 10);
        const auto match = m_joints->poses()->loadPose(path, &error);
        QVERIFY2(match, qPrintable(error.describe()));
        QCOMPARE(match->filled, 4);
        QVERIFY(match->notOnBus.isEmpty());
        QVERIFY(match->rowsWithoutEntry.isEmpty());
        for (int row = 0; row < 4; ++row)
            QCOMPARE(m_joints->target(row), std::optional<qint32>(targets.at(row)));
        QVERIFY(child<QLabel>("poseLabel")->text().contains(QStringLiteral("arm")));
        // Loading fills targets only: moving is a separate click.
        QVERIFY(m_joints->message().contains(QStringLiteral("Nothing moves")));
        readAll();
        QVERIFY(syncWritesReceived(logPath()).isEmpty());
    }

    void poseNamingAnAbsentServoIsReported()
    {
        connectAndScan();
        m_joints->setTarget(2, 2000);
        feetech::Pose pose;
        pose.name = QStringLiteral("partial");
        pose.servos = {{1, k1M, 1500}, {9, k1M, 100}, {2, 500000, 300}};
        const QString path = m_dir.filePath(QStringLiteral("partial.json"));
        QVERIFY(feetech::savePose(path, pose));

        util::FileError error;
        const auto match = m_joints->poses()->loadPose(path, &error);
        QVERIFY2(match, qPrintable(error.describe()));
        QCOMPARE(match->filled, 1);
        QCOMPARE(match->notOnBus.size(), 2);
        QCOMPARE(match->notOnBus.at(0).id, quint8(9));
        QCOMPARE(match->notOnBus.at(1).baud, 500000);
        QCOMPARE(match->rowsWithoutEntry, QVector<int>({1, 2, 3}));
        QCOMPARE(m_joints->target(0), std::optional<qint32>(1500));
        QCOMPARE(m_joints->target(2), std::optional<qint32>(2000)); // left as it was
        QVERIFY(!m_joints->target(1));
        const QString message = m_joints->message();
        QVERIFY2(message.contains(QStringLiteral("Not on the bus: ID 9 at 1 Mbps")),
                 qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("ID 2 at 500,000 bps"))
                     || message.contains(QStringLiteral("ID 2 at 500000 bps")),
                 qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("ID 4 (SCS15)")), qPrintable(message));
    }

    void invalidPoseFileChangesNoTarget()
    {
        connectAndScan();
        m_joints->setTarget(0, 1234);
        const QString path = m_dir.filePath(QStringLiteral("broken.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "servobench-pose", "version": 1, "servos": [)"
                   R"({"id": 1, "baud": 1000000, "position": 10.5}]})");
        file.close();
        util::FileError error;
        QVERIFY(!m_joints->poses()->loadPose(path, &error));
        QCOMPARE(error.code(), util::FileError::Code::BadValue);
        QVERIFY2(error.describe().contains(QStringLiteral("not an integer")),
                 qPrintable(error.describe()));
        QCOMPARE(m_joints->target(0), std::optional<qint32>(1234));
    }

    void positionsAreLiveWhileTheMonitorRuns()
    {
        connectAndScan();
        feetech::Refusal refusal;
        QVERIFY2(m_client->telemetry()->subscribe(this, {0, 1, 2, 3}, 50, &refusal),
                 qPrintable(refusal.describe()));
        for (int row = 0; row < 4; ++row)
            QTRY_VERIFY_WITH_TIMEOUT(m_joints->isPositionLive(row), 10000);
        QVERIFY(!child<QLabel>("liveHint")->text().contains(QStringLiteral("not running")));
        QVERIFY(!child<QPushButton>("readPositionsButton")->isVisible());

        // Turned by hand (torque is off): the table follows without any read.
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(2)->setPhysicalPosition(1500);
        });
        QTRY_COMPARE_WITH_TIMEOUT(m_joints->position(1), std::optional<qint32>(1500), 10000);
        QTRY_COMPARE_WITH_TIMEOUT(
            m_joints->table()->item(1, JointTableView::PositionColumn)->text(),
            QStringLiteral("1500"), 10000);

        // A servo that stops answering is no longer live, though its last sample stays.
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(3)->setValue(u"baud_rate", 1); // 500 kbps
        });
        QTRY_VERIFY_WITH_TIMEOUT(!m_joints->isPositionLive(2), 10000);
        QVERIFY(m_joints->position(2).has_value());
        QVERIFY(m_joints->isPositionLive(1));
        QVERIFY(child<QLabel>("liveHint")->text().contains(QStringLiteral("in grey")));

        m_client->telemetry()->unsubscribe(this);
        QVERIFY(!m_joints->isPositionLive(1));
        QVERIFY(child<QLabel>("liveHint")->text().contains(QStringLiteral("not running")));
        // The last sample stays the best known position until something newer is read.
        QCOMPARE(m_joints->position(1), std::optional<qint32>(1500));
        QCOMPARE(m_joints->capturePositions(), 4);
        QCOMPARE(m_joints->target(1), std::optional<qint32>(1500));
    }
};

QTEST_MAIN(TestJointTable)
#include "tst_jointtable.moc"
