// The live telemetry plot: bounded buffers per series, min/max decimation to the pixels in view,
// and a repaint timer, so that six servos at 100 Hz cost a few replace() calls a frame.
#include "feetechgui/telemetryplot.h"

#include <QChart>
#include <QChartView>
#include <QDir>
#include <QImageWriter>
#include <QLegend>
#include <QLineSeries>
#include <QPen>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace {

// Seconds kept beyond the window, so a view that has just moved on still has its left edge.
constexpr double kRetentionSlackSeconds = 1.0;
// At most this many points per horizontal pixel: a minimum and a maximum per column.
constexpr int kPointsPerPixel = 2;
// The narrowest time span a zoom may reach.
constexpr double kMinimumSpanSeconds = 0.01;
// Of the data's span, above and below it, so a trace never touches the chart's frame.
constexpr double kValueMargin = 0.05;
constexpr int kMinimumChartHeight = 110;

// Distinct on white and for the common colour-vision deficiencies, in the order servos come.
const QColor kServoColours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28),
                                QColor(0x2c, 0xa0, 0x2c), QColor(0xff, 0x7f, 0x0e),
                                QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf),
                                QColor(0x7f, 0x7f, 0x7f), QColor(0xbc, 0xbd, 0x22)};
constexpr int kColourCount = int(sizeof(kServoColours) / sizeof(kServoColours[0]));

// The smallest of 1, 2 and 5 times a power of ten that is at least `raw`.
double niceStep(double raw)
{
    if (!(raw > 0.0) || !std::isfinite(raw))
        return 1.0;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double factor : {1.0, 2.0, 5.0, 10.0}) {
        if (factor * power >= raw * (1.0 - 1e-9))
            return factor * power;
    }
    return 10.0 * power;
}

// Takes the mouse wheel for zooming the time axis; the rest is QChartView's (rubber band).
class PlotChartView : public QChartView
{
public:
    // `fraction`: where the pointer is across the plot area (0 left, 1 right).
    using WheelZoom = std::function<void(double fraction, double factor)>;

    PlotChartView(QChart *chart, QWidget *parent, WheelZoom zoom)
        : QChartView(chart, parent)
        , m_zoom(std::move(zoom))
    { }

protected:
    void wheelEvent(QWheelEvent *event) override
    {
        const QPointF position = chart()->mapFromScene(mapToScene(event->position().toPoint()));
        const QRectF area = chart()->plotArea();
        const int delta = event->angleDelta().y();
        if (!area.contains(position) || area.width() <= 0.0 || delta == 0) {
            QChartView::wheelEvent(event);
            return;
        }
        // One notch (120) zooms in to 80 %; turning back zooms out by as much.
        m_zoom((position.x() - area.left()) / area.width(), std::pow(0.8, delta / 120.0));
        event->accept();
    }

private:
    WheelZoom m_zoom;
};

// The points of `points` between `from` and `to`, with one neighbour either side so the line
// reaches the chart's edges; beyond `buckets` × 2 points, the lowest and highest of each bucket
// (in time order), so short peaks survive. `low`/`high` widen to the values in view.
QList<QPointF> pointsInView(const std::deque<QPointF> &points, double from, double to, int buckets,
                            double *low, double *high)
{
    QList<QPointF> out;
    if (points.empty())
        return out;
    const auto byTime = [](const QPointF &point, double x) {
        return point.x() < x;
    };
    const auto first = std::lower_bound(points.begin(), points.end(), from, byTime);
    const auto last =
        std::upper_bound(points.begin(), points.end(), to,
                         [](double x, const QPointF &point) { return x < point.x(); });
    const auto count = std::distance(first, last);
    out.reserve(int(std::min<qint64>(count, qint64(buckets) * kPointsPerPixel)) + 2);
    if (first != points.begin())
        out.append(*std::prev(first));
    const auto widen = [low, high](const QPointF &point) {
        *low = std::min(*low, point.y());
        *high = std::max(*high, point.y());
    };
    if (count <= qint64(buckets) * kPointsPerPixel) {
        for (auto it = first; it != last; ++it) {
            out.append(*it);
            widen(*it);
        }
    } else {
        const double width = (to - from) / buckets;
        int bucket = -1;
        QPointF lowest;
        QPointF highest;
        const auto flush = [&] {
            if (bucket < 0)
                return;
            if (lowest == highest) {
                out.append(lowest);
            } else if (lowest.x() <= highest.x()) {
                out.append(lowest);
                out.append(highest);
            } else {
                out.append(highest);
                out.append(lowest);
            }
            widen(lowest);
            widen(highest);
        };
        for (auto it = first; it != last; ++it) {
            const int index = std::clamp(int((it->x() - from) / width), 0, buckets - 1);
            if (index != bucket) {
                flush();
                bucket = index;
                lowest = highest = *it;
            } else if (it->y() < lowest.y()) {
                lowest = *it;
            } else if (it->y() > highest.y()) {
                highest = *it;
            }
        }
        flush();
    }
    if (last != points.end())
        out.append(*last);
    return out;
}

} // namespace

