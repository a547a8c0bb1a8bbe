// The telemetry plot's drawing: pane layout, axis ticks, the chrome painted only when it changes
// (frames, titles, legends, value labels) and, each frame, the plot areas with grids and traces.
#include "telemetryplotpainter.h"

#include <QElapsedTimer>
#include <QFontMetrics>
#include <QPaintEvent>
#include <QPainter>
#include <QWidget>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

// Distinct on white and for the common colour-vision deficiencies, in the order servos come.
const QColor kServoColours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28),
                                QColor(0x2c, 0xa0, 0x2c), QColor(0xff, 0x7f, 0x0e),
                                QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf),
                                QColor(0x7f, 0x7f, 0x7f), QColor(0xbc, 0xbd, 0x22)};
constexpr int kColourCount = int(sizeof(kServoColours) / sizeof(kServoColours[0]));

// Of the data's span, above and below it, so a trace never touches the pane's frame.
constexpr double kValueMargin = 0.05;
constexpr int kOuterMargin = 4;
constexpr int kPaneSpacing = 6;
constexpr int kRightMargin = 18; // room for half of the last time label
constexpr int kLabelGap = 6; // between a value label and the plot area
constexpr int kMaxTicks = 40;
constexpr int kLeastLabels = 3;
constexpr int kMaxStepChanges = 4;
constexpr int kLabelCacheSize = 512;

// Grid lines: a faint shade of the text colour over the plot's background, made opaque.
QColor gridColour(const QPalette &palette)
{
    const QColor base = palette.color(QPalette::Base);
    const QColor text = palette.color(QPalette::Text);
    constexpr double kShade = 0.14;
    return QColor::fromRgbF(float(base.redF() + (text.redF() - base.redF()) * kShade),
                            float(base.greenF() + (text.greenF() - base.greenF()) * kShade),
                            float(base.blueF() + (text.blueF() - base.blueF()) * kShade));
}

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

// A tick's label: the multiple of `step` nearest to `value`, without rounding noise.
QString tickText(double value, double step)
{
    double rounded = std::round(value / step) * step;
    if (std::abs(rounded) < step * 1e-6)
        rounded = 0.0; // never "-0"
    return QString::number(rounded, 'g', 10);
}

// The ticks of [from, to]: `from` itself and then the multiples of `step` up to `to`.
template<typename Visit>
void forEachTick(double from, double to, double step, Visit visit)
{
    if (!(step > 0.0) || !(to > from))
        return;
    const double first = std::ceil(from / step - 1e-9) * step;
    for (int i = 0; i < kMaxTicks; ++i) {
        const double value = first + i * step;
        if (value > to + step * 1e-9)
            break;
        visit(value);
    }
}

} // namespace

TelemetryPlotPainter::TelemetryPlotPainter(const QWidget &surface, const TelemetryBuffer &buffer)
    : m_surface(surface)
    , m_buffer(buffer)
{ }

void TelemetryPlotPainter::setQuantities(const QVector<feetech::Quantity> &quantities)
{
    m_panes.clear();
    for (const feetech::Quantity quantity : quantities) {
        Pane pane;
        pane.quantity = quantity;
        m_panes.push_back(pane);
    }
}

void TelemetryPlotPainter::tracesChanged()
{
    for (Pane &pane : m_panes)
        pane.shown.resize(m_buffer.traceCount());
    invalidateChrome(); // the legends name the servos
}

QColor TelemetryPlotPainter::traceColour(int index)
{
    return kServoColours[index % kColourCount];
}

bool TelemetryPlotPainter::setServoNames(const QHash<feetech::ServoAddress, QString> &names)
{
    if (names == m_names)
        return false;
    m_names = names;
    invalidateChrome();
    return true;
}

QString TelemetryPlotPainter::seriesName(const TelemetryBuffer::Servo &servo) const
{
    const QString named = m_names.value({servo.id, servo.baud});
    if (!named.isEmpty())
        return named;
    // Servos on different baud rates may share an ID: only then does the name say the rate.
    bool shared = false;
    for (int i = 0; i < m_buffer.traceCount(); ++i) {
        const TelemetryBuffer::Servo &other = m_buffer.servo(i);
        shared = shared || (other.id == servo.id && other.baud != servo.baud);
    }
    if (!shared)
        return tr("ID %1").arg(servo.id);
    return tr("ID %1 · %2").arg(servo.id).arg(feetech::baudText(servo.baud));
}

