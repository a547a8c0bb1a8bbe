// The live telemetry plot: one pane per quantity, stacked on a shared time axis, painted by
// TelemetryPlotPainter from bounded per-series buffers at most once per screen frame and only when
// it changed.
#pragma once

// telemetry.h names ServoInfo without defining it; feetechsession.h defines it.
#include "feetechsession.h"
#include "telemetry.h"
#include "telemetrybuffer.h"
#include "telemetryplotpainter.h"

#include <QHash>
#include <QList>
#include <QPointF>
#include <QRect>
#include <QVector>
#include <QWidget>

#include <utility>

class QTimer;

class TelemetryPlot : public QWidget
{
    Q_OBJECT

public:
    // A servo the plot draws, as the stream names it.
    using Servo = TelemetryBuffer::Servo;

    // No series keeps more points than this, whatever the rate and the window.
    static constexpr int kHardPointCap = 20000;
    // The fastest one servo is sampled on a 1 Mbps bus, for sizing a window's buffer.
    static constexpr double kMaxRateHz = 1000.0;
    // Frames per second at most: one per screen refresh, and no more than this, which keeps a
    // scrolling trace smooth (data comes in batches every 20 ms) at half the cost of 60.
    static constexpr int kMaxFramesPerSecond = 30;
    // The least height of one quantity's pane, in pixels: its title and a few value labels.
    static constexpr int kMinimumPaneHeight = 56;
    // The plot's least height holds this many panes; more panes share it in a short window
    // rather than push the window off a 1366x768 screen (the readouts below keep their rows).
    static constexpr int kPanesInLeastHeight = 2;

    explicit TelemetryPlot(QWidget *parent = nullptr);
    ~TelemetryPlot() override;

    // One pane each, in this order.
    void setQuantities(const QVector<feetech::Quantity> &quantities);
    QVector<feetech::Quantity> quantities() const { return m_quantities; }

    // The servos drawn, in this order (their colours follow it). Buffers of servos not listed
    // are dropped; a sample of an unlisted servo adds it at the end.
    void setServos(const QVector<Servo> &servos);
    QVector<Servo> servos() const;

    // Seconds of history in view while following live data.
    void setWindowSeconds(double seconds);
    double windowSeconds() const { return m_windowSeconds; }

    // Paused: the view stays where it is while samples are still buffered.
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    // Zoomed by the user (drag, wheel or setTimeRange): the view does not follow live.
    bool isZoomed() const { return m_zoomed; }
    // Back to following live data over the window.
    void resetZoom();
    // Shows [from, to] seconds (of the plot's time line) on every pane, as a zoom would.
    void setTimeRange(double from, double to);
    double viewFrom() const { return m_viewFrom; }
    double viewTo() const { return m_viewTo; }

    // Forgets every buffered point; the next sample becomes time 0.
    void clear();
    void addSamples(const QVector<feetech::FeedbackSample> &samples);
    // What the legends call the servos ("shoulder_pan (ID 1)" on an arm); one not named here
    // is "ID 1".
    void setServoNames(const QHash<feetech::ServoAddress, QString> &names);

    // Brings the view up to date now (the frame timer does this while data comes in).
    void refresh();

    // The panes of `quantities` (none given: those shown) as one PNG, drawn for the file at a
    // size of its own (kExportWidth wide, kExportPaneHeight a pane), whatever the window's;
    // false and *error when it cannot be written.
    static constexpr int kExportWidth = 1600;
    static constexpr int kExportPaneHeight = 300;
    bool exportPng(const QString &path, QString *error = nullptr,
                   const QVector<feetech::Quantity> &quantities = {});
    QSize exportSize(int panes) const;

    // How many panes fit in `height` pixels, each tall enough for its title and three labelled
    // values; the page shows fewer panes (with a chooser) when not all fit.
    int readablePanesIn(int height) const;

    // ---- for tests, the page and the benchmark
    int seriesCount() const; // drawn series: servos × quantities
    // Points buffered for this servo's quantity (baud 0: the first servo with that ID).
    int bufferedPointCount(quint8 id, feetech::Quantity quantity, qint32 baud = 0) const;
    // Points drawn for this servo's quantity at the last refresh (-1: no such series).
    int shownPointCount(quint8 id, feetech::Quantity quantity, qint32 baud = 0) const;
    // Those points, in seconds and the quantity's unit.
    QList<QPointF> shownPoints(quint8 id, feetech::Quantity quantity, qint32 baud = 0) const;
    qint64 bufferedPoints() const; // every series together
    int maxPointsPerSeries() const; // for the present window
    // Where the pane of this quantity draws its traces, in the plot's coordinates (empty when
    // the quantity is not shown), and the value range its axis spans.
    QRect plotArea(feetech::Quantity quantity) const;
    std::pair<double, double> valueRange(feetech::Quantity quantity) const;
    // The values its axis labels, lowest first.
    QVector<double> valueLabels(feetech::Quantity quantity) const;
    QColor servoColor(quint8 id, qint32 baud = 0) const;
    qint64 paintCount() const { return m_paintCount; }
    // A repaint is due at the next frame.
    bool isFramePending() const;

    QSize sizeHint() const override;

signals:
    void pausedChanged(bool paused);
    void zoomedChanged(bool zoomed);
    // After each paint: how long bringing the view up to date and painting took.
    void framePainted(qint64 nanoseconds);

protected:
    void paintEvent(QPaintEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void changeEvent(QEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;

private:
    TelemetryBuffer::Retention retention() const;
    void scheduleFrame();
    void layoutPanes();
    void prepareFrame(); // decimates the traces in view and fits the value axes
    void rebuildPanes();
    void onServosChanged();
    int paneAt(const QPoint &position) const; // -1 outside every plot area
    double timeAt(const TelemetryPlotPainter::Pane &pane, double x) const;
    void zoomAround(double fraction, double factor);
    void setFollowing();
    void setZoomed(bool zoomed);
    void requestPaint(); // of the frame region only, unless the chrome changed too

    QVector<feetech::Quantity> m_quantities;
    QHash<feetech::ServoAddress, QString> m_servoNames; // for a painter of an export
    TelemetryBuffer m_buffer;
    TelemetryPlotPainter m_painter {*this, m_buffer};
    QTimer *m_frameTimer = nullptr;

    double m_windowSeconds = 10.0;
    bool m_paused = false;
    bool m_zoomed = false;
    bool m_dirty = false; // new samples since the last refresh
    bool m_viewDirty = true; // the range, size or series changed: refresh even when frozen
    bool m_layoutDirty = true; // pane rectangles need placing again
    double m_viewFrom = 0.0;
    double m_viewTo = 10.0;

    qint64 m_paintCount = 0;
    qint64 m_prepareNs = 0; // the refresh behind the coming paint

    int m_dragPane = -1; // the pane a drag zoom started in
    int m_dragFromX = 0;
    int m_dragToX = 0;
};
