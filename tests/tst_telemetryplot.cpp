// Unit tests of the hand-painted telemetry plot: min/max decimation to pixel columns, repaints
// coalesced to one per frame, a paused plot that stays still, zoom and reset, and PNG export.
#include "feedbacksample.h"
#include "telemetrybuffer.h"
#include "telemetryplot.h"

#include <QImage>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QtTest>

#include <cmath>
#include <map>

using feetech::FeedbackSample;
using feetech::Quantity;

namespace {

// `count` batches of one sample per servo, 10 ms apart, from `startUs`; returns the time after.
qint64 feed(TelemetryPlot &plot, qint64 startUs, int count, int servos = 2)
{
    for (int i = 0; i < count; ++i) {
        QVector<FeedbackSample> batch;
        for (int id = 1; id <= servos; ++id)
            batch.append(testsupport::feedbackSample(quint8(id), startUs + i * 10000,
                                                     2048 + 500 * std::sin(i / 20.0)));
        plot.addSamples(batch);
    }
    return startUs + count * 10000;
}

} // namespace

class TestTelemetryPlot : public QObject
{
    Q_OBJECT

private:
    std::unique_ptr<TelemetryPlot> m_plot;
    QTemporaryDir m_dir;

    // Shown, laid out and with nothing left to paint.
    void settle()
    {
        QTRY_VERIFY(m_plot->paintCount() > 0);
        QTRY_VERIFY(!m_plot->isFramePending());
        QCoreApplication::processEvents();
        QCoreApplication::processEvents();
    }

private slots:
    void init()
    {
        m_plot = std::make_unique<TelemetryPlot>();
        m_plot->setQuantities({Quantity::Position, Quantity::Speed});
        m_plot->resize(800, 500);
        m_plot->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_plot.get()));
    }

    void cleanup() { m_plot.reset(); }

    void decimationKeepsEveryColumnsMinimumAndMaximumAndNoMoreThanTwoPointsAColumn()
    {
        TelemetryBuffer::Points points;
        for (int i = 0; i < 20000; ++i) {
            const double x = i * 0.0005;
            // A wave with a narrow spike every 997 points: the spikes must survive.
            points.emplace_back(x, std::sin(i / 37.0) * 100.0 + (i % 997 == 0 ? 900.0 : 0.0));
        }
        const double from = 1.23;
        const double to = 8.77;
        const int buckets = 300;
        double low = 1e9;
        double high = -1e9;
        const QList<QPointF> shown =
            TelemetryBuffer::pointsInView(points, from, to, buckets, &low, &high);
        QVERIFY(shown.size() <= 2 * buckets + 2); // plus one neighbour either side
        const double width = (to - from) / buckets;
        const auto column = [&](double x) {
            return std::clamp(int(std::floor(x / width) - std::floor(from / width)), 0,
                              buckets - 1);
        };
        std::map<int, std::pair<double, double>> expected; // column: lowest, highest
        for (const QPointF &point : points) {
            if (point.x() < from || point.x() > to)
                continue;
            auto [entry, added] = expected.try_emplace(column(point.x()), point.y(), point.y());
            entry->second.first = std::min(entry->second.first, point.y());
            entry->second.second = std::max(entry->second.second, point.y());
        }
        std::map<int, QList<double>> drawn;
        for (int i = 1; i + 1 < shown.size(); ++i) // without the two neighbours
            drawn[column(shown.at(i).x())].append(shown.at(i).y());
        QCOMPARE(drawn.size(), expected.size());
        for (const auto &[index, values] : drawn) {
            QVERIFY2(values.size() <= 2, qPrintable(QString::number(index)));
            const auto [lowest, highest] = expected.at(index);
            QVERIFY(values.contains(lowest));
            QVERIFY(values.contains(highest));
        }
        QVERIFY(high >= 900.0); // the spikes widen the range
        for (int i = 1; i < shown.size(); ++i)
            QVERIFY(shown.at(i - 1).x() <= shown.at(i).x()); // still in time order
    }

    void aShortPaneStillLabelsThreeValuesThatDoNotOverlap()
    {
        // An arm's joints far apart (890 to 3070 steps) in panes a few lines high, as the
        // Monitor has them in a short window: one label would say nothing of the scale.
        m_plot->setQuantities({Quantity::Position, Quantity::Speed, Quantity::Load});
        m_plot->resize(800, 270);
        for (int i = 0; i < 20; ++i) {
            m_plot->addSamples({testsupport::feedbackSample(1, 1000000 + i * 10000, 890),
                                testsupport::feedbackSample(2, 1000000 + i * 10000, 3070)});
        }
        settle();
        const QRect area = m_plot->plotArea(Quantity::Position);
        const int lineHeight = m_plot->fontMetrics().height();
        QVERIFY2(area.height() < 3 * lineHeight, qPrintable(QString::number(area.height())));
        const QVector<double> labels = m_plot->valueLabels(Quantity::Position);
        QVERIFY2(labels.size() >= 3, qPrintable(QString::number(labels.size())));
        const auto [from, to] = m_plot->valueRange(Quantity::Position);
        QVERIFY(from <= 890 && to >= 3070);
        const double pixelsApart = (labels.at(1) - labels.at(0)) / (to - from) * area.height();
        QVERIFY2(pixelsApart >= lineHeight, qPrintable(QString::number(pixelsApart)));
    }

    void aTallPaneKeepsAboutOneLabelPer35Pixels()
    {
        m_plot->setQuantities({Quantity::Position});
        m_plot->resize(800, 500);
        for (int i = 0; i < 20; ++i) {
            m_plot->addSamples({testsupport::feedbackSample(1, 1000000 + i * 10000, 890),
                                testsupport::feedbackSample(2, 1000000 + i * 10000, 3070)});
        }
        settle();
        const int height = m_plot->plotArea(Quantity::Position).height();
        const int labels = int(m_plot->valueLabels(Quantity::Position).size());
        QVERIFY2(labels >= 5 && labels <= height / 35 + 2,
                 qPrintable(QStringLiteral("%1 labels in %2 px").arg(labels).arg(height)));
    }

    void manySamplesWithinOneFrameGiveOnePaint()
    {
        feed(*m_plot, 1000000, 5);
        settle();
        const qint64 before = m_plot->paintCount();
        feed(*m_plot, 2000000, 1200); // twelve seconds of data, all before the next frame
        QVERIFY(m_plot->isFramePending());
        QCOMPARE(m_plot->paintCount(), before);
        QTRY_COMPARE(m_plot->paintCount(), before + 1);
        QVERIFY(!m_plot->isFramePending());
        QCoreApplication::processEvents();
        QCOMPARE(m_plot->paintCount(), before + 1);
        QCOMPARE(m_plot->viewTo(), 1.0 + 11.99); // the newest sample
    }

    void pausedPlotDoesNotRepaintForNewData()
    {
        qint64 now = feed(*m_plot, 1000000, 50);
        settle();
        QSignalSpy paused(m_plot.get(), &TelemetryPlot::pausedChanged);
        m_plot->setPaused(true);
        QCOMPARE(paused.count(), 1);
        const double viewTo = m_plot->viewTo();
        settle();
        const qint64 before = m_plot->paintCount();
        now = feed(*m_plot, now, 100);
        QVERIFY(!m_plot->isFramePending());
        QCoreApplication::processEvents();
        QCoreApplication::processEvents();
        QCOMPARE(m_plot->paintCount(), before);
        QCOMPARE(m_plot->viewTo(), viewTo);
        QCOMPARE(m_plot->bufferedPointCount(1, Quantity::Position), 150); // still buffered

        m_plot->setPaused(false);
        QCOMPARE(m_plot->viewTo(), m_plot->windowSeconds()); // 1.49 s of data: the window
        QTRY_VERIFY(m_plot->paintCount() > before);
    }

    void hiddenPlotDoesNotScheduleFrames()
    {
        settle();
        m_plot->hide();
        feed(*m_plot, 1000000, 20);
        QVERIFY(!m_plot->isFramePending());
        QCOMPARE(m_plot->bufferedPointCount(2, Quantity::Speed), 20);
    }

    void zoomFreezesTheViewAndResetFollowsTheNewestSampleAgain()
    {
        qint64 now = feed(*m_plot, 0, 1500); // 15 s
        m_plot->refresh();
        QSignalSpy zoomed(m_plot.get(), &TelemetryPlot::zoomedChanged);
        m_plot->setTimeRange(4.0, 6.0);
        QVERIFY(m_plot->isZoomed());
        QVERIFY(m_plot->isPaused());
        QCOMPARE(zoomed.count(), 1);
        feed(*m_plot, now, 100);
        m_plot->refresh();
        QCOMPARE(m_plot->viewFrom(), 4.0);
        QCOMPARE(m_plot->viewTo(), 6.0);
        // Only the points in view (and their neighbours) are drawn.
        QCOMPARE(m_plot->shownPointCount(1, Quantity::Position), 201 + 2);

        // Right-click zooms out to twice the span around the middle.
        const QRect area = m_plot->plotArea(Quantity::Speed);
        QVERIFY(area.width() > 100);
        QTest::mouseClick(m_plot.get(), Qt::RightButton, {}, area.center());
        const double middle = 4.0 + 2.0 * (area.center().x() - area.left()) / area.width();
        QVERIFY(qAbs(m_plot->viewFrom() - (middle - 2.0)) < 1e-9);
        QVERIFY(qAbs(m_plot->viewTo() - (middle + 2.0)) < 1e-9);

        // A wheel notch down zooms out around the pointer by as much as one up zooms in.
        const QPointF left(area.left(), area.center().y());
        QWheelEvent wheel(left, m_plot->mapToGlobal(left), {}, {0, -120}, Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(m_plot.get(), &wheel);
        QVERIFY(qAbs(m_plot->viewFrom() - (middle - 2.0)) < 1e-9); // the pointer's time stays
        QVERIFY(qAbs(m_plot->viewTo() - m_plot->viewFrom() - 4.0 / 0.8) < 1e-9);

        // A click without a drag is no zoom.
        const double from = m_plot->viewFrom();
        QTest::mouseClick(m_plot.get(), Qt::LeftButton, {}, area.center());
        QCOMPARE(m_plot->viewFrom(), from);

        m_plot->resetZoom();
        QVERIFY(!m_plot->isZoomed());
        QVERIFY(!m_plot->isPaused());
        QCOMPARE(zoomed.count(), 2);
        QCOMPARE(m_plot->viewTo(), 15.99);
        QCOMPARE(m_plot->viewFrom(), 15.99 - m_plot->windowSeconds());
    }

    void valueAxisFitsTheDataInViewWithRoundBounds()
    {
        m_plot->addSamples({testsupport::feedbackSample(1, 0, 1000.0),
                            testsupport::feedbackSample(1, 10000, 3000.0)});
        m_plot->refresh();
        const auto [low, high] = m_plot->valueRange(Quantity::Position);
        QVERIFY(low < 1000.0 && low > 800.0);
        QVERIFY(high > 3000.0 && high < 3200.0);
        QCOMPARE(m_plot->valueRange(Quantity::Load), std::make_pair(0.0, 0.0)); // not shown
        QVERIFY(m_plot->plotArea(Quantity::Load).isEmpty());
    }

    void exportPngWritesAnImageOfItsOwnSizeWithTheServosColours()
    {
        m_plot->resize(700, 420);
        feed(*m_plot, 0, 300, 2);
        const QString path = m_dir.filePath(QStringLiteral("plot.png"));
        QString error;
        QVERIFY2(m_plot->exportPng(path, &error), qPrintable(error));
        const QImage image(path);
        // Sized for the file, whatever the widget's size: a pane 300 px tall for each quantity.
        QCOMPARE(image.size(), m_plot->exportSize(int(m_plot->quantities().size())));
        QCOMPARE(image.width(), TelemetryPlot::kExportWidth);
        // Both traces are in it, in their servos' colours.
        for (const quint8 id : {quint8(1), quint8(2)}) {
            const QColor colour = m_plot->servoColor(id);
            bool found = false;
            for (int y = 0; y < image.height() && !found; ++y) {
                for (int x = 0; x < image.width() && !found; ++x)
                    found = image.pixelColor(x, y) == colour;
            }
            QVERIFY2(found, qPrintable(colour.name()));
        }
        QVERIFY(m_plot->servoColor(1) != m_plot->servoColor(2));

        QVERIFY(!m_plot->exportPng(m_dir.filePath(QStringLiteral("missing/plot.png")), &error));
        QVERIFY(error.contains(QStringLiteral("missing")));
        m_plot->setQuantities({});
        QVERIFY(!m_plot->exportPng(path, &error));
        QVERIFY(!error.isEmpty());
    }
};

QTEST_MAIN(TestTelemetryPlot)
#include "tst_telemetryplot.moc"
