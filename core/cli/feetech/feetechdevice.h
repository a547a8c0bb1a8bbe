// What every servoctl feetech command shares: one bus session run to completion per operation,
// and the servo's identity and registers as text and JSON.
#pragma once

#include "arguments.h"
#include "busoperations.h"
#include "commandoutput.h"
#include "feetechsession.h"
#include "servoparameters.h"

#include <QHash>
#include <QJsonObject>
#include <QMap>
#include <QString>
#include <QTextStream>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>

namespace cli {

using feetech::OperationResult;
using feetech::ServoInfo;

constexpr qint32 kDefaultBaud = 1000000;

// Register bytes by the address their READ started at.
using Memory = QMap<int, QByteArray>;

// The rate as --baud takes it ("1000000 bps"), not feetech::baudText's "1 Mbps": what servoctl
// prints about a servo can be typed back into its next command.
QString baudNumberText(qint32 baud);
// Every Feetech rate, for the message refusing another.
QString baudList();

QJsonObject servoJson(const ServoInfo &servo);
// "servo 1 at 1000000 bps: STS3215 (STS), firmware 3.10"
QString servoSummary(const ServoInfo &servo);
QString familyText(const ServoInfo &servo);

// Every register wholly inside the blocks read, in address order.
QVector<feetech::DecodedRegister> decodeMemory(const feetech::RegisterTable &table,
                                               const Memory &memory);
QHash<QString, qint32> valuesByKey(const QVector<feetech::DecodedRegister> &decoded);
QJsonObject registerJson(const feetech::DecodedRegister &item);
// The value in register units, right-aligned, and what it means where that says more ("8 V",
// "Position").
QString valueText(const feetech::Register &reg, qint32 value);

void printJson(QTextStream &out, const QJsonValue &value);

// One Feetech session on the port the arguments name, run to the end of each operation.
class FeetechDevice
{
public:
    FeetechDevice(const Arguments &args, const Output &output);
    // On `port` rather than --port (a second bus: teleoperation's leader arm).
    FeetechDevice(const QString &port, const Arguments &args, const Output &output);

    feetech::Session &session() { return *m_session; }
    const QString &port() const { return m_port; }
    const QString &error() const { return m_error; }

    bool open(qint32 baud);
    // Before open: the echo as something else found out (the port probe), not --echo's.
    void setEchoMode(seriallink::EchoMode echo) { m_echo = echo; }

    // PING, then READ of addresses 0-8: who answers at `id`, or nothing (and error()).
    std::optional<ServoInfo> identify(quint8 id, qint32 baud,
                                      std::chrono::microseconds *latency = nullptr);

    // The blocks (all of the servo's table when empty), or nothing (and error()).
    std::optional<Memory> read(const ServoInfo &servo, const QVector<feetech::Block> &blocks);

    // Runs one session operation (busoperations.h) to its operationFinished; `memory` gathers
    // what it read.
    // Nothing (and error()) when it did not finish in time, or after Ctrl-C: the first asks
    // the operation to stop cleanly (identify restores the servo, a set-up stops between
    // steps, a write finishes and relocks) and waits for it; a second stops waiting. Once
    // interrupted, no further operation starts.
    std::optional<OperationResult> operate(const feetech::BusOperation &operation,
                                           Memory *memory = nullptr);

    // Runs a scan to its end (or to Ctrl-C); false (and error()) when it did not complete.
    bool scan(const feetech::ScanOptions &options,
              const std::function<void(const ServoInfo &)> &found);

private:
    void trace(const seriallink::PacketLogEntry &entry);

    const Output &m_output;
    QString m_port;
    seriallink::EchoMode m_echo = seriallink::EchoMode::Auto;
    bool m_trace = false;
    std::unique_ptr<feetech::Session> m_session;
    QString m_error;
    bool m_interrupted = false;
};

} // namespace cli
