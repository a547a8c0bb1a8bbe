// Alerts from a shared bus's traffic: each condition, its message, raised once until it clears.
#include "sharealerts.h"

#include "feetechpacket.h"

#include <QCoreApplication>

namespace share {

namespace {

struct ShareAlertsTr
{
    Q_DECLARE_TR_FUNCTIONS(ShareAlerts)
};

constexpr quint8 kOverloadBit = 0x20;
constexpr qint32 kMultiTurnPhaseBit = 0x10;

QString key(const QString &code, quint8 id)
{
    return code + QLatin1Char('/') + QString::number(id);
}

} // namespace

void ShareAlerts::raise(QVector<ShareAlert> &alerts, const QString &code, quint8 id,
                        const QString &message, qint64 timeUs)
{
    alerts.append({code, id, message, timeUs});
    ++m_raised;
}

void ShareAlerts::set(QVector<ShareAlert> &alerts, bool when, const QString &code, quint8 id,
                      const QString &message, qint64 timeUs)
{
    const QString name = key(code, id);
    if (!when) {
        m_active.remove(name);
        return;
    }
    if (m_active.contains(name))
        return;
    m_active.insert(name);
    raise(alerts, code, id, message, timeUs);
}

QVector<ShareAlert> ShareAlerts::inspect(const SharedTransaction &transaction,
                                         const ObservedServos &servos)
{
    QVector<ShareAlert> alerts;
    const qint64 time = transaction.timeUs;
    for (const QByteArray &reply : transaction.replies) {
        const quint8 id = quint8(reply.at(2));
        const quint8 error = quint8(reply.at(4));
        set(alerts, error & kOverloadBit, QStringLiteral("overload"), id,
            ShareAlertsTr::tr(
                "Servo %1 reports overload: it stopped holding (torque off) until it is "
                "switched on again. Look for a blocked joint or a load too heavy for it.")
                .arg(id),
            time);
        const quint8 others = error & quint8(~kOverloadBit);
        set(alerts, others != 0, QStringLiteral("reply-error"), id,
            ShareAlertsTr::tr("Servo %1 answers with error bits set: %2.")
                .arg(id)
                .arg(feetech::statusBitNames(others).join(QStringLiteral(", "))),
            time);
        inspectServo(alerts, id, servos, time);
    }
    // Two servos answering at once garble each other: the same ID, again and again.
    if (transaction.askedIds().size() == 1 && transaction.id() != feetech::kBroadcastId
        && transaction.expectedReplies == 1) {
        const quint8 id = transaction.id();
        if (transaction.garbledBytes > 0 && (transaction.replies.isEmpty() || servos.answered(id)))
            ++m_garbled[id];
        else if (!transaction.replies.isEmpty())
            m_garbled[id] = qMax(0, m_garbled.value(id) - 1);
        if (m_garbled.value(id) >= kGarbledAnswers
            && !m_active.contains(key(QStringLiteral("shared-id"), id)))
            set(alerts, true, QStringLiteral("shared-id"), id,
                ShareAlertsTr::tr(
                    "Answers at ID %1 come garbled again and again: two servos may share "
                    "this ID. Connect them one at a time and give each its own ID.")
                    .arg(id),
                time);
    }
    inspectWrites(alerts, transaction, servos);
    return alerts;
}

void ShareAlerts::inspectServo(QVector<ShareAlert> &alerts, quint8 id, const ObservedServos &servos,
                               qint64 timeUs)
{
    const auto temperature = servos.scaled(id, u"present_temperature");
    const auto maxTemperature = servos.scaled(id, u"max_temperature");
    if (temperature && maxTemperature)
        set(alerts, *temperature >= *maxTemperature - kTemperatureMargin,
            QStringLiteral("temperature-high"), id,
            ShareAlertsTr::tr(
                "Servo %1 is at %2 °C, within %3 °C of its maximum (%4 °C): it will soon "
                "cut its torque. Let it cool, or lighten its load.")
                .arg(id)
                .arg(*temperature)
                .arg(kTemperatureMargin)
                .arg(*maxTemperature),
            timeUs);
    const auto voltage = servos.scaled(id, u"present_voltage");
    const auto minVoltage = servos.scaled(id, u"min_voltage");
    const auto maxVoltage = servos.scaled(id, u"max_voltage");
    if (voltage && minVoltage && maxVoltage && *maxVoltage > 0)
        set(alerts, *voltage < *minVoltage || *voltage > *maxVoltage,
            QStringLiteral("voltage-out-of-range"), id,
            ShareAlertsTr::tr(
                "Servo %1 measures %2 V, outside its limits %3-%4 V: check the supply.")
                .arg(id)
                .arg(*voltage, 0, 'f', 1)
                .arg(*minVoltage, 0, 'f', 1)
                .arg(*maxVoltage, 0, 'f', 1),
            timeUs);
    const auto status = servos.value(id, u"status");
    if (status && (*status & kOverloadBit))
        set(alerts, true, QStringLiteral("overload"), id,
            ShareAlertsTr::tr(
                "Servo %1 reports overload: it stopped holding (torque off) until it is "
                "switched on again. Look for a blocked joint or a load too heavy for it.")
                .arg(id),
            timeUs);
    const auto lock = servos.value(id, u"lock");
    if (lock && *lock != 0) {
        m_unlockedSinceUs.remove(id);
        set(alerts, false, QStringLiteral("eeprom-unlocked"), id, {}, timeUs);
    }
}

void ShareAlerts::inspectWrites(QVector<ShareAlert> &alerts, const SharedTransaction &transaction,
                                const ObservedServos &servos)
{
    for (const RegisterAccess &access : transaction.registers) {
        if (!access.written)
            continue;
        if (access.key == QLatin1String("phase") && (access.value & kMultiTurnPhaseBit))
            raise(alerts, QStringLiteral("multi-turn"), access.id,
                  ShareAlertsTr::tr(
                      "The program set phase bit 4 of servo %1 (multi-turn): its positions "
                      "will leave 0-4095 and a calibration made without it no longer fits.")
                      .arg(access.id),
                  transaction.timeUs);
        if (access.key == QLatin1String("torque_enable") && access.value == 1) {
            const auto goal = servos.value(access.id, u"goal_position");
            const auto present = servos.value(access.id, u"present_position");
            if (goal && present && qAbs(*goal - *present) > kJumpSteps)
                raise(
                    alerts, QStringLiteral("torque-jump"), access.id,
                    ShareAlertsTr::tr("The program switched torque on at servo %1 with its goal %2 "
                                      "steps from where it stands (%3 → %4): the horn jumps.")
                        .arg(access.id)
                        .arg(qAbs(*goal - *present))
                        .arg(*present)
                        .arg(*goal),
                    transaction.timeUs);
        }
        if (access.key == QLatin1String("lock")) {
            if (access.value == 0)
                m_unlockedSinceUs.insert(access.id, transaction.timeUs);
            else {
                m_unlockedSinceUs.remove(access.id);
                set(alerts, false, QStringLiteral("eeprom-unlocked"), access.id, {},
                    transaction.timeUs);
            }
        }
    }
}

QVector<ShareAlert> ShareAlerts::tick(qint64 nowUs)
{
    QVector<ShareAlert> alerts;
    for (auto it = m_unlockedSinceUs.cbegin(); it != m_unlockedSinceUs.cend(); ++it) {
        if (nowUs - it.value() >= kUnlockedUs)
            set(alerts, true, QStringLiteral("eeprom-unlocked"), it.key(),
                ShareAlertsTr::tr(
                    "The program unlocked the EEPROM of servo %1 and has not locked it "
                    "again: a stray write now changes its settings for good.")
                    .arg(it.key()),
                nowUs);
    }
    return alerts;
}

} // namespace share
