// A simulated PTK servo: answers the eight queries, applies the twelve writes, ignores the rest.
#pragma once

#include "ptkframe.h"
#include "ptkparameters.h"
#include "simrefusal.h"
#include "virtualdevice.h"

#include <QSet>

namespace sim {

class VirtualPtkServo final : public VirtualDevice
{
public:
    static constexpr qint32 kBaudRate = 115200;

    // Starts with the seed's sample values (soft start off).
    VirtualPtkServo();

    const seriallink::FrameFormat &frameFormat() const override { return m_format; }
    QVector<Response> handleFrame(const QByteArray &frame, qint32 hostBaud, qint64 nowUs) override;

    const ptk::ParameterSet &values() const { return m_values; }
    void setValue(ptk::Parameter parameter, quint16 wireValue)
    {
        m_values.set(parameter, wireValue);
    }

    // Parses "gain=20,min_pulse_us=900" (user units) into the servo's values; false and *why
    // (BadPtkValues) when they do not parse.
    bool setValues(const QString &assignments, SimRefusal *why);

    // A servo that silently drops writes with this command byte (for Mismatch tests).
    void ignoreWrites(quint8 command) { m_ignoredWrites.insert(command); }

    quint64 writesApplied() const { return m_writesApplied; }

private:
    ptk::FrameFormat m_format;
    ptk::ParameterSet m_values;
    QSet<quint8> m_ignoredWrites;
    quint64 m_writesApplied = 0;
};

} // namespace sim
