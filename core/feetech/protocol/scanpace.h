// How long a scan waits for an ID that may be missing, from the answers this link has shown.
#pragma once

#include <QtGlobal>

#include <chrono>
#include <deque>

namespace feetech {

// A missing ID costs a scan its whole wait, so the wait follows the link: every answer a scan
// hears (the broadcast probe's, each servo's PING) says how long this port, adapter and machine
// took beyond the bytes' own wire time. The wait for the first byte of an answer is the wire
// time of the PING and its answer at the rate, plus three times the median of the recent
// extras (behind a USB adapter's packets, half as much again as the slowest, when that is
// less) and a margin, at least
// kMinimumExtra; never more than the caller's cap (what a scan
// waited before this). An answer that comes later all the same is not lost: the scan hears it
// during a later wait or between two, by its ID, and asks that ID again with a patient timeout.
class ScanPace
{
public:
    // How many recent answers count: enough that one fast outlier cannot set the pace.
    static constexpr std::size_t kWindow = 8;
    // What the median recent extra is multiplied by, and what is added to it.
    static constexpr double kFactor = 3.0;
    // From this typical extra on, a USB adapter's packets set the pace: the slowest recent
    // answer times kSlowestFactor is waited for when that is less than kFactor times the median.
    // (4 ms: well above what a busy machine adds, well below FTDI's 16 ms.)
    static constexpr std::chrono::microseconds kPacketedExtra {4000};
    static constexpr double kSlowestFactor = 1.5;
    static constexpr std::chrono::microseconds kMargin {100};
    // The least time allowed beyond the wire time: the OS waking the program up.
    static constexpr std::chrono::microseconds kMinimumExtra {200};

    // An answer to a PING at `baud` began `latency` after the request left (the echo's wire
    // time already taken off, as the request engine measures it).
    void noteAnswer(std::chrono::microseconds latency, qint32 baud);
    void clear() { m_extras.clear(); }
    bool measured() const { return !m_extras.empty(); }
    // The median of the recent times beyond the wire time (the upper one of an even count:
    // with two answers, the slower); zero before any answer.
    std::chrono::microseconds typicalExtra() const;
    // The wait for the first byte of a PING's answer at `baud`, from the moment the request
    // left, wire time included. Without a measurement it is the cap's.
    std::chrono::microseconds pingWait(qint32 baud, bool echo,
                                       std::chrono::microseconds extraCap) const;

    // Ten bit times per byte (8N1).
    static std::chrono::microseconds wireTime(int bytes, qint32 baud);
    // A PING and its answer on the wire, with the PING's echo on a single-wire adapter.
    static std::chrono::microseconds pingWireTime(qint32 baud, bool echo);

private:
    std::deque<std::chrono::microseconds> m_extras;
};

} // namespace feetech
