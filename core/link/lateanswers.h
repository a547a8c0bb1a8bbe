// What a request engine remembers of requests that went unanswered: the ones still offered their
// late answers, the answers owed, and whether the link answers at once.
#pragma once

#include <QByteArray>

#include <chrono>
#include <deque>
#include <functional>
#include <optional>

namespace seriallink {

// A frame that comes while no request can be answered by it (too soon, or between requests) may
// be the late answer of an earlier one. Time is the engine's clock, in microseconds.
class LateAnswers
{
public:
    // A request that ended without all its answers and recognises its late ones.
    struct EndedRequest
    {
        std::function<bool(const QByteArray &, std::chrono::microseconds)> lateAnswer;
        qint64 writtenAtUs = 0;
        qint64 endedAtUs = 0;
        std::chrono::microseconds wireTime {0}; // request, echo and expected answer
        QByteArray request;
        bool several = false; // answered by several frames (SYNC READ)
    };

    // It is offered the frames no request accounts for, for a while.
    void remember(EndedRequest ended);
    // Offers the frame to the requests remembered, the newest first: how long after its request
    // (beyond the wire time) it came, when one took it as its late answer. A frame equal to a
    // request is taken for its echo when `echoExpected`, and is no answer to it.
    std::optional<std::chrono::microseconds> take(const QByteArray &frame, qint64 nowUs,
                                                  bool echoExpected);

    // An earlier request's answer may still come: one that timed out having heard nothing, whose
    // answer a frame that comes too soon for the next request is taken to be. The debt lapses
    // after a while.
    void oweAnswer(qint64 nowUs);
    bool answerOwed(qint64 nowUs) const;
    void answerPaid();

    // A device that answers sooner than the wire allows while nothing was owed answers at once,
    // and sends no late answers (what it does not answer at once, it never answers). A late
    // answer unlearns it.
    void answeredAtOnce() { m_answersAtOnce = true; }
    void answeredLate() { m_answersAtOnce = false; }
    bool answersAtOnce() const { return m_answersAtOnce; }

    // Nothing remembered answers anything that follows (the queue was cancelled).
    void forgetRequests();
    // A new port, or the same one again: what the last one taught is forgotten too.
    void forgetLink();

private:
    std::deque<EndedRequest> m_ended; // newest last
    int m_answersOwed = 0;
    qint64 m_answersOwedUntilUs = 0;
    bool m_answersAtOnce = false;
};

} // namespace seriallink
