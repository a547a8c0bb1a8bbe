// ServoBench between another program and the servos: start, forwarding, rate, alerts, recording.
#include "busshare.h"

#include "feetechpacket.h"
#include "linksession.h"
#include "porttransport.h"
#include "pseudoterminal.h"
#include "sharewatch.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace share {

namespace {

struct BusShareTr
{
    Q_DECLARE_TR_FUNCTIONS(BusShare)
};

// How often alerts that time raises are checked.
constexpr std::chrono::milliseconds kTickInterval {100};

constexpr int kFrameDataFrom = 5;

} // namespace

BusShare::BusShare(seriallink::LinkSession &link, QObject *parent)
    : QObject(parent)
    , m_link(link)
{
    qRegisterMetaType<share::SharedTransaction>();
    qRegisterMetaType<share::ShareAlert>();
    m_ticks.setInterval(kTickInterval);
    connect(&m_ticks, &QTimer::timeout, this, [this] {
        for (const ShareAlert &alert : m_alerts.tick(m_gate ? m_gate->nowUs() : 0))
            raise(alert);
    });
    connect(&m_link, &seriallink::LinkSession::statusChanged, this, &BusShare::onLinkStatus);
}

BusShare::~BusShare()
{
    stop();
}

QString BusShare::start(const ShareOptions &options)
{
    if (m_sharing)
        return BusShareTr::tr("The bus is shared already, at %1.").arg(linkPath());
    if (!m_link.isOpen())
        return BusShareTr::tr("The port is not open: connect to the bus first.");
    if (options.linkPath.isEmpty())
        return BusShareTr::tr("Name the path the other program opens.");
    const QString absolute = QFileInfo(options.linkPath).absoluteFilePath();
    if (absolute == QFileInfo(m_link.status().portName).absoluteFilePath())
        return BusShareTr::tr("%1 is the bus's own port: give the other program another path.")
            .arg(options.linkPath);
    auto *terminal = new seriallink::PseudoTerminal(this);
    QString error;
    if (!terminal->open(options.linkPath, &error)) {
        delete terminal;
        return error;
    }
    if (!options.recordPath.isEmpty()) {
        const util::FileError recording =
            m_recording.open(options.recordPath, m_link.status().portName, m_link.status().baud);
        if (recording) {
            delete terminal;
            return recording.describe();
        }
    }
    m_terminal = terminal;
    m_gate = new BusGate(m_link.transport(), this);
    m_link.engine().setTransport(*m_gate);
    m_watch = new ShareWatch(m_link.engine(), *m_gate, m_servos, this);
    connect(m_terminal, &seriallink::PseudoTerminal::received, this, &BusShare::onProgramBytes);
    connect(m_gate, &BusGate::toProgram, m_terminal, &seriallink::PseudoTerminal::write);
    connect(m_gate, &BusGate::transactionEnded, this, &BusShare::onTransaction);
    connect(m_gate, &BusGate::framePassed, this, [this](const RecordedFrame &frame) {
        record(frame);
        if (frame.direction == FrameDirection::ToProgram)
            m_watch->noteActivity();
        emit framePassed(frame);
    });
    m_programBaud = m_terminal->hostBaudRate();
    m_portAway = false;
    m_announced.clear(); // whoever listens now hears of every servo again
    m_sharing = true;
    m_watch->setEnabled(options.watch);
    m_ticks.start();
    emit sharingChanged(true);
    return {};
}

void BusShare::stop()
{
    if (!m_sharing)
        return;
    m_sharing = false;
    m_ticks.stop();
    m_gate->endAll(); // what is still open is said and recorded before the recording ends
    // The engine goes back to the port itself; the gate and everything on it go.
    m_link.engine().setTransport(m_link.transport());
    delete m_watch;
    m_watch = nullptr;
    delete m_gate;
    m_gate = nullptr;
    m_terminal->close();
    delete m_terminal;
    m_terminal = nullptr;
    m_recording.close();
    emit sharingChanged(false);
}

bool BusShare::isSharing() const
{
    return m_sharing;
}

QString BusShare::linkPath() const
{
    return m_terminal ? m_terminal->linkPath() : QString();
}

QString BusShare::terminalPath() const
{
    return m_terminal ? m_terminal->slavePath() : QString();
}

void BusShare::setWatch(bool enabled)
{
    if (m_watch)
        m_watch->setEnabled(enabled);
}

bool BusShare::isWatching() const
{
    return m_watch && m_watch->isEnabled();
}

qint64 BusShare::watchReads() const
{
    return m_watch ? m_watch->readsSent() : 0;
}

const ShareCounters &BusShare::counters() const
{
    static const ShareCounters none;
    return m_gate ? m_gate->counters() : none;
}

void BusShare::onProgramBytes(const QByteArray &bytes)
{
    // Its rate first: the bytes must leave at the rate the program set for them. Only then: a
    // program that closes its side resets the pty's rate, which means nothing for the bus.
    followProgramRate();
    m_gate->fromProgram(bytes);
    m_watch->noteActivity();
}

