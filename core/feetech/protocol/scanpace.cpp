// The scan's wait per ID: wire time plus what the link's recent answers took beyond it.
#include "scanpace.h"

#include "feetechpacket.h"

#include <algorithm>
#include <vector>

namespace feetech {

std::chrono::microseconds ScanPace::wireTime(int bytes, qint32 baud)
{
    return std::chrono::microseconds(qint64(bytes) * 10 * 1'000'000 / std::max(baud, 1));
}

std::chrono::microseconds ScanPace::pingWireTime(qint32 baud, bool echo)
{
    // A PING and its answer without parameters are both the shortest packet.
    return wireTime(kMinimumPacketSize * (echo ? 3 : 2), baud);
}

void ScanPace::noteAnswer(std::chrono::microseconds latency, qint32 baud)
{
    // The engine measures from the request leaving the program to the first byte of the
    // answer: the PING's and the answer's wire time are in it (a pty, like many adapters,
    // hands the answer over whole). What is left is the servo's, the adapter's and the OS's.
    const auto extra = std::max(std::chrono::microseconds(0), latency - pingWireTime(baud, false));
    m_extras.push_back(extra);
    while (m_extras.size() > kWindow)
        m_extras.pop_front();
}

std::chrono::microseconds ScanPace::typicalExtra() const
{
    if (m_extras.empty())
        return std::chrono::microseconds(0);
    // The median: the first exchange on a fresh port, or one that met a busy moment, can take
    // a hundred times the usual; it must not set the pace of the whole scan (its like is
    // what the late-answer recheck is there for).
    std::vector<std::chrono::microseconds> sorted(m_extras.begin(), m_extras.end());
    std::sort(sorted.begin(), sorted.end());
    return sorted.at(sorted.size() / 2);
}

std::chrono::microseconds ScanPace::pingWait(qint32 baud, bool echo,
                                             std::chrono::microseconds extraCap) const
{
    std::chrono::microseconds extra = extraCap;
    if (measured()) {
        // Three times the median. Behind a USB adapter that holds answers back for its packet
        // (FTDI's latency timer), every answer waits about equally long and three times that would
        // only slow the scan down: half as much again as the slowest is enough there. Below that
        // the OS's wake-up sets the extra, and it varies too much for the slowest to tell.
        const auto typical = typicalExtra();
        qint64 byAnswers = qint64(double(typical.count()) * kFactor);
        if (typical >= kPacketedExtra) {
            const auto slowest = *std::max_element(m_extras.begin(), m_extras.end());
            byAnswers = std::min(byAnswers, qint64(double(slowest.count()) * kSlowestFactor));
        }
        const auto scaled = std::chrono::microseconds(byAnswers + kMargin.count());
        extra = std::min(std::max(scaled, kMinimumExtra), extraCap);
    }
    return pingWireTime(baud, echo) + extra;
}

} // namespace feetech