TelemetryPlot::TelemetryPlot(QWidget *parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("telemetryPlot"));
    m_layout = new QVBoxLayout(this);
    m_layout->setContentsMargins(0, 0, 0, 0);
    m_layout->setSpacing(0);
    m_repaintTimer = new QTimer(this);
    m_repaintTimer->setInterval(1000 / kFramesPerSecond);
    connect(m_repaintTimer, &QTimer::timeout, this, &TelemetryPlot::refresh);
    m_viewTo = m_windowSeconds;
}

TelemetryPlot::~TelemetryPlot() = default;

void TelemetryPlot::setQuantities(const QVector<feetech::Quantity> &quantities)
{
    if (quantities == m_quantities)
        return;
    m_quantities = quantities;
    rebuildPanes();
}

void TelemetryPlot::setServos(const QVector<Servo> &servos)
{
    std::vector<Trace> traces;
    traces.reserve(std::size_t(servos.size()));
    for (const Servo &servo : servos) {
        const int index = traceIndex(servo.id, servo.baud);
        if (index >= 0) {
            traces.push_back(std::move(m_traces.at(std::size_t(index))));
        } else {
            Trace trace;
            trace.servo = servo;
            traces.push_back(std::move(trace));
        }
    }
    m_traces = std::move(traces);
    rebuildSeries();
}

QVector<TelemetryPlot::Servo> TelemetryPlot::servos() const
{
    QVector<Servo> servos;
    for (const Trace &trace : m_traces)
        servos.append(trace.servo);
    return servos;
}

void TelemetryPlot::setWindowSeconds(double seconds)
{
    if (!(seconds > 0.0) || seconds == m_windowSeconds)
        return;
    m_windowSeconds = seconds;
    trimAll();
    m_viewDirty = true;
    if (!m_paused)
        refresh();
}

void TelemetryPlot::setPaused(bool paused)
{
    if (!paused) {
        setFollowing();
        return;
    }
    if (m_paused)
        return;
    m_paused = true;
    emit pausedChanged(true);
}

void TelemetryPlot::resetZoom()
{
    setFollowing();
}

void TelemetryPlot::setTimeRange(double from, double to)
{
    if (!std::isfinite(from) || !std::isfinite(to))
        return;
    if (to - from < kMinimumSpanSeconds) {
        const double centre = (from + to) / 2.0;
        from = centre - kMinimumSpanSeconds / 2.0;
        to = centre + kMinimumSpanSeconds / 2.0;
    }
    m_viewFrom = from;
    m_viewTo = to;
    if (!m_paused) {
        m_paused = true;
        emit pausedChanged(true);
    }
    setZoomed(true);
    m_viewDirty = true;
    refresh();
}

void TelemetryPlot::clear()
{
    for (Trace &trace : m_traces) {
        for (auto &points : trace.points)
            points.clear();
    }
    m_hasOrigin = false;
    m_originUs = 0;
    m_newest = 0.0;
    m_dirty = true;
    m_viewDirty = true;
    if (m_paused || m_zoomed)
        setFollowing();
    else
        refresh();
}

