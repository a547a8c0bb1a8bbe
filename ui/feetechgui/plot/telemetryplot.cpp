// The live telemetry plot's state and interaction: bounded buffers per series, the view that
// follows live data or stays where the user put it, and repaints coalesced to one per frame.
#include "telemetryplot.h"

#include <QDir>
#include <QElapsedTimer>
#include <QImageWriter>
#include <QMouseEvent>
#include <QPaintEvent>
#include <QPainter>
#include <QScreen>
#include <QTimer>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

// The narrowest time span a zoom may reach.
constexpr double kMinimumSpanSeconds = 0.01;
// A drag shorter than this many pixels is a click, not a zoom.
constexpr int kMinimumDragPixels = 4;

} // namespace

TelemetryPlot::TelemetryPlot(QWidget *parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("telemetryPlot"));
    // Every paint covers what it was asked to paint: no background first.
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMouseTracking(false);
    setToolTip(tr("Drag across a time span to zoom in, right-click to zoom out, or turn the "
                  "wheel; Reset zoom goes back to live data"));
    m_frameTimer = new QTimer(this);
    m_frameTimer->setSingleShot(true);
    m_frameTimer->setInterval(1000 / kMaxFramesPerSecond);
    connect(m_frameTimer, &QTimer::timeout, this, &TelemetryPlot::refresh);
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
    onServosChanged();
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
    m_frameTimer->stop(); // a frame already due would move the view on
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
        m_frameTimer->stop();
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
        onServosChanged();
    m_dirty = true;
    if (!m_paused)
        scheduleFrame();
}

void TelemetryPlot::setServoNames(const QHash<feetech::ServoAddress, QString> &names)
{
    m_servoNames = names;
    if (m_painter.setServoNames(names)) {
        m_layoutDirty = true; // the legends' width changes with the names
        refresh();
    }
}

void TelemetryPlot::refresh()
{
    if (!m_paused) {
        m_viewTo = std::max(m_buffer.newest(), m_windowSeconds);
        m_viewFrom = m_viewTo - m_windowSeconds;
    }
    if (m_layoutDirty)
        layoutPanes(); // another width decimates to another number of columns
    if (m_paused && !m_viewDirty)
        return; // frozen: new samples are buffered but not drawn
    if (!m_paused && !m_dirty && !m_viewDirty)
        return;
    QElapsedTimer clock;
    clock.start();
    prepareFrame();
    m_dirty = false;
    m_viewDirty = false;
    m_prepareNs += clock.nsecsElapsed();
    requestPaint();
}

void TelemetryPlot::layoutPanes()
{
    m_layoutDirty = false;
    m_viewDirty = true;
    m_painter.layoutPanes();
}

void TelemetryPlot::prepareFrame()
{
    m_painter.fitToView(m_viewFrom, m_viewTo);
}

void TelemetryPlot::requestPaint()
{
    if (m_painter.isChromeValid())
        update(m_painter.frameRegion());
    else
        update();
}

void TelemetryPlot::paintEvent(QPaintEvent *event)
{
    QElapsedTimer clock;
    clock.start();
    if (m_layoutDirty) {
        layoutPanes();
        prepareFrame();
    }
    QPainter painter(this);
    TelemetryPlotPainter::View view;
    view.from = m_viewFrom;
    view.to = m_viewTo;
    view.dragging = m_dragPane >= 0;
    view.dragFromX = m_dragFromX;
    view.dragToX = m_dragToX;
    m_painter.paint(painter, event->region(), view);
    ++m_paintCount;
    const qint64 nanoseconds = m_prepareNs + clock.nsecsElapsed();
    m_prepareNs = 0;
    emit framePainted(nanoseconds);
}

bool TelemetryPlot::isFramePending() const
{
    return m_frameTimer->isActive();
}

void TelemetryPlot::scheduleFrame()
{
    // However many batches come in one frame, they are drawn together at its end.
    if (isVisible() && !m_frameTimer->isActive())
        m_frameTimer->start();
}

