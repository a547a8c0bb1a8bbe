// The Monitor page's readouts: a table with the newest value of every quantity of each servo,
// its samples per second, missed cycles and state.
#pragma once

// telemetry.h names ServoInfo without defining it; feetechsession.h defines it.
#include "feetechsession.h"
#include "telemetry.h"

#include <QColor>
#include <QHash>
#include <QPointer>
#include <QTableWidget>
#include <QVector>

#include <deque>

namespace feetech {
class BusClient;
}

// Samples only update what is kept; the cells change on refresh(), which the page calls on a
// timer: redrawing a table per sample would cost more than the bus delivers.
class MonitorReadouts : public QTableWidget
{
    Q_OBJECT

public:
    enum Column {
        ServoColumn,
        PositionColumn, // then one column per quantity, in kAllQuantities order
        SpeedColumn,
        LoadColumn,
        VoltageColumn,
        TemperatureColumn,
        CurrentColumn,
        MovingColumn,
        StatusColumn,
        RateColumn, // samples per second received
        MissedColumn,
        StateColumn, // waiting, receiving, not answering
        ColumnCount
    };

    // Rows the readouts show at the least, however short the window.
    static constexpr int kLeastRows = 3;

    // A tripped protection bit, a servo that stopped answering, a failed stream.
    static inline const QColor kProblemColour {0xc0, 0x1c, 0x1c};

    struct Row
    {
        feetech::ServoAddress key;
        QColor colour; // the servo's colour in the plot; invalid: none
        QString name; // "shoulder_pan (ID 1)" on an arm; empty: "ID 1"
    };

    // `client` names the status bits by each servo's register table.
    explicit MonitorReadouts(feetech::BusClient *client, QWidget *parent = nullptr);

    void addSample(const feetech::FeedbackSample &sample);
    void clearSamples(); // a new run: nothing received yet
    // Shows `rows` in that order; `running`: the stream is on (rates and states are live).
    void refresh(const QVector<Row> &rows, const feetech::TelemetryStats &stats, bool running);

private:
    struct Latest
    {
        feetech::FeedbackSample sample;
        std::deque<qint64> recent; // steady times of the last second's samples
    };

    QString statusText(const feetech::ServoAddress &key, quint8 bits) const;

    // Widens the columns whose text no longer fits; never narrows them, so they do not jitter.
    void fitColumns();

protected:
    void changeEvent(QEvent *event) override;

private:
    QPointer<feetech::BusClient> m_client;
    QHash<feetech::ServoAddress, Latest> m_latest;
    // The width each column's texts need, measured again only when one of them changed.
    QVector<int> m_neededWidths = QVector<int>(ColumnCount, -1);
};
