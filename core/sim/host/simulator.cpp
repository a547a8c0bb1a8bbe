// Simulator engine: pty or in-process port, wire-rate pacing, echo, faults and log around a
// device.
#include "simulator.h"

#include "inprocessport.h"
#include "pseudoterminal.h"
#include "simulatorfeetech.h"
#include "virtualptkservo.h"

#include <QCoreApplication>

#include <algorithm>
#include <chrono>
#include <cmath>

#if defined(Q_OS_LINUX)
#include <sys/prctl.h>
#endif

namespace {

struct SimulatorTr
{
    Q_DECLARE_TR_FUNCTIONS(Simulator)
};

} // namespace

namespace sim {

namespace {

// Motion and temperature advance at least this often even when the host is silent.
constexpr int kTickMs = 10;
// Waits shorter than this are slept through instead of going back to the event loop, so that
// sub-millisecond wire times stay sub-millisecond.
constexpr qint64 kSpinThresholdUs = 1500;
// A sleep ends some tens of microseconds late (more on a virtual machine), which would delay
// every reply's last byte: the last stretch before a reply is due is waited out awake.
constexpr qint64 kAwakeUs = 40;

// One start bit, eight data bits, one stop bit.
double byteTimeUs(qint32 baud)
{
    return baud > 0 ? 10e6 / double(baud) : 0.0;
}

} // namespace

std::unique_ptr<Simulator> Simulator::create(const SimulatorOptions &options, QString *error)
{
    std::unique_ptr<VirtualDevice> device;
    if (options.kind == SimulatorOptions::Kind::Ptk) {
        auto servo = std::make_unique<VirtualPtkServo>();
        SimRefusal why;
        if (!options.ptkValues.isEmpty() && !servo->setValues(options.ptkValues, &why)) {
            if (error)
                *error = why.describe();
            return nullptr;
        }
        device = std::move(servo);
    } else {
        device = createFeetechBus(options, error);
        if (!device)
            return nullptr;
    }
    return std::unique_ptr<Simulator>(new Simulator(options, std::move(device)));
}

Simulator::Simulator(const SimulatorOptions &options, std::unique_ptr<VirtualDevice> device)
    : m_options(options)
    , m_device(std::move(device))
    , m_sendTimer(new QTimer(this))
    , m_tickTimer(new QTimer(this))
{
    if (m_options.faults.any())
        m_faults.emplace(m_options.faults, m_options.seed);
    if (m_options.adapter)
        m_adapter.emplace(*m_options.adapter, m_options.seed);
    m_framer = std::make_unique<seriallink::StreamFramer>(
        m_device->frameFormat(), seriallink::StreamFramer::BadChecksumPolicy::Resync);
    m_sendTimer->setSingleShot(true);
    m_sendTimer->setTimerType(Qt::PreciseTimer);
    connect(m_sendTimer, &QTimer::timeout, this, &Simulator::sendDue);
    m_tickTimer->setInterval(kTickMs);
    connect(m_tickTimer, &QTimer::timeout, this, &Simulator::advanceNow);
}

Simulator::~Simulator()
{
    stop();
}

bool Simulator::start(QString *error)
{
    if (!m_options.logPath.isEmpty() && !m_log.open(m_options.logPath, error))
        return false;
    if (m_options.inProcess) {
        auto *port = new seriallink::InProcessPort(this);
        if (!port->open(m_options.linkPath, error)) {
            delete port;
            return false;
        }
        m_port = port;
    } else {
        auto *pty = new seriallink::PseudoTerminal(this);
        if (!pty->open(m_options.linkPath, error)) {
            delete pty;
            return false;
        }
        m_port = pty;
    }
    connect(m_port, &seriallink::DevicePort::received, this, &Simulator::onReceived);
#if defined(Q_OS_LINUX)
    // Replies are paced by short sleeps (sendDue); Linux lets a thread's sleep run up to 50 µs
    // late by default, which at 1 Mbps is five bytes of wire time per reply. This thread only
    // paces the wire, so it asks to be woken on time.
    ::prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
#endif
    m_clock.start();
    m_tickTimer->start();
    return true;
}

void Simulator::stop()
{
    m_tickTimer->stop();
    m_sendTimer->stop();
    m_outgoing.clear();
    if (m_adapter)
        m_adapter->clear();
    delete m_port;
    m_port = nullptr;
}

VirtualPtkServo *Simulator::ptkServo()
{
    return dynamic_cast<VirtualPtkServo *>(m_device.get());
}

VirtualFeetechBus *Simulator::feetechBus()
{
    return dynamic_cast<VirtualFeetechBus *>(m_device.get());
}

void Simulator::powerCycle()
{
    m_device->powerCycle();
}

void Simulator::advanceNow()
{
    const qint64 now = nowUs();
    m_device->advanceTo(now);
    if (VirtualFeetechBus *bus = feetechBus()) {
        for (const QString &note : bus->hand().takeNotes()) {
            m_log.write(now, "hand", {}, note);
            emit handNote(note);
        }
    }
}

void Simulator::setFaults(const FaultSettings &faults, quint32 seed)
{
    m_options.faults = faults;
    m_options.seed = seed;
    if (faults.any())
        m_faults.emplace(faults, seed);
    else
        m_faults.reset();
}

void Simulator::onReceived(const QByteArray &bytes)
{
    const qint64 now = nowUs();
    const qint32 hostBaud = m_port->hostBaudRate();
    // An instant device takes no time to hear a frame or to answer it.
    const double byteUs = m_options.instant ? 0.0 : byteTimeUs(hostBaud);
    // The port hands the bytes over at once; on a wire they would still be arriving. Through a
    // USB adapter they reach the wire with the next USB frame.
    const qint64 onWire = m_adapter ? m_adapter->requestOnWireUs(now) : now;
    m_inputEndUs = std::max(onWire, m_inputEndUs) + qint64(std::ceil(bytes.size() * byteUs));
    if (m_options.echo)
        schedule(m_inputEndUs - qint64(bytes.size() * byteUs), bytes, byteUs, "echo", {});

    m_framer->append(bytes);
    while (auto item = m_framer->next()) {
        switch (item->kind) {
        case seriallink::StreamItem::Kind::Frame: {
            if (m_faults && m_faults->loseRequest()) {
                m_log.write(now, "lost", item->bytes, QStringLiteral("lost on its way"));
                break;
            }
            m_log.write(now, "in", item->bytes);
            respond(m_device->handleFrame(item->bytes, hostBaud, now), hostBaud, m_inputEndUs);
            break;
        }
        case seriallink::StreamItem::Kind::BadChecksum:
            m_log.write(now, "in", item->bytes, QStringLiteral("bad checksum, ignored"));
            break;
        case seriallink::StreamItem::Kind::Garbage:
        case seriallink::StreamItem::Kind::Incomplete:
            m_log.write(now, "in", item->bytes, QStringLiteral("not a frame, ignored"));
            break;
        }
    }
}

void Simulator::respond(const QVector<Response> &responses, qint32 hostBaud, qint64 requestEndUs)
{
    const double byteUs = m_options.instant ? 0.0 : byteTimeUs(hostBaud);
    qint64 start = std::max(requestEndUs, m_busFreeUs);
    for (const Response &response : responses) {
        QByteArray bytes = response.bytes;
        QString note;
        qint64 extraUs = 0;
        if (m_faults) {
            const FaultOutcome outcome = m_faults->apply(bytes);
            if (outcome.bytes.isEmpty()) {
                m_log.write(nowUs(), "drop", bytes, outcome.note);
                continue;
            }
            bytes = outcome.bytes;
            note = outcome.note;
            extraUs = outcome.extraDelayUs;
        }
        if (!m_options.instant)
            start += response.turnaroundUs;
        start += m_options.replyDelayUs + extraUs;
        schedule(start, bytes, byteUs, "out", note);
        start += qint64(std::ceil(bytes.size() * byteUs));
    }
    m_busFreeUs = std::max(m_busFreeUs, start);
}

void Simulator::schedule(qint64 startUs, const QByteArray &frame, double byteUs,
                         const char *direction, const QString &note)
{
    Outgoing logged;
    logged.direction = direction;
    logged.frame = frame;
    logged.note = note;
    if (m_adapter) {
        // The adapter holds each byte from the moment it has crossed the wire and decides when
        // the program gets it; the frame is logged when its last byte is on the wire.
        for (int i = 0; i < frame.size(); ++i)
            m_adapter->heard(startUs + qint64(std::ceil((i + 1) * byteUs)), frame.at(i));
        logged.dueUs = startUs + qint64(std::ceil(frame.size() * byteUs));
        queue(std::move(logged));
        return;
    }
    // Hand the bytes to the port as they would finish crossing the wire, about a millisecond's
    // worth at a time (a USB adapter delivers in similar batches).
    const int perChunk = std::max(1, int(1000.0 / std::max(byteUs, 1e-3)));
    for (int offset = 0; offset < frame.size(); offset += perChunk) {
        const int length = std::min(perChunk, int(frame.size()) - offset);
        Outgoing chunk;
        chunk.dueUs = startUs + qint64(std::ceil((offset + length) * byteUs));
        chunk.bytes = frame.mid(offset, length);
        if (offset + length == frame.size()) {
            chunk.direction = logged.direction;
            chunk.frame = logged.frame;
            chunk.note = logged.note;
        }
        queue(std::move(chunk));
    }
}

void Simulator::queue(Outgoing chunk)
{
    if (m_port->takesBytesAhead() && !chunk.bytes.isEmpty()) {
        // The port lets the host have them at their time, however late this thread next runs;
        // only the log waits here for it.
        m_port->writeAt(chunk.bytes,
                        std::chrono::steady_clock::now()
                            + std::chrono::microseconds(chunk.dueUs - nowUs()));
        chunk.bytes.clear();
        // Nothing waits here for the bytes' time unless the frame is to be logged then.
        if (!chunk.direction || !m_log.isOpen())
            return;
    }
    // Kept in time order (echo may be scheduled before pending replies end).
    auto at = std::upper_bound(m_outgoing.begin(), m_outgoing.end(), chunk.dueUs,
                               [](qint64 due, const Outgoing &o) { return due < o.dueUs; });
    m_outgoing.insert(at, std::move(chunk));
    sendDue();
}

void Simulator::sendDue()
{
    for (;;) {
        const qint64 now = nowUs();
        while (!m_outgoing.empty() && m_outgoing.front().dueUs <= now) {
            const Outgoing chunk = m_outgoing.front();
            m_outgoing.pop_front();
            if (!chunk.bytes.isEmpty())
                m_port->write(chunk.bytes);
            if (chunk.direction)
                m_log.write(now, chunk.direction, chunk.frame, chunk.note);
        }
        qint64 next = m_outgoing.empty() ? UsbAdapter::kNever : m_outgoing.front().dueUs;
        if (m_adapter) {
            for (QByteArray packet = m_adapter->takeDelivery(now); !packet.isEmpty();
                 packet = m_adapter->takeDelivery(now))
                m_port->write(packet);
            next = std::min(next, m_adapter->nextDeliveryUs());
        }
        if (next == UsbAdapter::kNever)
            return;
        const qint64 wait = next - now;
        if (wait >= kSpinThresholdUs) {
            m_sendTimer->start(int(wait / 1000));
            return;
        }
        if (wait > kAwakeUs)
            QThread::usleep(static_cast<unsigned long>(wait - kAwakeUs));
    }
}

} // namespace sim
