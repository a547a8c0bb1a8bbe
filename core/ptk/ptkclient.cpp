// PTK client: the worker thread's lifetime, queued calls into the session, and model updates.
#include "ptk/ptkclient.h"

#include <QCoreApplication>
#include <QDateTime>

namespace ptk {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(PtkClient)
};

// Shutdown waits this long for the worker; a serial close never takes longer in practice.
constexpr unsigned long kThreadStopTimeoutMs = 3000;
constexpr qint64 kRateWindowMs = 2000;

} // namespace

Client::Client(const SessionTiming &timing, QObject *parent)
    : QObject(parent)
{
    m_model.setDefinitions(modelDefinitions());
    m_clock.start();
    m_thread.setObjectName(QStringLiteral("ptk-link"));
    m_thread.start();
    // The session, its QSerialPort and its timers are created inside the worker thread.
    auto *anchor = new QObject;
    anchor->moveToThread(&m_thread);
    QMetaObject::invokeMethod(
        anchor, [this, timing] { m_session = new Session(timing); }, Qt::BlockingQueuedConnection);
    anchor->deleteLater();

    connect(m_session, &Session::statusChanged, this, [this](const auto &status) {
        m_status = status;
        if (status.state != seriallink::ConnectionState::Connected)
            m_answerTimesMs.clear();
        // The session reports a read or Apply the link cut short; this is only a backstop.
        if (status.state == seriallink::ConnectionState::Disconnected
            || status.state == seriallink::ConnectionState::Lost) {
            m_reading = false;
            if (m_applying)
                onApplyFinished(false, status.message);
        }
        emit statusChanged(status);
    });
    connect(m_session, &Session::countersChanged, this, [this](const auto &counters) {
        m_counters = counters;
        emit countersChanged(counters);
    });
    connect(m_session, &Session::packetLogged, this, &Client::packetLogged);
    connect(m_session, &Session::valuesRead, this, &Client::onValuesRead);
    connect(m_session, &Session::readFinished, this, [this](bool ok, const QString &message) {
        m_reading = false;
        emit readFinished(ok, message);
    });
    connect(m_session, &Session::applyProgress, this, &Client::applyProgress);
    connect(m_session, &Session::applyFinished, this, &Client::onApplyFinished);
}

Client::~Client()
{
    Session *session = m_session;
    QMetaObject::invokeMethod(
        session, [session] { delete session; }, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait(kThreadStopTimeoutMs);
}

void Client::connectTo(const QString &portName, qint32 baud, seriallink::EchoMode echo)
{
    Session *session = m_session;
    inWorker([session, portName, baud, echo] { session->open(portName, baud, echo); });
}

void Client::disconnectFrom()
{
    Session *session = m_session;
    inWorker([session] { session->close(); });
}

void Client::setPolling(bool enabled)
{
    Session *session = m_session;
    inWorker([session, enabled] { session->setPolling(enabled); });
}

void Client::setPollInterval(int milliseconds, bool fast)
{
    Session *session = m_session;
    inWorker([session, milliseconds, fast] { session->setPollInterval(milliseconds, fast); });
}

void Client::readAll()
{
    if (isBusy())
        return; // the running read or Apply will bring fresh values anyway
    m_reading = true;
    Session *session = m_session;
    inWorker([session] { session->readAll(); });
}

QString Client::applyBlocker() const
{
    if (m_status.state != seriallink::ConnectionState::Connected)
        return Tr::tr("The servo is not connected.");
    if (isBusy())
        return Tr::tr("A read or write is already running.");
    if (!m_model.hasEdits())
        return Tr::tr("There are no changes to apply.");
    for (const model::Definition &definition : m_model.definitions()) {
        if (!m_model.deviceValue(definition.key))
            return Tr::tr("%1 has not been read yet.").arg(definition.label);
    }
    return QString();
}

bool Client::apply(QString *error)
{
    const QString blocker = applyBlocker();
    if (!blocker.isEmpty()) {
        if (error)
            *error = blocker;
        return false;
    }
    // Every parameter goes out: the user's edits, and what the servo holds for the rest.
    ParameterSet values;
    for (const ParameterInfo &meta : parameterInfos()) {
        const QString key = QLatin1String(meta.key);
        const auto raw =
            m_model.pendingValue(key) ? m_model.pendingValue(key) : m_model.deviceValue(key);
        values.set(meta.parameter, quint16(*raw));
    }
    m_model.takeWritePlan();
    m_applying = true;
    Session *session = m_session;
    inWorker([session, values] { session->apply(values); });
    return true;
}

double Client::pollRate() const
{
    const qint64 now = m_clock.elapsed();
    int recent = 0;
    for (const qint64 when : m_answerTimesMs) {
        if (now - when <= kRateWindowMs)
            ++recent;
    }
    return recent * 1000.0 / double(kRateWindowMs);
}

void Client::onValuesRead(const ParameterSet &values, ReadSource source)
{
    // Polls answered before the writes went out would settle the written parameters against
    // old values; during an Apply only its own read-back counts.
    if (m_applying && source != ReadSource::ReadBack)
        return;
    const qint64 now = m_clock.elapsed();
    if (source == ReadSource::Poll) {
        m_answerTimesMs.push_back(now);
        while (!m_answerTimesMs.empty() && now - m_answerTimesMs.front() > kRateWindowMs)
            m_answerTimesMs.pop_front();
    }
    const qint64 wallMs = QDateTime::currentMSecsSinceEpoch();
    for (const ParameterInfo &meta : parameterInfos()) {
        if (const auto wire = values.value(meta.parameter))
            m_model.setDeviceValue(QLatin1String(meta.key), *wire, wallMs);
    }
    emit valuesUpdated();
}

void Client::onApplyFinished(bool ok, const QString &message)
{
    if (!m_applying)
        return; // already ended (the status backstop came first)
    m_applying = false;
    // Whatever the read-back did not settle was written but not confirmed: keep the edit.
    for (const model::Definition &definition : m_model.definitions()) {
        if (m_model.state(definition.key) == model::State::Writing)
            m_model.markFailed(definition.key);
    }
    emit applyFinished(ok, message);
}

} // namespace ptk