void TelemetryPlotPainter::fitToView(double from, double to)
{
    // Twice at most: ticks that come out wider than before move the plot areas, and the
    // columns follow the areas' width.
    for (int pass = 0; pass < 2; ++pass) {
        bool ticksChanged = false;
        for (Pane &pane : m_panes) {
            const int buckets = std::max(16, pane.area.width());
            double low = std::numeric_limits<double>::infinity();
            double high = -std::numeric_limits<double>::infinity();
            pane.shown.resize(m_buffer.traceCount());
            for (int i = 0; i < m_buffer.traceCount(); ++i) {
                TelemetryBuffer::pointsInView(m_buffer.points(i, pane.quantity), from, to, buckets,
                                              &low, &high, &pane.shown[i]);
            }
            if (low > high)
                continue; // nothing in view: the axis stays as it was
            const double span = high - low;
            const double margin =
                span > 0.0 ? span * kValueMargin : std::max(1.0, std::abs(low) * kValueMargin);
            const Ticks ticks = chooseTicks(low - margin, high + margin, pane.area.height());
            if (ticks.from != pane.values.from || ticks.to != pane.values.to
                || ticks.step != pane.values.step) {
                pane.values = ticks;
                ticksChanged = true;
            }
        }
        if (!ticksChanged)
            return;
        invalidateChrome(); // the value grid and labels moved
        // Measured only now: the labels' widths cost more than fitting when nothing moved.
        if (leftMargin() == m_laidOutMargin)
            return;
        layoutPanes();
    }
}

TelemetryPlotPainter::Ticks TelemetryPlotPainter::chooseTicks(double low, double high,
                                                              int height) const
{
    // About one value label per 35 pixels. Bounds snap to a quarter of a label step, so the
    // scale stays put while the data wanders a little.
    const auto snapped = [low, high](double step) {
        Ticks ticks;
        ticks.step = step;
        const double quantum = step / 4.0;
        ticks.from = std::floor(low / quantum) * quantum;
        ticks.to = std::ceil(high / quantum) * quantum;
        return ticks;
    };
    // Labels a line apart at the least, or they overlap.
    const int lineHeight = QFontMetrics(m_surface.font()).height();
    const auto apart = [height, lineHeight](const Ticks &ticks) {
        return ticks.step / (ticks.to - ticks.from) * height >= lineHeight;
    };
    Ticks ticks = snapped(niceStep((high - low) / std::clamp(height / 35, 2, 8)));
    // A pane a few lines high still gets three labels where three fit a line apart: one label
    // says nothing of the scale. The next smaller step of 1, 2 and 5 times a power of ten
    // while too few show, the next larger while they would overlap.
    for (int i = 0; i < kMaxStepChanges && labelledValues(ticks).size() < kLeastLabels; ++i) {
        const Ticks closer = snapped(niceStep(ticks.step * 0.4));
        if (!apart(closer))
            break;
        ticks = closer;
    }
    for (int i = 0; i < kMaxStepChanges && !apart(ticks); ++i)
        ticks = snapped(niceStep(ticks.step * 1.5));
    return ticks;
}

QVector<double> TelemetryPlotPainter::labelledValues(const Ticks &ticks)
{
    QVector<double> values;
    forEachTick(ticks.from, ticks.to, ticks.step,
                [&values](double value) { values.append(value); });
    return values;
}

int TelemetryPlotPainter::leftMargin() const
{
    const QFontMetrics metrics(m_surface.font());
    int widest = metrics.horizontalAdvance(QStringLiteral("0000"));
    for (const Pane &pane : m_panes) {
        forEachTick(pane.values.from, pane.values.to, pane.values.step, [&](double value) {
            widest = std::max(widest, metrics.horizontalAdvance(tickText(value, pane.values.step)));
        });
    }
    return widest + kLabelGap + kOuterMargin;
}

void TelemetryPlotPainter::layoutPanes()
{
    invalidateChrome();
    m_frameRegion = QRegion();
    if (m_panes.empty())
        return;
    const QFontMetrics metrics(m_surface.font());
    const int titleHeight = metrics.height() + 8;
    const int timeAxisHeight = 2 * metrics.height() + 14; // tick labels and "Time (s)"
    const int count = int(m_panes.size());
    const int available =
        m_surface.height() - 2 * kOuterMargin - timeAxisHeight - kPaneSpacing * (count - 1);
    const int paneHeight = std::max(titleHeight + 16, available / count);
    const int left = leftMargin();
    m_laidOutMargin = left;
    int top = kOuterMargin;
    for (int i = 0; i < count; ++i) {
        Pane &pane = m_panes[std::size_t(i)];
        const bool lowest = i == count - 1;
        pane.frame = QRect(kOuterMargin, top, m_surface.width() - 2 * kOuterMargin,
                           paneHeight + (lowest ? timeAxisHeight : 0));
        pane.area = QRect(pane.frame.left() + left, top + titleHeight,
                          std::max(1, pane.frame.width() - left - kRightMargin),
                          std::max(1, paneHeight - titleHeight - 6));
        m_frameRegion += pane.area;
        top += pane.frame.height() + kPaneSpacing;
    }
    // The time labels go under the lowest value label, which hangs below its grid line.
    const Pane &lowest = m_panes.back();
    m_timeLabelTop = lowest.area.bottom() + metrics.ascent() / 2 + 4;
    m_frameRegion +=
        QRect(lowest.frame.left(), m_timeLabelTop, lowest.frame.width(), metrics.height() + 2);
}

