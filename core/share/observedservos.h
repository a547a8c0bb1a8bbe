// What a shared bus's traffic has shown of each servo: its memory as read and written, its model.
#pragma once

#include "bustypes.h"
#include "sharedtransaction.h"
#include "telemetry.h"

#include <QBitArray>
#include <QByteArray>
#include <QMap>

#include <optional>

namespace share {

// Every READ answer, SYNC READ answer, WRITE and SYNC WRITE that passes goes into a copy of
// the servo's memory; once addresses 3-4 have been seen (a program reads the model number
// when it connects; the watch reads it) the servo's table gives the bytes their meaning.
class ObservedServos
{
public:
    // Learns from a transaction and fills its `registers` where the model is known.
    void learn(SharedTransaction &transaction, qint32 baud);

    // The servos that have answered, in ID order.
    QVector<quint8> ids() const;
    bool answered(quint8 id) const;
    // Its table, once its model is known.
    const feetech::RegisterTable *table(quint8 id) const;
    // What addresses 0-8 said, once all of them have been seen.
    std::optional<feetech::ServoInfo> info(quint8 id) const;
    // What is known of it once its model is: info() when addresses 0-8 have all been seen,
    // else its ID, rate and model (a program reads the model number alone when it connects).
    std::optional<feetech::ServoInfo> knownServo(quint8 id) const;
    // A register's last value, when its bytes have been seen and the model is known.
    std::optional<qint32> value(quint8 id, QStringView key) const;
    // A register's last value in its unit (raw times the table's scale).
    std::optional<double> scaled(quint8 id, QStringView key) const;
    // The feedback block as one sample, when the transaction just learned read all of it.
    std::optional<feetech::FeedbackSample> feedback(quint8 id, qint64 steadyUs) const;
    // Whether the bytes [address, address + size) of `id` have been seen.
    bool known(quint8 id, int address, int size) const;

private:
    struct Servo
    {
        QByteArray memory = QByteArray(256, '\0');
        QBitArray seen = QBitArray(256);
        qint32 baud = 0;
        bool answered = false; // writes alone do not prove a servo is there
    };

    // Copies bytes into the servo's memory and lists the registers they cover.
    void store(SharedTransaction &transaction, quint8 id, int address, const QByteArray &bytes,
               bool written);
    Servo &servo(quint8 id, qint32 baud);

    QMap<quint8, Servo> m_servos;
};

} // namespace share
