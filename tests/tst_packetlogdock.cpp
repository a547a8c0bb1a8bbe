// Tests the packet log dock: its tool bar pauses, clears and filters the log it shows.
#include "packetlogentries.h"

#include "packetlogdock.h"
#include "packetlogmodel.h"

#include <QLabel>
#include <QScrollBar>
#include <QTableView>
#include <QToolButton>
#include <QtTest>

using seriallink::Direction;
using seriallink::PacketLogEntry;
using seriallink::PacketLogModel;

namespace {

using testsupport::logEntry;

QToolButton *button(const PacketLogDock &dock, const char *name)
{
    return dock.findChild<QToolButton *>(QLatin1String(name));
}

} // namespace

class TestPacketLogDock : public QObject
{
    Q_OBJECT

private slots:
    void theToolBarButtonsCanBeFoundByName()
    {
        PacketLogDock dock;
        QCOMPARE(dock.windowTitle(), QStringLiteral("Packet log"));
        for (const char *name :
             {"pauseLogButton", "clearLogButton", "exportLogButton", "errorsOnlyButton"})
            QVERIFY2(button(dock, name), name);
        QVERIFY(button(dock, "pauseLogButton")->isCheckable());
        QVERIFY(button(dock, "errorsOnlyButton")->isCheckable());
    }

    void thePauseButtonPausesTheModel()
    {
        PacketLogDock dock;
        dock.append(logEntry(0));
        QTRY_COMPARE(dock.view()->model()->rowCount(), 1);

        button(dock, "pauseLogButton")->click();
        QVERIFY(dock.model()->isPaused());
        dock.append(logEntry(1));
        dock.model()->flush();
        QCOMPARE(dock.view()->model()->rowCount(), 1);

        button(dock, "pauseLogButton")->click();
        QVERIFY(!dock.model()->isPaused());
        QCOMPARE(dock.view()->model()->rowCount(), 2);
    }

    void theClearButtonEmptiesTheLogAndTheCounts()
    {
        PacketLogDock dock;
        auto *counts = dock.findChild<QLabel *>(QStringLiteral("logCountLabel"));
        QVERIFY(counts);
        dock.append(logEntry(0));
        dock.append(logEntry(1, QStringLiteral("timeout")));
        QTRY_COMPARE(dock.view()->model()->rowCount(), 2);
        QCOMPARE(counts->text(), QStringLiteral("2 frame(s), 1 error(s)"));

        button(dock, "clearLogButton")->click();
        QCOMPARE(dock.view()->model()->rowCount(), 0);
        QCOMPARE(dock.model()->totalCount(), 0);
        QCOMPARE(counts->text(), QStringLiteral("0 frame(s), 0 error(s)"));
    }

    void theErrorsOnlyFilterHidesGoodRows()
    {
        PacketLogDock dock;
        dock.append(logEntry(0));
        dock.append(logEntry(1, QStringLiteral("bad checksum")));
        dock.append(logEntry(2));
        QTRY_COMPARE(dock.view()->model()->rowCount(), 3);

        button(dock, "errorsOnlyButton")->click();
        QAbstractItemModel *shown = dock.view()->model();
        QCOMPARE(shown->rowCount(), 1);
        QCOMPARE(shown->index(0, PacketLogModel::MeaningColumn).data().toString(),
                 QStringLiteral("frame 1"));
        dock.append(logEntry(3));
        dock.append(logEntry(4, QStringLiteral("timeout")));
        QTRY_COMPARE(dock.model()->rowCount(), 5);
        QCOMPARE(shown->rowCount(), 2);

        button(dock, "errorsOnlyButton")->click();
        QCOMPARE(shown->rowCount(), 5);
    }

    void errorRowsAreDrawnInAnotherColour()
    {
        PacketLogDock dock;
        dock.append(logEntry(0));
        dock.append(logEntry(1, QStringLiteral("bad checksum")));
        QTRY_COMPARE(dock.view()->model()->rowCount(), 2);
        QAbstractItemModel *shown = dock.view()->model();
        QVERIFY(!shown->index(0, 0).data(Qt::ForegroundRole).isValid());
        QVERIFY(shown->index(1, 0).data(Qt::ForegroundRole).canConvert<QColor>());
        QVERIFY(shown->index(1, PacketLogModel::BytesColumn).data(Qt::FontRole).isValid());
    }

    void theViewFollowsNewRowsOnlyWhileAtTheBottom()
    {
        PacketLogDock dock;
        dock.resize(700, 240);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        QScrollBar *scroll = dock.view()->verticalScrollBar();
        for (int n = 0; n < 200; ++n)
            dock.append(logEntry(n));
        QTRY_VERIFY(scroll->maximum() > 0 && scroll->value() == scroll->maximum());

        scroll->setValue(0); // the user scrolls up to read
        const int before = scroll->maximum();
        for (int n = 200; n < 400; ++n)
            dock.append(logEntry(n));
        QTRY_VERIFY(scroll->maximum() > before);
        QCOMPARE(scroll->value(), 0);
    }
};

QTEST_MAIN(TestPacketLogDock)
#include "tst_packetlogdock.moc"