bool TelemetryPlot::exportPng(const QString &path, QString *error,
                              const QVector<feetech::Quantity> &quantities)
{
    const auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    const QVector<feetech::Quantity> drawn = quantities.isEmpty() ? m_quantities : quantities;
    if (drawn.isEmpty())
        return fail(tr("There is nothing to export: choose at least one quantity to plot."));
    if (path.isEmpty())
        return fail(tr("No file name was given for the image."));
    m_viewDirty = true;
    refresh();
    // A surface of the file's size, never shown, painted as the plot paints itself.
    QWidget canvas;
    canvas.setAttribute(Qt::WA_DontShowOnScreen);
    canvas.setFont(font());
    canvas.setPalette(palette());
    canvas.resize(exportSize(int(drawn.size())));
    TelemetryPlotPainter painter(canvas, m_buffer);
    painter.setServoNames(m_servoNames);
    painter.setQuantities(drawn);
    painter.tracesChanged();
    painter.layoutPanes();
    painter.fitToView(m_viewFrom, m_viewTo);
    QImage image(canvas.size(), QImage::Format_ARGB32_Premultiplied);
    image.fill(palette().color(QPalette::Window));
    {
        QPainter onImage(&image);
        TelemetryPlotPainter::View view;
        view.from = m_viewFrom;
        view.to = m_viewTo;
        painter.paint(onImage, QRegion(canvas.rect()), view);
    }
    if (image.isNull())
        return fail(tr("The plot could not be drawn into an image (it has no size)."));
    QImageWriter writer(path, "png");
    if (!writer.write(image)) {
        return fail(tr("Could not save the plot to %1: %2.")
                        .arg(QDir::toNativeSeparators(path), writer.errorString()));
    }
    return true;
}

QSize TelemetryPlot::exportSize(int panes) const
{
    const QFontMetrics metrics(font());
    return {kExportWidth, kExportPaneHeight * std::max(1, panes) + 2 * metrics.height() + 30};
}

int TelemetryPlot::readablePanesIn(int height) const
{
    const QFontMetrics metrics(font());
    const int title = metrics.height() + 8;
    const int timeAxis = 2 * metrics.height() + 14;
    // Three labels a pane, each hanging half a line around its grid line, a line apart.
    const int pane = title + 5 * metrics.height() + 12;
    return std::max(1, (height - timeAxis) / pane);
}

QColor TelemetryPlot::servoColor(quint8 id, qint32 baud) const
{
    const int index = m_buffer.findTrace(id, baud);
    return index < 0 ? QColor() : TelemetryPlotPainter::traceColour(index);
}

QSize TelemetryPlot::sizeHint() const
{
    return {640, std::max(1, int(m_painter.panes().size())) * 2 * kMinimumPaneHeight};
}

int TelemetryPlot::seriesCount() const
{
    return int(m_painter.panes().size()) * m_buffer.traceCount();
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
    for (const TelemetryPlotPainter::Pane &pane : m_painter.panes()) {
        if (pane.quantity == quantity && index < pane.shown.size())
            return int(pane.shown.at(index).size());
    }
    return -1;
}

QList<QPointF> TelemetryPlot::shownPoints(quint8 id, feetech::Quantity quantity, qint32 baud) const
{
    const int index = m_buffer.findTrace(id, baud);
    for (const TelemetryPlotPainter::Pane &pane : m_painter.panes()) {
        if (pane.quantity == quantity && index >= 0 && index < pane.shown.size())
            return pane.shown.at(index);
    }
    return {};
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

QRect TelemetryPlot::plotArea(feetech::Quantity quantity) const
{
    for (const TelemetryPlotPainter::Pane &pane : m_painter.panes()) {
        if (pane.quantity == quantity)
            return pane.area;
    }
    return {};
}

std::pair<double, double> TelemetryPlot::valueRange(feetech::Quantity quantity) const
{
    for (const TelemetryPlotPainter::Pane &pane : m_painter.panes()) {
        if (pane.quantity == quantity)
            return {pane.values.from, pane.values.to};
    }
    return {0.0, 0.0};
}

QVector<double> TelemetryPlot::valueLabels(feetech::Quantity quantity) const
{
    for (const TelemetryPlotPainter::Pane &pane : m_painter.panes()) {
        if (pane.quantity == quantity)
            return TelemetryPlotPainter::labelledValues(pane.values);
    }
    return {};
}

void TelemetryPlot::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    // One frame per screen refresh at most, and kMaxFramesPerSecond.
    const QScreen *screen = this->screen();
    double hz = kMaxFramesPerSecond;
    if (screen && screen->refreshRate() >= 1.0)
        hz = std::min(hz, screen->refreshRate());
    m_frameTimer->setInterval(int(std::lround(1000.0 / hz)));
    m_viewDirty = true;
    m_layoutDirty = true;
    refresh(); // what came while hidden
}

