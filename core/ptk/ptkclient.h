// The GUI thread's handle on a PTK servo: runs the session in its own worker thread and keeps a
// parameter model in step with what the servo reports.
#pragma once

#include "linkmirror.h"
#include "linktypes.h"
#include "parametermodel.h"
#include "ptksession.h"
#include "requestengine.h"
#include "sessionthread.h"

#include <QElapsedTimer>
#include <QObject>

#include <deque>

namespace ptk {

class Client : public QObject
{
    Q_OBJECT

public:
    explicit Client(const SessionTiming &timing = {}, QObject *parent = nullptr);
    ~Client() override; // quits the worker thread with a bounded wait

    model::ParameterModel *model() { return &m_model; }
    // The link's state, counters and packet log, on this thread.
    seriallink::LinkMirror *link() { return &m_link; }
    const seriallink::ConnectionStatus &status() const { return m_link.status(); }
    const seriallink::LinkCounters &counters() const { return m_link.counters(); }
    bool isConnected() const { return m_link.isConnected(); }
    bool isBusy() const { return m_applying || m_reading; }

    void connectTo(const QString &portName, qint32 baud = 115200,
                   seriallink::EchoMode echo = seriallink::EchoMode::Auto);
    void disconnectFrom();
    void setPolling(bool enabled);
    void setPollInterval(int milliseconds, bool fast);

    // One read of all eight queries now.
    void readAll();
    // Why Apply cannot run now (empty when it can).
    QString applyBlocker() const;
    // Sends the full N1..N12 sequence: the edits, and the device values of everything else.
    // Returns false (and *error) when nothing was sent.
    bool apply(QString *error = nullptr);
    // A frame built by hand (the packet window), sent once (Session::sendFrame); frameSent
    // follows. Refused, false and *error, when the servo is not connected.
    bool sendFrame(const QByteArray &frame, bool expectsReply, QString *error = nullptr);

    // Answers per second over the last two seconds of polling.
    double pollRate() const;

signals:
    void statusChanged(const seriallink::ConnectionStatus &status);
    void readFinished(bool ok, const QString &message);
    void applyProgress(int done, int total);
    void applyFinished(bool ok, const QString &message);
    void frameSent(bool ok, const QString &message);
    void valuesUpdated();

private:
    void onValuesRead(const ptk::ParameterSet &values, ptk::ReadSource source);
    void onApplyFinished(bool ok, const QString &message);
    void onStatusChanged(const seriallink::ConnectionStatus &status);

    seriallink::SessionThread<Session> m_worker;
    seriallink::LinkMirror m_link;
    model::ParameterModel m_model;
    bool m_applying = false;
    bool m_reading = false;
    QElapsedTimer m_clock;
    std::deque<qint64> m_answerTimesMs; // poll answers of the last two seconds
};

} // namespace ptk
