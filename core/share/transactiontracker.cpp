// Pairs the requests on a shared bus with their answers: echo, answers, time up.
#include "transactiontracker.h"

#include "feetechpacket.h"

namespace share {

namespace {

constexpr int kStatusOverhead = 6; // header, ID, length, error, checksum
// A request nothing answers may still come back as the echo: how long past its wire time.
constexpr qint64 kEchoAllowanceUs = 2000;
// How long past its time a request's missing answers still count as its sender's: longer than
// any program waits (the SDKs wait some tens of milliseconds; LeRobot's bus code about as long).
constexpr qint64 kLateAnswersUs = 500000;

using feetech::Instruction;

bool is(quint8 code, Instruction instruction)
{
    return code == quint8(instruction);
}

} // namespace

TransactionTracker::TransactionTracker(Completed completed)
    : m_completed(std::move(completed))
{ }

bool TransactionTracker::isAnswered(const QByteArray &frame)
{
    SharedTransaction transaction;
    transaction.request = frame;
    const quint8 code = transaction.instruction();
    if (is(code, Instruction::SyncRead))
        return !transaction.askedIds().isEmpty();
    if (transaction.id() == feetech::kBroadcastId)
        return is(code, Instruction::Ping);
    return !is(code, Instruction::SyncWrite);
}

void TransactionTracker::request(const QByteArray &frame, qint64 nowUs)
{
    if (m_current)
        complete();
    endLate(); // its sender gave up on answers still to come
    Outstanding outstanding;
    outstanding.transaction.timeUs = nowUs;
    outstanding.transaction.request = frame;
    outstanding.transaction.own = m_own;
    const quint8 id = outstanding.transaction.id();
    const quint8 code = outstanding.transaction.instruction();
    const int parameters = int(frame.size()) - kStatusOverhead;
    int expected = 0;
    if (is(code, Instruction::SyncRead)) {
        outstanding.ids = outstanding.transaction.askedIds();
        expected = int(outstanding.ids.size());
        const int length = parameters >= 2 ? quint8(frame.at(6)) : 0;
        outstanding.replySize = expected * (kStatusOverhead + length);
        outstanding.answerSize = kStatusOverhead + length;
    } else if (id == feetech::kBroadcastId) {
        // A broadcast PING is answered by every servo, each when it likes; nothing else is.
        expected = is(code, Instruction::Ping) ? -1 : 0;
        outstanding.replySize = is(code, Instruction::Ping) ? kStatusOverhead : 0;
    } else if (is(code, Instruction::SyncWrite)) {
        expected = 0;
    } else {
        outstanding.ids = {id};
        expected = 1;
        const int length = is(code, Instruction::Read) && parameters >= 2 ? quint8(frame.at(6)) : 0;
        outstanding.replySize = kStatusOverhead + length;
        outstanding.answerSize = is(code, Instruction::Read) ? outstanding.replySize : 0;
    }
    outstanding.transaction.expectedReplies = expected;
    m_current = std::move(outstanding);
    if (expected == 0 && m_echoes == false)
        complete(); // nothing comes back for it
}

void TransactionTracker::heard(const seriallink::StreamItem &item, qint64 nowUs)
{
    if (!m_current) {
        if (item.kind == seriallink::StreamItem::Kind::Frame && heardLate(item.bytes, nowUs))
            return;
        ++m_strayFrames;
        m_strayBytes += item.bytes.size();
        return;
    }
    SharedTransaction &transaction = m_current->transaction;
    if (item.kind != seriallink::StreamItem::Kind::Frame) {
        transaction.garbledBytes += int(item.bytes.size());
        return;
    }
    if (!m_current->echoSeen && transaction.replies.isEmpty() && m_echoes != false
        && item.bytes == transaction.request) {
        // The adapter's echo (a PING answered with its very bytes is told apart only once the
        // adapter is known not to echo).
        m_current->echoSeen = true;
        m_echoes = true;
        transaction.echoBytes = int(item.bytes.size());
        if (transaction.expectedReplies == 0)
            complete();
        return;
    }
    if (!isAnswer(item.bytes)) {
        if (heardLate(item.bytes, nowUs))
            return;
        ++m_strayFrames;
        m_strayBytes += item.bytes.size();
        return;
    }
    if (!m_current->echoSeen && !m_echoes)
        m_echoes = false;
    transaction.replies.append(item.bytes);
    transaction.roundTripUs = nowUs - transaction.timeUs;
    if (transaction.expectedReplies > 0
        && transaction.replies.size() >= transaction.expectedReplies)
        complete();
}

bool TransactionTracker::claims(const QByteArray &frame) const
{
    if (frame.size() < kStatusOverhead)
        return false;
    if (m_current) {
        if (frame == m_current->transaction.request)
            return true; // the adapter's echo
        if (isAnswer(frame)
            && (m_current->answerSize == 0 || frame.size() == m_current->answerSize))
            return true;
    }
    return isLateAnswer(frame);
}

bool TransactionTracker::isLateAnswer(const QByteArray &frame) const
{
    return m_late && frame.size() >= kStatusOverhead && m_late->ids.contains(quint8(frame.at(2)))
        && (m_late->answerSize == 0 || frame.size() == m_late->answerSize);
}

bool TransactionTracker::isAnswer(const QByteArray &frame) const
{
    if (frame.size() < kStatusOverhead)
        return false;
    const quint8 id = quint8(frame.at(2));
    return m_current->ids.isEmpty() ? m_current->transaction.expectedReplies != 0
                                    : m_current->ids.contains(id);
}

std::optional<qint64> TransactionTracker::deadlineUs() const
{
    if (!m_current)
        return m_late ? std::optional<qint64>(m_late->untilUs) : std::nullopt;
    const SharedTransaction &transaction = m_current->transaction;
    const int requestSize = int(transaction.request.size());
    if (transaction.expectedReplies == 0)
        return transaction.timeUs + wireTimeUs(2 * requestSize) + kEchoAllowanceUs;
    const int echoSize = m_echoes == false ? 0 : requestSize;
    return transaction.timeUs + wireTimeUs(requestSize + echoSize + m_current->replySize)
        + m_answerWait.count();
}

bool TransactionTracker::expire(qint64 nowUs)
{
    bool ended = false;
    if (m_current) {
        const std::optional<qint64> deadline = deadlineUs();
        if (!deadline || nowUs < *deadline)
            return false;
        complete();
        ended = true;
    }
    if (m_late && nowUs >= m_late->untilUs) {
        endLate();
        ended = true;
    }
    return ended;
}

bool TransactionTracker::heardLate(const QByteArray &frame, qint64 nowUs)
{
    if (!isLateAnswer(frame))
        return false;
    m_late->ids.removeOne(quint8(frame.at(2)));
    m_late->transaction.replies.append(frame);
    m_late->transaction.roundTripUs = nowUs - m_late->transaction.timeUs;
    if (m_late->ids.isEmpty())
        endLate();
    return true;
}

void TransactionTracker::endLate()
{
    if (!m_late)
        return;
    SharedTransaction transaction = std::move(m_late->transaction);
    m_late.reset();
    m_completed(std::move(transaction));
}

void TransactionTracker::complete()
{
    if (!m_current)
        return;
    endLate();
    const qint64 deadline = deadlineUs().value_or(0);
    SharedTransaction transaction = std::move(m_current->transaction);
    QVector<quint8> missing = m_current->ids;
    const int answerSize = m_current->answerSize;
    m_current.reset();
    if (transaction.unanswered() && !missing.isEmpty()) {
        for (const QByteArray &reply : std::as_const(transaction.replies))
            missing.removeOne(quint8(reply.at(2)));
        m_late = Late {std::move(transaction), std::move(missing), answerSize,
                       deadline + kLateAnswersUs};
        return;
    }
    m_completed(std::move(transaction));
}

qint64 TransactionTracker::wireTimeUs(int bytes) const
{
    return qint64(bytes) * 10 * 1000000 / m_baud;
}

} // namespace share
