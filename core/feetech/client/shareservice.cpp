// Sharing the bus with another program, from the GUI thread: queued calls to the link thread.
#include "shareservice.h"

#include "busclient.h"
#include "linksession.h"
#include "porttransport.h"

#include <QDir>

namespace feetech {

ShareService::ShareService(BusClient *client)
    : QObject(client)
    , m_client(client)
{
    share::BusShare *shared = &client->session()->share();
    connect(shared, &share::BusShare::sharingChanged, this, [this](bool sharing) {
        // Stopped in the link thread (a stop asked for, or the bus disconnected).
        if (!sharing)
            setState(State::Off);
    });
    connect(shared, &share::BusShare::servoSeen, this, &ShareService::onServoSeen);
    connect(shared, &share::BusShare::alertRaised, this, [this](const share::ShareAlert &alert) {
        if (m_state == State::Off)
            return;
        m_alerts.append(alert);
        emit alertRaised(alert);
    });
    connect(shared, &share::BusShare::noted, this, &ShareService::noted);
    m_countersTimer.setInterval(kCountersInterval);
    connect(&m_countersTimer, &QTimer::timeout, this, &ShareService::fetchCounters);
}

QString ShareService::defaultLinkPath()
{
    return QDir(QDir::tempPath()).filePath(QStringLiteral("ttyServoBench"));
}

bool ShareService::start(const share::ShareOptions &options, Refusal *refusal)
{
    Refusal why;
    if (!m_client->link()->isConnected())
        why = Refusal(Refusal::Code::NotConnected);
    else if (isActive())
        why = Refusal(Refusal::Code::AlreadyShared);
    else if (options.linkPath.trimmed().isEmpty())
        why = Refusal(Refusal::Code::NoSharePath);
    if (refused(why, refusal))
        return false;
    m_alerts.clear();
    m_counters = {};
    m_watchReads = 0;
    m_watch = options.watch;
    m_recordPath = options.recordPath;
    setState(State::Starting);
    m_client->runInSession([this, options](Session &session) {
        const QString failed = session.share().start(options);
        const QString link = session.share().linkPath();
        const QString terminal = session.share().terminalPath();
        const qint32 baud = session.link().transport().baudRate();
        // The service outlives the link thread (BusClient ends it first): posting is safe.
        QMetaObject::invokeMethod(
            this,
            [this, failed, link, terminal, baud] { onStartAnswered(failed, link, terminal, baud); },
            Qt::QueuedConnection);
    });
    return true;
}

void ShareService::onStartAnswered(const QString &why, const QString &linkPath,
                                   const QString &terminalPath, qint32 baud)
{
    if (!why.isEmpty()) {
        setState(State::Off);
        emit startFailed(why);
        return;
    }
    m_linkPath = linkPath;
    m_terminalPath = terminalPath;
    m_portBaud = baud;
    setState(State::Sharing);
}

void ShareService::stop()
{
    if (!isActive())
        return;
    // Queued behind a start still on its way: the share that start makes ends too.
    m_client->runInSession([](Session &session) { session.share().stop(); });
}

void ShareService::setWatch(bool enabled)
{
    m_watch = enabled;
    m_client->runInSession([enabled](Session &session) { session.share().setWatch(enabled); });
}

void ShareService::setState(State state)
{
    if (state == m_state)
        return;
    m_state = state;
    if (state == State::Sharing) {
        m_countersTimer.start();
    } else {
        m_countersTimer.stop();
    }
    emit stateChanged(state);
}

void ShareService::fetchCounters()
{
    m_client->runInSession([this](Session &session) {
        const share::ShareCounters counters = session.share().counters();
        const qint64 watchReads = session.share().watchReads();
        const qint32 baud = session.link().transport().baudRate();
        const bool sharing = session.share().isSharing();
        QMetaObject::invokeMethod(
            this,
            [this, counters, watchReads, baud, sharing] {
                // A share that ended counts nothing any more: its last figures stay.
                if (!sharing)
                    return;
                m_counters = counters;
                m_watchReads = watchReads;
                m_portBaud = baud;
                emit countersChanged();
            },
            Qt::QueuedConnection);
    });
}

void ShareService::onServoSeen(const ServoInfo &servo)
{
    ServoList *servos = m_client->servos();
    const int index = servos->indexOf(servo.address());
    if (index < 0) {
        servos->add(servo);
        return;
    }
    // Known already (a scan, or the model alone before): only a fuller identity changes it.
    const ServoInfo &known = servos->at(index).info;
    if (known.firmwareMajor == 0 && known.firmwareMinor == 0
        && (servo.firmwareMajor != 0 || servo.firmwareMinor != 0)
        && known.model.family == servo.model.family)
        servos->move(index, servo);
}

} // namespace feetech
