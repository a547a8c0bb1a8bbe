// Feetech bus client: a frame built by hand (the packet window), queued like any command.
#include "busclient.h"
#include "registertable.h"

#include <QCoreApplication>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechBusClient)
};

} // namespace

namespace feetech {

OperationReply *BusClient::sendPacket(const QByteArray &frame, qint32 baud,
                                      std::optional<quint8> replyId, int replyDataSize,
                                      QString *error)
{
    QString refusal;
    if (!isConnected())
        refusal = Tr::tr("The bus is not connected.");
    else if (!decodePacket(frame))
        refusal = Tr::tr("That is not a whole Feetech frame (header, length and checksum).");
    else if (!baudCode(baud))
        refusal = Tr::tr("%1 bps is not a Feetech baud rate.").arg(baud);
    if (!refusal.isEmpty()) {
        if (error)
            *error = refusal;
        return nullptr;
    }
    return submit(Operation::SendPacket, replyId.value_or(kBroadcastId), baud, Work::Foreground,
                  [frame, baud, replyId, replyDataSize](Session &s) {
                      s.sendPacket(frame, baud, replyId, replyDataSize);
                  });
}

} // namespace feetech
