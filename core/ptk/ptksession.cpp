// PTK session: the poll loop, the Apply sequence with its gaps, read-back and reconnection.
#include "ptksession.h"

#include "linksession.h"
#include "ptkdescription.h"

#include <QCoreApplication>

namespace {

struct PtkSessionTr
{
    Q_DECLARE_TR_FUNCTIONS(PtkSession)
};

} // namespace

namespace ptk {

namespace {

constexpr int kQueryCount = int(std::tuple_size_v<std::decay_t<decltype(queryLayouts())>>);
constexpr int kWriteCount = int(std::tuple_size_v<std::decay_t<decltype(writeLayouts())>>);

// Replies carry no command byte, so a reply that cannot belong to this query is refused: a
// word no parameter uses is zero, and on/off parameters are 0 or 1 (spec, read map).
bool isPlausibleReply(const FrameLayout &query, const Reply &reply)
{
    for (const auto &[slot, word] :
         {std::pair {query.word0, reply.word0}, std::pair {query.word1, reply.word1}}) {
        if (!slot && word != 0)
            return false;
        if (slot && info(*slot).isSwitch && word > 1)
            return false;
    }
    return true;
}

QString parameterNames(const FrameLayout &layout)
{
    QStringList names;
    for (const auto slot : {layout.word0, layout.word1}) {
        if (slot)
            names.append(translatedLabel(*slot));
    }
    return names.join(QStringLiteral(", "));
}

} // namespace

Session::Session(const SessionTiming &timing, QObject *parent)
    : QObject(parent)
    , m_timing(timing)
    , m_link(new seriallink::LinkSession(m_format, describeFrame, this))
    , m_engine(&m_link->engine())
    , m_pollTimer(new QTimer(this))
{
    qRegisterMetaType<ptk::ParameterSet>();
    qRegisterMetaType<ptk::ReadSource>();
    m_engine->setTiming(m_timing.engine);
    m_link->setReconnectInterval(m_timing.reconnectInterval);
    m_link->setLinkDownHook([this](const QString &message, seriallink::Failure failure) {
        onLinkDown(message, failure);
    });
    // The servo has to answer before the link counts as connected again.
    m_link->setReconnectedHook([this] {
        m_link->setState(seriallink::ConnectionState::Connecting);
        resumePolling();
    });
    connect(m_link, &seriallink::LinkSession::statusChanged, this, &Session::statusChanged);
    connect(m_link, &seriallink::LinkSession::packetLogged, this, &Session::packetLogged);
    connect(m_link, &seriallink::LinkSession::countersChanged, this, &Session::countersChanged);
    m_pollTimer->setTimerType(Qt::PreciseTimer);
    connect(m_pollTimer, &QTimer::timeout, this, &Session::pollNext);
}

Session::~Session()
{
    close();
}

const seriallink::LinkCounters &Session::counters() const
{
    return m_link->counters();
}

const seriallink::ConnectionStatus &Session::status() const
{
    return m_link->status();
}

void Session::open(const QString &portName, qint32 baud, seriallink::EchoMode echo)
{
    if (m_link->open(portName, baud, echo))
        resumePolling();
}

void Session::close()
{
    m_link->close();
}

void Session::onLinkDown(const QString &message, seriallink::Failure failure)
{
    const bool wasApplying = isApplying();
    const bool wasReading = m_phase == Phase::Reading;
    m_pollTimer->stop();
    m_phase = Phase::Idle;
    m_pollInFlight = false;
    // Whoever waits for a read or an Apply hears that it ended, so nothing stays busy.
    const bool closed = failure == seriallink::Failure::Cancelled;
    if (wasApplying)
        emit applyFinished(
            false,
            closed ? PtkSessionTr::tr("Disconnected during Apply; the servo may hold only "
                                      "part of the new values.")
                   : PtkSessionTr::tr("The link went down during Apply: %1").arg(message));
    if (wasReading)
        emit readFinished(false,
                          closed ? PtkSessionTr::tr("Disconnected during the read.") : message);
}

void Session::setPolling(bool enabled)
{
    m_pollingEnabled = enabled;
    if (m_phase == Phase::Polling && !enabled) {
        m_pollTimer->stop();
        m_phase = Phase::Idle; // before the cancelled polls' callbacks run
        m_engine->cancelPolls();
    } else if (m_phase == Phase::Idle && enabled && m_link->isOpen()) {
        resumePolling();
    }
}

void Session::setPollInterval(int milliseconds, bool fast)
{
    m_timing.pollInterval = std::chrono::milliseconds(milliseconds);
    m_timing.fastPolling = fast;
    if (m_phase == Phase::Polling)
        resumePolling();
}

void Session::resumePolling()
{
    m_phase = m_pollingEnabled ? Phase::Polling : Phase::Idle;
    m_pollTimer->stop();
    if (m_phase != Phase::Polling) {
        // Without polling, one query still tells whether a servo is there.
        if (status().state == seriallink::ConnectionState::Connecting && m_link->isOpen())
            submitQuery(0, seriallink::Transaction::Priority::Command, [](bool) {});
        return;
    }
    if (!m_timing.fastPolling)
        m_pollTimer->start(m_timing.pollInterval);
    pollNext();
}

void Session::pollNext()
{
    if (m_phase != Phase::Polling || m_pollInFlight || !m_link->isOpen())
        return;
    m_pollInFlight = true;
    const int index = m_nextPoll;
    m_nextPoll = (m_nextPoll + 1) % kQueryCount;
    const quint64 generation = m_link->generation();
    submitQuery(index, seriallink::Transaction::Priority::Poll, [this, generation](bool) {
        if (generation != m_link->generation())
            return;
        m_pollInFlight = false;
        if (m_timing.fastPolling)
            pollNext();
    });
}

void Session::submitQuery(int index, seriallink::Transaction::Priority priority,
                          std::function<void(bool ok)> then)
{
    const FrameLayout &layout = queryLayouts().at(std::size_t(index));
    const ReadSource source = m_phase == Phase::ReadingBack ? ReadSource::ReadBack
        : m_phase == Phase::Reading                         ? ReadSource::Read
                                                            : ReadSource::Poll;
    seriallink::Transaction transaction;
    transaction.request = encodeQuery(layout.command);
    transaction.priority = priority;
    // A reply carries no command byte: any well-formed reply answers the one query in flight,
    // which is why the engine discards everything received before the query went out.
    transaction.acceptsReply = [&layout](const QByteArray &frame) {
        const auto reply = decodeReply(frame);
        return reply && isPlausibleReply(layout, *reply);
    };
    transaction.expectedReplySize = kReplySize;
    const quint64 generation = m_link->generation();
    transaction.done = [this, &layout, source, generation,
                        then = std::move(then)](const seriallink::TransactionResult &result) {
        if (generation != m_link->generation())
            return;
        if (result.failure == seriallink::Failure::Cancelled
            || result.failure == seriallink::Failure::LinkDown) {
            then(false);
            return;
        }
        const auto reply = decodeReply(result.reply);
        noteAnswer(reply.has_value());
        if (reply) {
            ParameterSet values;
            applyReply(layout, *reply, values);
            emit valuesRead(values, source);
        }
        then(reply.has_value());
    };
    m_engine->submit(std::move(transaction));
}

void Session::readAll()
{
    if (!m_link->isOpen()) {
        emit readFinished(false, PtkSessionTr::tr("Not connected."));
        return;
    }
    if (isApplying() || m_phase == Phase::Reading) {
        emit readFinished(false, PtkSessionTr::tr("Busy: a read or write is already running."));
        return;
    }
    startSweep(Phase::Reading);
}

void Session::startSweep(Phase phase)
{
    m_phase = phase;
    m_pollTimer->stop();
    m_engine->cancelPolls();
    sweepStep(0, phase, {});
}

void Session::sweepStep(int index, Phase phase, QVector<QString> failed)
{
    if (index == kQueryCount) {
        const bool ok = failed.isEmpty();
        const QString message = ok
            ? QString()
            : PtkSessionTr::tr("No answer to the query for %1.")
                  .arg(QStringList(failed.toList()).join(QStringLiteral("; ")));
        resumePolling();
        if (phase == Phase::ReadingBack) {
            emit applyFinished(ok,
                               ok ? QString()
                                  : PtkSessionTr::tr("Written, but not verified. %1").arg(message));
        } else {
            emit readFinished(ok, message);
        }
        return;
    }
    const FrameLayout &layout = queryLayouts().at(std::size_t(index));
    const quint64 generation = m_link->generation();
    submitQuery(index, seriallink::Transaction::Priority::Command,
                [this, index, phase, failed, generation, &layout](bool ok) mutable {
                    if (generation != m_link->generation())
                        return;
                    if (!m_link->isOpen()) {
                        // The port went away mid-sweep; onPortFailed has said so.
                        if (phase == Phase::ReadingBack)
                            emit applyFinished(false,
                                               PtkSessionTr::tr("The link went down before the "
                                                                "values could be read back."));
                        else
                            emit readFinished(false, PtkSessionTr::tr("The link went down."));
                        return;
                    }
                    if (!ok)
                        failed.append(parameterNames(layout));
                    if (phase == Phase::ReadingBack)
                        emit applyProgress(kWriteCount + index + 1, kWriteCount + kQueryCount);
                    sweepStep(index + 1, phase, failed);
                });
}

void Session::apply(const ParameterSet &values)
{
    if (!m_link->isOpen()) {
        emit applyFinished(false, PtkSessionTr::tr("Not connected."));
        return;
    }
    if (isApplying() || m_phase == Phase::Reading) {
        emit applyFinished(false, PtkSessionTr::tr("Busy: a read or write is already running."));
        return;
    }
    // Nothing leaves unless every value is complete and inside its range.
    for (const ParameterInfo &meta : parameterInfos()) {
        const auto wire = values.value(meta.parameter);
        if (!wire) {
            emit applyFinished(false,
                               PtkSessionTr::tr("%1 has not been read yet; nothing was written.")
                                   .arg(translatedLabel(meta.parameter)));
            return;
        }
        QString error;
        if (!fromUserValue(meta.parameter, toUserValue(meta.parameter, *wire), &error)
            || *wire % meta.wirePerUnit != 0) {
            emit applyFinished(false,
                               PtkSessionTr::tr("%1; nothing was written.")
                                   .arg(error.isEmpty() ? translatedLabel(meta.parameter) : error));
            return;
        }
    }
    const auto sequence = writeSequence(values);
    m_writes = *sequence;
    m_phase = Phase::Writing;
    m_pollTimer->stop();
    m_engine->cancelPolls();
    writeStep(0);
}

void Session::writeStep(int index)
{
    if (index == m_writes.size()) {
        startSweep(Phase::ReadingBack);
        return;
    }
    seriallink::Transaction transaction;
    transaction.request = encodeRequest(m_writes.at(index));
    transaction.priority = seriallink::Transaction::Priority::Command;
    const quint64 generation = m_link->generation();
    transaction.done = [this, index, generation](const seriallink::TransactionResult &result) {
        if (generation != m_link->generation())
            return;
        if (!result.ok()) {
            const char *name = writeLayouts().at(std::size_t(index)).name;
            resumePolling();
            emit applyFinished(false,
                               PtkSessionTr::tr("The link went down while writing %1; the servo "
                                                "may hold only part of the new values.")
                                   .arg(QLatin1String(name)));
            return;
        }
        emit applyProgress(index + 1, kWriteCount + kQueryCount);
        // The servo never acknowledges a write; PTK's own software leaves it this long.
        QTimer::singleShot(m_timing.writeGap, this, [this, index, generation] {
            if (generation == m_link->generation() && m_phase == Phase::Writing)
                writeStep(index + 1);
        });
    };
    m_engine->submit(std::move(transaction));
}

void Session::noteAnswer(bool ok)
{
    using seriallink::ConnectionState;
    if (ok && status().state != ConnectionState::Connected)
        m_link->setState(ConnectionState::Connected);
    else if (!ok && status().state != ConnectionState::NoReply)
        m_link->setState(
            ConnectionState::NoReply,
            PtkSessionTr::tr("The port is open but the servo does not answer. Check that it is "
                             "powered and plugged into the programmer."));
}

void Session::sendFrame(const QByteArray &frame, bool expectsReply)
{
    seriallink::Transaction transaction;
    transaction.request = frame;
    transaction.priority = seriallink::Transaction::Priority::Command;
    transaction.retryCount = 0; // sent once, as the user built it
    if (expectsReply) {
        transaction.acceptsReply = [](const QByteArray &reply) {
            return decodeReply(reply).has_value();
        };
        transaction.expectedReplySize = kReplySize;
    } // else a write: the servo never acknowledges one
    const quint64 generation = m_link->generation();
    transaction.done = [this, generation,
                        expectsReply](const seriallink::TransactionResult &result) {
        if (generation != m_link->generation())
            return;
        if (result.failure == seriallink::Failure::LinkDown
            || result.failure == seriallink::Failure::Cancelled) {
            emit frameSent(false, PtkSessionTr::tr("The frame was not sent: the link is down."));
            return;
        }
        if (!expectsReply) {
            emit frameSent(true, PtkSessionTr::tr("Sent."));
            return;
        }
        const bool answered = decodeReply(result.reply).has_value();
        emit frameSent(answered,
                       answered ? PtkSessionTr::tr("The servo answered.")
                                : PtkSessionTr::tr("Sent; the servo did not answer."));
    };
    m_engine->submit(std::move(transaction));
}

} // namespace ptk
