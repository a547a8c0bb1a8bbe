// Simulated PTK servo (spec/ptk-protocol.md): replies to queries, never to writes.
#include "virtualptkservo.h"

#include <QStringList>

namespace sim {

VirtualPtkServo::VirtualPtkServo()
    : m_values(ptk::ParameterSet::seedSample(false))
{ }

QVector<Response> VirtualPtkServo::handleFrame(const QByteArray &frame, qint32 hostBaud,
                                               qint64 nowUs)
{
    Q_UNUSED(nowUs);
    if (hostBaud != kBaudRate)
        return {}; // at another rate the servo hears only noise
    const auto request = ptk::decodeRequest(frame);
    if (!request)
        return {}; // a reply-shaped frame (our own, echoed) or a bad one
    if (const ptk::FrameLayout *query = ptk::findQuery(request->command)) {
        if (request->word0 != 0 || request->word1 != 0)
            return {};
        return {Response {ptk::encodeReply(ptk::replyFor(*query, m_values)), 0}};
    }
    if (const ptk::FrameLayout *write = ptk::findWrite(request->command)) {
        if (!m_ignoredWrites.contains(request->command)) {
            ptk::applyWrite(*write, *request, m_values);
            ++m_writesApplied;
        }
    }
    return {}; // writes are fire-and-forget; unknown commands are ignored
}

bool VirtualPtkServo::setValues(const QString &assignments, SimRefusal *why)
{
    QString reason;
    const auto values = ptk::parseAssignments(assignments.split(u',', Qt::SkipEmptyParts), &reason);
    if (!values)
        return !refused(SimRefusal(SimRefusal::Code::BadPtkValues, 0, 0, reason), why);
    for (const ptk::ParameterInfo &meta : ptk::parameterInfos()) {
        if (const auto wire = values->value(meta.parameter))
            m_values.set(meta.parameter, *wire);
    }
    return true;
}

} // namespace sim