void TelemetryPlot::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    m_frameTimer->stop(); // nothing to draw for; samples are still buffered
}

void TelemetryPlot::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    m_layoutDirty = true; // the number of pixels, and so the decimation, changed
    m_viewDirty = true;
    refresh();
}

void TelemetryPlot::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange
        || event->type() == QEvent::StyleChange) {
        m_painter.forgetLabels();
        m_layoutDirty = true;
        m_viewDirty = true;
        m_painter.invalidateChrome();
        refresh();
    }
}

void TelemetryPlot::mousePressEvent(QMouseEvent *event)
{
    const int index = paneAt(event->position().toPoint());
    if (index < 0) {
        QWidget::mousePressEvent(event);
        return;
    }
    const TelemetryPlotPainter::Pane &pane = m_painter.panes().at(std::size_t(index));
    if (event->button() == Qt::LeftButton) {
        m_dragPane = index;
        m_dragFromX = m_dragToX = event->position().toPoint().x();
        event->accept();
    } else if (event->button() == Qt::RightButton) {
        // Zooms out to twice the span around the middle of the view.
        const double centre = timeAt(pane, pane.area.center().x());
        const double span = m_viewTo - m_viewFrom;
        setTimeRange(centre - span, centre + span);
        event->accept();
    }
}

void TelemetryPlot::mouseMoveEvent(QMouseEvent *event)
{
    if (m_dragPane < 0) {
        QWidget::mouseMoveEvent(event);
        return;
    }
    const QRect &area = m_painter.panes().at(std::size_t(m_dragPane)).area;
    m_dragToX = std::clamp(event->position().toPoint().x(), area.left(), area.right());
    requestPaint();
}

void TelemetryPlot::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_dragPane < 0 || event->button() != Qt::LeftButton) {
        QWidget::mouseReleaseEvent(event);
        return;
    }
    const TelemetryPlotPainter::Pane &pane = m_painter.panes().at(std::size_t(m_dragPane));
    m_dragToX = std::clamp(event->position().toPoint().x(), pane.area.left(), pane.area.right());
    const int left = std::min(m_dragFromX, m_dragToX);
    const int right = std::max(m_dragFromX, m_dragToX);
    const double from = timeAt(pane, left);
    const double to = timeAt(pane, right);
    m_dragPane = -1;
    if (right - left >= kMinimumDragPixels)
        setTimeRange(from, to);
    requestPaint();
}

void TelemetryPlot::wheelEvent(QWheelEvent *event)
{
    const int index = paneAt(event->position().toPoint());
    const int delta = event->angleDelta().y();
    if (index < 0 || delta == 0) {
        QWidget::wheelEvent(event);
        return;
    }
    const QRect &area = m_painter.panes().at(std::size_t(index)).area;
    // One notch (120) zooms in to 80 %; turning back zooms out by as much.
    zoomAround((event->position().x() - area.left()) / std::max(1, area.width()),
               std::pow(0.8, delta / 120.0));
    event->accept();
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

void TelemetryPlot::rebuildPanes()
{
    m_painter.setQuantities(m_quantities);
    setMinimumHeight(std::min(int(m_painter.panes().size()), kPanesInLeastHeight)
                     * kMinimumPaneHeight);
    updateGeometry();
    m_layoutDirty = true;
    onServosChanged();
}

void TelemetryPlot::onServosChanged()
{
    m_painter.tracesChanged();
    m_viewDirty = true;
    refresh();
}

int TelemetryPlot::paneAt(const QPoint &position) const
{
    for (std::size_t i = 0; i < m_painter.panes().size(); ++i) {
        if (m_painter.panes()[i].area.contains(position))
            return int(i);
    }
    return -1;
}

double TelemetryPlot::timeAt(const TelemetryPlotPainter::Pane &pane, double x) const
{
    const double fraction = (x - pane.area.left()) / std::max(1, pane.area.width());
    return m_viewFrom + fraction * (m_viewTo - m_viewFrom);
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
