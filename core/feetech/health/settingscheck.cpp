// The settings check's rules: each reading against what lets a joint servo move as asked, then
// against the robot template's values; firmware mismatches as the health check finds them.
#include "settingscheck.h"

#include "registerkeys.h"
#include "servohealth.h"
#include "settingschecktr.h"

#include <QCoreApplication>

#include <algorithm>

namespace feetech {

using namespace registerkeys;

namespace {

// Phase bit 4: the servo reports its position over several turns, beyond 0-4095.
constexpr int kMultiTurnBit = 4;
// Position mode, the only one in which a joint follows its goal position.
constexpr qint32 kPositionMode = 0;

const QString kPhase = QStringLiteral("phase");
const QString kTorqueLimit = QStringLiteral("torque_limit");
const QString kMaxTorque = QStringLiteral("max_torque");
const QString kReturnDelay = QStringLiteral("return_delay");
const QString kLock = QStringLiteral("lock");
const QString kMaxVoltage = QStringLiteral("max_voltage");
const QString kMinVoltage = QStringLiteral("min_voltage");
const QString kPresentVoltage = QStringLiteral("present_voltage");

QString fixedText(double value, int decimals)
{
    return QString::number(value, 'f', decimals);
}

// Collects one servo's findings, at most one per register.
class ServoFindings
{
public:
    ServoFindings(const SettingsReading &reading, const SettingsExpectations &expected)
        : m_reading(reading)
        , m_expected(expected.byId.value(reading.servo.id))
        , m_cleared(expected.clearedBitsById.value(reading.servo.id))
        , m_source(expected.source)
    { }

    std::optional<qint32> value(const QString &key) const
    {
        const auto found = m_reading.values.constFind(key);
        return found == m_reading.values.constEnd() ? std::nullopt : std::optional(*found);
    }
    const Register *reg(const QString &key) const { return m_reading.servo.table().find(key); }
    // The template's value of `key`, else `fallback`.
    qint32 expected(const QString &key, qint32 fallback) const
    {
        return m_expected.value(key, fallback);
    }

    void add(const QString &code, const QString &key, std::optional<qint32> expected,
             const QString &why)
    {
        if (std::any_of(m_findings.begin(), m_findings.end(),
                        [&key](const SettingsFinding &f) { return f.key == key; }))
            return;
        SettingsFinding finding;
        finding.servo = m_reading.servo;
        finding.code = code;
        finding.key = key;
        finding.value = value(key);
        finding.expected = expected;
        finding.why = why;
        finding.needsTorqueOff = needsTorqueOff(key);
        m_findings.append(finding);
    }

    // The template's values the rules did not already speak of.
    void addTemplateDifferences()
    {
        for (auto it = m_expected.cbegin(); it != m_expected.cend(); ++it) {
            const auto held = value(it.key());
            if (!held || *held == it.value())
                continue;
            const Register *r = reg(it.key());
            const bool lostAtPowerOff = r && r->storage == Storage::Ram;
            add(QStringLiteral("template"), it.key(), it.value(),
                lostAtPowerOff
                    ? SettingsCheckTr::tr("%1 is %2; %3 sets %4 (a RAM register: it is lost at "
                                          "power-off and set again at every connect).")
                          .arg(it.key())
                          .arg(*held)
                          .arg(m_source)
                          .arg(it.value())
                    : SettingsCheckTr::tr("%1 is %2; %3 sets %4.")
                          .arg(it.key())
                          .arg(*held)
                          .arg(m_source)
                          .arg(it.value()));
        }
    }

    // The template's bits to clear that are set; the other bits stay as they are.
    void addTemplateBits()
    {
        for (auto it = m_cleared.cbegin(); it != m_cleared.cend(); ++it) {
            const auto held = value(it.key());
            if (!held || !(quint32(*held) & it.value()))
                continue;
            add(QStringLiteral("template"), it.key(), qint32(quint32(*held) & ~it.value()),
                SettingsCheckTr::tr("%1 is %2 with bits 0x%3 set; %4 clears them.")
                    .arg(it.key())
                    .arg(*held)
                    .arg(quint32(*held) & it.value(), 2, 16, QLatin1Char('0'))
                    .arg(m_source));
        }
    }