void BusShare::followProgramRate()
{
    if (!m_terminal)
        return;
    const qint32 baud = m_terminal->hostBaudRate();
    if (baud <= 0 || baud == m_programBaud)
        return;
    m_programBaud = baud;
    if (baud == m_link.transport().baudRate())
        return;
    if (!m_link.setBaudRate(baud)) {
        note(BusShareTr::tr("The program set %1 baud, which the port refuses; it stays at %2 baud.")
                 .arg(baud)
                 .arg(m_link.transport().baudRate()));
        return;
    }
    m_gate->setBaudRate(baud);
    note(BusShareTr::tr("The program set %1 baud; the port follows.").arg(baud));
}

void BusShare::onLinkStatus()
{
    if (!m_sharing)
        return;
    const bool away = !m_link.isOpen();
    if (away == m_portAway)
        return;
    m_portAway = away;
    if (away) {
        m_gate->portLost();
        note(
            BusShareTr::tr("The adapter went away (%1): what the program sends is lost until it is "
                           "back; the share waits for it.")
                .arg(m_link.status().message));
    } else {
        // The link reopened the port at the rate it had, the last the program set.
        note(BusShareTr::tr("The adapter is back: the share goes on."));
    }
}

void BusShare::note(const QString &text)
{
    record({m_gate ? m_gate->nowUs() : 0, FrameDirection::Note, {}, text});
    emit noted(text);
}

void BusShare::record(const RecordedFrame &frame)
{
    if (m_recording.write(frame))
        return;
    note(BusShareTr::tr("The recording stopped after %1 line(s): %2. The share goes on.")
             .arg(m_recording.framesWritten())
             .arg(m_recording.error()));
}

void BusShare::raise(const ShareAlert &alert)
{
    record({alert.timeUs,
            FrameDirection::Note,
            {},
            QStringLiteral("alert %1 %2: %3").arg(alert.code).arg(alert.id).arg(alert.message)});
    emit alertRaised(alert);
}

void BusShare::onTransaction(const SharedTransaction &ended)
{
    SharedTransaction transaction = ended;
    const qint32 baud = m_link.transport().baudRate();
    m_servos.learn(transaction, baud);
    announceServos();
    const quint8 code = transaction.instruction();
    if ((code == quint8(feetech::Instruction::Read)
         || code == quint8(feetech::Instruction::SyncRead))
        && transaction.request.size() > kFrameDataFrom + 1) {
        const int address = quint8(transaction.request.at(kFrameDataFrom));
        const qint64 steady = feetech::steadyMicroseconds();
        QVector<feetech::FeedbackSample> samples;
        for (const QByteArray &reply : std::as_const(transaction.replies)) {
            const quint8 id = quint8(reply.at(2));
            const feetech::RegisterTable *table = m_servos.table(id);
            if (!table || reply.size() <= kFrameDataFrom + 1)
                continue;
            const QByteArrayView data =
                QByteArrayView(reply).sliced(kFrameDataFrom, reply.size() - kFrameDataFrom - 1);
            if (const auto sample = feetech::decodeFeedbackPart(*table, id, baud, steady, address,
                                                                data, quint8(reply.at(4))))
                samples.append(*sample);
        }
        if (!samples.isEmpty())
            emit feedbackSeen(samples);
    }
    const QVector<ShareAlert> alerts = m_alerts.inspect(transaction, m_servos);
    emit transactionEnded(transaction);
    for (const ShareAlert &alert : alerts)
        raise(alert);
}

void BusShare::announceServos()
{
    for (const quint8 id : m_servos.ids()) {
        const auto told = m_announced.constFind(id);
        if (told != m_announced.cend() && *told)
            continue; // its whole identity was told already
        const std::optional<feetech::ServoInfo> known = m_servos.knownServo(id);
        if (!known)
            continue;
        const bool whole = m_servos.info(id).has_value();
        if (told != m_announced.cend() && !whole)
            continue; // nothing new since its model was told
        m_announced.insert(id, whole);
        emit servoSeen(*known);
    }
}

QString BusShare::summary() const
{
    const ShareCounters &count = counters();
    return BusShareTr::tr(
               "%1 frame(s) (%2 bytes) from the program, %3 frame(s) (%4 bytes) back to it; "
               "%5 request(s) unanswered, %6 garbled byte(s), %7 alert(s), %8 watch read(s), "
               "%9 request(s) not sent because the program had sent the next.")
        .arg(count.framesFromProgram)
        .arg(count.bytesFromProgram)
        .arg(count.framesToProgram)
        .arg(count.bytesToProgram)
        .arg(count.unanswered)
        .arg(count.garbledBytes)
        .arg(m_alerts.raisedCount())
        .arg(watchReads())
        .arg(count.givenUp);
}

} // namespace share
