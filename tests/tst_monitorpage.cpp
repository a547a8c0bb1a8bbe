// GUI tests of the Monitor page: bounded plot memory under a long synthetic stream, CSV
// recordings that parse back, PNG export, and live monitoring of a simulated bus.
#include "feedbacksample.h"
#include "feetechbus.h"
#include "monitorpage.h"
#include "monitorrecording.h"
#include "monitorservolist.h"
#include "monitorstatusline.h"
#include "telemetrycsv.h"
#include "telemetryplot.h"

#include <QImage>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTabBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

using feetech::FeedbackSample;
using feetech::Quantity;

namespace {

constexpr qint32 k1M = 1000000;
constexpr int kServos = 6;
constexpr int kRateHz = 100;
constexpr qint64 kPeriodUs = 1000000 / kRateHz;

// `seconds` of samples for `servos` servos at kRateHz, fed to the page in the stream's batches
// of 20 ms, starting at `startUs`; returns the time after the last one.
qint64 feed(MonitorPage &page, qint64 startUs, int seconds, int servos = kServos)
{
    constexpr int kCyclesPerBatch = kRateHz / 50;
    const int cycles = seconds * kRateHz;
    QVector<FeedbackSample> batch;
    for (int cycle = 0; cycle < cycles; ++cycle) {
        const qint64 us = startUs + cycle * kPeriodUs;
        for (int id = 1; id <= servos; ++id)
            batch.append(testsupport::feedbackSample(quint8(id), us,
                                                     2048 + 1000 * std::sin(cycle / 50.0 + id)));
        if ((cycle + 1) % kCyclesPerBatch == 0) {
            page.addSamples(batch);
            batch.clear();
        }
    }
    page.addSamples(batch);
    return startUs + cycles * kPeriodUs;
}

} // namespace

class TestMonitorPage : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;
    std::unique_ptr<MonitorPage> m_page;

    void startSimulatorAndScan()
    {
        QString error;
        const auto servos =
            testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"STS3215", u"SCS15"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 6));
        QCOMPARE(m_client->servos()->count(), 4);
    }

    int readoutRow(quint8 id) const
    {
        QTableWidget *table = m_page->readouts();
        for (int row = 0; row < table->rowCount(); ++row) {
            if (table->item(row, MonitorReadouts::ServoColumn)->text()
                == QStringLiteral("ID %1").arg(id))
                return row;
        }
        return -1;
    }

    QString readout(quint8 id, int column) const
    {
        const int row = readoutRow(id);
        return row < 0 ? QString() : m_page->readouts()->item(row, column)->text();
    }

