// End to end through the GUI (offscreen): the main window against the simulated PTK servo.
#include "simclient.h"

#include "connectionbar.h"
#include "hex.h"
#include "mainwindow.h"
#include "packetlogdock.h"
#include "packetlogmodel.h"
#include "parameterpage.h"
#include "ptkclient.h"
#include "ptkframe.h"
#include "ptkparameters.h"
#include "simulatorthread.h"
#include "virtualptkservo.h"

#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QtTest>

namespace {

void typeInto(QAbstractSpinBox *spin, const QString &text)
{
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, text);
    QTest::keyClick(spin, Qt::Key_Tab);
}

} // namespace

class TestPtkGui : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    sim::SimulatorOptions options(const QString &name, bool echo = true)
    {
        return testsupport::ptkOptions(m_dir, name, echo);
    }

private slots:
    void init() { QSettings().clear(); } // nothing remembered from an earlier case

    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
    }

    void editingGainAndDeadbandThenApplyWritesTwelveFramesAndVerifies()
    {
        sim::SimulatorThread simulator;
        QString error;
        const auto opts = options(QStringLiteral("gui"));
        QVERIFY2(simulator.start(opts, &error), qPrintable(error));

        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.connectToPort(simulator.linkPath());
        ParameterPage *page = window.ptkPage();
        QTRY_COMPARE(window.ptkClient()->status().state, seriallink::ConnectionState::Connected);
        QTRY_COMPARE(page->deviceLabel(QStringLiteral("deadband"))->text(), QStringLiteral("15"));
        QTRY_VERIFY(page->editor(QStringLiteral("soft_start"))->isEnabled());

        auto *gain = qobject_cast<QSpinBox *>(page->editor(QStringLiteral("gain")));
        auto *deadband = qobject_cast<QSpinBox *>(page->editor(QStringLiteral("deadband")));
        QVERIFY(gain && deadband);
        typeInto(gain, QStringLiteral("21"));
        typeInto(deadband, QStringLiteral("7"));
        QCOMPARE(*window.ptkClient()->model()->pendingValue(QStringLiteral("gain")), 21);
        QCOMPARE(*window.ptkClient()->model()->pendingValue(QStringLiteral("deadband")), 7);

        auto *apply = page->findChild<QPushButton *>(QStringLiteral("applyButton"));
        QVERIFY(apply);
        QTRY_VERIFY(apply->isEnabled());
        QSignalSpy finished(window.ptkClient(), &ptk::Client::applyFinished);
        QTest::mouseClick(apply, Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);

        ptk::ParameterSet expected = ptk::ParameterSet::seedSample(false);
        expected.set(ptk::Parameter::Gain, 21);
        expected.set(ptk::Parameter::Deadband, 7);
        const QStringList frames = testsupport::ptkWriteFrames(expected);
        QCOMPARE(frames.size(), 12);
        QCOMPARE(testsupport::ptkWritesReceived(opts.logPath), frames);

        QTRY_VERIFY(page->stateLabel(QStringLiteral("gain"))
                        ->text()
                        .contains(model::ParameterModel::stateName(model::State::Verified)));
        QVERIFY(page->stateLabel(QStringLiteral("deadband"))
                    ->text()
                    .contains(model::ParameterModel::stateName(model::State::Verified)));
        QCOMPARE(page->deviceLabel(QStringLiteral("gain"))->text(), QStringLiteral("21"));
        QCOMPARE(gain->value(), 21);
        QVERIFY(!window.findChild<QLabel *>(QStringLiteral("problemBanner"))->isVisible());
        // The packet log saw the writes too.
        QTRY_VERIFY(window.packetLog()->model()->totalCount() > 12);
    }

    void unpluggingShowsDisconnectedWithoutADialogAndReconnects()
    {
        sim::SimulatorThread simulator;
        QString error;
        const auto opts = options(QStringLiteral("unplug"));
        QVERIFY2(simulator.start(opts, &error), qPrintable(error));
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.connectToPort(simulator.linkPath());
        auto *state = window.findChild<QLabel *>(QStringLiteral("connectionState"));
        QTRY_VERIFY(state->text().startsWith(QStringLiteral("Connected")));

        simulator.stop();
        QTRY_VERIFY_WITH_TIMEOUT(state->text().startsWith(QStringLiteral("Disconnected")), 5000);
        QVERIFY(window.findChild<QLabel *>(QStringLiteral("problemBanner"))->isVisible());
        QVERIFY(
            !window.ptkPage()->findChild<QPushButton *>(QStringLiteral("readButton"))->isEnabled());
        QCOMPARE(QApplication::activeModalWidget(), nullptr);

        QVERIFY2(simulator.start(opts, &error), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(state->text().startsWith(QStringLiteral("Connected")), 5000);
        QVERIFY(!window.findChild<QLabel *>(QStringLiteral("problemBanner"))->isVisible());
    }

    void aSavedProfileHoldsTheServosValues()
    {
        sim::SimulatorThread simulator;
        QString error;
        QVERIFY2(simulator.start(options(QStringLiteral("profile")), &error), qPrintable(error));
        MainWindow window;
        window.connectToPort(simulator.linkPath());
        QTRY_VERIFY(window.ptkClient()->model()->deviceValue(QStringLiteral("soft_start")));
        QTRY_VERIFY(window.ptkClient()->model()->deviceValue(QStringLiteral("gain")));
        const QString path = m_dir.filePath(QStringLiteral("gui-profile.json"));
        QTRY_VERIFY(window.saveProfile(path));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.readAll().contains("\"min_pulse_us\": 500"));
    }

    void theSimulatedServoEntryConnectsWithoutHardware()
    {
        MainWindow window;
        window.startDemo();
        QTRY_COMPARE_WITH_TIMEOUT(window.ptkClient()->status().state,
                                  seriallink::ConnectionState::Connected, 5000);
        QTRY_VERIFY(window.ptkClient()->model()->deviceValue(QStringLiteral("neutral")));
    }
};

QTEST_MAIN(TestPtkGui)
#include "tst_ptkgui.moc"
