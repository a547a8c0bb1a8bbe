// A servo's health: what the health check read of it, and the verdict (ok, warning, fault) with
// its reasons, each a finding with a stable code and a message for the user.
#pragma once

#include "bustypes.h"
#include "stepresponse.h"
#include "telemetry.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QMetaType>
#include <QString>
#include <QVector>

#include <optional>

namespace feetech {

// The feedback reads a check makes of each servo, unless asked otherwise.
constexpr int kDefaultHealthReads = 20;

// How the repeated reads of one servo went: the link's counters over those reads only.
struct CommQuality
{
    int reads = 0; // asked
    int answered = 0; // answered, after retries or not
    qint64 retries = 0;
    qint64 timeouts = 0; // each try without a valid reply
    qint64 checksumErrors = 0;

    bool clean() const
    {
        return answered == reads && retries == 0 && timeouts == 0 && checksumErrors == 0;
    }
};

// What the check read of one servo. Limits in real units (V, °C, steps, %), as its table scales
// them; nothing where the family has no such register or the read failed.
struct HealthReading
{
    ServoInfo servo;
    QString failure; // its settings could not be read: nothing else is known
    std::optional<double> minVoltage;
    std::optional<double> maxVoltage;
    std::optional<double> maxTemperature;
    std::optional<double> minAngle;
    std::optional<double> maxAngle;
    std::optional<double> overloadPercent; // overload_torque: the load at which it protects itself
    QVector<FeedbackSample> samples; // the answered feedback reads
    CommQuality comm;
};

// A short move made only after a confirmation, and how the servo followed it.
struct MoveTestResult
{
    quint8 id = 0;
    qint32 baud = 0;
    bool ok = false; // moved, measured and put back as it was
    OperationFailure failure = OperationFailure::None; // why not, when !ok
    QString message; // what happened, for the user
    qint32 start = 0; // steps: where it stood (and stands again)
    qint32 target = 0;
    std::optional<StepMetrics> metrics;
};

enum class Verdict { Ok, Warning, Fault };
QString verdictKey(Verdict verdict); // "ok", "warning", "fault"
QString verdictName(Verdict verdict); // translated: "OK", "Warning", "Fault"

struct HealthFinding
{
    QString code; // stable: "voltage-high", "status-temperature", "firmware-mismatch", ...
    QString message; // translated
    Verdict severity = Verdict::Warning;
};

// A servo's verdict: the worst of its findings' severities (ok without any).
struct ServoHealth
{
    quint8 id = 0;
    qint32 baud = 0;
    QString model;
    QString firmware;
    Verdict verdict = Verdict::Ok;
    QVector<HealthFinding> findings;
    std::optional<double> voltage; // the mean of the reads
    std::optional<double> temperature; // the highest read
    std::optional<double> load; // the mean of |load|, %
    std::optional<double> position; // the last read, steps
    quint8 status = 0; // the status bits seen in any read
    QString statusText; // their names ("none")
    CommQuality comm;
    std::optional<MoveTestResult> move;

    void add(const QString &code, Verdict severity, const QString &message);
};

// Thresholds of the verdict; the defaults are what the report states.
struct HealthLimits
{
    double voltageMargin = 0.05; // of the limit: this close to min or max voltage is a warning
    double temperatureMargin = 10.0; // °C below the maximum: a warning
    double loadWarningPercent = 80.0; // at rest, when overload_torque was not read
    double overshootWarningPercent = 10.0; // move test
    double steadyErrorWarning = 10.0; // steps, move test
};

// The verdict of one servo from what was read (firmware mismatches come from flagFirmware).
ServoHealth assessHealth(const HealthReading &reading, const HealthLimits &limits = {});
// Adds the move test's outcome and findings.
void addMoveTest(ServoHealth &health, const MoveTestResult &move, const HealthLimits &limits = {});
// Servos of one model with different firmware: each of them gets a firmware-mismatch warning
// naming the others.
void flagFirmwareMismatches(QVector<ServoHealth> &servos);
bool anyFault(const QVector<ServoHealth> &servos);

// The CLI's and the report's JSON: {"id", "baud", "model", "verdict", "findings": [{"code",
// "message", "severity"}], "voltage", "temperature", "firmware", "load", "position", "status",
// "comm": {...}, "move": {...}}; null for what was not read.
QJsonObject healthJson(const ServoHealth &health);
QJsonArray healthJson(const QVector<ServoHealth> &servos);
// "20/20 answered, 0 retries, 0 timeouts, 0 checksum errors"
QString commText(const CommQuality &comm);
// "rise 0.120 s, overshoot 2.0 %, steady-state error 1 step"; "not measured" when none.
QString moveText(const MoveTestResult &move);

} // namespace feetech

Q_DECLARE_METATYPE(feetech::HealthReading)
Q_DECLARE_METATYPE(feetech::MoveTestResult)
