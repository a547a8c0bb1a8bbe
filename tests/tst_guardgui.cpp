// GUI tests of the guard on the Control page against a simulated bus: the banner says what the
// guard did to a blocked servo, a latched overload is walked through its recovery, and the
// settings dialog gives per-servo limits with defaults from the registers; a servo left unlocked
// is shown and locked on request.
#include "controlpage.h"
#include "feetechbus.h"
#include "guardbanner.h"
#include "guardsettingsdialog.h"
#include "namedchild.h"
#include "overloadguard.h"
#include "overloadrecoverydialog.h"
#include "unlockednotice.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QtTest>

#include <memory>

namespace {

constexpr qint32 k1M = 1000000;

} // namespace

class TestGuardGui : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;
    std::unique_ptr<ControlPage> m_page;
    int m_index = -1;

    template<typename T>
    T *child(const char *name) const
    {
        return testsupport::namedChild<T>(m_page.get(), name);
    }

    void blockServo()
    {
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setExternalLoad(1000); }));
    }

private slots:
    void init()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215"})),
                                &error),
                 qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>(testsupport::patientTiming());
        m_page = std::make_unique<ControlPage>(m_client.get());
        m_page->setConfirmMoves(false);
        m_page->resize(900, 700);
        m_page->show();
        // The servo's own overload trip as late as it goes (2.54 s): a loaded machine delays
        // the guard's samples, and the tests are about the guard, not about that race.
        setSimulatorValue(1, u"protection_time", 254);
        m_index = testsupport::connectScanAndRead(*m_client, m_simulator->linkPath(), 2, 1);
        QVERIFY(m_index >= 0);
        m_page->setServo(m_index);
    }

    void cleanup()
    {
        m_page.reset();
        m_client.reset();
        m_simulator.reset();
    }

    void anUnlockedServoShowsTheNoticeAndLockClosesIt()
    {
        UnlockedNotice notice(m_client.get());
        notice.showServo(m_index);
        QVERIFY(notice.isHidden()); // locked, as servos power on
        setSimulatorValue(1, u"lock", 0); // a write cut short before its relock
        m_client->readServo(m_index);
        QTRY_VERIFY_WITH_TIMEOUT(!notice.isHidden(), 10000);
        QVERIFY2(notice.text().contains(QLatin1String("Note: servo 1's EEPROM is unlocked")),
                 qPrintable(notice.text()));
        QCOMPARE(simulatorValue(1, u"lock"), 0); // shown, not acted on
        notice.lockButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(notice.isHidden(), 10000);
        QCOMPARE(simulatorValue(1, u"lock"), 1);
    }

    void aDismissedNoteStaysAwayForThatServoAndTheLockIsLeftAsItIs()
    {
        UnlockedNotice notice(m_client.get());
        notice.showServo(m_index);
        setSimulatorValue(1, u"lock", 0); // as LeRobot leaves it
        m_client->readServo(m_index);
        QTRY_VERIFY_WITH_TIMEOUT(!notice.isHidden(), 10000);
        notice.findChild<QPushButton *>(QStringLiteral("dismissUnlockedButton"))->click();
        QVERIFY(notice.isHidden());
        // Read again: the servo still reads unlocked, and the note stays away.
        QSignalSpy updated(m_client->servos(), &feetech::ServoList::servoUpdated);
        m_client->readServo(m_index);
        QTRY_VERIFY_WITH_TIMEOUT(!updated.isEmpty(), 10000);
        QVERIFY(m_client->servos()->eepromUnlocked(m_index));
        QVERIFY(notice.isHidden());
        QCOMPARE(simulatorValue(1, u"lock"), 0);
    }

    void theBannerSaysTheGuardIsOnBeforeAnythingHappens()
    {
        QVERIFY(child<QWidget>("guardBanner")->isVisible());
        QVERIFY2(m_page->guardBanner()->text().contains(QLatin1String("Guard on")),
                 qPrintable(m_page->guardBanner()->text()));
        QVERIFY(!child<QPushButton>("guardRecoverButton")->isVisible());
    }

    void theControlPageShowsThatTheGuardHeldABlockedServo()
    {
        blockServo();
        const qint32 start = simulatorValue(1, u"present_position");
        child<QPushButton>("torqueOnButton")->click();
        QTRY_COMPARE_WITH_TIMEOUT(simulatorValue(1, u"torque_enable"), 1, 10000);
        QVERIFY(m_page->moveTo(start > 2048 ? 600 : 3400));
        QTRY_VERIFY_WITH_TIMEOUT(
            m_page->guardBanner()->text().contains(QLatin1String("was overloaded")), 15000);
        const QString text = m_page->guardBanner()->text();
        QVERIFY2(text.contains(QLatin1String("Servo ID 1")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("where it stands (%1)").arg(start)),
                 qPrintable(text));
        QCOMPARE(simulatorValue(1, u"goal_position"), start);
    }

    void aSweepOnABlockedServoIsStoppedWhenTheGuardHoldsIt()
    {
        blockServo();
        QSignalSpy failed(m_page->motionTest(), &feetech::MotionTest::failed);
        feetech::MotionTestRefusal refusal;
        QVERIFY2(m_page->motionTest()->startSweep(testsupport::longSweep(m_index), &refusal),
                 qPrintable(refusal.describe()));
        QVERIFY(failed.wait(20000));
        const QString message = failed.first().at(0).toString();
        QVERIFY2(message.contains(QLatin1String("Guard")), qPrintable(message));
        QVERIFY(!m_page->motionTest()->isRunning());
        QVERIFY(m_page->guardBanner()->text().contains(QLatin1String("was overloaded")));
    }

    void aLatchedOverloadIsWalkedThroughItsRecovery()
    {
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setOverloadLatched(true); }));
        child<QPushButton>("torqueOnButton")->click();
        QTRY_VERIFY_WITH_TIMEOUT(child<QPushButton>("guardRecoverButton")->isVisible(), 15000);
        QVERIFY(m_page->guardBanner()->text().contains(QLatin1String("protection tripped")));
        child<QPushButton>("guardRecoverButton")->click();
        auto *dialog = m_page->findChild<OverloadRecoveryDialog *>();
        QVERIFY(dialog);
        dialog->actionButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(dialog->text().contains(QLatin1String("power")), 10000);
        QCOMPARE(dialog->actionButton()->text(), QStringLiteral("Check again"));
        // The user cycles the power, then checks.
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->setPowered(0, false);
            simulator.feetechBus()->setPowered(0, true);
        });
        QTRY_VERIFY_WITH_TIMEOUT(dialog->actionButton()->isEnabled(), 10000);
        dialog->actionButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(dialog->text().contains(QLatin1String("clear")), 10000);
        QVERIFY(!dialog->actionButton()->isVisible());
        QVERIFY(!child<QPushButton>("guardRecoverButton")->isVisible());
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        dialog->close();
    }

    void theSettingsDialogShowsEachServosDefaultsAndSetsOneServoApart()
    {
        GuardSettingsDialog dialog(m_client.get());
        QTableWidget *table = dialog.table();
        QCOMPARE(table->rowCount(), 2);
        auto *load =
            qobject_cast<QDoubleSpinBox *>(table->cellWidget(0, GuardSettingsDialog::LoadColumn));
        QCOMPARE(load->value(), 80.0); // the servo's overload torque register
        QVERIFY(dialog.settings().servos.isEmpty()); // all at their defaults
        load->setValue(40.0);
        auto *action =
            qobject_cast<QComboBox *>(table->cellWidget(0, GuardSettingsDialog::ActionColumn));
        action->setCurrentIndex(action->findData(int(feetech::GuardAction::TorqueOff)));
        const feetech::GuardSettings settings = dialog.settings();
        QCOMPARE(settings.servos.size(), 1);
        const feetech::GuardLimits limits = settings.servos.value({1, k1M});
        QCOMPARE(limits.loadPercent, 40.0);
        QCOMPARE(limits.action, feetech::GuardAction::TorqueOff);
        m_client->guard()->setSettings(settings);
        QCOMPARE(m_client->guard()->limits(m_index).loadPercent, 40.0);
        QCOMPARE(m_client->guard()->limits(m_client->servos()->indexOf({2, k1M})).loadPercent,
                 80.0);
    }
};

QTEST_MAIN(TestGuardGui)
#include "tst_guardgui.moc"