void TelemetryPlotPainter::invalidateChrome()
{
    m_chromeValid = false;
}

const QStaticText &TelemetryPlotPainter::label(const QString &text)
{
    auto found = m_labels.find(text);
    if (found != m_labels.end())
        return *found;
    if (m_labels.size() >= kLabelCacheSize)
        m_labels.clear(); // the view wandered far: start over rather than grow
    QStaticText laidOut(text);
    laidOut.setTextFormat(Qt::PlainText);
    laidOut.prepare(QTransform(), m_surface.font());
    return *m_labels.insert(text, laidOut);
}

void TelemetryPlotPainter::paintChrome(QPainter &painter)
{
    painter.fillRect(m_surface.rect(), m_surface.palette().window());
    const QColor text = m_surface.palette().color(QPalette::Text);
    QColor axis = text;
    axis.setAlpha(140);
    QFont titleFont = m_surface.font();
    titleFont.setBold(true);
    const QFontMetrics metrics(m_surface.font());
    const QFontMetrics titleMetrics(titleFont);
    for (std::size_t p = 0; p < m_panes.size(); ++p) {
        const Pane &pane = m_panes[p];
        painter.fillRect(pane.frame, m_surface.palette().base());

        // Title on the left, the legend on the same line to the right.
        const int baseline = pane.frame.top() + 4 + titleMetrics.ascent();
        const QString title = tr("%1 (%2)").arg(feetech::quantityName(pane.quantity),
                                                feetech::quantityUnit(pane.quantity));
        painter.setPen(text);
        painter.setFont(titleFont);
        painter.drawText(pane.area.left(), baseline, title);
        painter.setFont(m_surface.font());
        const int swatch = metrics.ascent() - 2;
        int legendWidth = 0;
        for (int i = 0; i < m_buffer.traceCount(); ++i) {
            legendWidth +=
                swatch + 4 + metrics.horizontalAdvance(seriesName(m_buffer.servo(i))) + 12;
        }
        const int titleEnd = pane.area.left() + titleMetrics.horizontalAdvance(title) + 24;
        int x = std::max(titleEnd, pane.area.right() - legendWidth + 12);
        for (int i = 0; i < m_buffer.traceCount(); ++i) {
            const QString name = seriesName(m_buffer.servo(i));
            const int itemWidth = swatch + 4 + metrics.horizontalAdvance(name);
            if (x + itemWidth > pane.frame.right()) {
                painter.drawText(x, baseline, QStringLiteral("…"));
                break;
            }
            painter.fillRect(QRect(x, baseline - swatch, swatch, swatch), traceColour(i));
            painter.drawText(x + swatch + 4, baseline, name);
            x += itemWidth + 12;
        }

        // The value labels beside the grid lines the frame draws.
        const Ticks &ticks = pane.values;
        const double scale = pane.area.height() / (ticks.to - ticks.from);
        painter.setPen(text);
        forEachTick(ticks.from, ticks.to, ticks.step, [&](double value) {
            const double y = pane.area.bottom() + 1 - (value - ticks.from) * scale;
            const QString label = tickText(value, ticks.step);
            painter.drawText(
                QPointF(pane.area.left() - kLabelGap - metrics.horizontalAdvance(label),
                        y + metrics.ascent() / 2.0 - 1),
                label);
        });
        painter.setPen(axis);
        painter.drawLine(pane.area.bottomLeft() + QPoint(0, 1),
                         pane.area.bottomRight() + QPoint(0, 1));
        painter.drawLine(pane.area.topLeft() - QPoint(1, 0), pane.area.bottomLeft() - QPoint(1, 0));
        if (p + 1 == m_panes.size()) {
            // The time axis is shared: only the lowest pane names it.
            const QString name = tr("Time (s)");
            painter.setPen(text);
            painter.setFont(titleFont);
            painter.drawText(
                QPointF(pane.area.center().x() - titleMetrics.horizontalAdvance(name) / 2.0,
                        m_timeLabelTop + metrics.height() + 4 + titleMetrics.ascent()),
                name);
            painter.setFont(m_surface.font());
        }
    }
}

void TelemetryPlotPainter::forgetLabels()
{
    m_labels.clear();
}

