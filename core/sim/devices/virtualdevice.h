// What the simulator's transport needs from a simulated device: frame format and replies.
#pragma once

#include "streamframer.h"

#include <QByteArray>
#include <QVector>

namespace sim {

// One reply on the bus. `turnaroundUs` is the silence before its first byte, counted from the
// end of the request (or of the reply before it): the servo's return delay.
struct Response
{
    QByteArray bytes;
    qint64 turnaroundUs = 0;
};

class VirtualDevice
{
public:
    virtual ~VirtualDevice() = default;

    virtual const seriallink::FrameFormat &frameFormat() const = 0;

    // A complete, checksum-valid frame from the host, sent at `hostBaud` bits per second and
    // fully received at `nowUs` (simulator clock, microseconds). A device with motion brings
    // itself up to `nowUs` first. Returns the replies in the order they go out on the bus; a
    // device at another baud rate hears only noise.
    virtual QVector<Response> handleFrame(const QByteArray &frame, qint32 hostBaud,
                                          qint64 nowUs) = 0;

    // Lets time pass (motion, temperature) while the host is silent; called periodically.
    virtual void advanceTo(qint64 nowUs) { Q_UNUSED(nowUs); }

    // Power off and on again: EEPROM values are reloaded, RAM returns to its power-on state.
    virtual void powerCycle() { }
};

} // namespace sim