private slots:
    void init()
    {
        QSettings().clear(); // the Monitor remembers its choices
        m_client = std::make_unique<feetech::BusClient>();
        m_page = std::make_unique<MonitorPage>(m_client.get());
        m_page->resize(1180, 820);
        m_page->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_page.get()));
    }

    void cleanup()
    {
        m_page.reset();
        m_client.reset();
        m_simulator.reset();
    }

    void defaultsArePositionSpeedAndLoadAtFiftyHertz()
    {
        QCOMPARE(m_page->quantities(),
                 (QVector<Quantity> {Quantity::Position, Quantity::Speed, Quantity::Load}));
        QCOMPARE(m_page->rate(), 50.0);
        QCOMPARE(m_page->plot()->windowSeconds(), 10.0);
        // Not connected: nothing to start, and starting says why.
        QVERIFY(
            !m_page->findChild<QPushButton *>(QStringLiteral("monitorStartButton"))->isEnabled());
        QString error;
        QVERIFY(!m_page->start(&error));
        QVERIFY(!error.isEmpty());
        QVERIFY(
            m_page->findChild<QLabel *>(QStringLiteral("monitorMessage"))->text().contains(error));
    }

    void tenMinutesAtOneHundredHertzForSixServosStayBounded()
    {
        m_page->resize(1180, 1600); // room for all six panes: every series drawn
        m_page->setQuantities(
            {std::begin(feetech::kAllQuantities), std::end(feetech::kAllQuantities)});
        TelemetryPlot *plot = m_page->plot();
        QTRY_COMPARE(plot->quantities().size(), feetech::kQuantityCount);
        QCOMPARE(plot->seriesCount(), 0);
        const qint64 origin = 1000000000;
        qint64 now = origin;
        for (int minute = 0; minute < 10; ++minute) {
            now = feed(*m_page, now, 60);
            plot->refresh();
        }
        QCOMPARE(plot->seriesCount(), kServos * feetech::kQuantityCount);
        // The window (10 s) plus a second of slack at 100 Hz, and within the hard bounds.
        const int perSeries = int((plot->windowSeconds() + 1.0) * kRateHz) + 1;
        QVERIFY(perSeries <= plot->maxPointsPerSeries());
        QVERIFY(plot->maxPointsPerSeries() <= TelemetryPlot::kHardPointCap);
        for (int id = 1; id <= kServos; ++id) {
            for (const Quantity quantity : feetech::kAllQuantities) {
                const int count = plot->bufferedPointCount(quint8(id), quantity);
                QVERIFY2(count <= perSeries, qPrintable(QString::number(count)));
                // Still holds the whole window: nothing in view was dropped.
                QVERIFY(count >= int(plot->windowSeconds()) * kRateHz);
            }
        }
        QVERIFY(plot->bufferedPoints() <= qint64(perSeries) * kServos * feetech::kQuantityCount);

        // Paused, the view keeps what it shows, but never more than the per-series cap.
        m_page->setWindowSeconds(5);
        QCOMPARE(plot->maxPointsPerSeries(), 5 * int(TelemetryPlot::kMaxRateHz));
        plot->setPaused(true);
        now = feed(*m_page, now, 60);
        for (int id = 1; id <= kServos; ++id) {
            QVERIFY(plot->bufferedPointCount(quint8(id), Quantity::Position)
                    <= plot->maxPointsPerSeries());
        }
        QVERIFY(plot->bufferedPointCount(1, Quantity::Position) > 6 * kRateHz);
        // Live again, the surplus goes.
        plot->setPaused(false);
        QVERIFY(plot->bufferedPointCount(1, Quantity::Position) <= 6 * kRateHz + 1);
        QVERIFY(plot->bufferedPoints()
                <= qint64(6 * kRateHz + 1) * kServos * feetech::kQuantityCount);
    }

    void longWindowIsDecimatedAndKeepsPeaks()
    {
        m_page->setQuantities({Quantity::Position});
        m_page->setWindowSeconds(120);
        TelemetryPlot *plot = m_page->plot();
        QTRY_VERIFY(plot->plotArea(Quantity::Position).width() > 100); // laid out
        qint64 now = 5000000;
        now = feed(*m_page, now, 60, 2);
        // One short spike far above the rest (which stay within 1048..3048).
        FeedbackSample spike = testsupport::feedbackSample(1, now, 4000);
        m_page->addSamples({spike});
        now = feed(*m_page, now + kPeriodUs, 60, 2);
        plot->refresh();
        QCOMPARE(plot->bufferedPointCount(1, Quantity::Position), 120 * kRateHz + 1);
        const int pixels = plot->plotArea(Quantity::Position).width();
        QVERIFY(pixels > 100);
        const int shown = plot->shownPointCount(1, Quantity::Position);
        QVERIFY2(shown <= 2 * pixels + 2,
                 qPrintable(QStringLiteral("%1 > 2 × %2").arg(shown).arg(pixels)));
        QVERIFY(shown < 120 * kRateHz);
        const QList<QPointF> points = plot->shownPoints(1, Quantity::Position);
        QCOMPARE(points.size(), shown);
        QVERIFY(std::any_of(points.begin(), points.end(),
                            [](const QPointF &point) { return point.y() == 4000.0; }));
        // The value axis follows the data in view, the spike included.
        const auto [low, high] = plot->valueRange(Quantity::Position);
        QVERIFY(high >= 4000.0);
        QVERIFY(low <= 1048.0 && low > 0.0); // yet not much lower
    }

    void zoomFreezesTheViewAndResetReturnsToLive()
    {
        TelemetryPlot *plot = m_page->plot();
        QSignalSpy zoomed(plot, &TelemetryPlot::zoomedChanged);
        qint64 now = feed(*m_page, 0, 20, 2);
        plot->refresh();
        QCOMPARE(plot->viewTo(), 20.0 - 0.01);
        plot->setTimeRange(12.0, 14.0);
        QVERIFY(plot->isZoomed());
        QVERIFY(plot->isPaused());
        QCOMPARE(zoomed.count(), 1);
        auto *reset = m_page->findChild<QPushButton *>(QStringLiteral("monitorResetZoomButton"));
        QVERIFY(reset->isEnabled());
        now = feed(*m_page, now, 5, 2);
        plot->refresh();
        QCOMPARE(plot->viewFrom(), 12.0); // frozen while new samples come
        reset->click();
        QVERIFY(!plot->isZoomed());
        QVERIFY(!plot->isPaused());
        QCOMPARE(plot->viewTo(), 25.0 - 0.01); // the newest sample
        QCOMPARE(plot->viewFrom(), plot->viewTo() - plot->windowSeconds());
        QVERIFY(!reset->isEnabled());

        // Pause freezes the view while samples are still buffered; Resume jumps to live.
        auto *pause = m_page->findChild<QPushButton *>(QStringLiteral("monitorPauseButton"));
        pause->click();
        QVERIFY(plot->isPaused());
        QCOMPARE(pause->text(), QStringLiteral("Resume"));
        const int buffered = plot->bufferedPointCount(1, Quantity::Position);
        feed(*m_page, now, 2, 2);
        plot->refresh();
        QCOMPARE(plot->viewTo(), 25.0 - 0.01);
        QCOMPARE(plot->bufferedPointCount(1, Quantity::Position), buffered + 2 * kRateHz);
        pause->click();
        QVERIFY(!plot->isPaused());
        QCOMPARE(pause->text(), QStringLiteral("Pause"));
        QCOMPARE(plot->viewTo(), 27.0 - 0.01);
    }

    void dragAndWheelZoomTheTimeAxisOfEveryChart()
    {
        TelemetryPlot *plot = m_page->plot();
        QTRY_VERIFY(plot->plotArea(Quantity::Position).width() > 100); // laid out
        feed(*m_page, 0, 20, 2);
        plot->refresh();
        const double from = plot->viewFrom();
        const double span = plot->viewTo() - plot->viewFrom();
        // Dragged across the middle half of the position pane.
        const QRect area = plot->plotArea(Quantity::Position);
        const QPoint start(area.left() + area.width() / 4, area.center().y());
        const QPoint end(area.left() + area.width() * 3 / 4, area.center().y());
        QTest::mousePress(plot, Qt::LeftButton, {}, start);
        QTest::mouseMove(plot, end);
        QTest::mouseRelease(plot, Qt::LeftButton, {}, end);
        QVERIFY(plot->isZoomed());
        QVERIFY(plot->isPaused());
        QVERIFY(qAbs(plot->viewFrom() - (from + span / 4)) < span / 50);
        QVERIFY(qAbs(plot->viewTo() - (from + span * 3 / 4)) < span / 50);
        // The other pane shares the time axis: its plot area spans the same pixels.
        const QRect speedArea = plot->plotArea(Quantity::Speed);
        QCOMPARE(speedArea.left(), area.left());
        QCOMPARE(speedArea.width(), area.width());

        // One wheel notch up zooms in around the pointer.
        const double zoomedSpan = plot->viewTo() - plot->viewFrom();
        const QPointF centre = QPointF(area.center());
        QWheelEvent wheel(centre, plot->mapToGlobal(centre), {}, {0, 120}, Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(plot, &wheel);
        QVERIFY(qAbs((plot->viewTo() - plot->viewFrom()) - zoomedSpan * 0.8) < 1e-6);

        plot->resetZoom();
        QVERIFY(!plot->isZoomed());
        QCOMPARE(plot->viewTo(), 20.0 - 0.01);
    }

    void recordingParsesBackWithTheSameIdsTimesAndValues()
    {
        const QString path = m_dir.filePath(QStringLiteral("recording.csv"));
        util::FileError notRecording;
        QVERIFY2(m_page->recording()->startRecording(path, &notRecording),
                 qPrintable(notRecording.describe()));
        QVERIFY(m_page->recording()->isRecording());
        const qint64 start = m_page->recording()->recorder()->startUs();
        // Taken before recording started: not part of it.
        m_page->addSamples({testsupport::feedbackSample(1, start - 5000, 1)});
        QVector<FeedbackSample> written;
        for (int i = 0; i < 50; ++i) {
            QVector<FeedbackSample> batch;
            for (quint8 id = 1; id <= 3; ++id) {
                FeedbackSample sample =
                    testsupport::feedbackSample(id, start + i * 10000 + id * 100, 2048 + i);
                sample.values[int(Quantity::Speed)] = -120.5 + i;
                sample.values[int(Quantity::Voltage)] = 11.9;
                if (id == 3)
                    sample.values[int(Quantity::Current)].reset(); // not reported
                sample.servoStatus = id == 2 ? 0x24 : 0;
                sample.moving = i % 2 == 1;
                batch.append(sample);
            }
            m_page->addSamples(batch);
            written += batch;
        }
        QCOMPARE(m_page->recording()->recorder()->rowCount(), qint64(written.size()));
        m_page->recording()->stopRecording();
        QVERIFY(!m_page->recording()->isRecording());

        QString error;
        const auto rows = testsupport::readTelemetryCsv(path, &error);
        QVERIFY2(rows, qPrintable(error));
        testsupport::compareTelemetryRows(*rows, written, start);
    }

    void recordingToAnUnwritablePlaceSaysWhy()
    {
        const QString path = m_dir.filePath(QStringLiteral("no/such/folder/recording.csv"));
        util::FileError error;
        QVERIFY(!m_page->recording()->startRecording(path, &error));
        QVERIFY(!m_page->recording()->isRecording());
        QCOMPARE(error.code(), util::FileError::Code::CannotWrite);
        QVERIFY(error.describe().contains(QDir::toNativeSeparators(path)));
        QVERIFY(m_page->findChild<QLabel *>(QStringLiteral("monitorMessage"))->isVisible());
    }

    void exportPngWritesALoadableImage()
    {
        feed(*m_page, 0, 3, 3);
        const QString path = m_dir.filePath(QStringLiteral("plot.png"));
        QString error;
        QVERIFY2(m_page->exportPng(path, &error), qPrintable(error));
        const QImage image(path);
        QVERIFY(!image.isNull());
        QVERIFY(image.width() > 0 && image.height() > 0);
        // All three charts, stacked, at the file's own size, not the window's.
        QCOMPARE(image.size(), m_page->plot()->exportSize(3));

        QVERIFY(!m_page->exportPng(m_dir.filePath(QStringLiteral("missing/plot.png")), &error));
        QVERIFY(!error.isEmpty());
        m_page->setQuantities({});
        QVERIFY(!m_page->exportPng(path, &error));
        QVERIFY(error.contains(QStringLiteral("quantity")));
    }

    // Six quantities in the Monitor of a 1366x768 window: not six unreadable slivers, but one
    // pane at a time, chosen by a tab, with three labelled values at least; tall enough, all.
    void aShortPlotShowsOneQuantityAtATimeEachReadable()
    {
        m_page->resize(1000, 430);
        m_page->setQuantities(
            {std::begin(feetech::kAllQuantities), std::end(feetech::kAllQuantities)});
        feed(*m_page, 0, 3, 3);
        auto *tabs = m_page->findChild<QTabBar *>(QStringLiteral("monitorQuantityTabs"));
        QVERIFY(tabs);
        QTRY_VERIFY(tabs->isVisible());
        QCOMPARE(tabs->count(), feetech::kQuantityCount);
        TelemetryPlot *plot = m_page->plot();
        for (int tab = 0; tab < tabs->count(); ++tab) {
            tabs->setCurrentIndex(tab);
            QCOMPARE(plot->quantities().size(), 1);
            const auto quantity = feetech::Quantity(tabs->tabData(tab).toInt());
            QCOMPARE(plot->quantities().first(), quantity);
            plot->refresh();
            QVERIFY2(plot->valueLabels(quantity).size() >= 3,
                     qPrintable(QString::number(plot->valueLabels(quantity).size())));
        }
        // Given the room, every quantity its pane again.
        m_page->resize(1000, 1600);
        QTRY_VERIFY(!tabs->isVisible());
        QCOMPARE(plot->quantities().size(), feetech::kQuantityCount);
    }

    void monitoringTheSimulatedBusFillsReadoutsAndPlot()
    {
        startSimulatorAndScan();
        QListWidget *list = m_page->servoList();
        QCOMPARE(list->count(), 4);
        QCOMPARE(list->item(0)->text(), QStringLiteral("ID 1 · STS3215 · 1 Mbps"));
        QCOMPARE(list->item(3)->text(), QStringLiteral("ID 4 · SCS15 · 1 Mbps"));
        QCOMPARE(m_page->selectedServos(), (QVector<int> {0, 1, 2, 3})); // all ticked

        m_page->setRate(100);
        QString error;
        QVERIFY2(m_page->start(&error), qPrintable(error));
        QVERIFY(m_page->isRunning());
        QCOMPARE(m_client->telemetry()->options().rateHz, 100.0);
        for (quint8 id = 1; id <= 4; ++id) {
            QTRY_COMPARE_WITH_TIMEOUT(readout(id, MonitorReadouts::StateColumn),
                                      QStringLiteral("OK"), 10000);
            QTRY_VERIFY_WITH_TIMEOUT(m_page->plot()->bufferedPointCount(id, Quantity::Position) > 0,
                                     10000);
            QVERIFY(readout(id, MonitorReadouts::PositionColumn) != QStringLiteral("—"));
            QVERIFY(readout(id, MonitorReadouts::VoltageColumn) != QStringLiteral("—"));
        }
        QCOMPARE(readout(1, MonitorReadouts::StatusColumn), QStringLiteral("none"));
        QCOMPARE(readout(1, MonitorReadouts::MovingColumn), QStringLiteral("no"));
        // SCS current has no documented scale: not shown rather than made up.
        QCOMPARE(readout(4, MonitorReadouts::CurrentColumn), QStringLiteral("—"));
        QTRY_VERIFY_WITH_TIMEOUT(readout(1, MonitorReadouts::RateColumn).toInt() > 0, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(m_page->plot()->shownPointCount(1, Quantity::Position) > 0, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(m_page->findChild<QLabel *>(QStringLiteral("monitorStatus"))
                                     ->text()
                                     .contains(QStringLiteral("samples/s")),
                                 10000);
        QCOMPARE(m_page->plot()->seriesCount(), 4 * 3);

        // Unticking a servo restarts the stream without it.
        list->item(1)->setCheckState(Qt::Unchecked);
        QVERIFY(m_page->isRunning());
        QCOMPARE(m_client->telemetry()->options().servos.size(), 3);
        QVERIFY(!m_client->telemetry()->isStreamed(1));
        QCOMPARE(readoutRow(2), -1);
        QCOMPARE(m_page->plot()->seriesCount(), 3 * 3);
        QSignalSpy received(m_client->telemetry(), &feetech::TelemetryHub::samplesReceived);
        QTRY_VERIFY_WITH_TIMEOUT(received.count() >= 5, 10000);

        // Recorded while streaming, ended by Stop.
        const QString path = m_dir.filePath(QStringLiteral("live.csv"));
        util::FileError notRecording;
        QVERIFY2(m_page->recording()->startRecording(path, &notRecording),
                 qPrintable(notRecording.describe()));
        QTRY_VERIFY_WITH_TIMEOUT(m_page->recording()->recorder()->rowCount() >= 30, 10000);
        m_page->stop();
        QVERIFY(!m_page->isRunning());
        QVERIFY(!m_page->recording()->isRecording());
        const auto rows = testsupport::readTelemetryCsv(path, &error);
        QVERIFY2(rows, qPrintable(error));
        QVERIFY(rows->size() >= 30);
        QSet<int> ids;
        for (const feetech::CsvSample &row : *rows) {
            ids.insert(row.id);
            QVERIFY(row.timeSeconds >= 0.0);
            QVERIFY(row.values.at(int(Quantity::Position)).has_value());
        }
        QCOMPARE(ids, (QSet<int> {1, 3, 4}));
    }

    void anArmsServosAreNamedByTheirJoints()
    {
        // Six STS3215 at IDs 1-6 are an SO-101 arm: its template names each joint.
        QString error;
        const auto servos = testsupport::servosAt(
            k1M, {u"STS3215", u"STS3215", u"STS3215", u"STS3215", u"STS3215", u"STS3215"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 8));
        QCOMPARE(m_client->servos()->count(), 6);
        QListWidget *list = m_page->servoList();
        QCOMPARE(list->item(0)->text(), QStringLiteral("shoulder_pan (ID 1) · STS3215 · 1 Mbps"));
        QCOMPARE(list->item(5)->text(), QStringLiteral("gripper (ID 6) · STS3215 · 1 Mbps"));
        QVERIFY2(m_page->start(&error), qPrintable(error));
        QTableWidget *table = m_page->readouts();
        QTRY_COMPARE_WITH_TIMEOUT(table->rowCount(), 6, 10000);
        QStringList names;
        for (int row = 0; row < table->rowCount(); ++row)
            names.append(table->item(row, MonitorReadouts::ServoColumn)->text());
        QVERIFY2(names.contains(QStringLiteral("elbow_flex (ID 3)")), qPrintable(names.join(u',')));
    }

    // A re-scan (the Doctor's, Scan) takes the bus and the list: the Monitor says it pauses,
    // and goes on with the same servos once they are found again.
    void aScanPausesTheMonitorWhichStartsAgainWithTheServosFound()
    {
        startSimulatorAndScan();
        QString error;
        QVERIFY2(m_page->start(&error), qPrintable(error));
        QVERIFY(m_page->isRunning());
        auto *message = m_page->findChild<QLabel *>(QStringLiteral("monitorMessage"));
        QVERIFY(message);
        QSignalSpy scanned(m_client.get(), &feetech::BusClient::scanFinished);
        feetech::ScanOptions options;
        options.lastId = 10;
        QVERIFY(m_client->scan(options));
        QVERIFY(!m_page->isRunning());
        QVERIFY2(message->text().contains(QStringLiteral("paused while the bus is scanned")),
                 qPrintable(message->text()));
        QTRY_COMPARE_WITH_TIMEOUT(scanned.size(), 1, 30000);
        QTRY_VERIFY2_WITH_TIMEOUT(m_page->isRunning(), qPrintable(message->text()), 10000);
        QVERIFY2(message->text().contains(QStringLiteral("Monitoring again")),
                 qPrintable(message->text()));
    }

    void servoThatStopsAnsweringIsFlagged()
    {
        startSimulatorAndScan();
        m_page->setSelectedServos({0, 1, 2});
        QString error;
        QVERIFY2(m_page->start(&error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(readout(2, MonitorReadouts::StateColumn), QStringLiteral("OK"),
                                  10000);
        // Servo 2 goes silent: its ID moves away.
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(2)->setValue(u"id", 20);
        });
        QTRY_COMPARE_WITH_TIMEOUT(readout(2, MonitorReadouts::StateColumn),
                                  QStringLiteral("Not answering"), 10000);
        const int row = readoutRow(2);
        QCOMPARE(m_page->readouts()->item(row, MonitorReadouts::StateColumn)->foreground().color(),
                 QColor(0xc0, 0x1c, 0x1c));
        QVERIFY(readout(2, MonitorReadouts::MissedColumn).toInt() >= 3);
        // The others go on.
        QCOMPARE(readout(1, MonitorReadouts::StateColumn), QStringLiteral("OK"));
        const int before = m_page->plot()->bufferedPointCount(3, Quantity::Position);
        QTRY_VERIFY_WITH_TIMEOUT(
            m_page->plot()->bufferedPointCount(3, Quantity::Position) > before + 10, 10000);
    }

    void disconnectEndsTheRecording()
    {
        startSimulatorAndScan();
        QString error;
        QVERIFY2(m_page->start(&error), qPrintable(error));
        util::FileError notRecording;
        QVERIFY2(m_page->recording()->startRecording(m_dir.filePath(QStringLiteral("cut.csv")),
                                                     &notRecording),
                 qPrintable(notRecording.describe()));
        QTRY_VERIFY_WITH_TIMEOUT(m_page->recording()->recorder()->rowCount() > 0, 10000);
        QSignalSpy recording(m_page->recording(), &MonitorRecording::recordingChanged);
        m_client->disconnectFrom();
        QTRY_VERIFY_WITH_TIMEOUT(!m_page->recording()->isRecording(), 10000);
        QCOMPARE(recording.count(), 1);
        QTRY_VERIFY_WITH_TIMEOUT(!m_page->isRunning(), 10000);
        QString parseError;
        QVERIFY2(
            testsupport::readTelemetryCsv(m_dir.filePath(QStringLiteral("cut.csv")), &parseError),
            qPrintable(parseError));
    }

    void statusLineAsksForTheSizeASelectableLabelWould()
    {
        MonitorStatusLine line;
        QLabel label;
        label.setTextInteractionFlags(Qt::TextSelectableByMouse);
        for (const QString &text :
             {QStringLiteral("Stopped"),
              QStringLiteral("Streaming · 100 cycles/s · 600 samples/s · 0 missed · 0 late"),
              QStringLiteral("Streaming · 9 cycles/s · 54 samples/s · 1234 missed · 7 late"
                             " · plot paused (samples are still received)")}) {
            line.setText(text);
            label.setText(text);
            QCOMPARE(line.sizeHint(), label.sizeHint());
            QCOMPARE(line.minimumSizeHint(), label.minimumSizeHint());
        }
        QVERIFY(line.textInteractionFlags() & Qt::TextSelectableByMouse);
    }
};

QTEST_MAIN(TestMonitorPage)
#include "tst_monitorpage.moc"
