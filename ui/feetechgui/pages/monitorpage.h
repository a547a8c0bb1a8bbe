// The Monitor page of the Feetech workspace: choose servos and quantities, stream their
// feedback, plot it live, read the latest values, record CSV and export the plot.
#pragma once

// telemetry.h names ServoInfo without defining it; feetechsession.h defines it.
#include "feetechsession.h"
#include "monitorreadouts.h"
#include "telemetry.h"

#include <QHash>
#include <QPointer>
#include <QVector>
#include <QWidget>

class QTabBar;
class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QTimer;
class MonitorRecording;
class MonitorServoList;
class TelemetryPlot;

namespace feetech {
class BusClient;
}

class MonitorPage : public QWidget
{
    Q_OBJECT

public:
    // The plot's history when the page opens.
    static constexpr int kDefaultWindowSeconds = 10;
    // Readouts refresh at most this often, however fast samples come.
    static constexpr int kReadoutIntervalMs = 250;

    explicit MonitorPage(feetech::BusClient *client, QWidget *parent = nullptr);
    ~MonitorPage() override;

    // Servos by their index in the bus client; a running stream restarts with the new ones.
    void setSelectedServos(const QVector<int> &indexes);
    QVector<int> selectedServos() const;
    void setQuantities(const QVector<feetech::Quantity> &quantities);
    QVector<feetech::Quantity> quantities() const;
    // Samples per second per servo, one of the rates offered (0: as fast as the bus allows);
    // a running stream restarts at it.
    void setRate(double rateHz);
    double rate() const;
    void setWindowSeconds(double seconds);

    // Streams the selected servos; false and *error (also shown on the page) when refused.
    bool start(QString *error = nullptr);
    void stop(); // also ends a recording
    bool isRunning() const;

    bool exportPng(const QString &path, QString *error = nullptr);

    // The slot the telemetry's samplesReceived is connected to: samples of unticked servos are
    // dropped, the rest go to the plot, the readouts and the recording.
    void addSamples(const QVector<feetech::FeedbackSample> &samples);
    void updateReadouts(); // now rather than on the next tick

    TelemetryPlot *plot() const { return m_plot; }
    MonitorReadouts *readouts() const { return m_readouts; }
    MonitorServoList *servoList() const { return m_servoList; }
    // Every sample of the ticked servos taken while it records goes to its CSV file.
    MonitorRecording *recording() const { return m_recording; }

signals:
    void problem(const QString &message);

protected:
    void showEvent(QShowEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    using Key = feetech::ServoAddress;

    QWidget *buildControls();
    void rebuildServoList();
    void onTicksChanged();
    void onQuantityToggled();
    void onRateChosen();
    void onWindowChosen();
    void onMonitoringChanged(bool monitoring);
    void onStatsChanged(const feetech::TelemetryStats &stats);
    void onStatusChanged();
    void toggleStream();
    void togglePause();
    void chooseExportFile();
    void restartIfRunning();
    // Every quantity ticked a pane where they all fit readably, else one pane and a tab each.
    void fitPanes();
    // After a scan that paused it: monitoring again, of the ticked servos found.
    void resumeAfterScan();
    void updatePlotServos();
    void updateControls();
    void updateStatusLine();
    void showMessage(const QString &text, bool isError);
    QVector<Key> readoutKeys() const;

    QPointer<feetech::BusClient> m_client;
    TelemetryPlot *m_plot = nullptr;
    MonitorServoList *m_servoList = nullptr;
    QVector<QCheckBox *> m_quantityChecks; // in kAllQuantities order
    QComboBox *m_rateCombo = nullptr;
    QComboBox *m_windowCombo = nullptr;
    QPushButton *m_startButton = nullptr;
    QPushButton *m_pauseButton = nullptr;
    QPushButton *m_resetZoomButton = nullptr;
    QPushButton *m_exportButton = nullptr;
    MonitorRecording *m_recording = nullptr;
    QLabel *m_message = nullptr;
    QLabel *m_statusLine = nullptr;
    MonitorReadouts *m_readouts = nullptr;
    QTimer *m_readoutTimer = nullptr;

    bool m_readoutsDirty = true;

    QWidget *m_plotBox = nullptr;
    QTabBar *m_quantityTabs = nullptr;
    bool m_fittingPanes = false;
    bool m_resumeWhenListed = false; // stopped by a new scan: starts again once it has servos
    QVector<Key> m_unlisted; // servos samples came for that the list does not name
    feetech::TelemetryStats m_stats;
};