void TelemetryPlot::addSamples(const QVector<feetech::FeedbackSample> &samples)
{
    if (samples.isEmpty())
        return;
    const std::size_t tracesBefore = m_traces.size();
    for (const feetech::FeedbackSample &sample : samples) {
        if (!m_hasOrigin) {
            m_hasOrigin = true;
            m_originUs = sample.steadyUs;
        }
        const double seconds = double(sample.steadyUs - m_originUs) / 1e6;
        m_newest = std::max(m_newest, seconds);
        Trace &trace = traceFor(sample.id, sample.baud);
        for (int q = 0; q < feetech::kQuantityCount; ++q) {
            const std::optional<double> &value = sample.values.at(std::size_t(q));
            if (!value)
                continue;
            std::deque<QPointF> &points = trace.points.at(std::size_t(q));
            // Batches from one stream come in time order; an out-of-order sample would break
            // the binary search over the buffer, so it is placed where it belongs.
            if (points.empty() || points.back().x() <= seconds) {
                points.emplace_back(seconds, *value);
            } else {
                const auto at =
                    std::upper_bound(points.begin(), points.end(), seconds,
                                     [](double x, const QPointF &point) { return x < point.x(); });
                points.insert(at, QPointF(seconds, *value));
            }
            trim(points); // bounded even within one large batch
        }
    }
    if (m_traces.size() != tracesBefore)
        rebuildSeries();
    m_dirty = true;
}

void TelemetryPlot::refresh()
{
    if (!m_paused) {
        m_viewTo = std::max(m_newest, m_windowSeconds);
        m_viewFrom = m_viewTo - m_windowSeconds;
    }
    // A chart laid out anew (added, resized) has another number of pixels to decimate to.
    for (const auto &pane : m_panes)
        m_viewDirty = m_viewDirty || bucketsFor(*pane) != pane->buckets;
    if (m_paused && !m_viewDirty)
        return; // frozen: new samples are buffered but not drawn
    if (!m_paused && !m_dirty && !m_viewDirty)
        return;
    for (auto &pane : m_panes)
        repaintPane(*pane, m_viewFrom, m_viewTo);
    m_dirty = false;
    m_viewDirty = false;
    alignPlotAreas();
}

bool TelemetryPlot::exportPng(const QString &path, QString *error)
{
    const auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (m_panes.empty())
        return fail(tr("There is nothing to export: choose at least one quantity to plot."));
    if (path.isEmpty())
        return fail(tr("No file name was given for the image."));
    if (QLayout *layout = this->layout())
        layout->activate();
    m_viewDirty = true;
    refresh();
    const QImage image = grab().toImage();
    if (image.isNull() || image.width() <= 0 || image.height() <= 0)
        return fail(tr("The plot could not be drawn into an image (it has no size)."));
    QImageWriter writer(path, "png");
    if (!writer.write(image)) {
        return fail(tr("Could not save the plot to %1: %2.")
                        .arg(QDir::toNativeSeparators(path), writer.errorString()));
    }
    return true;
}

int TelemetryPlot::seriesCount() const
{
    int count = 0;
    for (const auto &pane : m_panes)
        count += int(pane->series.size());
    return count;
}

int TelemetryPlot::bufferedPointCount(quint8 id, feetech::Quantity quantity, qint32 baud) const
{
    const int index = findTrace(id, baud);
    if (index < 0)
        return 0;
    return int(m_traces.at(std::size_t(index)).points.at(std::size_t(quantity)).size());
}

int TelemetryPlot::shownPointCount(quint8 id, feetech::Quantity quantity, qint32 baud) const
{
    const int index = findTrace(id, baud);
    if (index < 0)
        return -1;
    for (const auto &pane : m_panes) {
        if (pane->quantity == quantity && index < pane->shown.size())
            return pane->shown.at(index);
    }
    return -1;
}

