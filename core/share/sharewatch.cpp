// The watch of a shared bus: quiet detection and the round of READs it sends.
#include "sharewatch.h"

#include "busgate.h"
#include "feetechpacket.h"
#include "registerkeys.h"
#include "requestengine.h"

namespace share {

namespace {

// Identity (0-8) through the phase register (18): model, limits, maximum temperature, supply.
constexpr int kLimitsEnd = 19;

} // namespace

ShareWatch::ShareWatch(seriallink::RequestEngine &engine, BusGate &gate,
                       const ObservedServos &servos, QObject *parent)
    : QObject(parent)
    , m_engine(engine)
    , m_gate(gate)
    , m_servos(servos)
{
    m_quiet.setSingleShot(true);
    m_quiet.setTimerType(Qt::PreciseTimer);
    connect(&m_quiet, &QTimer::timeout, this, &ShareWatch::onQuiet);
}

void ShareWatch::setEnabled(bool enabled)
{
    m_enabled = enabled;
    if (enabled)
        noteActivity();
    else
        m_quiet.stop();
}

void ShareWatch::noteActivity()
{
    if (!m_enabled)
        return;
    // QTimer counts whole milliseconds: the least gap rounds up to them.
    m_quiet.start(std::chrono::ceil<std::chrono::milliseconds>(kLeastGap));
}

void ShareWatch::onQuiet()
{
    if (!m_enabled || m_reading)
        return;
    if (m_gate.programBusy() || !m_engine.isIdle()) {
        noteActivity();
        return;
    }
    const qint64 now = m_gate.nowUs();
    const qint64 due = m_lastReadUs < 0
        ? now
        : m_lastReadUs + std::chrono::duration_cast<std::chrono::microseconds>(kInterval).count();
    if (now < due) {
        m_quiet.start(std::chrono::milliseconds((due - now + 999) / 1000));
        return;
    }
    readNext();
}

void ShareWatch::readNext()
{
    const QVector<quint8> ids = m_servos.ids();
    if (ids.isEmpty()) {
        noteActivity();
        return;
    }
    const quint8 id = ids.at(m_next++ % ids.size());
    int address = 0;
    int length = kLimitsEnd;
    const feetech::RegisterTable *table = m_servos.table(id);
    if (table && m_servos.known(id, 0, kLimitsEnd)) {
        const feetech::Register *torque = table->find(feetech::registerkeys::kTorqueEnable);
        const feetech::Block feedback = table->feedbackBlock();
        address = torque ? torque->address : feedback.address;
        length = feedback.address + feedback.size - address;
    }
    seriallink::Transaction read;
    read.request = feetech::read(id, quint8(address), quint8(length));
    read.priority = seriallink::Transaction::Priority::Poll;
    read.retryCount = 0;
    read.expectedReplySize = 6 + length;
    read.acceptsReply = [id](const QByteArray &frame) {
        return frame.size() >= 6 && quint8(frame.at(2)) == id;
    };
    read.done = [this](const seriallink::TransactionResult &) {
        m_reading = false;
        noteActivity();
    };
    m_reading = true;
    m_lastReadUs = m_gate.nowUs();
    ++m_reads;
    m_engine.submit(std::move(read));
}

} // namespace share
