// Pairs the requests on a shared bus with their answers: echo, answers, time up.
#include "transactiontracker.h"

#include "feetechpacket.h"

namespace share {

namespace {

constexpr int kStatusOverhead = 6; // header, ID, length, error, checksum
// A request nothing answers may still come back as the echo: how long past its wire time.
constexpr qint64 kEchoAllowanceUs = 2000;

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
    }
    outstanding.transaction.expectedReplies = expected;
    m_current = std::move(outstanding);
    if (expected == 0 && m_echoes == false)
        complete(); // nothing comes back for it
}

void TransactionTracker::heard(const seriallink::StreamItem &item, qint64 nowUs)
{
    if (!m_current) {
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
        return std::nullopt;
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
    const std::optional<qint64> deadline = deadlineUs();
    if (!deadline || nowUs < *deadline)
        return false;
    complete();
    return true;
}

void TransactionTracker::complete()
{
    if (!m_current)
        return;
    SharedTransaction transaction = std::move(m_current->transaction);
    m_current.reset();
    m_completed(std::move(transaction));
}

qint64 TransactionTracker::wireTimeUs(int bytes) const
{
    return qint64(bytes) * 10 * 1000000 / m_baud;
}

} // namespace share
