// The GUI thread's servo commands that are no register edits: middle calibration, factory reset,
// reboot, clearing the status, locking EEPROM, and frames built by hand.
#pragma once

#include "refusal.h"

#include <QByteArray>
#include <QObject>

#include <optional>

namespace feetech {

class BusClient;
class OperationReply;

// Belongs to a BusClient (BusClient::commands()). Each command returns its OperationReply, or
// nullptr and *refusal when nothing was sent.
class ServoCommands : public QObject
{
    Q_OBJECT

public:
    explicit ServoCommands(BusClient *client);

    // Why a command that is no register write (reboot, clear status) cannot be sent to servo
    // `index` now, or none.
    Refusal blocker(int index) const;

    OperationReply *calibrateMiddle(int index, Refusal *refusal = nullptr);
    OperationReply *factoryReset(int index, Refusal *refusal = nullptr);
    OperationReply *reboot(int index, Refusal *refusal = nullptr);
    OperationReply *clearStatus(int index, Refusal *refusal = nullptr);
    // Closes it and reads it back (Session::lockEeprom).
    OperationReply *lockEeprom(int index, Refusal *refusal = nullptr);
    // A frame built by hand (the packet window), queued like any command and sent once at
    // `baud` (Session::sendPacket). The caller has asked before anything that writes EEPROM.
    OperationReply *sendPacket(const QByteArray &frame, qint32 baud, std::optional<quint8> replyId,
                               int replyDataSize, Refusal *refusal = nullptr);

private:
    BusClient *m_client;
};

} // namespace feetech
