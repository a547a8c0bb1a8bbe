// USB serial adapter timing: FTDI's latency timer, CH34x and CP210x packets in 1 ms USB frames.
#include "usbadapter.h"

#include <algorithm>

namespace sim {

std::optional<AdapterProfile> adapterProfile(const QString &name)
{
    AdapterProfile profile;
    profile.name = name;
    if (name == QLatin1String("ftdi") || name == QLatin1String("ftdi-1ms")) {
        // FT232R: 64-byte packets of which two are modem status; a latency timer of 16 ms by
        // default, 1 ms once lowered (docs/hardware.md: "USB adapters and latency").
        profile.packetBytes = 62;
        profile.latencyTimerUs = name == QLatin1String("ftdi") ? 16000 : 1000;
        profile.jitterUs = 150;
        return profile;
    }
    if (name == QLatin1String("ch340")) {
        // 32-byte packets, sent once the line is quiet; the least regular of the four.
        profile.packetBytes = 32;
        profile.idleFlushUs = 200;
        profile.jitterUs = 400;
        profile.stallChance = 0.02;
        profile.stallFrames = 3;
        return profile;
    }
    if (name == QLatin1String("ch343")) {
        profile.packetBytes = 64;
        profile.idleFlushUs = 100;
        profile.jitterUs = 200;
        profile.stallChance = 0.005;
        profile.stallFrames = 2;
        return profile;
    }
    if (name == QLatin1String("cp2102")) {
        profile.packetBytes = 64;
        profile.idleFlushUs = 250;
        profile.jitterUs = 300;
        profile.stallChance = 0.01;
        profile.stallFrames = 2;
        return profile;
    }
    return std::nullopt;
}

QStringList adapterProfileNames()
{
    return {QStringLiteral("ideal"), QStringLiteral("ftdi"),  QStringLiteral("ftdi-1ms"),
            QStringLiteral("ch340"), QStringLiteral("ch343"), QStringLiteral("cp2102")};
}

UsbAdapter::UsbAdapter(const AdapterProfile &profile, quint32 seed)
    : m_profile(profile)
    , m_random(seed)
{ }

qint64 UsbAdapter::nextFrame(qint64 us) const
{
    const qint64 frame = m_profile.frameUs;
    if (frame <= 0)
        return us;
    return (us + frame - 1) / frame * frame;
}

qint64 UsbAdapter::requestOnWireUs(qint64 writtenUs) const
{
    return nextFrame(writtenUs);
}

void UsbAdapter::heard(qint64 wireUs, char byte)
{
    const auto at = std::upper_bound(m_held.begin(), m_held.end(), wireUs,
                                     [](qint64 us, const Held &held) { return us < held.wireUs; });
    m_held.insert(at, Held {wireUs, byte});
}

qint64 UsbAdapter::triggerUs() const
{
    // The moment the chip lets its first packet go, judged by the bytes the wire brings: every
    // byte is known before it arrives (the simulator schedules whole replies).
    const qint64 first = m_held.front().wireUs;
    qint64 trigger = kNever;
    const auto packet = std::size_t(std::max(1, m_profile.packetBytes));
    if (m_held.size() >= packet)
        trigger = m_held.at(packet - 1).wireUs; // a full packet goes at once
    if (m_profile.latencyTimerUs > 0) {
        const qint64 period = m_profile.latencyTimerUs;
        const qint64 since = first - m_timerStartUs;
        const qint64 periods = std::max<qint64>(1, (since + period - 1) / period);
        trigger = std::min(trigger, m_timerStartUs + periods * period);
    }
    if (m_profile.idleFlushUs > 0) {
        for (std::size_t i = 0; i < m_held.size() && i < packet; ++i) {
            const bool last = i + 1 == m_held.size();
            if (last || m_held.at(i + 1).wireUs - m_held.at(i).wireUs > m_profile.idleFlushUs) {
                trigger = std::min(trigger, m_held.at(i).wireUs + m_profile.idleFlushUs);
                break;
            }
        }
    }
    if (m_profile.latencyTimerUs <= 0 && m_profile.idleFlushUs <= 0)
        trigger = std::min(trigger, first); // whatever is held goes with the next frame
    return trigger;
}

qint64 UsbAdapter::nextDeliveryUs()
{
    if (m_held.empty())
        return kNever;
    if (!m_extraUs) {
        qint64 extra = m_profile.jitterUs > 0 ? m_random.bounded(m_profile.jitterUs + 1) : 0;
        const bool stalls = m_random.generateDouble() < m_profile.stallChance;
        if (stalls && m_profile.stallFrames > 0)
            extra += m_profile.frameUs * (1 + m_random.bounded(m_profile.stallFrames));
        m_extraUs = extra;
    }
    return nextFrame(triggerUs()) + *m_extraUs;
}

QByteArray UsbAdapter::takeDelivery(qint64 nowUs)
{
    const qint64 due = nextDeliveryUs();
    if (due == kNever || due > nowUs)
        return {};
    // The packet leaves the chip at the frame; what the wire brought by then goes with it.
    const qint64 handedOver = nextFrame(triggerUs());
    QByteArray packet;
    while (!m_held.empty() && packet.size() < m_profile.packetBytes
           && m_held.front().wireUs <= handedOver) {
        packet.append(m_held.front().byte);
        m_held.pop_front();
    }
    m_timerStartUs = handedOver;
    m_extraUs.reset();
    return packet;
}

void UsbAdapter::clear()
{
    m_held.clear();
    m_extraUs.reset();
}

} // namespace sim
