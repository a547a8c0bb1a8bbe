// Request engine: late answers (matched to the requests they answer), input between requests,
// and the default wait that follows the slow end of the link's answers.
#include "requestengine.h"

#include "transport.h"

#include <QCoreApplication>

#include <algorithm>
#include <vector>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(RequestEngine)
};

} // namespace

namespace seriallink {

namespace {

// How long ended transactions are offered late answers.
constexpr qint64 kLateAnswerMemoryUs = 1'000'000;
// The default wait follows this many recent answers, with this factor and margin, and grows to
// no more than kLongestGrownWait: a link slower than that is broken, not slow.
constexpr std::size_t kAnswerTimes = 32;
constexpr double kSlowEndFactor = 1.5;
constexpr std::chrono::microseconds kSlowEndMargin {2000};
constexpr std::chrono::microseconds kLongestGrownWait {250000};

} // namespace

std::optional<std::chrono::microseconds> slowEnd(const std::deque<std::chrono::microseconds> &times)
{
    if (times.empty())
        return std::nullopt;
    std::vector<std::chrono::microseconds> sorted(times.begin(), times.end());
    std::sort(sorted.begin(), sorted.end());
    return sorted.at((sorted.size() - 1) * 95 / 100);
}

bool RequestEngine::takeLateAnswer(const QByteArray &frame)
{
    const qint64 now = m_clock.nsecsElapsed() / 1000;
    while (!m_ended.empty() && now - m_ended.front().endedAtUs > kLateAnswerMemoryUs)
        m_ended.pop_front();
    // The newest first: a servo that answers late answers the request that asked it last.
    for (auto ended = m_ended.rbegin(); ended != m_ended.rend(); ++ended) {
        // Our own request coming back is no answer to it (a Feetech request decodes like one).
        if (frame == ended->request && echoExpected())
            continue;
        const auto after =
            std::max(std::chrono::microseconds(0),
                     std::chrono::microseconds(now - ended->writtenAtUs) - ended->wireTime);
        if (!ended->lateAnswer(frame, after))
            continue;
        // A request one servo answers is answered once.
        if (!ended->several)
            m_ended.erase(std::next(ended).base());
        noteAnswerTime(after);
        ++m_counters.lateReplies;
        log(Direction::In, frame, {},
            Tr::tr("late answer, %1 ms after its request")
                .arg(double(after.count()) / 1000.0, 0, 'f', 1));
        return true;
    }
    return false;
}

void RequestEngine::onInputBetweenRequests(const QByteArray &bytes, const QString &why)
{
    // Frame by frame: a late answer is no stray input. What forms no frame yet stays in the
    // framer (the rest of a late answer may follow) until the next request goes out.
    const bool settling = m_state == State::Settling;
    m_framer.append(bytes);
    QByteArray stray;
    while (auto item = m_framer.next()) {
        if (item->kind == StreamItem::Kind::Frame) {
            if (item->bytes == m_lastRequest && !m_echoConsumed && echoExpected()) {
                // The echo of the last request, after its exchange had ended.
                m_echoConsumed = true;
                m_counters.echoBytes += item->bytes.size();
                log(Direction::Echo, item->bytes, {}, Tr::tr("late"));
                continue;
            }
            if (takeLateAnswer(item->bytes)) {
                m_answersAtOnce = false; // this link does answer late
                continue;
            }
            // Whatever comes while nothing waits may be the answer an earlier request is owed.
            answerPaid();
            if (settling) {
                m_answersAtOnce = false;
                // The engine holds requests back after a timeout precisely for this answer.
                noteAnswerTime(std::max(
                    std::chrono::microseconds(0),
                    std::chrono::microseconds(m_clock.nsecsElapsed() / 1000 - m_writtenAtUs)
                        - m_replyWireTime - wireTime(int(item->bytes.size()))));
                ++m_counters.lateReplies;
                m_counters.discardedBytes += item->bytes.size();
                log(Direction::In, item->bytes, {}, Tr::tr("late answer, discarded"));
                continue;
            }
        }
        stray += item->bytes;
    }
    if (!stray.isEmpty()) {
        m_counters.discardedBytes += stray.size();
        log(Direction::Stray, stray, why);
    }
    publishCounters();
}

void RequestEngine::oweAnswer()
{
    ++m_answersOwed;
    m_answersOwedUntilUs = m_clock.nsecsElapsed() / 1000 + kLateAnswerMemoryUs;
}

bool RequestEngine::answerOwed() const
{
    return m_answersOwed > 0 && !m_answersAtOnce
        && m_clock.nsecsElapsed() / 1000 < m_answersOwedUntilUs;
}

void RequestEngine::answerPaid()
{
    if (m_answersOwed > 0)
        --m_answersOwed;
}

std::chrono::microseconds RequestEngine::replyTimeout() const
{
    if (m_current && m_current->replyTimeout)
        return *m_current->replyTimeout;
    // Behind an adapter that holds answers back (FTDI's latency timer, an echo and its answer
    // in two of its packets), the set time may be too short: the slow end of the answers says.
    const auto slow = slowEnd(m_answerTimes);
    if (!slow)
        return m_timing.replyTimeout;
    const auto bySlowEnd =
        std::chrono::microseconds(qint64(double(slow->count()) * kSlowEndFactor)) + kSlowEndMargin;
    return std::max<std::chrono::microseconds>(m_timing.replyTimeout,
                                               std::min(bySlowEnd, kLongestGrownWait));
}

void RequestEngine::noteAnswerTime(std::chrono::microseconds time)
{
    // An answer slower than any wait may grow to says nothing about the link's pace (a servo
    // that was busy, bytes measured from a request long gone).
    if (time > kLongestGrownWait)
        return;
    m_answerTimes.push_back(time);
    while (m_answerTimes.size() > kAnswerTimes)
        m_answerTimes.pop_front();
}

} // namespace seriallink
