// Telemetry samples: feedback block decoding, quantity names and units, and the CSV form.
#include "telemetry.h"

#include "bustypes.h"
#include "servoparameters.h"

#include <QCoreApplication>

#include <array>
#include <chrono>

namespace {

struct FeetechTelemetryTr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechTelemetry)
};

} // namespace

namespace feetech {

namespace {

struct QuantityInfo
{
    const char *key;
    const char *registerKey;
    const char *unit;
    const char *csvColumn;
};

// One unit per quantity for every family: a register whose table gives another unit (SCS
// current) is not reported, rather than plotted on the wrong scale.
constexpr QuantityInfo kQuantities[kQuantityCount] = {
    {"position", "present_position", "step", "position_step"},
    {"speed", "present_speed", "step/s", "speed_step_per_s"},
    {"load", "present_load", "%", "load_percent"},
    {"voltage", "present_voltage", "V", "voltage_v"},
    {"temperature", "present_temperature", "°C", "temperature_c"},
    {"current", "present_current", "mA", "current_ma"},
};

const QuantityInfo &info(Quantity quantity)
{
    return kQuantities[int(quantity)];
}

// The register keys and units of kQuantities as strings, made once: a sample's decoding
// compares every register of the block with them.
struct QuantityTexts
{
    QString registerKey;
    QString unit;
};

const std::array<QuantityTexts, kQuantityCount> &quantityTexts()
{
    static const std::array<QuantityTexts, kQuantityCount> texts = [] {
        std::array<QuantityTexts, kQuantityCount> made;
        for (int q = 0; q < kQuantityCount; ++q) {
            made[std::size_t(q)] = {QString::fromLatin1(kQuantities[q].registerKey),
                                    QString::fromUtf8(kQuantities[q].unit)};
        }
        return made;
    }();
    return texts;
}

QString formatNumber(double value)
{
    // Up to 4 decimals, without trailing zeros; always a dot, whatever the locale.
    QString text = QString::number(value, 'f', 4);
    while (text.contains(QLatin1Char('.')) && (text.endsWith(QLatin1Char('0'))))
        text.chop(1);
    if (text.endsWith(QLatin1Char('.')))
        text.chop(1);
    return text;
}

} // namespace

QString quantityKey(Quantity quantity)
{
    return QString::fromLatin1(info(quantity).key);
}

QString quantityName(Quantity quantity)
{
    switch (quantity) {
    case Quantity::Position:
        return FeetechTelemetryTr::tr("Position");
    case Quantity::Speed:
        return FeetechTelemetryTr::tr("Speed");
    case Quantity::Load:
        return FeetechTelemetryTr::tr("Load");
    case Quantity::Voltage:
        return FeetechTelemetryTr::tr("Voltage");
    case Quantity::Temperature:
        return FeetechTelemetryTr::tr("Temperature");
    case Quantity::Current:
        return FeetechTelemetryTr::tr("Current");
    }
    return {};
}

QString quantityUnit(Quantity quantity)
{
    // The register tables' unit, translated where the Memory table's is.
    return unitText(QString::fromUtf8(info(quantity).unit));
}

std::optional<Quantity> quantityFromKey(QStringView key)
{
    for (const Quantity quantity : kAllQuantities) {
        if (key == QLatin1String(info(quantity).key))
            return quantity;
    }
    return std::nullopt;
}

qint64 steadyMicroseconds()
{
    return std::chrono::duration_cast<std::chrono::microseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

std::optional<FeedbackSample> decodeFeedback(const RegisterTable &table, quint8 id, qint32 baud,
                                             qint64 steadyUs, QByteArrayView bytes,
                                             quint8 replyStatus)
{
    const Block block = table.feedbackBlock();
    if (block.size == 0 || bytes.size() < block.size)
        return std::nullopt;
    return decodeFeedbackPart(table, id, baud, steadyUs, block.address, bytes.first(block.size),
                              replyStatus);
}

std::optional<FeedbackSample> decodeFeedbackPart(const RegisterTable &table, quint8 id, qint32 baud,
                                                 qint64 steadyUs, int address, QByteArrayView bytes,
                                                 quint8 replyStatus)
{
    FeedbackSample sample;
    sample.id = id;
    sample.baud = baud;
    sample.steadyUs = steadyUs;
    sample.replyStatus = replyStatus;
    static const QString statusKey = QStringLiteral("status");
    static const QString movingKey = QStringLiteral("moving");
    const auto &texts = quantityTexts();
    bool measured = false;
    for (const DecodedRegister &item : decodeRegisters(table, address, bytes)) {
        const QString &key = item.reg->key;
        if (key == statusKey) {
            sample.servoStatus = quint8(item.value);
            continue;
        }
        if (key == movingKey) {
            sample.moving = item.value != 0;
            continue;
        }
        for (int q = 0; q < kQuantityCount; ++q) {
            const QuantityTexts &what = texts[std::size_t(q)];
            if (key == what.registerKey && item.reg->unit == what.unit) {
                sample.values.at(std::size_t(q)) = item.value * item.reg->scale;
                measured = true;
            }
        }
    }
    if (!measured)
        return std::nullopt;
    return sample;
}

QString servoStatusText(const RegisterTable &table, quint8 servoStatus)
{
    const Register *status = table.find(u"status");
    if (!status)
        return servoStatus == 0 ? FeetechTelemetryTr::tr("none")
                                : QStringLiteral("0x%1").arg(servoStatus, 2, 16);
    return bitNames(*status, servoStatus);
}

bool supportsSyncRead(const ServoInfo &servo)
{
    return servo.hasTable() && servo.model.family != Family::Scs;
}

QString telemetryCsvHeader()
{
    QStringList columns {QStringLiteral("time_s"), QStringLiteral("id")};
    for (const QuantityInfo &what : kQuantities)
        columns.append(QString::fromLatin1(what.csvColumn));
    columns << QStringLiteral("status") << QStringLiteral("moving");
    return columns.join(QLatin1Char(','));
}

QString telemetryCsvRow(const FeedbackSample &sample, qint64 startUs)
{
    QStringList cells {QString::number(double(sample.steadyUs - startUs) / 1e6, 'f', 6),
                       QString::number(sample.id)};
    for (const auto &value : sample.values)
        cells.append(value ? formatNumber(*value) : QString());
    cells << QString::number(sample.servoStatus) << QString::number(sample.moving ? 1 : 0);
    return cells.join(QLatin1Char(','));
}

std::optional<QVector<CsvSample>> parseTelemetryCsv(const QString &text, QString *error)
{
    const auto fail = [error](int line, const QString &why) {
        if (error)
            *error = FeetechTelemetryTr::tr("Line %1: %2").arg(line).arg(why);
        return std::nullopt;
    };
    const QStringList lines = text.split(QLatin1Char('\n'));
    if (lines.isEmpty() || lines.first().trimmed() != telemetryCsvHeader())
        return fail(
            1, FeetechTelemetryTr::tr("not a ServoBench telemetry recording (unexpected header)"));
    const int columns = kQuantityCount + 4;
    QVector<CsvSample> samples;
    for (int i = 1; i < lines.size(); ++i) {
        const QString line = lines.at(i).trimmed();
        if (line.isEmpty())
            continue;
        const QStringList cells = line.split(QLatin1Char(','));
        if (cells.size() != columns)
            return fail(
                i + 1,
                FeetechTelemetryTr::tr("%1 cells instead of %2").arg(cells.size()).arg(columns));
        CsvSample sample;
        bool ok = false;
        sample.timeSeconds = cells.at(0).toDouble(&ok);
        if (!ok)
            return fail(i + 1, FeetechTelemetryTr::tr("the time is not a number"));
        sample.id = cells.at(1).toInt(&ok);
        if (!ok || sample.id < 0 || sample.id > kMaxServoId)
            return fail(i + 1, FeetechTelemetryTr::tr("the ID is not a servo ID"));
        for (int q = 0; q < kQuantityCount; ++q) {
            const QString &cell = cells.at(2 + q);
            if (cell.isEmpty())
                continue;
            const double value = cell.toDouble(&ok);
            if (!ok)
                return fail(i + 1,
                            FeetechTelemetryTr::tr("%1 is not a number")
                                .arg(quantityName(kAllQuantities[q])));
            sample.values.at(q) = value;
        }
        sample.servoStatus = cells.at(2 + kQuantityCount).toInt(&ok);
        if (!ok || sample.servoStatus < 0 || sample.servoStatus > 255)
            return fail(i + 1, FeetechTelemetryTr::tr("the status is not a byte"));
        const QString &moving = cells.at(3 + kQuantityCount);
        if (moving != u"0" && moving != u"1")
            return fail(i + 1, FeetechTelemetryTr::tr("moving is neither 0 nor 1"));
        sample.moving = moving == u"1";
        samples.append(sample);
    }
    return samples;
}

} // namespace feetech
