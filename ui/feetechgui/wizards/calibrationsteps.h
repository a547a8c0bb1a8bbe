// Reads and verified writes of several servos through the bus client, one servo at a time, for
// the arm calibration wizard and the loading of calibration files.
#pragma once

#include "parametermodel.h"

#include <QObject>
#include <QVector>

namespace feetech {
class BusClient;
struct OperationResult;
} // namespace feetech

class CalibrationSteps : public QObject
{
    Q_OBJECT

public:
    struct Step
    {
        int index = 0; // the servo, as the client lists it
        // Written (EEPROM ones unlocked, written, locked again), then compared with what the
        // servo reads back; a fresh read of the whole servo when empty.
        QVector<model::WriteItem> writes;
    };

    explicit CalibrationSteps(feetech::BusClient *client, QObject *parent = nullptr);

    // Runs `steps` in order; a step that fails does not stop the ones after it (each joint
    // stands alone). False when steps are already running.
    bool start(const QVector<Step> &steps);
    bool isRunning() const { return m_next > 0 && m_next <= m_steps.size(); }
    // Register `key` of servo `index` (as the client lists it) as last read; 0 when it was never
    // read.
    static qint32 lastRead(const feetech::BusClient &client, int index, const QString &key);

signals:
    void stepFinished(int step, bool ok, const QString &message);
    void progress(int done, int total);
    void finished(bool allOk);

private:
    void startNext();
    void onOperationFinished(const feetech::OperationResult &result);

    feetech::BusClient *m_client = nullptr;
    QVector<Step> m_steps;
    int m_next = 0; // one past the running step
    bool m_allOk = true;
};
