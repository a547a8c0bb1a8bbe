// Tests the packet window against a simulated bus: frames built with their checksum, sent and
// answered, risky writes asked about first, the history resent, sequences saved and loaded.
#include "feetechbus.h"
#include "namedchild.h"
#include "packetsequence.h"
#include "packetwindow.h"
#include "ptkclient.h"

#include <QComboBox>
#include <QLineEdit>
#include <QSpinBox>
#include <QTableWidget>
#include <QtTest>

#include <memory>

namespace {

constexpr qint32 k1M = 1000000;
constexpr int kOutcomeColumn = 3;

} // namespace

class TestPacketWindow : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_feetech;
    std::unique_ptr<ptk::Client> m_ptk;
    std::unique_ptr<PacketWindow> m_window;
    QStringList m_asked; // the risks the window asked about

    template<typename T>
    T *child(const char *name) const
    {
        return testsupport::namedChild<T>(m_window.get(), name);
    }

    void choose(const char *combo, int data)
    {
        auto *box = child<QComboBox>(combo);
        box->setCurrentIndex(box->findData(data));
    }

    // Sends what the form holds and waits for its outcome.
    bool sendForm()
    {
        QSignalSpy sent(m_window.get(), &PacketWindow::sent);
        QString error;
        const auto frame = m_window->builtFrame(&error);
        if (!frame || !m_window->send({*frame}, &error)) {
            qWarning() << error;
            return false;
        }
        return sent.wait(10000) && sent.first().first().toBool();
    }

    QString lastOutcome() const
    {
        return m_window->history()
            ->item(m_window->history()->rowCount() - 1, kOutcomeColumn)
            ->text();
    }

