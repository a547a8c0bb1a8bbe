// Live telemetry of Feetech servos: the feedback block decoded into samples, stream settings and
// statistics, and the CSV form of a recording.
#pragma once

#include "registertable.h"

#include <QByteArrayView>
#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QVector>

#include <array>
#include <chrono>
#include <optional>

namespace feetech {

struct ServoInfo;

// What a sample measures, each in one unit for every family (see quantityUnit).
enum class Quantity { Position, Speed, Load, Voltage, Temperature, Current };
constexpr int kQuantityCount = 6;
constexpr Quantity kAllQuantities[kQuantityCount] = {Quantity::Position,    Quantity::Speed,
                                                     Quantity::Load,        Quantity::Voltage,
                                                     Quantity::Temperature, Quantity::Current};

QString quantityKey(Quantity quantity); // "position", "speed", ... (CSV, JSON, command line)
QString quantityName(Quantity quantity); // translated: "Position"
QString quantityUnit(Quantity quantity); // translated: "step", "step/s", "%", "V", "°C", "mA"
std::optional<Quantity> quantityFromKey(QStringView key);

struct FeedbackSample
{
    quint8 id = 0;
    qint32 baud = 0;
    // When the reply was in: microseconds of the steady clock (std::chrono::steady_clock), the
    // same clock in every thread, so a GUI action can be placed on the samples' time line.
    qint64 steadyUs = 0;
    // In the quantity's unit; nothing where the servo's family does not report it in that unit
    // (SCS current has no documented scale): a value is never made up.
    std::array<std::optional<double>, kQuantityCount> values;
    quint8 servoStatus = 0; // register 65: the protection bits that tripped
    bool moving = false; // register 66
    quint8 replyStatus = 0; // the status byte of the reply

    std::optional<double> value(Quantity quantity) const { return values.at(int(quantity)); }
};

// The feedback block of one servo (the table's feedbackBlock()); nothing when `bytes` is short.
std::optional<FeedbackSample> decodeFeedback(const RegisterTable &table, quint8 id, qint32 baud,
                                             qint64 steadyUs, QByteArrayView bytes,
                                             quint8 replyStatus);
// The quantities that `bytes`, read from `address` on, cover (a program that reads only the
// positions, say); the others stay empty. Nothing when they cover none.
std::optional<FeedbackSample> decodeFeedbackPart(const RegisterTable &table, quint8 id, qint32 baud,
                                                 qint64 steadyUs, int address, QByteArrayView bytes,
                                                 quint8 replyStatus);
qint64 steadyMicroseconds(); // now, on the samples' clock

// The names of the servo-status bits that are set ("voltage, overload"), or "none".
QString servoStatusText(const RegisterTable &table, quint8 servoStatus);

// Whether the family answers SYNC READ (spec §2.4: STS, SMS and HLS do; SCS does not).
bool supportsSyncRead(const ServoInfo &servo);

struct ServoTelemetry
{
    quint8 id = 0;
    qint32 baud = 0;
    qint64 samples = 0;
    qint64 missed = 0; // cycles in which it was asked and its answer never came
    qint64 late = 0; // answers that came after their wait (still taken as samples)
    bool missing = false; // out of the cycle, asked alone now and then
};

struct TelemetryStats
{
    quint64 stream = 0; // TelemetryOptions::stream of the stream they describe
    bool running = false;
    qint64 cycles = 0;
    qint64 samples = 0;
    qint64 missed = 0;
    qint64 late = 0;
    double elapsedSeconds = 0.0;
    double cyclesPerSecond = 0.0; // over the last second
    double samplesPerSecond = 0.0; // over the last second, all servos together
    QVector<ServoTelemetry> servos;
};

// ---- CSV: one row per sample; empty cells where a value is not reported.

// time_s,id,position_step,speed_step_per_s,load_percent,voltage_v,temperature_c,current_ma,
// status,moving
QString telemetryCsvHeader();
// `startUs`: the steady time that becomes time 0 of the recording.
QString telemetryCsvRow(const FeedbackSample &sample, qint64 startUs);

struct CsvSample
{
    double timeSeconds = 0.0;
    int id = 0;
    std::array<std::optional<double>, kQuantityCount> values;
    int servoStatus = 0;
    bool moving = false;
};
// Parses a recording written with the functions above; nothing and *error (with the line
// number) when it is not one.
std::optional<QVector<CsvSample>> parseTelemetryCsv(const QString &text, QString *error);

} // namespace feetech

Q_DECLARE_METATYPE(feetech::FeedbackSample)
Q_DECLARE_METATYPE(feetech::TelemetryStats)