qint64 TelemetryPlot::bufferedPoints() const
{
    qint64 total = 0;
    for (const Trace &trace : m_traces) {
        for (const auto &points : trace.points)
            total += qint64(points.size());
    }
    return total;
}

int TelemetryPlot::maxPointsPerSeries() const
{
    const double forWindow = std::ceil(m_windowSeconds * kMaxRateHz);
    return int(std::min<double>(kHardPointCap, std::max(1.0, forWindow)));
}

QChartView *TelemetryPlot::chartView(feetech::Quantity quantity) const
{
    for (const auto &pane : m_panes) {
        if (pane->quantity == quantity)
            return pane->view;
    }
    return nullptr;
}

QColor TelemetryPlot::servoColor(quint8 id, qint32 baud) const
{
    const int index = findTrace(id, baud);
    return index < 0 ? QColor() : kServoColours[index % kColourCount];
}

void TelemetryPlot::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    m_viewDirty = true;
    m_repaintTimer->start();
}

void TelemetryPlot::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    m_repaintTimer->stop(); // nothing to draw for; samples are still buffered
}

void TelemetryPlot::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    m_viewDirty = true; // the number of pixels, and so the decimation, changed
}

int TelemetryPlot::traceIndex(quint8 id, qint32 baud) const
{
    for (std::size_t i = 0; i < m_traces.size(); ++i) {
        if (m_traces[i].servo.id == id && m_traces[i].servo.baud == baud)
            return int(i);
    }
    return -1;
}

int TelemetryPlot::findTrace(quint8 id, qint32 baud) const
{
    if (baud != 0)
        return traceIndex(id, baud);
    for (std::size_t i = 0; i < m_traces.size(); ++i) {
        if (m_traces[i].servo.id == id)
            return int(i);
    }
    return -1;
}

TelemetryPlot::Trace &TelemetryPlot::traceFor(quint8 id, qint32 baud)
{
    const int index = traceIndex(id, baud);
    if (index >= 0)
        return m_traces.at(std::size_t(index));
    Trace trace;
    trace.servo = {id, baud};
    m_traces.push_back(std::move(trace));
    return m_traces.back();
}

void TelemetryPlot::rebuildPanes()
{
    for (auto &pane : m_panes)
        delete pane->view; // owns its chart, which owns the axes and series
    m_panes.clear();
    for (const feetech::Quantity quantity : std::as_const(m_quantities)) {
        auto pane = std::make_unique<Pane>();
        pane->quantity = quantity;
        pane->chart = new QChart;
        pane->chart->setTitle(
            tr("%1 (%2)").arg(feetech::quantityName(quantity), feetech::quantityUnit(quantity)));
        QFont titleFont = pane->chart->titleFont();
        titleFont.setBold(true);
        pane->chart->setTitleFont(titleFont);
        pane->chart->setBackgroundRoundness(0);
        pane->chart->setMargins(QMargins(4, 2, 4, 2));
        pane->chart->legend()->setVisible(true);
        pane->chart->legend()->setAlignment(Qt::AlignRight);
        pane->chart->setAnimationOptions(QChart::NoAnimation);

        pane->timeAxis = new QValueAxis(pane->chart);
        pane->timeAxis->setLabelFormat(QStringLiteral("%g"));
        pane->timeAxis->setTickType(QValueAxis::TicksDynamic);
        pane->timeAxis->setTickAnchor(0.0);
        pane->chart->addAxis(pane->timeAxis, Qt::AlignBottom);
        pane->valueAxis = new QValueAxis(pane->chart);
        pane->valueAxis->setLabelFormat(QStringLiteral("%g"));
        pane->valueAxis->setTickType(QValueAxis::TicksDynamic);
        pane->valueAxis->setTickAnchor(0.0);
        pane->chart->addAxis(pane->valueAxis, Qt::AlignLeft);
        connect(pane->timeAxis, &QValueAxis::rangeChanged, this, &TelemetryPlot::onTimeAxisChanged);

        pane->view = new PlotChartView(pane->chart, this, [this](double fraction, double factor) {
            zoomAround(fraction, factor);
        });
        pane->view->setObjectName(QStringLiteral("chart_%1").arg(feetech::quantityKey(quantity)));
        pane->view->setRenderHint(QPainter::Antialiasing);
        pane->view->setRubberBand(QChartView::HorizontalRubberBand);
        pane->view->setMinimumHeight(kMinimumChartHeight);
        pane->view->setToolTip(
            tr("Drag across a time span to zoom in, right-click to zoom out, or turn the wheel; "
               "Reset zoom goes back to live data"));
        m_layout->addWidget(pane->view, 1);
        m_panes.push_back(std::move(pane));
    }
    // The time axis is shared: only the lowest chart names it.
    if (!m_panes.empty())
        m_panes.back()->timeAxis->setTitleText(tr("Time (s)"));
    rebuildSeries();
}