void TelemetryPlotPainter::paint(QPainter &painter, const QRegion &exposed, const View &view)
{
    // A frame asks for m_frameRegion only; anything beyond it (first show, resize, a covered
    // window exposed again, new ticks or servos) needs the chrome too.
    if (!m_chromeValid || !(exposed - m_frameRegion).isEmpty()) {
        paintChrome(painter);
        m_chromeValid = true;
    }
    paintFrame(painter, view);
}

void TelemetryPlotPainter::paintFrame(QPainter &painter, const View &view)
{
    if (m_panes.empty())
        return;
    const QBrush base = m_surface.palette().base();
    const QColor text = m_surface.palette().color(QPalette::Text);
    const QColor grid = gridColour(m_surface.palette());
    const Pane &lowest = m_panes.back();
    painter.fillRect(QRect(lowest.frame.left(), m_timeLabelTop, lowest.frame.width(),
                           QFontMetrics(m_surface.font()).height() + 2),
                     base);
    // The value grid of each pane, then the time grid across all of them. Grid lines are
    // one-pixel opaque rectangles: plain fills, many times cheaper than blended lines.
    for (const Pane &pane : m_panes) {
        painter.fillRect(pane.area, base);
        const Ticks &ticks = pane.values;
        const double scale = pane.area.height() / (ticks.to - ticks.from);
        forEachTick(ticks.from, ticks.to, ticks.step, [&](double value) {
            const int y =
                std::min(pane.area.bottom(),
                         int(std::lround(pane.area.bottom() + 1 - (value - ticks.from) * scale)));
            painter.fillRect(QRect(pane.area.left(), y, pane.area.width(), 1), grid);
        });
    }
    const double span = view.to - view.from;
    if (span > 0.0) {
        // About one time label per 90 pixels; each label's text is laid out once.
        const double step = niceStep(span / std::clamp(lowest.area.width() / 90, 2, 12));
        const double scale = lowest.area.width() / span;
        painter.setFont(m_surface.font());
        forEachTick(view.from, view.to, step, [&](double value) {
            const int x =
                std::min(lowest.area.right(),
                         int(std::lround(lowest.area.left() + (value - view.from) * scale)));
            for (const Pane &pane : m_panes)
                painter.fillRect(QRect(x, pane.area.top(), 1, pane.area.height()), grid);
            const QStaticText &label = this->label(tickText(value, step));
            painter.setPen(text);
            painter.drawStaticText(QPointF(x - label.size().width() / 2.0, m_timeLabelTop), label);
        });
    }
    for (const Pane &pane : m_panes)
        paintTraces(painter, pane, view);
    if (view.dragging) {
        QColor band = m_surface.palette().color(QPalette::Highlight);
        band.setAlpha(60);
        for (const Pane &pane : m_panes) {
            painter.fillRect(QRect(std::min(view.dragFromX, view.dragToX), pane.area.top(),
                                   std::abs(view.dragToX - view.dragFromX) + 1, pane.area.height()),
                             band);
        }
    }
}

void TelemetryPlotPainter::paintTraces(QPainter &painter, const Pane &pane, const View &view)
{
    const double span = view.to - view.from;
    const double valueSpan = pane.values.to - pane.values.from;
    if (!(span > 0.0) || !(valueSpan > 0.0))
        return;
    const QRectF area(pane.area);
    const double xScale = area.width() / span;
    const double yScale = area.height() / valueSpan;
    const double bottom = area.bottom() + 1.0; // QRect's bottom is its last row
    painter.save();
    painter.setClipRect(pane.area.adjusted(0, -1, 0, 1));
    painter.setRenderHint(QPainter::Antialiasing);
    for (int i = 0; i < pane.shown.size(); ++i) {
        const QList<QPointF> &points = pane.shown.at(i);
        if (points.isEmpty())
            continue;
        // Written through a pointer: appending point by point cost more than the mapping.
        if (m_polyline.size() < points.size())
            m_polyline.resize(points.size());
        QPointF *const polyline = m_polyline.data();
        qsizetype count = 0;
        for (const QPointF &point : points) {
            const QPointF mapped(area.left() + (point.x() - view.from) * xScale,
                                 bottom - (point.y() - pane.values.from) * yScale);
            // A servo at rest sends the same value again and again: a level run is drawn as
            // one segment from its first point to its last, which looks the same.
            if (count >= 2 && polyline[count - 1].y() == mapped.y()
                && polyline[count - 2].y() == mapped.y()) {
                polyline[count - 1] = mapped;
            } else {
                polyline[count++] = mapped;
            }
        }
        // One pixel wide: the raster engine's fast path for thin lines, antialiased alike.
        painter.setPen(QPen(traceColour(i), 1.0));
        if (count == 1)
            painter.drawPoint(polyline[0]);
        else
            painter.drawPolyline(polyline, int(count));
    }
    painter.restore();
}
