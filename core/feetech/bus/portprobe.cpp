// Port probe: a PTK query and a broadcast PING per Feetech rate, each answer sorted by what came.
#include "portprobe.h"

#include "feetechpacket.h"
#include "modeltable.h"
#include "porttransport.h"
#include "ptkframe.h"
#include "ptkparameters.h"
#include "registertable.h"
#include "streamframer.h"

#include <QCoreApplication>
#include <QTimer>

namespace {

struct PortProbeTr
{
    Q_DECLARE_TR_FUNCTIONS(PortProbe)
};

} // namespace

namespace feetech {

namespace {

constexpr qint32 kPtkBaud = 115200;

// The bytes heard besides the echo of `request`: a single-wire adapter sends the question
// back before any answer. Nothing yet while what came may still be the start of the echo.
QByteArray answerBytes(const QByteArray &heard, const QByteArray &request, bool *echo)
{
    *echo = false;
    if (heard.startsWith(request)) {
        *echo = true;
        return heard.mid(request.size());
    }
    if (request.startsWith(heard))
        return {};
    return heard;
}

} // namespace

PortProbe::PortProbe(const ProbeTiming &timing, QObject *parent)
    : QObject(parent)
    , m_timing(timing)
    , m_deadline(new QTimer(this))
{
    qRegisterMetaType<feetech::PortProbeReport>();
    m_deadline->setSingleShot(true);
    m_deadline->setTimerType(Qt::PreciseTimer);
    connect(m_deadline, &QTimer::timeout, this, &PortProbe::endQuestion);
}

PortProbe::~PortProbe() = default;

int PortProbe::stepCount()
{
    return 1 + int(baudRates().size());
}

void PortProbe::start(const QString &portPath)
{
    m_report = {};
    m_report.port = portPath;
    m_cancelled = false;
    m_running = true;
    m_transport.reset(seriallink::PortTransport::forPort(portPath));
    connect(m_transport.get(), &seriallink::Transport::received, this, &PortProbe::onReceived);
    // A port that fails while the probe runs ends it: what was heard so far is the report.
    connect(m_transport.get(), &seriallink::Transport::failed, this,
            [this](const QString &message) {
                m_report.access.problem = seriallink::PortAccess::Problem::Other;
                m_report.access.detail = message;
                finish();
            });
    if (!m_transport->open(portPath, kPtkBaud, nullptr)) {
        // The transport says why in words; the probe needs the kind of failure as well.
        m_report.access = seriallink::checkPortAccess(portPath);
        if (m_report.opened())
            m_report.access.problem = seriallink::PortAccess::Problem::Other;
        finish();
        return;
    }
    ask(0);
}

void PortProbe::ask(int step)
{
    if (m_cancelled) {
        m_report.cancelled = true;
        finish();
        return;
    }
    if (step >= stepCount() || (step > 0 && m_report.ptk)) {
        finish();
        return;
    }
    m_step = step;
    const qint32 baud = step == 0 ? kPtkBaud : baudRates().at(step - 1);
    emit progress(step, stepCount(),
                  step == 0
                      ? PortProbeTr::tr("Asking for a PTK servo at %1…").arg(baudText(baud))
                      : PortProbeTr::tr("Asking for Feetech servos at %1…").arg(baudText(baud)));
    if (!m_transport->setBaudRate(baud)) {
        m_report.access.problem = seriallink::PortAccess::Problem::Other;
        m_report.access.detail = PortProbeTr::tr("the port refused %1").arg(baudText(baud));
        finish();
        return;
    }
    m_transport->discardInput();
    m_heard.clear();
    m_answering = false;
    m_request = step == 0 ? ptk::encodeQuery(ptk::queryLayouts().front().command)
                          : feetech::ping(kBroadcastId);
    m_transport->write(m_request);
    m_deadline->start(step == 0 ? m_timing.ptkWait : m_timing.feetechWait);
}

void PortProbe::onReceived(const QByteArray &bytes)
{
    if (!m_deadline->isActive())
        return; // between questions: nothing asked for it
    m_heard += bytes;
    bool echo = false;
    if (!m_answering && !answerBytes(m_heard, m_request, &echo).isEmpty()) {
        // The answers have begun: the rest of them come within the settle time.
        m_answering = true;
        m_deadline->start(m_timing.settle);
    }
}

void PortProbe::endQuestion()
{
    m_transport->deliverPendingInput();
    bool echo = false;
    const QByteArray answer = answerBytes(m_heard, m_request, &echo);
    m_report.echo = m_report.echo || echo;
    if (m_step == 0) {
        const ptk::FrameFormat format;
        seriallink::StreamFramer framer(format);
        framer.append(answer);
        while (const auto item = framer.next()) {
            if (item->kind == seriallink::StreamItem::Kind::Frame
                && item->bytes.size() == ptk::kReplySize)
                m_report.ptk = true;
        }
        m_report.ptkBytes = int(answer.size());
    } else {
        RateProbe rate;
        rate.baud = baudRates().at(m_step - 1);
        rate.bytes = int(answer.size());
        const FrameFormat format;
        seriallink::StreamFramer framer(format);
        framer.append(answer);
        while (const auto item = framer.next()) {
            if (item->kind != seriallink::StreamItem::Kind::Frame)
                continue;
            const auto packet = decodePacket(item->bytes);
            if (packet && packet->id != kBroadcastId && !rate.ids.contains(packet->id))
                rate.ids.append(packet->id);
        }
        rate.heard = !rate.ids.isEmpty() ? RateHeard::Frames
            : answer.isEmpty()           ? RateHeard::Silence
                                         : RateHeard::Unframed;
        m_report.rates.append(rate);
    }
    ask(m_step + 1);
}

void PortProbe::finish()
{
    if (!m_running)
        return;
    m_running = false;
    m_deadline->stop();
    // Closed, not deleted: this may run inside one of the transport's own signals. The next
    // start (or the probe's end) deletes it.
    if (m_transport)
        m_transport->close();
    emit progress(stepCount(), stepCount(), QString());
    emit finished(m_report);
}

} // namespace feetech
