// The bus doctor: what a probe, a scan and a look at each servo say is wrong, and what to do.
#pragma once

#include "bustypes.h"
#include "portprobe.h"

#include <QMap>
#include <QString>
#include <QVector>

#include <functional>
#include <optional>

namespace feetech {

// The stable codes of the findings (servoctl doctor --json prints them; scripts rely on them).
namespace doctorcodes {
inline const QString kPortPermission = QStringLiteral("PORT_PERMISSION");
inline const QString kPortBusy = QStringLiteral("PORT_BUSY");
inline const QString kPortMissing = QStringLiteral("PORT_MISSING");
inline const QString kPortFailed = QStringLiteral("PORT_FAILED");
inline const QString kNoBytes = QStringLiteral("NO_BYTES");
inline const QString kUnframedBytes = QStringLiteral("UNFRAMED_BYTES");
inline const QString kPtkServo = QStringLiteral("PTK_SERVO");
inline const QString kNoServoFound = QStringLiteral("NO_SERVO_FOUND");
inline const QString kUnexpectedId = QStringLiteral("UNEXPECTED_ID");
inline const QString kUnexpectedBaud = QStringLiteral("UNEXPECTED_BAUD");
inline const QString kChainBreak = QStringLiteral("CHAIN_BREAK");
inline const QString kMissingServos = QStringLiteral("MISSING_SERVOS");
inline const QString kSharedId = QStringLiteral("SHARED_ID");
inline const QString kVoltage = QStringLiteral("VOLTAGE");
} // namespace doctorcodes

// A servo the bus should hold; baud 0: at any rate.
struct ExpectedServo
{
    quint8 id = 0;
    qint32 baud = 0;
};

// What a READ of a found servo's table says about it.
struct ServoCondition
{
    ServoInfo servo;
    bool readable = false; // its table came back whole and valid
    std::optional<double> voltage; // volts
    std::optional<double> minVoltage;
    std::optional<double> maxVoltage;
    quint8 status = 0; // the status register's error bits (0x01: voltage)
};

// The condition `memory` (READ bytes by start address) shows; unreadable when it is empty.
ServoCondition servoCondition(const ServoInfo &servo, const QMap<int, QByteArray> &memory);
// The same from register values by key (register units), as a parameter model holds them.
ServoCondition servoCondition(const ServoInfo &servo, bool readable,
                              const std::function<std::optional<qint64>(const QString &)> &value);

// A move the doctor offers: the servo found at (servo.id, servo.baud) to a new ID or rate.
struct ServoMove
{
    ServoInfo servo;
    int newId = -1; // -1: the ID stays
    qint32 newBaud = 0; // 0: the rate stays
};

struct DoctorFinding
{
    QString code; // one of doctorcodes
    QString message; // translated: what is wrong and what to do
    QVector<int> ids; // the servo IDs concerned
    QVector<ServoMove> moves; // what the GUI may offer to do about it
};

// What a finding's code means, as a short translated sentence: the title the Doctor panel shows
// (the code stays for scripts and servoctl). An unknown code comes back as it is.
QString doctorTitle(const QString &code);

// Everything looked at on one port.
struct BusObservation
{
    PortProbeReport probe;
    // The probe ran (every rate heard). Without it only the scan's rates are known: nothing is
    // said about silence or bytes that never frame.
    bool probed = true;
    QVector<qint32> scannedBauds; // the rates scanned, for what a scan without a probe says
    bool scanned = false; // the rates that answered were scanned
    QVector<ServoInfo> found;
    QVector<ServoCondition> conditions; // of the servos found, when they were read
};

// The findings, most fundamental first (the port, then the wire, then the servos). None: the
// bus holds what was expected (and, with nothing expected, at least one servo or PTK answers).
// `expected` is in chain order: the servo nearest the adapter first.
QVector<DoctorFinding> diagnoseBus(const BusObservation &seen,
                                   const QVector<ExpectedServo> &expected);

// The servos the doctor expects on a port, remembered from the last time it was scanned.
// Kept with QSettings (group "doctor", keyed by port); empty when the port was never scanned.
QVector<ExpectedServo> rememberedServos(const QString &port);
void rememberServos(const QString &port, const QVector<ServoInfo> &servos);

} // namespace feetech
