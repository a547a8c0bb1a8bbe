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
    m_buffer.setServos(servos);
    rebuildSeries();
}
QVector<TelemetryPlot::Servo> TelemetryPlot::servos() const
{
    return m_buffer.servos();
}
void TelemetryPlot::setWindowSeconds(double seconds)
{
    if (!(seconds > 0.0) || seconds == m_windowSeconds)
        return;
    m_windowSeconds = seconds;
    m_buffer.trimAll(retention());
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
    m_buffer.clear();
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
    if (m_buffer.add(samples, retention()))
        rebuildSeries();
    m_dirty = true;
}
void TelemetryPlot::refresh()
{
    if (!m_paused) {
        m_viewTo = std::max(m_buffer.newest(), m_windowSeconds);
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
    const int index = m_buffer.findTrace(id, baud);
    if (index < 0)
        return 0;
    return int(m_buffer.points(index, quantity).size());
}

int TelemetryPlot::shownPointCount(quint8 id, feetech::Quantity quantity, qint32 baud) const
{
    const int index = m_buffer.findTrace(id, baud);
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
    return m_buffer.pointCount();
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
    const int index = m_buffer.findTrace(id, baud);
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
        for (int i = 0; i < m_buffer.traceCount(); ++i)
            addSeries(*pane, i);
    }
    m_viewDirty = true;
    refresh();
}

void TelemetryPlot::addSeries(Pane &pane, int trace)
{
    auto *series = new QLineSeries(pane.chart);
    series->setName(seriesName(m_buffer.servo(trace)));
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
    for (int i = 0; i < m_buffer.traceCount(); ++i) {
        const Servo &other = m_buffer.servo(i);
        shared = shared || (other.id == servo.id && other.baud != servo.baud);
    }
    if (!shared)
        return tr("ID %1").arg(servo.id);
    return tr("ID %1 · %2").arg(servo.id).arg(feetech::baudText(servo.baud));
}

TelemetryBuffer::Retention TelemetryPlot::retention() const
{
    TelemetryBuffer::Retention retention;
    retention.cap = std::size_t(maxPointsPerSeries());
    retention.windowSeconds = m_windowSeconds;
    if (m_paused || m_zoomed)
        retention.holdFrom = m_viewFrom; // what is in view
    return retention;
}
void TelemetryPlot::repaintPane(Pane &pane, double from, double to)
{
    const int buckets = bucketsFor(pane);
    pane.buckets = buckets;
    double low = std::numeric_limits<double>::infinity();
    double high = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < pane.series.size() && i < m_buffer.traceCount(); ++i) {
        const QList<QPointF> points = TelemetryBuffer::pointsInView(
            m_buffer.points(i, pane.quantity), from, to, buckets, &low, &high);
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
    m_buffer.trimAll(retention()); // what was kept for the frozen view is no longer needed
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
