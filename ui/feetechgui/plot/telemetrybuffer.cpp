// Bounded per-series buffers of the telemetry plot, and the decimation of a range to pixels.
#include "telemetrybuffer.h"

#include <algorithm>
#include <cmath>
#include <iterator>

QVector<TelemetryBuffer::Servo> TelemetryBuffer::servos() const
{
    QVector<Servo> servos;
    for (const Trace &trace : m_traces)
        servos.append(trace.servo);
    return servos;
}

int TelemetryBuffer::traceIndex(quint8 id, qint32 baud) const
{
    for (std::size_t i = 0; i < m_traces.size(); ++i) {
        if (m_traces[i].servo.id == id && m_traces[i].servo.baud == baud)
            return int(i);
    }
    return -1;
}

int TelemetryBuffer::findTrace(quint8 id, qint32 baud) const
{
    if (baud != 0)
        return traceIndex(id, baud);
    for (std::size_t i = 0; i < m_traces.size(); ++i) {
        if (m_traces[i].servo.id == id)
            return int(i);
    }
    return -1;
}

qint64 TelemetryBuffer::pointCount() const
{
    qint64 total = 0;
    for (const Trace &trace : m_traces) {
        for (const auto &points : trace.points)
            total += qint64(points.size());
    }
    return total;
}

void TelemetryBuffer::setServos(const QVector<Servo> &servos)
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
}

void TelemetryBuffer::clear()
{
    for (Trace &trace : m_traces) {
        for (auto &points : trace.points)
            points.clear();
    }
    m_hasOrigin = false;
    m_originUs = 0;
    m_newest = 0.0;
}

bool TelemetryBuffer::add(const QVector<feetech::FeedbackSample> &samples,
                          const Retention &retention)
{
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
            Points &points = trace.points.at(std::size_t(q));
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
            trim(points, retention); // bounded even within one large batch
        }
    }
    return m_traces.size() != tracesBefore;
}

void TelemetryBuffer::trimAll(const Retention &retention)
{
    for (Trace &trace : m_traces) {
        for (auto &points : trace.points)
            trim(points, retention);
    }
}

TelemetryBuffer::Trace &TelemetryBuffer::traceFor(quint8 id, qint32 baud)
{
    const int index = traceIndex(id, baud);
    if (index >= 0)
        return m_traces.at(std::size_t(index));
    Trace trace;
    trace.servo = {id, baud};
    m_traces.push_back(std::move(trace));
    return m_traces.back();
}

void TelemetryBuffer::trim(Points &points, const Retention &retention) const
{
    while (points.size() > retention.cap)
        points.pop_front();
    double keepFrom = m_newest - retention.windowSeconds - kRetentionSlackSeconds;
    if (retention.holdFrom)
        keepFrom = std::min(keepFrom, *retention.holdFrom - kRetentionSlackSeconds); // in view
    while (!points.empty() && points.front().x() < keepFrom)
        points.pop_front();
}

QList<QPointF> TelemetryBuffer::pointsInView(const Points &points, double from, double to,
                                             int buckets, double *low, double *high)
{
    QList<QPointF> out;
    pointsInView(points, from, to, buckets, low, high, &out);
    return out;
}

void TelemetryBuffer::pointsInView(const Points &points, double from, double to, int buckets,
                                   double *low, double *high, QList<QPointF> *out)
{
    out->clear(); // keeps the capacity unless the list is shared
    if (points.empty())
        return;
    const auto byTime = [](const QPointF &point, double x) {
        return point.x() < x;
    };
    const auto first = std::lower_bound(points.begin(), points.end(), from, byTime);
    const auto last =
        std::upper_bound(points.begin(), points.end(), to,
                         [](double x, const QPointF &point) { return x < point.x(); });
    const auto count = std::distance(first, last);
    // Written through a pointer into storage sized for the most there can be: appending point
    // by point costs more than finding the points.
    out->resize(qsizetype(std::min<qint64>(count, qint64(buckets) * kPointsPerPixel)) + 2);
    QPointF *const begin = out->data();
    QPointF *next = begin;
    if (first != points.begin())
        *next++ = *std::prev(first);
    double lowest = *low;
    double highest = *high;
    if (count <= qint64(buckets) * kPointsPerPixel) {
        for (auto it = first; it != last; ++it) {
            *next++ = *it;
            lowest = std::min(lowest, it->y());
            highest = std::max(highest, it->y());
        }
    } else {
        // Columns sit on a grid fixed in time rather than to the view's edge, so that as the view
        // scrolls a column keeps the same points and the trace does not shimmer.
        const double width = (to - from) / buckets;
        const double firstColumn = std::floor(from / width);
        int bucket = -1;
        QPointF columnLow;
        QPointF columnHigh;
        const auto flush = [&] {
            if (bucket < 0)
                return;
            if (columnLow == columnHigh) {
                *next++ = columnLow;
            } else if (columnLow.x() <= columnHigh.x()) {
                *next++ = columnLow;
                *next++ = columnHigh;
            } else {
                *next++ = columnHigh;
                *next++ = columnLow;
            }
            lowest = std::min(lowest, columnLow.y());
            highest = std::max(highest, columnHigh.y());
        };
        for (auto it = first; it != last; ++it) {
            const int index = int(
                std::clamp(std::floor(it->x() / width) - firstColumn, 0.0, double(buckets - 1)));
            if (index != bucket) {
                flush();
                bucket = index;
                columnLow = columnHigh = *it;
            } else if (it->y() < columnLow.y()) {
                columnLow = *it;
            } else if (it->y() > columnHigh.y()) {
                columnHigh = *it;
            }
        }
        flush();
    }
    if (last != points.end())
        *next++ = *last;
    *low = lowest;
    *high = highest;
    out->resize(next - begin);
}
