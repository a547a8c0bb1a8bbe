// Fault injection: drop, corrupt, truncate, noise and delay of replies from one seeded
// generator, and lost requests from another.
#include "faultinjector.h"

#include <QStringList>

namespace sim {

FaultInjector::FaultInjector(const FaultSettings &settings, quint32 seed)
    : m_settings(settings)
    , m_random(seed)
    , m_requestRandom(seed ^ 0x5EEDu)
{ }

bool FaultInjector::loseRequest()
{
    return m_requestRandom.generateDouble() < m_settings.lost;
}

FaultOutcome FaultInjector::apply(const QByteArray &reply)
{
    // Draw everything first, in a fixed order, so outcomes never shift the random sequence.
    const double dropDraw = m_random.generateDouble();
    const double corruptDraw = m_random.generateDouble();
    const double truncateDraw = m_random.generateDouble();
    const double noiseDraw = m_random.generateDouble();
    const quint32 position = m_random.generate();
    const quint32 bit = m_random.generate();
    const quint32 cut = m_random.generate();
    const quint32 noise = m_random.generate();
    const quint32 delay = m_random.generate();

    FaultOutcome outcome {reply, 0, {}};
    QStringList notes;
    if (dropDraw < m_settings.drop)
        return {QByteArray(), 0, QStringLiteral("drop")};
    if (m_settings.delayMs > 0) {
        outcome.extraDelayUs = qint64(delay % quint32(m_settings.delayMs * 1000 + 1));
        notes.append(QStringLiteral("delay %1us").arg(outcome.extraDelayUs));
    }
    if (!reply.isEmpty() && corruptDraw < m_settings.corrupt) {
        const int index = int(position % quint32(reply.size()));
        outcome.bytes[index] = char(outcome.bytes[index] ^ char(1u << (bit % 8)));
        notes.append(QStringLiteral("corrupt"));
    }
    if (reply.size() > 1 && truncateDraw < m_settings.truncate) {
        outcome.bytes.truncate(int(1 + cut % quint32(reply.size() - 1)));
        notes.append(QStringLiteral("truncate"));
    }
    if (noiseDraw < m_settings.noise) {
        QByteArray stray;
        for (quint32 i = 0; i < 1 + noise % 3; ++i)
            stray.append(char((noise >> (8 * (i + 1))) & 0xFF));
        outcome.bytes.prepend(stray);
        notes.append(QStringLiteral("noise"));
    }
    outcome.note = notes.join(u' ');
    return outcome;
}

} // namespace sim
