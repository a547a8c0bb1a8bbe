// Simulated PTK servo (spec/ptk-protocol.md): replies to queries, never to writes.
#include "sim/virtualptkservo.h"

#include <QCoreApplication>
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

bool VirtualPtkServo::setValues(const QString &assignments, QString *error)
{
    ptk::ParameterSet updated = m_values;
    for (const QString &assignment : assignments.split(u',', Qt::SkipEmptyParts)) {
        const int eq = assignment.indexOf(u'=');
        const QString key = assignment.left(eq).trimmed();
        const ptk::ParameterInfo *meta = eq > 0 ? ptk::findParameter(key) : nullptr;
        bool ok = false;
        const double value = assignment.mid(eq + 1).toDouble(&ok);
        if (!meta || !ok) {
            if (error)
                *error = QCoreApplication::translate("VirtualPtkServo",
                                                     "--values: \"%1\" is not KEY=NUMBER with a "
                                                     "PTK parameter key")
                             .arg(assignment);
            return false;
        }
        const auto wire = ptk::fromUserValue(meta->parameter, value, error);
        if (!wire)
            return false;
        updated.set(meta->parameter, *wire);
    }
    m_values = updated;
    return true;
}

} // namespace sim
