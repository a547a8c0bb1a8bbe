// The junction of a shared bus: forwarding both ways, own requests between the program's.
#include "busgate.h"

#include "precisetimer.h"

#include <QMetaObject>

namespace share {

namespace {

constexpr std::chrono::milliseconds kOwnAnswerWait {100};

} // namespace

BusGate::BusGate(seriallink::Transport &port, QObject *parent)
    : Transport(parent)
    , m_port(port)
    , m_programFramer(m_format, seriallink::StreamFramer::BadChecksumPolicy::ConsumeFrame)
    , m_portFramer(m_format, seriallink::StreamFramer::BadChecksumPolicy::ConsumeFrame)
    , m_program([this](SharedTransaction &&transaction) {
        if (transaction.unanswered())
            ++m_counters.unanswered;
        emit transactionEnded(transaction);
    })
    , m_own([this](SharedTransaction &&transaction) {
        ++m_counters.ownTransactions;
        emit transactionEnded(transaction);
    })
    , m_deadline(new seriallink::PreciseTimer(this))
{
    m_own.setOwn(true);
    // An own request goes only to a servo known to answer: its answer is waited for long, so
    // that a late one (a loaded machine, a USB adapter's latency timer) can never reach the
    // program after its held bytes have gone on.
    m_own.setAnswerWait(kOwnAnswerWait);
    m_clock.start();
    setBaudRate(port.baudRate());
    connect(&m_port, &Transport::received, this, &BusGate::onPortBytes);
    connect(&m_port, &Transport::failed, this, &Transport::failed);
}

BusGate::~BusGate() = default;

bool BusGate::isOpen() const
{
    return m_port.isOpen();
}

qint32 BusGate::baudRate() const
{
    return m_port.baudRate();
}

void BusGate::setBaudRate(qint32 baud)
{
    m_program.setBaudRate(baud);
    m_own.setBaudRate(baud);
}

QByteArray BusGate::discardInput()
{
    return {}; // nothing is kept back from the engine: the port's bytes come as they arrive
}

void BusGate::deliverPendingInput()
{
    m_port.deliverPendingInput();
}

bool BusGate::programBusy() const
{
    return m_program.isOutstanding() || m_programFramer.pendingBytes() > 0;
}

void BusGate::write(const QByteArray &bytes)
{
    m_ownWaiting += bytes;
    pump();
}

void BusGate::fromProgram(const QByteArray &bytes)
{
    if (!m_port.isOpen()) {
        // A real wire loses what is sent while the adapter is unplugged; so does this.
        m_counters.bytesWhileAway += bytes.size();
        return;
    }
    if (m_ownActive || !m_held.isEmpty()) {
        m_held += bytes;
        m_counters.heldBytes += bytes.size();
        return;
    }
    forwardProgramBytes(bytes);
}

void BusGate::forwardProgramBytes(const QByteArray &bytes)
{
    m_programActivityUs = nowUs();
    m_port.write(bytes);
    m_counters.bytesFromProgram += bytes.size();
    m_programFramer.append(bytes);
    passProgramFrames();
    armDeadline();
}

void BusGate::onPortBytes(const QByteArray &bytes)
{
    // Frame by frame, by what was asked: a frame the own request asked for (its answer, a late
    // one too) is ServoBench's, and everything else is the program's, whenever it came. The
    // program's bytes of one read go on in one write.
    m_portFramer.append(bytes);
    QByteArray forProgram;
    while (const std::optional<seriallink::StreamItem> item = m_portFramer.next()) {
        const qint64 now = nowUs();
        const bool frame = item->kind == seriallink::StreamItem::Kind::Frame;
        if (!frame)
            m_counters.garbledBytes += item->bytes.size();
        const bool own = frame ? m_own.claims(item->bytes) : m_ownActive;
        if (own) {
            if (m_ownActive)
                emit received(item->bytes);
            m_own.heard(*item, now);
            emit framePassed({now, FrameDirection::OwnAnswer, item->bytes, {}});
            continue;
        }
        m_programActivityUs = now;
        forProgram += item->bytes;
        if (frame)
            ++m_counters.framesToProgram;
        m_program.heard(*item, now);
        emit framePassed({now, FrameDirection::ToProgram, item->bytes, {}});
    }
    if (!forProgram.isEmpty()) {
        emit toProgram(forProgram);
        m_counters.bytesToProgram += forProgram.size();
    }
    pump();
}

qint64 BusGate::quietInUs() const
{
    return qMax<qint64>(0, m_programActivityUs + kQuietBeforeOwn.count() - nowUs());
}

void BusGate::passProgramFrames()
{
    while (const std::optional<seriallink::StreamItem> item = m_programFramer.next()) {
        const qint64 now = nowUs();
        if (item->kind == seriallink::StreamItem::Kind::Frame) {
            ++m_counters.framesFromProgram;
            m_program.request(item->bytes, now);
        } else {
            m_counters.garbledBytes += item->bytes.size();
        }
        emit framePassed({now, FrameDirection::FromProgram, item->bytes, {}});
    }
}

void BusGate::pump()
{
    if (m_ownActive && !m_own.isOutstanding()) {
        m_ownActive = false;
        m_program.setEchoes(m_own.echoes());
        const QByteArray held = withoutGivenUp(std::exchange(m_held, {}));
        if (!held.isEmpty())
            forwardProgramBytes(held);
    }
    // Not while answers may still come late, to the program's request or to an own one: who
    // they are for is told by what was asked, and two requests alike would not tell it.
    if (!m_ownActive && !m_ownWaiting.isEmpty() && !programBusy() && quietInUs() == 0
        && !m_program.hasLate() && !m_own.hasLate())
        startOwnRequest();
    armDeadline();
}

QByteArray BusGate::withoutGivenUp(const QByteArray &held)
{
    // Held bytes start at a frame boundary: an own request goes only when the program is not
    // in the middle of one.
    seriallink::StreamFramer framer(m_format,
                                    seriallink::StreamFramer::BadChecksumPolicy::ConsumeFrame);
    framer.append(held);
    QVector<seriallink::StreamItem> items;
    while (std::optional<seriallink::StreamItem> item = framer.next())
        items.append(std::move(*item));
    const QByteArray unfinished = held.right(framer.pendingBytes());
    QByteArray kept;
    for (qsizetype i = 0; i < items.size(); ++i) {
        const bool followed = i + 1 < items.size() || !unfinished.isEmpty();
        if (followed && items.at(i).kind == seriallink::StreamItem::Kind::Frame
            && TransactionTracker::isAnswered(items.at(i).bytes)) {
            ++m_counters.givenUp;
            continue;
        }
        kept += items.at(i).bytes;
    }
    return kept + unfinished;
}

void BusGate::startOwnRequest()
{
    const QByteArray request = std::exchange(m_ownWaiting, {});
    m_ownActive = true;
    m_own.setEchoes(m_program.echoes());
    m_port.write(request);
    const qint64 now = nowUs();
    m_own.request(request, now);
    emit framePassed({now, FrameDirection::Own, request, {}});
    // The engine counts its wait from this; told later, as a port would, never inside write().
    QMetaObject::invokeMethod(
        this, [this, size = request.size()] { emit bytesWritten(size); }, Qt::QueuedConnection);
    if (!m_own.isOutstanding())
        pump(); // nothing answers it (a broadcast): the program goes on at once
}

void BusGate::armDeadline()
{
    std::optional<qint64> deadline = m_program.deadlineUs();
    const auto sooner = [&deadline](qint64 at) {
        deadline = deadline ? qMin(*deadline, at) : at;
    };
    if (const auto own = m_own.deadlineUs())
        sooner(*own);
    if (!m_ownActive && !m_ownWaiting.isEmpty() && !programBusy())
        sooner(nowUs() + quietInUs()); // the own request goes once the program is quiet
    if (!deadline) {
        m_deadline->stop();
        return;
    }
    m_deadline->start(std::chrono::microseconds(qMax<qint64>(0, *deadline - nowUs())),
                      [this] { onDeadline(); });
}

void BusGate::onDeadline()
{
    const qint64 now = nowUs();
    m_program.expire(now);
    m_own.expire(now);
    pump();
}

void BusGate::endAll()
{
    const qint64 now = nowUs() + (qint64(1) << 40); // past every wait
    m_program.expire(now);
    m_own.expire(now);
    m_deadline->stop();
}

void BusGate::portLost()
{
    m_counters.bytesWhileAway += m_held.size();
    m_held.clear();
    m_ownWaiting.clear();
    m_ownActive = false;
    m_programFramer.discardPending();
    m_portFramer.discardPending();
    endAll();
}

} // namespace share
