// PTK client: the worker thread's lifetime, queued calls into the session, and model updates.
#include "ptkclient.h"

#include "linksession.h"

#include <QCoreApplication>
#include <QDateTime>

namespace {

struct PtkClientTr
{
    Q_DECLARE_TR_FUNCTIONS(PtkClient)
};

} // namespace

namespace ptk {

namespace {

constexpr qint64 kRateWindowMs = 2000;

} // namespace

Client::Client(const SessionTiming &timing, QObject *parent)
    : QObject(parent)
    , m_worker(QStringLiteral("ptk-link"), timing)
{
    m_model.setDefinitions(modelDefinitions());
    m_clock.start();
    Session *session = m_worker.session();
    // First, so the client has settled before the main window hears of a change.
    connect(&m_link, &seriallink::LinkMirror::statusChanged, this, &Client::onStatusChanged);
    m_link.follow(&session->link());
    connect(session, &Session::valuesRead, this, &Client::onValuesRead);
    connect(session, &Session::readFinished, this, [this](bool ok, const QString &message) {
        m_reading = false;
        emit readFinished(ok, message);
    });
    connect(session, &Session::applyProgress, this, &Client::applyProgress);
    connect(session, &Session::applyFinished, this, &Client::onApplyFinished);
    connect(session, &Session::frameSent, this, &Client::frameSent);
}

Client::~Client() = default;

void Client::onStatusChanged(const seriallink::ConnectionStatus &status)
{
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
}

void Client::connectTo(const QString &portName, qint32 baud, seriallink::EchoMode echo)
{
    m_worker.run([portName, baud, echo](Session &session) { session.open(portName, baud, echo); });
}

void Client::disconnectFrom()
{
    m_worker.run([](Session &session) { session.close(); });
}

void Client::setPolling(bool enabled)
{
    m_worker.run([enabled](Session &session) { session.setPolling(enabled); });
}

void Client::setPollInterval(int milliseconds, bool fast)
{
    m_worker.run(
        [milliseconds, fast](Session &session) { session.setPollInterval(milliseconds, fast); });
}

void Client::readAll()
{
    if (isBusy())
        return; // the running read or Apply will bring fresh values anyway
    m_reading = true;
    m_worker.run([](Session &session) { session.readAll(); });
}

QString Client::applyBlocker() const
{
    if (!isConnected())
        return PtkClientTr::tr("The servo is not connected.");
    if (isBusy())
        return PtkClientTr::tr("A read or write is already running.");
    if (!m_model.hasEdits())
        return PtkClientTr::tr("There are no changes to apply.");
    for (const model::Definition &definition : m_model.definitions()) {
        if (!m_model.deviceValue(definition.key))
            return PtkClientTr::tr("%1 has not been read yet.").arg(definition.label);
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
    m_worker.run([values](Session &session) { session.apply(values); });
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
    // Whatever the read-back did not settle was written but not confirmed: its outcome is
    // unknown (a PTK write is never answered); the edit stays, and the next read settles it.
    for (const model::Definition &definition : m_model.definitions()) {
        if (m_model.state(definition.key) == model::State::Writing)
            m_model.markUnknown(definition.key);
    }
    emit applyFinished(ok, message);
}

bool Client::sendFrame(const QByteArray &frame, bool expectsReply, QString *error)
{
    if (!isConnected() || isBusy()) {
        if (error)
            *error = isConnected()
                ? PtkClientTr::tr("Wait until the servo's read or Apply has finished.")
                : PtkClientTr::tr("The servo is not connected.");
        return false;
    }
    m_worker.run(
        [frame, expectsReply](Session &session) { session.sendFrame(frame, expectsReply); });
    return true;
}

} // namespace ptk
