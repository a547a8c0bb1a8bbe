// The telemetry plot's data: per servo and quantity a bounded, time-ordered point buffer, and
// the min/max decimation of a time range to the pixel columns that show it.
#pragma once

// telemetry.h names ServoInfo without defining it; feetechsession.h defines it.
#include "feetechsession.h"
#include "telemetry.h"

#include <QList>
#include <QPointF>
#include <QVector>

#include <array>
#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

class TelemetryBuffer
{
public:
    // A servo the plot draws, as the stream names it.
    struct Servo
    {
        quint8 id = 0;
        qint32 baud = 0;
    };
    // How much a buffer keeps: at most `cap` points, and the window before the newest sample
    // (or, while the view is frozen, everything from `holdFrom` on).
    struct Retention
    {
        std::size_t cap = 0;
        double windowSeconds = 0.0;
        std::optional<double> holdFrom;
    };
    using Points = std::deque<QPointF>; // (seconds, value), in time order

    // Seconds kept beyond the window, so a view that has just moved on still has its left edge.
    static constexpr double kRetentionSlackSeconds = 1.0;
    // At most this many points per horizontal pixel: a minimum and a maximum per column.
    static constexpr int kPointsPerPixel = 2;

    int traceCount() const { return int(m_traces.size()); }
    const Servo &servo(int trace) const { return m_traces.at(std::size_t(trace)).servo; }
    QVector<Servo> servos() const;
    const Points &points(int trace, feetech::Quantity quantity) const
    {
        return m_traces.at(std::size_t(trace)).points.at(std::size_t(quantity));
    }
    int traceIndex(quint8 id, qint32 baud) const; // exact match, -1 when absent
    int findTrace(quint8 id, qint32 baud) const; // baud 0 matches any
    qint64 pointCount() const; // every buffer together
    double newest() const { return m_newest; } // seconds: the newest sample

    // Keeps these servos' traces, in this order (new ones empty), and drops the others.
    void setServos(const QVector<Servo> &servos);
    // Forgets every point; the next sample becomes time 0.
    void clear();
    // Adds the samples' values, a servo not seen before as a new trace at the end; true when
    // one was added. Buffers stay within `retention` even inside one large batch.
    bool add(const QVector<feetech::FeedbackSample> &samples, const Retention &retention);
    void trimAll(const Retention &retention);

    // The points of `points` between `from` and `to`, with one neighbour either side so the
    // line reaches the plot's edges; beyond `buckets` × kPointsPerPixel points, the lowest and
    // highest of each bucket (in time order), so short peaks survive. Buckets are
    // (to - from) / buckets wide and lie on a grid from time 0. `low`/`high` widen to
    // the values in view.
    static QList<QPointF> pointsInView(const Points &points, double from, double to, int buckets,
                                       double *low, double *high);
    // The same into `out`, whose storage is reused frame after frame.
    static void pointsInView(const Points &points, double from, double to, int buckets, double *low,
                             double *high, QList<QPointF> *out);

private:
    struct Trace
    {
        Servo servo;
        std::array<Points, feetech::kQuantityCount> points;
    };

    Trace &traceFor(quint8 id, qint32 baud);
    void trim(Points &points, const Retention &retention) const;

    std::vector<Trace> m_traces;
    bool m_hasOrigin = false;
    qint64 m_originUs = 0; // the steady time of time 0
    double m_newest = 0.0;
};
