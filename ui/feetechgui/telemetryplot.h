// The live telemetry plot: one Qt Charts chart per quantity, stacked on a shared time axis, fed
// from bounded per-series buffers and repainted on a timer rather than per sample.
#pragma once

// telemetry.h names ServoInfo without defining it; feetechsession.h defines it.
#include "feetech/feetechsession.h"
#include "feetech/telemetry.h"
#include "feetechgui/telemetrybuffer.h"

#include <QColor>
#include <QPointF>
#include <QVector>
#include <QWidget>

#include <memory>
#include <vector>

class QChart;
class QChartView;
class QLineSeries;
class QTimer;
class QVBoxLayout;
class QValueAxis;

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
    // Repaints per second while data comes in.
    static constexpr int kFramesPerSecond = 25;

    explicit TelemetryPlot(QWidget *parent = nullptr);
    ~TelemetryPlot() override;

    // One chart each, in this order.
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
    // Zoomed by the user (rubber band, wheel or setTimeRange): the view does not follow live.
    bool isZoomed() const { return m_zoomed; }
    // Back to following live data over the window.
    void resetZoom();
    // Shows [from, to] seconds (of the plot's time line) on every chart, as a zoom would.
    void setTimeRange(double from, double to);
    double viewFrom() const { return m_viewFrom; }
    double viewTo() const { return m_viewTo; }

    // Forgets every buffered point; the next sample becomes time 0.
    void clear();
    void addSamples(const QVector<feetech::FeedbackSample> &samples);

    // Brings the charts up to date now (the repaint timer does this while data comes in).
    void refresh();

    // The whole stack of charts as one PNG; false and *error when it cannot be written.
    bool exportPng(const QString &path, QString *error = nullptr);

    // ---- for tests and the page
    int seriesCount() const; // drawn series: servos × quantities
    // Points buffered for this servo's quantity (baud 0: the first servo with that ID).
    int bufferedPointCount(quint8 id, feetech::Quantity quantity, qint32 baud = 0) const;
    // Points handed to the chart's series at the last repaint (-1: no such series).
    int shownPointCount(quint8 id, feetech::Quantity quantity, qint32 baud = 0) const;
    qint64 bufferedPoints() const; // every series together
    int maxPointsPerSeries() const; // for the present window
    QChartView *chartView(feetech::Quantity quantity) const; // nullptr when not shown
    QColor servoColor(quint8 id, qint32 baud = 0) const;

signals:
    void pausedChanged(bool paused);
    void zoomedChanged(bool zoomed);

protected:
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    struct Pane
    {
        feetech::Quantity quantity = feetech::Quantity::Position;
        QChartView *view = nullptr;
        QChart *chart = nullptr;
        QValueAxis *timeAxis = nullptr;
        QValueAxis *valueAxis = nullptr;
        QVector<QLineSeries *> series; // one per trace, in the same order
        QVector<int> shown; // points given to each series at the last repaint
        int buckets = 0; // the pixel columns decimated to at the last repaint
        double extraLeft = 0.0; // margin added so every chart's plot area starts at one x
        double extraRight = 0.0;
    };

    void rebuildPanes();
    void rebuildSeries();
    void addSeries(Pane &pane, int trace);
    QString seriesName(const Servo &servo) const;
    TelemetryBuffer::Retention retention() const;
    int bucketsFor(const Pane &pane) const;
    void repaintPane(Pane &pane, double from, double to);
    void setAxisRange(QValueAxis *axis, double from, double to, int intervals, bool roundBounds);
    void alignPlotAreas();
    void onTimeAxisChanged(double from, double to);
    void zoomAround(double fraction, double factor);
    void setFollowing();
    void setZoomed(bool zoomed);

    QVector<feetech::Quantity> m_quantities;
    TelemetryBuffer m_buffer;
    std::vector<std::unique_ptr<Pane>> m_panes;
    QVBoxLayout *m_layout = nullptr;
    QTimer *m_repaintTimer = nullptr;

    double m_windowSeconds = 10.0;
    bool m_paused = false;
    bool m_zoomed = false;
    bool m_dirty = false; // new samples since the last repaint
    bool m_viewDirty = true; // the range, size or series changed: repaint even when frozen
    bool m_settingAxes = false; // our own axis changes are not the user's zoom
    double m_viewFrom = 0.0;
    double m_viewTo = 10.0;
};
