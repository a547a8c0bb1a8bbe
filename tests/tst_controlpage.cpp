// GUI tests of the Control page against a simulated bus (STS3215 ×2 + SCS15 at 1 Mbps): torque,
// goals, the throttled slider, operating mode, step and sweep tests, and All torque off.
#include "controlpage.h"
#include "feetechbus.h"
#include "motiontest.h"
#include "namedchild.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

namespace {

constexpr qint32 k1M = 1000000;
constexpr int kGoalAddress = 42;
constexpr int kTorqueAddress = 40;
constexpr quint8 kWrite = 0x03;

} // namespace

class TestControlPage : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;
    std::unique_ptr<ControlPage> m_page;

    void setSimulatorValue(quint8 id, const QString &key, qint32 value)
    {
        m_simulator->call([&](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(id)->setValue(key, value);
        });
    }

    // Every WRITE instruction frame servo `id` received, in order.
    QList<QByteArray> writesReceived(quint8 id) const
    {
        QList<QByteArray> frames;
        for (const QByteArray &bytes : testsupport::feetechFramesReceived(logPath())) {
            if (bytes.size() > 6 && quint8(bytes.at(2)) == id && quint8(bytes.at(4)) == kWrite)
                frames.append(bytes);
        }
        return frames;
    }

    // The little-endian word each WRITE to `id` put at `address` (STS byte order).
    QList<int> writtenWords(quint8 id, int address) const
    {
        QList<int> words;
        for (const QByteArray &frame : writesReceived(id)) {
            const int start = quint8(frame.at(5));
            const int dataSize =
                quint8(frame.at(3)) - 3; // length = instruction + address + data + checksum
            const int offset = address - start;
            if (offset >= 0 && offset + 2 <= dataSize)
                words.append(quint8(frame.at(6 + offset)) | (quint8(frame.at(7 + offset)) << 8));
        }
        return words;
    }

    QList<int> writtenBytes(quint8 id, int address) const
    {
        QList<int> values;
        for (const QByteArray &frame : writesReceived(id)) {
            const int start = quint8(frame.at(5));
            const int dataSize = quint8(frame.at(3)) - 3;
            const int offset = address - start;
            if (offset >= 0 && offset < dataSize)
                values.append(quint8(frame.at(6 + offset)));
        }
        return values;
    }

    template<typename T>
    T *child(const char *name) const
    {
        return testsupport::namedChild<T>(m_page.get(), name);
    }

    // Connects, scans IDs 1-5 and shows servo `id` on the page, read in full.
    int showServo(quint8 id)
    {
        if (!testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 5)
            || m_client->servos()->count() != 3)
            return -1;
        const int index = m_client->servos()->indexOf({id, k1M});
        m_client->readServo(index);
        [&] {
            QTRY_VERIFY_WITH_TIMEOUT(m_client->servos()->at(index).read, 10000);
        }();
        if (QTest::currentTestFailed())
            return -1;
        m_page->setServo(index);
        return index;
    }

    model::ParameterModel *parameters(int index) const
    {
        return m_client->servos()->parameters(index);
    }

