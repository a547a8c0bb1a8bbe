// A device session living in its own worker thread, for a GUI-thread client to drive.
#pragma once

#include <QMetaObject>
#include <QObject>
#include <QThread>

#include <utility>

namespace seriallink {

// Creates the session inside the thread (so its QSerialPort and timers belong there), deletes
// it there, and stops with quit() plus a bounded wait(), never terminate().
template<typename Session>
class SessionThread
{
public:
    // Shutdown waits this long for the worker; a serial close never takes longer in practice.
    static constexpr unsigned long kStopTimeoutMs = 3000;

    template<typename... Arguments>
    explicit SessionThread(const QString &name, Arguments... arguments)
    {
        m_thread.setObjectName(name);
        m_thread.start();
        auto *anchor = new QObject;
        anchor->moveToThread(&m_thread);
        QMetaObject::invokeMethod(
            anchor, [this, arguments...] { m_session = new Session(arguments...); },
            Qt::BlockingQueuedConnection);
        anchor->deleteLater();
    }

    ~SessionThread()
    {
        Session *session = m_session;
        QMetaObject::invokeMethod(
            session, [session] { delete session; }, Qt::BlockingQueuedConnection);
        m_thread.quit();
        m_thread.wait(kStopTimeoutMs);
    }

    SessionThread(const SessionThread &) = delete;
    SessionThread &operator=(const SessionThread &) = delete;

    // For connecting signals; call its methods only through run().
    Session *session() const { return m_session; }

    // Runs `work(session)` in the worker thread, after whatever was asked before it.
    template<typename Work>
    void run(Work work) const
    {
        Session *session = m_session;
        QMetaObject::invokeMethod(
            session, [session, work = std::move(work)] { work(*session); }, Qt::QueuedConnection);
    }

private:
    QThread m_thread;
    Session *m_session = nullptr;
};

} // namespace seriallink
