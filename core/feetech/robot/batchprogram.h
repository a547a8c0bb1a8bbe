// Programs several servos of a bus client with one settings file, one servo after the other:
// each is read, diffed, written through BusClient::apply (locked, verified EEPROM writes) and
// reported; one failure does not stop the others.
#pragma once

#include "settingsfile.h"

#include <QMetaType>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QVector>

#include <optional>
#include <utility>

namespace seriallink {
struct ConnectionStatus;
}

namespace feetech {

class BusClient;
struct OperationResult;

class BatchProgram : public QObject
{
    Q_OBJECT

public:
    explicit BatchProgram(BusClient *client, QObject *parent = nullptr);

    // Starts with the servos `indexes` (as the client numbers them). False and *error, with
    // nothing sent, when the bus is not connected, busy, or no servo is given.
    bool start(const QVector<int> &indexes, const SettingsFile &file, QString *error = nullptr);
    bool isRunning() const { return m_phase != Phase::Idle; }
    const QVector<ProgramOutcome> &outcomes() const { return m_outcomes; }

signals:
    void runningChanged(bool running);
    // Before each servo: how many are done, of how many, and which comes now.
    void progress(int done, int total, const QString &message);
    void finished(const QVector<feetech::ProgramOutcome> &outcomes);

private:
    enum class Phase { Idle, Reading, Writing };

    void next();
    void diffAndWrite(int index);
    void settle(const OperationResult &result);
    void onOperationFinished(const OperationResult &result);
    void onStatusChanged(const seriallink::ConnectionStatus &status);
    void failCurrent(const QString &error);

    QPointer<BusClient> m_client;
    std::optional<SettingsFile> m_file;
    QVector<std::pair<quint8, qint32>> m_servos; // ID and baud, in the order given
    int m_next = 0;
    Phase m_phase = Phase::Idle;
    ProgramOutcome m_current;
    QVector<ProgramOutcome> m_outcomes;
};

} // namespace feetech

Q_DECLARE_METATYPE(feetech::ProgramOutcome)
