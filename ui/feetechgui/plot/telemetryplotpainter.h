// The telemetry plot's drawing: places one pane per quantity on the widget, fits each pane's
// value axis to the traces in view and paints the panes, keeping apart the chrome that stays put
// from the frame that moves as time goes by.
#pragma once

// telemetry.h names ServoInfo without defining it; feetechsession.h defines it.
#include "feetechsession.h"
#include "telemetry.h"
#include "telemetrybuffer.h"

#include <QColor>
#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QPointF>
#include <QPolygonF>
#include <QRect>
#include <QRegion>
#include <QStaticText>
#include <QVector>

#include <vector>

class QPainter;
class QWidget;

class TelemetryPlotPainter
{
    Q_DECLARE_TR_FUNCTIONS(TelemetryPlotPainter)

public:
    // Ticks of one axis: the values labelled, and the step between them.
    struct Ticks
    {
        double from = 0.0;
        double to = 1.0;
        double step = 0.5;
    };
    struct Pane
    {
        feetech::Quantity quantity = feetech::Quantity::Position;
        QRect frame; // the whole pane
        QRect area; // where the traces go
        Ticks values;
        QVector<QList<QPointF>> shown; // per trace, decimated, at the last fit
    };
    // What a frame shows: the time span in view and, while the user drags a zoom, the band
    // selected (x pixels).
    struct View
    {
        double from = 0.0;
        double to = 1.0;
        bool dragging = false;
        int dragFromX = 0;
        int dragToX = 0;
    };

    // Paints on `surface` (its size, font and palette) the traces of `buffer`; both outlive it.
    TelemetryPlotPainter(const QWidget &surface, const TelemetryBuffer &buffer);

    // The values an axis labels, lowest first.
    static QVector<double> labelledValues(const Ticks &ticks);

    // One pane each, in this order.
    void setQuantities(const QVector<feetech::Quantity> &quantities);
    const std::vector<Pane> &panes() const { return m_panes; }
    // The buffer's servos changed: the legends name them and each pane has a trace per servo.
    void tracesChanged();
    // What the legends call the servos; false when they were already called so.
    bool setServoNames(const QHash<feetech::ServoAddress, QString> &names);
    // A trace's colour, by its index in the buffer.
    static QColor traceColour(int index);

    // Places the panes on the surface as it is now.
    void layoutPanes();
    // Decimates the traces in [from, to] and fits the value axes to them; places the panes
    // again when the value labels came out wider or narrower.
    void fitToView(double from, double to);

    // The chrome (frames, titles, legends, value labels) must be painted again.
    void invalidateChrome();
    bool isChromeValid() const { return m_chromeValid; }
    // The laid-out label texts depend on the font: forgotten when it changes.
    void forgetLabels();
    // Only this is painted again each frame; the rest stays in the backing store until it
    // changes, so a frame costs a fill of the plot areas and the lines on it.
    QRegion frameRegion() const { return m_frameRegion; }

    // Paints what `exposed` asks for: the frame, and the chrome too when it is not valid or
    // more than the frame is exposed.
    void paint(QPainter &painter, const QRegion &exposed, const View &view);

private:
    // The labels of an axis over [low, high] that is `height` pixels high.
    Ticks chooseTicks(double low, double high, int height) const;
    int leftMargin() const;
    QString seriesName(const TelemetryBuffer::Servo &servo) const;
    // What stays put as time goes by: frames, titles, legends, value labels.
    void paintChrome(QPainter &painter);
    // What moves each frame, inside m_frameRegion: plot areas, grids, traces, time labels.
    void paintFrame(QPainter &painter, const View &view);
    void paintTraces(QPainter &painter, const Pane &pane, const View &view);
    const QStaticText &label(const QString &text);

    const QWidget &m_surface;
    const TelemetryBuffer &m_buffer;
    std::vector<Pane> m_panes;
    QHash<feetech::ServoAddress, QString> m_names;
    QRegion m_frameRegion;
    bool m_chromeValid = false;
    int m_laidOutMargin = -1; // the left margin the panes were placed with
    int m_timeLabelTop = 0; // where the time tick labels start, under the lowest pane
    QHash<QString, QStaticText> m_labels; // laid-out tick texts, reused frame after frame
    QPolygonF m_polyline; // reused from trace to trace and frame to frame: no allocation
};
