// The Feetech session's hand-built frames (the packet window): sent once, answered or listened.
#include "feetechsession.h"

#include <QCoreApplication>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};

// A frame whose answers cannot be named in advance (broadcast, SYNC READ) is listened to this
// long; what comes back shows in the packet log.
constexpr std::chrono::milliseconds kListenWindow {150};

} // namespace

namespace feetech {

void Session::sendPacket(const QByteArray &frame, qint32 baud, std::optional<quint8> replyId,
                         int replyDataSize)
{
    // Like any write: one asked for before All torque off must not power the servos again.
    const quint64 epoch = m_torqueOffEpoch;
    enqueue(Operation::SendPacket, [this, frame, baud, replyId, replyDataSize, epoch] {
        if (refusedAfterTorqueOff(Operation::SendPacket, epoch))
            return;
        m_bus->setBaud(
            baud)([this, frame, baud, replyId, replyDataSize](bool ok, const QString &message) {
            OperationResult result {Operation::SendPacket, false, message, {}, {}};
            result.servo.baud = baud;
            if (!ok) {
                finishOperation(result);
                return;
            }
            Exchange ask;
            ask.request = frame;
            ask.retryCount = 0; // sent once, as the user built it
            if (replyId) {
                ask.replyId = replyId;
                ask.replyDataSize = replyDataSize;
                result.servo.id = *replyId;
            } else {
                ask.listenOnly = true;
                ask.silenceExpected = true;
                ask.replyTimeout = kListenWindow;
            }
            m_bus->exchange(ask,
                            [this, result, replyId](const seriallink::TransactionResult &answer,
                                                    const std::optional<Packet> &reply) mutable {
                                result.latency = answer.latency;
                                if (answer.failure == seriallink::Failure::LinkDown) {
                                    result.message = failureText(answer);
                                } else if (!replyId) {
                                    result.ok = true;
                                    result.message = Tr::tr("Sent; its answers, if any, are in "
                                                            "the packet log.");
                                } else {
                                    result.ok = reply.has_value();
                                    result.message = reply
                                        ? Tr::tr("Servo %1 answered.").arg(*replyId)
                                        : Tr::tr("Sent; servo %1 did not answer: %2")
                                              .arg(*replyId)
                                              .arg(failureText(answer));
                                }
                                finishOperation(result);
                            });
        });
    });
}

} // namespace feetech
