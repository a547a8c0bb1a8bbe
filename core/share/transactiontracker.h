// Pairs the requests on a shared bus with the answers the bus gave, as the bytes pass.
#pragma once

#include "sharedtransaction.h"
#include "streamframer.h"

#include <chrono>
#include <functional>
#include <optional>

namespace share {

// Sees frames only, never touches the bytes: the share forwards them as they come and shows
// this tracker the same frames. A request is outstanding until its answers are all in, its
// time is up, or the next request comes (its sender has given up waiting). One whose time ran
// out is completed only once its missing answers came late, the next request came, or half a
// second passed: what it reports is what its sender really got. A frame equal to
// the request before any answer is the adapter's echo; the first request tells whether the
// adapter echoes, and the answer then waits for it.
class TransactionTracker
{
public:
    using Completed = std::function<void(SharedTransaction &&transaction)>;

    explicit TransactionTracker(Completed completed);

    // For the wire time in each request's wait.
    void setBaudRate(qint32 baud) { m_baud = baud > 0 ? baud : m_baud; }
    // How long an answer may take beyond its wire time before the request counts unanswered.
    void setAnswerWait(std::chrono::microseconds wait) { m_answerWait = wait; }
    // Whether the adapter sends every byte back (nothing: not known yet).
    std::optional<bool> echoes() const { return m_echoes; }
    void setEchoes(std::optional<bool> echoes) { m_echoes = echoes; }
    // The transactions it completes are ServoBench's own.
    void setOwn(bool own) { m_own = own; }

    // Whether a request frame is answered at all (a broadcast other than PING, and a SYNC
    // WRITE, are not).
    static bool isAnswered(const QByteArray &frame);
    // A whole request frame left for the bus at `nowUs`; one still outstanding ends first.
    void request(const QByteArray &frame, qint64 nowUs);
    // A piece the bus sent back: a frame, a frame with a bad checksum, or bytes that are none.
    void heard(const seriallink::StreamItem &item, qint64 nowUs);
    // Ends the outstanding request when its time is up, and the late one when its time is;
    // true when either ended.
    bool expire(qint64 nowUs);

    bool isOutstanding() const { return m_current.has_value(); }
    // Whether a request whose time ran out may still be answered (see the class comment).
    bool hasLate() const { return m_late.has_value(); }
    // Whether `frame` is what the outstanding request waits for (its echo, or an answer from an
    // ID it asked with the size its answer has), or a late answer to the request before. A
    // frame neither asked for (an answer to another's request) is not, whatever its timing.
    bool claims(const QByteArray &frame) const;
    // When expire() should be called next; nothing while no request is outstanding or late.
    std::optional<qint64> deadlineUs() const;

    qint64 strayFrames() const { return m_strayFrames; }
    qint64 strayBytes() const { return m_strayBytes; }

private:
    struct Outstanding
    {
        SharedTransaction transaction;
        QVector<quint8> ids; // who may answer; empty: anyone (a broadcast PING)
        int replySize = 0; // the answers' bytes together, for the wire time
        int answerSize = 0; // one answer's frame; 0: any (a WRITE's status, a PING's)
        bool echoSeen = false;
    };

    void complete();
    bool isAnswer(const QByteArray &frame) const;
    qint64 wireTimeUs(int bytes) const;

    // A request whose time ran out before every answer came: the bus is free for another, but
    // its sender (whose own wait is longer) may still get them, until it sends its next request.
    struct Late
    {
        SharedTransaction transaction;
        QVector<quint8> ids; // who has not answered yet
        int answerSize = 0;
        qint64 untilUs = 0; // after this, what is missing never came
    };
    // Whether `frame` answers the late request (an ID it still waits for, the answer's size).
    bool isLateAnswer(const QByteArray &frame) const;
    // An answer to the late request; true when it was one.
    bool heardLate(const QByteArray &frame, qint64 nowUs);
    // The late request is complete as it is: answered late, or not at all.
    void endLate();

    Completed m_completed;
    std::optional<Late> m_late;
    std::optional<Outstanding> m_current;
    std::optional<bool> m_echoes;
    qint32 m_baud = 1000000;
    std::chrono::microseconds m_answerWait {30000};
    bool m_own = false;
    qint64 m_strayFrames = 0;
    qint64 m_strayBytes = 0;
};

} // namespace share