private slots:
    void init()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215"})),
                                &error),
                 qPrintable(error));
        m_feetech = std::make_unique<feetech::BusClient>();
        m_ptk = std::make_unique<ptk::Client>();
        m_window = std::make_unique<PacketWindow>(m_feetech.get(), m_ptk.get());
        m_asked.clear();
        m_window->setConfirm([this](const QString &risk) {
            m_asked.append(risk);
            return false;
        });
        m_window->show();
    }

    void cleanup()
    {
        m_window.reset();
        m_feetech.reset();
        m_ptk.reset();
    }

    void aReadIsBuiltWithItsChecksumSentAndAnswered()
    {
        choose("instructionCombo", int(feetech::Instruction::Read));
        child<QSpinBox>("packetIdSpin")->setValue(1);
        child<QSpinBox>("packetAddressSpin")->setValue(56);
        child<QSpinBox>("packetLengthSpin")->setValue(2);
        // FF FF ID LEN INSTR ADDR N CHK, CHK = ~(1 + 4 + 2 + 0x38 + 2) = 0xBE
        QCOMPARE(child<QLineEdit>("packetPreview")->text(),
                 QStringLiteral("FF FF 01 04 02 38 02 BE"));
        QVERIFY(!child<QPushButton>("sendPacketButton")->isEnabled()); // not connected yet

        m_feetech->connectTo(m_simulator->linkPath(), k1M);
        QTRY_VERIFY_WITH_TIMEOUT(m_feetech->link()->isConnected(), 10000);
        QTRY_VERIFY(child<QPushButton>("sendPacketButton")->isEnabled());
        QVERIFY(sendForm());
        // The answer: servo 1, no error, the two bytes of its present position (2048 = 00 08).
        QTRY_VERIFY(lastOutcome().startsWith(QStringLiteral("FF FF 01 04 00 00 08")));
        QVERIFY(m_asked.isEmpty()); // a read asks nothing
    }

    void aWriteToTheIdRegisterAsksFirstAndSendsNothingWhenRefused()
    {
        m_feetech->connectTo(m_simulator->linkPath(), k1M);
        QTRY_VERIFY_WITH_TIMEOUT(m_feetech->link()->isConnected(), 10000);
        choose("instructionCombo", int(feetech::Instruction::Write));
        child<QSpinBox>("packetIdSpin")->setValue(1);
        child<QSpinBox>("packetAddressSpin")->setValue(5); // the ID
        child<QLineEdit>("packetDataEdit")->setText(QStringLiteral("07"));
        const auto frame = m_window->builtFrame();
        QVERIFY(frame);
        QString error;
        QVERIFY(!m_window->send({*frame}, &error));
        QCOMPARE(m_asked.size(), 1);
        QVERIFY2(m_asked.first().contains(QStringLiteral("ID")), qPrintable(m_asked.first()));
        QCOMPARE(m_window->history()->rowCount(), 0);
        QCOMPARE(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).size(), 0);

        // Allowed: it goes out, and the servo answers at its new ID from then on.
        m_window->setConfirm([](const QString &) { return true; });
        QSignalSpy sent(m_window.get(), &PacketWindow::sent);
        QVERIFY(m_window->send({*frame}, &error));
        QVERIFY(sent.wait(10000));
        QCOMPARE(simulatorValue(7, u"id"), 7);
    }

    void theHistoryIsResentAndSavedAndLoadedAsASequence()
    {
        m_feetech->connectTo(m_simulator->linkPath(), k1M);
        QTRY_VERIFY_WITH_TIMEOUT(m_feetech->link()->isConnected(), 10000);
        choose("instructionCombo", int(feetech::Instruction::Ping));
        child<QSpinBox>("packetIdSpin")->setValue(2);
        QVERIFY(sendForm());
        QVERIFY(lastOutcome().startsWith(QStringLiteral("FF FF 02 02 00")));
        // Resent from the history: a second row, answered again.
        m_window->history()->selectRow(0);
        QSignalSpy sent(m_window.get(), &PacketWindow::sent);
        child<QPushButton>("resendButton")->click();
        QVERIFY(sent.wait(10000));
        QCOMPARE(m_window->history()->rowCount(), 2);
        QVERIFY(lastOutcome().startsWith(QStringLiteral("FF FF 02 02 00")));
        QCOMPARE(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Ping).size(),
                 2);

        const QString path = writeTestFile(QStringLiteral("sequence.json"), {});
        util::FileError error;
        QVERIFY2(m_window->sequenceFiles()->save(path, &error), qPrintable(error.describe()));
        PacketWindow other(m_feetech.get(), m_ptk.get());
        QVERIFY2(other.sequenceFiles()->load(path, &error), qPrintable(error.describe()));
        QCOMPARE(other.historyFrames(), m_window->historyFrames());
        QCOMPARE(other.historyFrames().first().replyId, std::optional<quint8>(2));
    }

    void aBadSequenceFileIsRefusedWithItsReason()
    {
        const QString garbled = writeTestFile(QStringLiteral("garbled.json"), "{\"format\":");
        const QString wrongFrame = writeTestFile(
            QStringLiteral("wrong.json"),
            R"({"format":"servobench-packets","version":1,"frames":[{"protocol":"feetech","baud":1000000,"hex":"FF FF 01 02 01 00"}]})");
        util::FileError error;
        QVERIFY(!m_window->sequenceFiles()->load(garbled, &error));
        QCOMPARE(error.code(), util::FileError::Code::NotJson);
        QVERIFY(error.describe().contains(QStringLiteral("garbled.json")));
        QVERIFY(!m_window->sequenceFiles()->load(wrongFrame, &error));
        QCOMPARE(error.code(), util::FileError::Code::BadValue);
        QVERIFY2(error.describe().contains(QStringLiteral("frame 1")),
                 qPrintable(error.describe()));
        QCOMPARE(m_window->history()->rowCount(), 0);
    }

    void aPtkQueryIsBuiltAndNeedsAPtkServo()
    {
        auto *tabs = m_window->findChild<QTabWidget *>();
        tabs->setCurrentIndex(1);
        const auto frame = m_window->builtFrame();
        QVERIFY(frame);
        QCOMPARE(frame->protocol, PacketFrame::Protocol::Ptk);
        QVERIFY(frame->expectsReply);
        QCOMPARE(frame->bytes.size(), 10);
        QVERIFY(packetsequence::riskOf(*frame).isEmpty());
        QString error;
        QVERIFY(!m_window->send({*frame}, &error));
        QVERIFY(error.contains(QStringLiteral("PTK")));

        // With a simulated PTK servo: the query goes out between the polls and is answered.
        sim::SimulatorThread servo;
        QVERIFY2(servo.start(testsupport::ptkOptions(m_dir, QStringLiteral("ptk")), &error),
                 qPrintable(error));
        m_ptk->connectTo(servo.linkPath());
        QTRY_VERIFY_WITH_TIMEOUT(m_ptk->isConnected(), 10000);
        QSignalSpy sent(m_window.get(), &PacketWindow::sent);
        QVERIFY2(m_window->send({*frame}, &error), qPrintable(error));
        QVERIFY(sent.wait(10000));
        QVERIFY2(sent.first().first().toBool(), qPrintable(sent.first().at(1).toString()));
        QVERIFY(lastOutcome().startsWith(QStringLiteral("AF FA")));
        m_ptk->disconnectFrom();
    }
};

QTEST_MAIN(TestPacketWindow)
#include "tst_packetwindow.moc"