    QVector<SettingsFinding> take()
    {
        const RegisterTable &table = m_reading.servo.table();
        std::stable_sort(m_findings.begin(), m_findings.end(),
                         [&table](const SettingsFinding &a, const SettingsFinding &b) {
                             const Register *ra = table.find(a.key);
                             const Register *rb = table.find(b.key);
                             return (ra ? ra->address : -1) < (rb ? rb->address : -1);
                         });
        return m_findings;
    }

private:
    const SettingsReading &m_reading;
    QMap<QString, qint32> m_expected;
    QMap<QString, quint32> m_cleared;
    QString m_source;
    QVector<SettingsFinding> m_findings;
};

// Whether the family's phase register has the multi-turn bit (not every family's bit 4 is it).
bool hasMultiTurnBit(const Register *phase)
{
    return phase && std::any_of(phase->bits.begin(), phase->bits.end(), [](const BitName &named) {
               return named.bit == kMultiTurnBit;
           });
}

void checkMotion(ServoFindings &servo)
{
    if (const auto phase = servo.value(kPhase);
        phase && (*phase & (1 << kMultiTurnBit)) && hasMultiTurnBit(servo.reg(kPhase))) {
        servo.add(
            QStringLiteral("multi-turn"), kPhase,
            servo.expected(kPhase, *phase & ~(1 << kMultiTurnBit)),
            SettingsCheckTr::tr("Phase bit 4 is set: the servo counts whole turns, so its position "
                                "leaves 0-4095 and goals and calibration no longer match it."));
    }
    if (const auto limit = servo.value(kTorqueLimit); limit && *limit == 0) {
        const Register *r = servo.reg(kTorqueLimit);
        const qint32 maxTorque = servo.value(kMaxTorque).value_or(0);
        servo.add(
            QStringLiteral("torque-limit-zero"), kTorqueLimit,
            maxTorque > 0 ? maxTorque : (r ? r->maximum : 1000),
            SettingsCheckTr::tr("The torque limit is 0: the servo has no force to move with."));
    }
    if (const auto maxTorque = servo.value(kMaxTorque); maxTorque && *maxTorque == 0) {
        const Register *r = servo.reg(kMaxTorque);
        servo.add(QStringLiteral("max-torque-zero"), kMaxTorque,
                  servo.expected(kMaxTorque, r ? r->maximum : 1000),
                  SettingsCheckTr::tr(
                      "The maximum torque is 0: at every power-on the torque limit starts at "
                      "0, and the servo does not move."));
    }
    if (const auto mode = servo.value(kMode); mode && *mode != kPositionMode) {
        servo.add(QStringLiteral("mode"), kMode, servo.expected(kMode, kPositionMode),
                  SettingsCheckTr::tr(
                      "The operating mode is %1, not position (0): a joint does not follow "
                      "its goal position.")
                      .arg(*mode));
    }
    const auto low = servo.value(kMinAngleLimit);
    const auto high = servo.value(kMaxAngleLimit);
    if (low && high && (*low == 0 && *high == 0)) {
        const Register *r = servo.reg(kMaxAngleLimit);
        const qint32 top = r ? r->maximum : 4095;
        const QString why =
            SettingsCheckTr::tr("Both angle limits are 0: the servo turns without end (multi-turn "
                                "or wheel), not as a joint.");
        servo.add(QStringLiteral("angle-limits-zero"), kMaxAngleLimit,
                  servo.expected(kMaxAngleLimit, top), why);
    } else if (low && high && *low >= *high) {
        const Register *r = servo.reg(kMaxAngleLimit);
        const QString why =
            SettingsCheckTr::tr("The minimum angle limit %1 is not below the maximum %2: the "
                                "servo refuses every goal.")
                .arg(*low)
                .arg(*high);
        servo.add(QStringLiteral("angle-limits-order"), kMinAngleLimit,
                  servo.expected(kMinAngleLimit, 0), why);
        servo.add(QStringLiteral("angle-limits-order"), kMaxAngleLimit,
                  servo.expected(kMaxAngleLimit, r ? r->maximum : 4095), why);
    }
}

void checkBus(ServoFindings &servo)
{
    if (const auto delay = servo.value(kReturnDelay); delay && *delay > 0) {
        const Register *r = servo.reg(kReturnDelay);
        servo.add(QStringLiteral("return-delay"), kReturnDelay, servo.expected(kReturnDelay, 0),
                  SettingsCheckTr::tr(
                      "The servo waits %1 µs before each answer: every read of the bus is "
                      "that much slower.")
                      .arg(fixedText(*delay * (r ? r->scale : 2.0), 0)));
    }
    if (const auto lock = servo.value(kLock); lock && *lock == 0) {
        servo.add(QStringLiteral("unlocked"), kLock, 1,
                  SettingsCheckTr::tr(
                      "The EEPROM is unlocked: a stray write would change settings for good."));
    }
}

void checkVoltage(ServoFindings &servo)
{
    const Register *present = servo.reg(kPresentVoltage);
    const auto raw = servo.value(kPresentVoltage);
    if (!present || !raw || *raw == 0)
        return;
    const double volts = *raw * present->scale;
    const auto limitVolts = [&servo](const QString &key) -> std::optional<double> {
        const Register *r = servo.reg(key);
        const auto value = servo.value(key);
        return r && value ? std::optional(*value * r->scale) : std::nullopt;
    };
    if (const auto high = limitVolts(kMaxVoltage); high && *high > 0 && volts > *high) {
        servo.add(QStringLiteral("voltage-limit"), kMaxVoltage, std::nullopt,
                  SettingsCheckTr::tr(
                      "The supply reads %1 V, above the maximum voltage setting of %2 V: the "
                      "servo reports a voltage error and may not move. Use a supply it is "
                      "made for, or raise the limit if it is a higher-voltage model.")
                      .arg(fixedText(volts, 1), fixedText(*high, 1)));
    }
    if (const auto low = limitVolts(kMinVoltage); low && volts < *low) {
        servo.add(QStringLiteral("voltage-limit"), kMinVoltage, std::nullopt,
                  SettingsCheckTr::tr(
                      "The supply reads %1 V, below the minimum voltage setting of %2 V: the "
                      "servo reports a voltage error and may not move. Charge the battery or "
                      "check the supply.")
                      .arg(fixedText(volts, 1), fixedText(*low, 1)));
    }
}

// Servos of one model with different firmware, found as the health check finds them.
QVector<SettingsFinding> firmwareFindings(const QVector<SettingsReading> &readings)
{
    QVector<ServoHealth> servos;
    QVector<const ServoInfo *> infos;
    for (const SettingsReading &reading : readings) {
        if (!reading.failure.isEmpty() || reading.servo.model.name.isEmpty())
            continue;
        ServoHealth health;
        health.id = reading.servo.id;
        health.baud = reading.servo.baud;
        health.model = reading.servo.model.name;
        health.firmware = reading.servo.firmware();
        servos.append(health);
        infos.append(&reading.servo);
    }
    flagFirmwareMismatches(servos);
    QVector<SettingsFinding> findings;
    for (int i = 0; i < servos.size(); ++i) {
        for (const HealthFinding &mismatch : std::as_const(servos.at(i).findings)) {
            SettingsFinding finding;
            finding.servo = *infos.at(i);
            finding.code = mismatch.code;
            finding.key = QStringLiteral("firmware");
            finding.valueText = servos.at(i).firmware;
            finding.why = mismatch.message;
            findings.append(finding);
        }
    }
    return findings;
}

QJsonValue optionalJson(const std::optional<qint32> &value)
{
    return value ? QJsonValue(*value) : QJsonValue();
}

} // namespace

QStringList SettingsExpectations::keys() const
{
    QStringList found;
    for (const auto &settings : byId)
        found += settings.keys();
    for (const auto &bits : clearedBitsById)
        found += bits.keys();
    found.removeDuplicates();
    return found;
}

bool needsTorqueOff(const QString &key)
{
    // The phase register changes how the position reads: under torque the servo would chase
    // its goal through the new reading.
    return key == kMinAngleLimit || key == kMaxAngleLimit || key == kMode || key == kTorqueLimit
        || key == kPhase || key == QLatin1String("position_offset");
}

QVector<SettingsFinding> checkSettings(const QVector<SettingsReading> &readings,
                                       const SettingsExpectations &expected)
{
    const QVector<SettingsFinding> firmware = firmwareFindings(readings);
    QVector<SettingsFinding> findings;
    for (const SettingsReading &reading : readings) {
        if (!reading.failure.isEmpty()) {
            SettingsFinding finding;
            finding.servo = reading.servo;
            finding.code = QStringLiteral("unreadable");
            finding.why =
                SettingsCheckTr::tr("Its settings could not be read: %1").arg(reading.failure);
            findings.append(finding);
            continue;
        }
        ServoFindings servo(reading, expected);
        checkMotion(servo);
        checkBus(servo);
        checkVoltage(servo);
        servo.addTemplateDifferences();
        servo.addTemplateBits();
        findings += servo.take();
        for (const SettingsFinding &finding : firmware) {
            if (finding.servo.id == reading.servo.id && finding.servo.baud == reading.servo.baud)
                findings.append(finding);
        }
    }
    return findings;
}

QJsonObject settingsFindingJson(const SettingsFinding &finding)
{
    QJsonValue value = optionalJson(finding.value);
    if (!finding.valueText.isEmpty())
        value = finding.valueText;
    return {{QStringLiteral("id"), finding.servo.id},
            {QStringLiteral("baud"), finding.servo.baud},
            {QStringLiteral("code"), finding.code},
            {QStringLiteral("key"), finding.key.isEmpty() ? QJsonValue() : QJsonValue(finding.key)},
            {QStringLiteral("value"), value},
            {QStringLiteral("expected"), optionalJson(finding.expected)},
            {QStringLiteral("why"), finding.why}};
}

QJsonObject settingsFixJson(const SettingsFixOutcome &outcome)
{
    QJsonObject json = settingsFindingJson(outcome.finding);
    json.insert(QStringLiteral("fixed"), outcome.verified());
    json.insert(QStringLiteral("result"), fixOutcomeText(outcome));
    return json;
}

QString fixOutcomeText(const SettingsFixOutcome &outcome)
{
    if (outcome.verified())
        return SettingsCheckTr::tr("fixed, verified");
    return outcome.why;
}

} // namespace feetech
