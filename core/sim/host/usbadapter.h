// How a USB serial adapter hands a servo's bytes to the computer: servosim's --adapter profiles.
#pragma once

#include <QByteArray>
#include <QRandomGenerator>
#include <QString>
#include <QStringList>

#include <deque>
#include <limits>
#include <optional>

namespace sim {

// A pty hands every byte over the moment it is written. A USB adapter does not: the computer
// asks it for input once per USB frame (1 ms at full speed), and the chip holds what the line
// brought until a packet is full or its own rule lets the bytes go.
struct AdapterProfile
{
    QString name;
    qint64 frameUs = 1000; // the host asks for input once per USB frame, in both directions
    int packetBytes = 64; // the most one packet carries to the host
    // FTDI: what the chip holds goes when this timer runs out; the timer starts again with every
    // packet, also the empty ones it sends when there is nothing to say. 0: no such timer.
    qint64 latencyTimerUs = 0;
    // CH34x and CP210x: what the chip holds goes once the line has been quiet this long.
    qint64 idleFlushUs = 0;
    qint64 jitterUs = 0; // a packet reaches the program up to this much later (the USB stack)
    // Now and then a packet misses its frame (a busy hub, the host controller) and goes in one
    // of the next `stallFrames` frames instead.
    double stallChance = 0.0;
    int stallFrames = 0;
};

// ftdi (16 ms latency timer, the default), ftdi-1ms, ch340, ch343, cp2102; nothing for another
// name. "ideal" is no profile: the pty's own timing; nor is "instant", a device with no wire
// time at all (SimulatorOptions::instant).
std::optional<AdapterProfile> adapterProfile(const QString &name);
QStringList adapterProfileNames(); // the names adapterProfile() knows, "ideal" first

// The adapter between the simulated bus and the pty: takes each byte as it finishes crossing
// the wire and gives it to the program in packets, when the profile says. Deterministic for a
// seed. Times are the simulator's microseconds.
class UsbAdapter
{
public:
    UsbAdapter(const AdapterProfile &profile, quint32 seed);

    const AdapterProfile &profile() const { return m_profile; }
    // When bytes the program writes at `writtenUs` begin to cross the wire: they leave the
    // computer with the next USB frame.
    qint64 requestOnWireUs(qint64 writtenUs) const;
    // A byte that finished crossing the wire at `wireUs` (in any order of time).
    void heard(qint64 wireUs, char byte);
    // When the next packet reaches the program; the largest time when nothing is held.
    qint64 nextDeliveryUs();
    // The packet due by `nowUs`, taken out of the adapter; empty when none is due.
    QByteArray takeDelivery(qint64 nowUs);
    void clear();

    static constexpr qint64 kNever = std::numeric_limits<qint64>::max();

private:
    struct Held
    {
        qint64 wireUs = 0;
        char byte = 0;
    };
    qint64 nextFrame(qint64 us) const;
    qint64 triggerUs() const;

    AdapterProfile m_profile;
    QRandomGenerator m_random;
    std::deque<Held> m_held;
    qint64 m_timerStartUs = 0; // FTDI: when its latency timer last started
    std::optional<qint64> m_extraUs; // the next packet's jitter and stall, drawn once
};

} // namespace sim