void TelemetryPlot::rebuildSeries()
{
    for (auto &pane : m_panes) {
        pane->chart->removeAllSeries(); // deletes them
        pane->series.clear();
        pane->shown.clear();
        for (int i = 0; i < int(m_traces.size()); ++i)
            addSeries(*pane, i);
    }
    m_viewDirty = true;
    refresh();
}

void TelemetryPlot::addSeries(Pane &pane, int trace)
{
    auto *series = new QLineSeries(pane.chart);
    series->setName(seriesName(m_traces.at(std::size_t(trace)).servo));
    QPen pen(kServoColours[trace % kColourCount]);
    pen.setWidthF(1.5);
    series->setPen(pen);
    pane.chart->addSeries(series);
    series->attachAxis(pane.timeAxis);
    series->attachAxis(pane.valueAxis);
    pane.series.append(series);
    pane.shown.append(0);
}

QString TelemetryPlot::seriesName(const Servo &servo) const
{
    // Servos on different baud rates may share an ID: only then does the name say the rate.
    bool shared = false;
    for (const Trace &trace : m_traces)
        shared = shared || (trace.servo.id == servo.id && trace.servo.baud != servo.baud);
    if (!shared)
        return tr("ID %1").arg(servo.id);
    return tr("ID %1 · %2").arg(servo.id).arg(feetech::baudText(servo.baud));
}

void TelemetryPlot::trim(std::deque<QPointF> &points) const
{
    const std::size_t cap = std::size_t(maxPointsPerSeries());
    while (points.size() > cap)
        points.pop_front();
    double keepFrom = m_newest - m_windowSeconds - kRetentionSlackSeconds;
    if (m_paused || m_zoomed)
        keepFrom = std::min(keepFrom, m_viewFrom - kRetentionSlackSeconds); // what is in view
    while (!points.empty() && points.front().x() < keepFrom)
        points.pop_front();
}

void TelemetryPlot::trimAll()
{
    for (Trace &trace : m_traces) {
        for (auto &points : trace.points)
            trim(points);
    }
}

void TelemetryPlot::repaintPane(Pane &pane, double from, double to)
{
    const int buckets = bucketsFor(pane);
    pane.buckets = buckets;
    double low = std::numeric_limits<double>::infinity();
    double high = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < pane.series.size() && i < int(m_traces.size()); ++i) {
        const QList<QPointF> points =
            pointsInView(m_traces.at(std::size_t(i)).points.at(std::size_t(pane.quantity)), from,
                         to, buckets, &low, &high);
        pane.series.at(i)->replace(points);
        pane.shown[i] = int(points.size());
    }
    // About one time label per 90 pixels, one value label per 35.
    setAxisRange(pane.timeAxis, from, to, std::clamp(buckets / 90, 2, 12), false);
    const int valueIntervals = std::clamp(int(pane.chart->plotArea().height() / 35.0), 2, 8);
    if (low <= high) {
        const double span = high - low;
        const double margin =
            span > 0.0 ? span * kValueMargin : std::max(1.0, std::abs(low) * kValueMargin);
        setAxisRange(pane.valueAxis, low - margin, high + margin, valueIntervals, true);
    } else if (pane.valueAxis->min() >= pane.valueAxis->max()) {
        setAxisRange(pane.valueAxis, 0.0, 1.0, valueIntervals, true);
    }
}

