// The GUI's bus doctor run: after a scan, each servo found is read, then the findings are made.
#pragma once

#include "busdoctor.h"

#include <QObject>
#include <QTimer>

namespace feetech {

class BusClient;

// Reads the table of every servo the client found (the supply voltage, its limits, the status
// bits; a servo whose reads come back garbled may share its ID), then diagnoses the bus.
// Lives in the GUI thread beside the client; one run at a time.
class DoctorCheck : public QObject
{
    Q_OBJECT

public:
    explicit DoctorCheck(BusClient *client, QObject *parent = nullptr);

    // `seen` carries the probe (or says there was none) and the rates scanned; the servos
    // found are the client's.
    void start(const BusObservation &seen, const QVector<ExpectedServo> &expected);
    bool isRunning() const { return m_running; }

signals:
    void progress(int done, int total);
    void finished(const QVector<feetech::DoctorFinding> &findings);

private:
    void readNext();
    void onRead(bool readable);

    BusClient *m_client = nullptr;
    BusObservation m_seen;
    QVector<ExpectedServo> m_expected;
    int m_next = 0;
    bool m_running = false;
    QTimer m_guard; // a read that never reports does not hold the doctor up
};

} // namespace feetech