private slots:
    void init()
    {
        QString error;
        const auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"SCS15"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>();
        m_page = std::make_unique<ControlPage>(m_client.get());
        m_page->setMotionTiming(testsupport::quickMotionTiming());
        m_page->resize(900, 700);
        m_page->show();
    }

    void cleanup()
    {
        m_page.reset();
        m_client.reset();
        m_simulator.reset();
    }

    void withoutAServoEverythingIsDisabledWithAHint()
    {
        m_page->setServo(-1);
        QVERIFY(child<QLabel>("controlHint")->isVisible());
        QVERIFY(!child<QLabel>("controlHint")->text().isEmpty());
        for (const char *name : {"torqueOnButton", "torqueOffButton", "moveButton",
                                 "stepTestButton", "sweepButton", "stopTestButton", "modeCombo"})
            QVERIFY2(!child<QWidget>(name)->isEnabled(), name);
        QVERIFY(!child<QSlider>("goalSlider")->isEnabled());
    }

    void torqueButtonsSwitchTheServosTorque()
    {
        const int index = showServo(1);
        QVERIFY(index >= 0);
        QVERIFY(!child<QLabel>("controlHint")->isVisible());
        auto *on = child<QPushButton>("torqueOnButton");
        auto *off = child<QPushButton>("torqueOffButton");
        QTRY_VERIFY(on->isEnabled());
        QCOMPARE(simulatorValue(1, QStringLiteral("torque_enable")), 0);
        QVERIFY(off->isChecked()); // what the servo reported

        on->click();
        QTRY_COMPARE_WITH_TIMEOUT(simulatorValue(1, QStringLiteral("torque_enable")), 1, 5000);
        QTRY_COMPARE(parameters(index)->deviceValue(QStringLiteral("torque_enable")),
                     std::optional<qint64>(1));
        QTRY_VERIFY(on->isChecked());
        QVERIFY(writtenBytes(1, kTorqueAddress).contains(1));

        off->click();
        QTRY_COMPARE_WITH_TIMEOUT(simulatorValue(1, QStringLiteral("torque_enable")), 0, 5000);
        QTRY_VERIFY(off->isChecked());
        QCOMPARE(writtenBytes(1, kTorqueAddress).last(), 0);

        // STS knows damping (torque enable 2).
        auto *damping = child<QPushButton>("torqueDampingButton");
        QVERIFY(damping->isEnabled());
        damping->click();
        QTRY_COMPARE_WITH_TIMEOUT(simulatorValue(1, QStringLiteral("torque_enable")), 2, 5000);
        QTRY_VERIFY(damping->isChecked());
    }

    void moveSendsTheGoalAndTheServoGetsThere()
    {
        const int index = showServo(1);
        QVERIFY(index >= 0);
        const int standing = simulatorValue(1, QStringLiteral("present_position"));
        child<QPushButton>("torqueOnButton")->click();
        QTRY_COMPARE_WITH_TIMEOUT(simulatorValue(1, QStringLiteral("torque_enable")), 1, 5000);
        QTRY_VERIFY(child<QPushButton>("torqueOnButton")->isChecked()); // read back
        // Torque on holds the horn where it stands: that goal went first.
        QCOMPARE(writtenWords(1, kGoalAddress), QList<int>({standing}));
        child<QSpinBox>("goalSpeedSpinBox")->setValue(2000);
        auto *goal = child<QSpinBox>("goalSpinBox");
        goal->setValue(2600);
        QCOMPARE(child<QSlider>("goalSlider")->value(), 2600); // kept in step
        QCOMPARE(writtenWords(1, kGoalAddress).size(), 1); // typing alone sends nothing
        child<QPushButton>("moveButton")->click();
        QTRY_COMPARE_WITH_TIMEOUT(parameters(index)->deviceValue(QStringLiteral("goal_position")),
                                  std::optional<qint64>(2600), 5000);
        // The page keeps reading the servo while it moves: the present position arrives.
        QTRY_COMPARE_WITH_TIMEOUT(
            parameters(index)->deviceValue(QStringLiteral("present_position")),
            std::optional<qint64>(2600), 10000);
        QTRY_COMPARE(child<QLabel>("presentPositionLabel")->text(), QStringLiteral("2600 step"));
        QCOMPARE(writtenWords(1, kGoalAddress), QList<int>({standing, 2600}));
        QCOMPARE(writtenWords(1, 46), QList<int>({2000})); // the speed went with it
        QVERIFY(m_page->statusText().isEmpty());
    }

    void accelerationShowsTheMemoryTablesUnitAndSnapsVisibly()
    {
        const int index = showServo(1);
        QVERIFY(index >= 0);
        auto *acceleration = child<QSpinBox>("accelerationSpinBox");
        QTRY_VERIFY(acceleration->isEnabled());
        // One unit everywhere: the register's real unit, as the Memory table shows it.
        acceleration->setValue(50);
        QCOMPARE(acceleration->text(), QStringLiteral("5000 step/s²"));
        // The arrows move by one step of the register: 100 step/s².
        acceleration->stepUp();
        QCOMPARE(acceleration->value(), 51);
        QCOMPARE(acceleration->text(), QStringLiteral("5100 step/s²"));
        auto *note = child<QLabel>("controlValueNote");
        QVERIFY(note->isHidden());
        // 50 step/s² lies between two steps: it becomes 100 step/s², and the page says so.
        acceleration->setFocus();
        acceleration->selectAll();
        QTest::keyClicks(acceleration, QStringLiteral("50"));
        QTest::keyClick(acceleration, Qt::Key_Return);
        QCOMPARE(acceleration->value(), 1);
        QCOMPARE(acceleration->text(), QStringLiteral("100 step/s²"));
        QVERIFY(!note->isHidden());
        QVERIFY2(note->text().contains(QStringLiteral("50 step/s²"))
                     && note->text().contains(QStringLiteral("100 step/s²")),
                 qPrintable(note->text()));
    }

    void sliderSendsOnlyTheNewestGoalBehindTheOneInFlight()
    {
        const int index = showServo(1);
        QVERIFY(index >= 0);
        auto *slider = child<QSlider>("goalSlider");
        QTRY_VERIFY(slider->isEnabled());
        // A drag faster than the bus: the first goal goes out, the rest wait as one.
        for (int value : {2100, 2150, 2200, 2250, 2300})
            slider->setValue(value);
        QCOMPARE(child<QSpinBox>("goalSpinBox")->value(), 2300);
        QTRY_COMPARE_WITH_TIMEOUT(parameters(index)->deviceValue(QStringLiteral("goal_position")),
                                  std::optional<qint64>(2300), 5000);
        QTRY_COMPARE(writtenWords(1, kGoalAddress), QList<int>({2100, 2300}));
        QCOMPARE(simulatorValue(1, QStringLiteral("goal_position")), 2300);
    }

    void goalOutsideTheAngleLimitsIsRefusedWithNothingSent()
    {
        setSimulatorValue(1, QStringLiteral("min_angle_limit"), 1000);
        setSimulatorValue(1, QStringLiteral("max_angle_limit"), 3000);
        const int index = showServo(1);
        QVERIFY(index >= 0);
        auto *goal = child<QSpinBox>("goalSpinBox");
        QTRY_COMPARE(goal->maximum(), 3000);
        QCOMPARE(goal->minimum(), 1000);
        QCOMPARE(child<QSpinBox>("testFromSpinBox")->maximum(), 3000);
        QCOMPARE(child<QSlider>("goalSlider")->minimum(), 1000);

        QString error;
        QVERIFY(!m_page->moveTo(3500, &error));
        QVERIFY(error.contains(QLatin1String("3000")));
        QCOMPARE(m_page->statusText(), error);

        feetech::MotionPlan plan;
        plan.index = index;
        plan.from = 500;
        plan.to = 2000;
        feetech::MotionTestRefusal refusal;
        QVERIFY(!m_page->motionTest()->startStep(plan, &refusal));
        QCOMPARE(refusal.code(), feetech::MotionTestRefusal::Code::OutsideRange);
        QVERIFY(refusal.range().fromAngleLimits);
        QVERIFY(refusal.describe().contains(QLatin1String("angle limits")));
        QVERIFY(!m_page->motionTest()->isRunning());

        // A goal inside the limits goes out after them: nothing was sent for the refused ones.
        QVERIFY(m_page->moveTo(2900));
        QTRY_COMPARE_WITH_TIMEOUT(writtenWords(1, kGoalAddress), QList<int>({2900}), 5000);
        // The refusal no longer applies; the horn will not move with torque off, though.
        QVERIFY(!m_page->statusText().contains(QLatin1String("3500")));
        QVERIFY(m_page->statusText().contains(QLatin1String("Torque is off")));
    }

    void stepTestMeasuresTheResponse()
    {
        const int index = showServo(1);
        QVERIFY(index >= 0);
        QVERIFY(!m_client->telemetry()->isStreaming());
        m_page->setConfirmMoves(false);
        child<QSpinBox>("testFromSpinBox")->setValue(2000);
        child<QSpinBox>("testToSpinBox")->setValue(2200);
        child<QSpinBox>("testSpeedSpinBox")->setValue(1500);
        child<QSpinBox>("testAccelerationSpinBox")->setValue(100);
        child<QDoubleSpinBox>("recordSecondsSpinBox")->setValue(1.0);
        feetech::MotionTest *test = m_page->motionTest();
        QSignalSpy finished(test, &feetech::MotionTest::stepFinished);
        QSignalSpy failed(test, &feetech::MotionTest::failed);
        child<QPushButton>("stepTestButton")->click();
        QVERIFY(test->isRunning());
        QVERIFY(child<QPushButton>("stopTestButton")->isEnabled());
        QVERIFY(!child<QPushButton>("moveButton")->isEnabled()); // the test owns the goal
        QVERIFY(m_client->telemetry()->isStreaming()); // the test needs the stream
        QTRY_COMPARE_WITH_TIMEOUT(finished.size() + failed.size(), 1, 20000);
        QVERIFY2(failed.isEmpty(),
                 failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
        const auto metrics = finished.first().first().value<feetech::StepMetrics>();
        QCOMPARE(metrics.target, 2200.0);
        QVERIFY(std::abs(metrics.start - 2000.0)
                <= testsupport::quickMotionTiming().reachTolerance);
        QVERIFY(metrics.riseTime.has_value());
        QVERIFY(*metrics.riseTime > 0.0);
        QVERIFY(metrics.settled);
        QVERIFY(metrics.steadyStateError.has_value());
        QVERIFY(std::abs(*metrics.steadyStateError) <= 3.0);
        QVERIFY(metrics.sampleCount >= 10);
        QCOMPARE(simulatorValue(1, QStringLiteral("torque_enable")), 1); // switched on for it
        QCOMPARE(simulatorValue(1, QStringLiteral("goal_position")), 2200);

        // Shown in the form, and the monitor is back to how it was: off.
        QVERIFY(child<QLabel>("riseTimeLabel")->text().endsWith(QLatin1String("ms")));
        QVERIFY(child<QLabel>("settlingTimeLabel")->text().endsWith(QLatin1String("ms")));
        QVERIFY(child<QLabel>("steadyStateErrorLabel")->text().contains(QLatin1String("step")));
        QTRY_VERIFY(!m_client->telemetry()->isStreaming());
        QVERIFY(!test->isRunning());
        QVERIFY(child<QPushButton>("moveButton")->isEnabled());
        // A sweep after it draws its own line and leaves the step's numbers as they were.
        const QString riseTime = child<QLabel>("riseTimeLabel")->text();
        child<QSpinBox>("sweepLegsSpinBox")->setValue(2);
        QSignalSpy swept(test, &feetech::MotionTest::sweepFinished);
        child<QPushButton>("sweepButton")->click();
        QTRY_COMPARE_WITH_TIMEOUT(swept.size() + failed.size(), 1, 20000);
        QVERIFY(failed.isEmpty());
        QCOMPARE(child<QLabel>("riseTimeLabel")->text(), riseTime);
        QVERIFY2(test->recording().size() > 5,
                 qPrintable(QString::number(test->recording().size())));
    }

    void stepTestAsksFirstWithCancelAsTheDefault()
    {
        const int index = showServo(1);
        QVERIFY(index >= 0);
        QVERIFY(m_page->confirmMoves());
        child<QSpinBox>("testFromSpinBox")->setValue(2000);
        child<QSpinBox>("testToSpinBox")->setValue(2200);
        bool cancelWasDefault = false;
        QTimer::singleShot(0, this, [&] {
            QTRY_VERIFY(qobject_cast<QMessageBox *>(QApplication::activeModalWidget()));
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            cancelWasDefault = box->defaultButton() == box->button(QMessageBox::Cancel);
            box->button(QMessageBox::Cancel)->click();
        });
        child<QPushButton>("stepTestButton")->click(); // returns once the box is answered
        QVERIFY(cancelWasDefault);
        QVERIFY(!m_page->motionTest()->isRunning());
        QVERIFY(!m_client->telemetry()->isStreaming());
        QVERIFY(writesReceived(1).isEmpty());
    }

    void allTorqueOffAbortsARunningSweep()
    {
        const int index = showServo(1);
        QVERIFY(index >= 0);
        m_page->setConfirmMoves(false);
        child<QSpinBox>("testFromSpinBox")->setValue(1500);
        child<QSpinBox>("testToSpinBox")->setValue(2500);
        child<QSpinBox>("testSpeedSpinBox")->setValue(400);
        child<QSpinBox>("sweepLegsSpinBox")->setValue(40);
        feetech::MotionTest *test = m_page->motionTest();
        QSignalSpy progress(test, &feetech::MotionTest::progress);
        QSignalSpy failed(test, &feetech::MotionTest::failed);
        QSignalSpy finished(test, &feetech::MotionTest::sweepFinished);
        child<QPushButton>("sweepButton")->click();
        QVERIFY(test->isRunning());
        // Under way: past the start position, on its first leg.
        QTRY_VERIFY_WITH_TIMEOUT(std::any_of(progress.cbegin(), progress.cend(),
                                             [](const QList<QVariant> &args) {
                                                 return args.first().toString().contains(
                                                     QLatin1String("leg 1 of 40"));
                                             }),
                                 15000);
        QCOMPARE(simulatorValue(1, QStringLiteral("torque_enable")), 1);

        m_client->allTorqueOff();
        QVERIFY(!test->isRunning());
        QCOMPARE(failed.size(), 1);
        QVERIFY(failed.first().first().toString().contains(QLatin1String("torque")));
        QVERIFY(finished.isEmpty());
        QVERIFY(m_page->statusText().contains(QLatin1String("All torque off")));
        QVERIFY(!child<QPushButton>("stopTestButton")->isEnabled());
        QVERIFY(child<QPushButton>("sweepButton")->isEnabled());
        for (quint8 id : {1, 2, 3})
            QTRY_COMPARE_WITH_TIMEOUT(simulatorValue(id, QStringLiteral("torque_enable")), 0, 5000);
        QTRY_VERIFY(!m_client->telemetry()->isStreaming()); // as it was before the sweep
        QTRY_VERIFY(child<QPushButton>("torqueOffButton")->isChecked());
    }

    void disconnectingAbortsARunningStepTest()
    {
        const int index = showServo(1);
        QVERIFY(index >= 0);
        m_page->setConfirmMoves(false);
        child<QSpinBox>("testFromSpinBox")->setValue(2000);
        child<QSpinBox>("testToSpinBox")->setValue(2300);
        child<QDoubleSpinBox>("recordSecondsSpinBox")->setValue(20.0);
        feetech::MotionTest *test = m_page->motionTest();
        QSignalSpy progress(test, &feetech::MotionTest::progress);
        QSignalSpy failed(test, &feetech::MotionTest::failed);
        child<QPushButton>("stepTestButton")->click();
        QTRY_VERIFY_WITH_TIMEOUT(std::any_of(progress.cbegin(), progress.cend(),
                                             [](const QList<QVariant> &args) {
                                                 return args.first().toString().contains(
                                                     QLatin1String("recording"));
                                             }),
                                 15000);
        m_client->disconnectFrom();
        QTRY_VERIFY_WITH_TIMEOUT(!test->isRunning(), 5000);
        QCOMPARE(failed.size(), 1);
        QVERIFY(failed.first().first().toString().contains(QLatin1String("disconnected")));
        QVERIFY(!m_client->telemetry()->isStreaming());
        QVERIFY(!m_page->statusText().isEmpty());
    }

    void aFailedGoalWriteAbortsTheSweep()
    {
        const int index = showServo(1);
        QVERIFY(index >= 0);
        feetech::MotionTiming timing = testsupport::quickMotionTiming();
        timing.reachTimeout = std::chrono::milliseconds(300); // each leg gives up quickly
        m_page->setMotionTiming(timing);
        m_page->setConfirmMoves(false);
        child<QSpinBox>("testFromSpinBox")->setValue(1900);
        child<QSpinBox>("testToSpinBox")->setValue(2300);
        child<QSpinBox>("testSpeedSpinBox")->setValue(200);
        child<QSpinBox>("sweepLegsSpinBox")->setValue(100);
        feetech::MotionTest *test = m_page->motionTest();
        QSignalSpy progress(test, &feetech::MotionTest::progress);
        QSignalSpy failed(test, &feetech::MotionTest::failed);
        child<QPushButton>("sweepButton")->click();
        QTRY_VERIFY_WITH_TIMEOUT(std::any_of(progress.cbegin(), progress.cend(),
                                             [](const QList<QVariant> &args) {
                                                 return args.first().toString().contains(
                                                     QLatin1String("leg 1 of 100"));
                                             }),
                                 15000);
        // The servo stops answering at its ID: the next leg's goal write gets no reply.
        setSimulatorValue(1, QStringLiteral("id"), 9);
        QTRY_VERIFY_WITH_TIMEOUT(!test->isRunning(), 10000);
        QCOMPARE(failed.size(), 1);
        QVERIFY2(failed.first().first().toString().contains(QLatin1String("failed")),
                 qPrintable(failed.first().first().toString()));
        QVERIFY(m_page->statusText().contains(QLatin1String("failed")));
        QTRY_VERIFY(!m_client->telemetry()->isStreaming());
    }

    void stopEndsASweepAndKeepsTheMonitorThatWasRunning()
    {
        const int index = showServo(1);
        QVERIFY(index >= 0);
        const int other = m_client->servos()->indexOf({2, k1M});
        QVERIFY(m_client->telemetry()->subscribe(this, {other}, 20.0));
        QTRY_VERIFY(m_client->telemetry()->isStreaming());
        m_page->setConfirmMoves(false);
        child<QSpinBox>("testFromSpinBox")->setValue(1800);
        child<QSpinBox>("testToSpinBox")->setValue(2300);
        child<QSpinBox>("testSpeedSpinBox")->setValue(300);
        child<QSpinBox>("sweepLegsSpinBox")->setValue(10);
        feetech::MotionTest *test = m_page->motionTest();
        QSignalSpy failed(test, &feetech::MotionTest::failed);
        child<QPushButton>("sweepButton")->click();
        QVERIFY(test->isRunning());
        // The stream now carries the tested servo too, fast enough for the test.
        QVERIFY(m_client->telemetry()->isStreamed(index));
        QVERIFY(m_client->telemetry()->isStreamed(other));
        QCOMPARE(m_client->telemetry()->options().rateHz,
                 feetech::MotionTiming::kDefaultMonitorRateHz);

        child<QPushButton>("stopTestButton")->click();
        QVERIFY(!test->isRunning());
        QCOMPARE(failed.size(), 1);
        QVERIFY(m_page->statusText().isEmpty()); // a stop the user asked for is no error
        QVERIFY(child<QLabel>("testProgressLabel")->text().contains(QLatin1String("stopped")));
        // Back to streaming only servo 2 at 20 Hz.
        QTRY_VERIFY(m_client->telemetry()->isStreaming());
        QVERIFY(!m_client->telemetry()->isStreamed(index));
        QVERIFY(m_client->telemetry()->isStreamed(other));
        QCOMPARE(m_client->telemetry()->options().rateHz, 20.0);
    }

    void operatingModeIsWrittenWhereTheFamilyHasIt()
    {
        const int index = showServo(1);
        QVERIFY(index >= 0);
        m_page->setConfirmMoves(false);
        auto *mode = child<QComboBox>("modeCombo");
        auto *apply = child<QPushButton>("modeApplyButton");
        QTRY_VERIFY(mode->isEnabled());
        QCOMPARE(mode->count(), 4); // STS: position, speed, PWM, step
        QCOMPARE(mode->currentIndex(), 0);
        QVERIFY(!apply->isEnabled()); // nothing chosen yet
        mode->setCurrentIndex(1);
        emit mode->activated(1);
        QVERIFY(apply->isEnabled());
        apply->click();
        QTRY_COMPARE_WITH_TIMEOUT(simulatorValue(1, QStringLiteral("mode")), 1, 5000);
        QTRY_COMPARE(parameters(index)->deviceValue(QStringLiteral("mode")),
                     std::optional<qint64>(1));
        QTRY_VERIFY(!apply->isEnabled());
        QCOMPARE(mode->currentIndex(), 1);
        // A test refuses to run outside position mode.
        feetech::MotionPlan plan;
        plan.index = index;
        plan.from = 2000;
        plan.to = 2200;
        feetech::MotionTestRefusal refusal;
        QVERIFY(!m_page->motionTest()->validate(plan, feetech::MotionTest::Kind::Step, &refusal));
        QCOMPARE(refusal.code(), feetech::MotionTestRefusal::Code::NotInPositionMode);
        QCOMPARE(refusal.servoId(), quint8(1));
        QVERIFY(refusal.describe().contains(QLatin1String("position mode")));

        // SCS has no mode register.
        m_page->setServo(m_client->servos()->indexOf({3, k1M}));
        QVERIFY(!mode->isEnabled());
        QCOMPARE(mode->count(), 0);
        QVERIFY(child<QPushButton>("torqueOnButton")->isEnabled());
    }
};

QTEST_MAIN(TestControlPage)
#include "tst_controlpage.moc"