int TelemetryPlot::bucketsFor(const Pane &pane) const
{
    // One per pixel column of the plot area (the view's width before the chart is laid out).
    const double width = pane.chart->plotArea().width();
    return std::max(16, int(width > 1.0 ? width : pane.view->width()));
}

void TelemetryPlot::setAxisRange(QValueAxis *axis, double from, double to, int intervals,
                                 bool roundBounds)
{
    const double span = to - from;
    if (!(span > 0.0))
        return;
    // Labels 1, 2 or 5 × 10^n apart. Value bounds snap to a quarter of that, so the scale
    // stays put while the data wanders a little, without wasting much of the chart's height.
    const double step = niceStep(span / std::max(1, intervals));
    if (roundBounds) {
        const double quantum = step / 4.0;
        from = std::floor(from / quantum) * quantum;
        to = std::ceil(to / quantum) * quantum;
    }
    m_settingAxes = true;
    if (axis->tickInterval() != step)
        axis->setTickInterval(step);
    if (axis->min() != from || axis->max() != to)
        axis->setRange(from, to);
    m_settingAxes = false;
}

void TelemetryPlot::alignPlotAreas()
{
    // Value labels differ in width from chart to chart; without this the stacked plot areas,
    // and so their time axes, would not line up.
    if (m_panes.size() < 2)
        return;
    double left = 0.0;
    double right = 0.0;
    for (const auto &pane : m_panes) {
        const QRectF area = pane->chart->plotArea();
        left = std::max(left, area.left() - pane->extraLeft);
        right = std::max(right, pane->chart->size().width() - area.right() - pane->extraRight);
    }
    for (auto &pane : m_panes) {
        const QRectF area = pane->chart->plotArea();
        const double naturalLeft = area.left() - pane->extraLeft;
        const double naturalRight = pane->chart->size().width() - area.right() - pane->extraRight;
        const double extraLeft = std::round(left - naturalLeft);
        const double extraRight = std::round(right - naturalRight);
        if (extraLeft == pane->extraLeft && extraRight == pane->extraRight)
            continue;
        pane->extraLeft = extraLeft;
        pane->extraRight = extraRight;
        QMargins margins = pane->chart->margins();
        margins.setLeft(4 + int(extraLeft));
        margins.setRight(4 + int(extraRight));
        pane->chart->setMargins(margins);
    }
}

void TelemetryPlot::onTimeAxisChanged(double from, double to)
{
    if (m_settingAxes)
        return;
    // The user zoomed with the rubber band or zoomed out with the right button. The chart is
    // still in the middle of zooming (its value axis comes next): repaint once it is done.
    m_viewFrom = from;
    m_viewTo = std::max(to, from + kMinimumSpanSeconds);
    if (!m_paused) {
        m_paused = true;
        emit pausedChanged(true);
    }
    setZoomed(true);
    m_viewDirty = true;
    QMetaObject::invokeMethod(this, &TelemetryPlot::refresh, Qt::QueuedConnection);
}

void TelemetryPlot::zoomAround(double fraction, double factor)
{
    const double span = m_viewTo - m_viewFrom;
    const double centre = m_viewFrom + fraction * span;
    const double newSpan = std::max(kMinimumSpanSeconds, span * factor);
    setTimeRange(centre - fraction * newSpan, centre - fraction * newSpan + newSpan);
}

void TelemetryPlot::setFollowing()
{
    const bool wasPaused = m_paused;
    m_paused = false;
    setZoomed(false);
    trimAll(); // what was kept for the frozen view is no longer needed
    m_viewDirty = true;
    refresh();
    if (wasPaused)
        emit pausedChanged(false);
}

void TelemetryPlot::setZoomed(bool zoomed)
{
    if (zoomed == m_zoomed)
        return;
    m_zoomed = zoomed;
    emit zoomedChanged(zoomed);
}
