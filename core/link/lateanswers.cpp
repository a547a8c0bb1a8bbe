// Late answers: the requests they may answer, the answers owed, and how long both are kept.
#include "lateanswers.h"

#include <algorithm>
#include <iterator>

namespace seriallink {

namespace {

// How many ended requests are offered late answers, and for how long; how long an owed answer
// is waited for.
constexpr std::size_t kLateAnswerMemory = 8;
constexpr qint64 kLateAnswerMemoryUs = 1'000'000;

} // namespace

void LateAnswers::remember(EndedRequest ended)
{
    m_ended.push_back(std::move(ended));
    while (m_ended.size() > kLateAnswerMemory)
        m_ended.pop_front();
}

std::optional<std::chrono::microseconds> LateAnswers::take(const QByteArray &frame, qint64 nowUs,
                                                           bool echoExpected)
{
    while (!m_ended.empty() && nowUs - m_ended.front().endedAtUs > kLateAnswerMemoryUs)
        m_ended.pop_front();
    // The newest first: a servo that answers late answers the request that asked it last.
    for (auto ended = m_ended.rbegin(); ended != m_ended.rend(); ++ended) {
        // Our own request coming back is no answer to it (a Feetech request decodes like one).
        if (frame == ended->request && echoExpected)
            continue;
        const auto after =
            std::max(std::chrono::microseconds(0),
                     std::chrono::microseconds(nowUs - ended->writtenAtUs) - ended->wireTime);
        if (!ended->lateAnswer(frame, after))
            continue;
        // A request one servo answers is answered once.
        if (!ended->several)
            m_ended.erase(std::next(ended).base());
        return after;
    }
    return std::nullopt;
}

void LateAnswers::oweAnswer(qint64 nowUs)
{
    ++m_answersOwed;
    m_answersOwedUntilUs = nowUs + kLateAnswerMemoryUs;
}

bool LateAnswers::answerOwed(qint64 nowUs) const
{
    return m_answersOwed > 0 && !m_answersAtOnce && nowUs < m_answersOwedUntilUs;
}

void LateAnswers::answerPaid()
{
    if (m_answersOwed > 0)
        --m_answersOwed;
}

void LateAnswers::forgetRequests()
{
    m_ended.clear();
    m_answersOwed = 0;
}

void LateAnswers::forgetLink()
{
    forgetRequests();
    m_answersAtOnce = false;
}

} // namespace seriallink
