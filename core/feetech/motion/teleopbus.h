// One arm's bus as teleoperation uses it from the GUI thread: the window's connected bus (the
// follower) or a session of its own in a worker thread (the leader). Either way, operations run
// one after another, each handing back its result and the memory it read.
#pragma once

#include "busclient.h"
#include "busoperation.h"
#include "feetechsession.h"
#include "sessionthread.h"

#include <QMap>
#include <QObject>
#include <QPointer>

#include <deque>
#include <functional>
#include <memory>

namespace feetech {

class TeleopBus : public QObject
{
    Q_OBJECT

public:
    // What a read brought back: its bytes by address.
    using Memory = QMap<int, QByteArray>;
    using Done = std::function<void(const OperationResult &result, const Memory &memory)>;

    // The bus `client` has open; operations go through it as control work, so the window sees
    // them and they leave it free for the other pages.
    explicit TeleopBus(BusClient *client, QObject *parent = nullptr);
    // A session of its own for `portName` (opened at `baud` by open()), in its own thread.
    TeleopBus(const QString &portName, qint32 baud, QObject *parent = nullptr);
    ~TeleopBus() override;

    // For connecting its signals (queued); never called from here but through run().
    Session *session() const;
    const QString &portName() const { return m_portName; }
    void open();

    // Queues `operation` on servo `id` at `baud`; `done` gets its result once it ended.
    void run(const BusOperation &operation, quint8 id, qint32 baud, Done done);
    // Runs `work` in the session's thread, after what was asked before.
    void runInSession(const std::function<void(Session &)> &work);
    // The results still owed are not waited for any more (the link went down).
    void forget();

private:
    struct Owed
    {
        quint8 id = 0;
        Done done;
        Memory memory;
        const QObject *reply = nullptr; // the client's, when it goes through the client
    };
    void onMemoryRead(quint8 id, int address, const QByteArray &bytes);
    // The oldest result owed (for `reply`, when it went through the client) is in.
    void finish(const QObject *reply, const OperationResult &result);

    QPointer<BusClient> m_client;
    std::unique_ptr<seriallink::SessionThread<Session>> m_own;
    QString m_portName;
    qint32 m_baud = 0;
    std::deque<Owed> m_owed;
};

} // namespace feetech
