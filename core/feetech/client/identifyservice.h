// The GUI thread's side of identifying a joint (a slow wiggle, everything put back), and of the
// servos that something else moves meanwhile (a motion test), which identify leaves alone.
#pragma once

#include "bustypes.h"
#include "refusal.h"

#include <QHash>
#include <QObject>
#include <QString>

#include <optional>

namespace feetech {

class BusClient;
class OperationReply;

// Belongs to a BusClient (BusClient::identify()).
class IdentifyService : public QObject
{
    Q_OBJECT

public:
    explicit IdentifyService(BusClient *client);

    // Why servo `index` cannot be identified (or moved by the health check's move test) now:
    // none when it can. No bus, an unknown model, another operation, a servo held by something
    // that moves it, or no goal position register.
    Refusal blocker(int index) const;
    // The wiggle (operations::identifyJoint); nullptr and *refusal when refused.
    OperationReply *start(int index, Refusal *refusal = nullptr);
    // Whether servo `index` is being identified (running, paused between moves or queued).
    bool isRunning(int index) const;
    // What moves a servo outside the session's operations (a motion test) holds it while it
    // runs: blocker gives ServoHeld with `reason` meanwhile.
    void hold(int index, const QString &reason);
    void release(const ServoAddress &address);

private:
    BusClient *m_client;
    std::optional<ServoAddress> m_running;
    QHash<ServoAddress, QString> m_held; // why
};

} // namespace feetech
