// Table facts: the torque-enable values, the feedback block and the baud codes, read and checked.
#include "tablefacts.h"

#include "registertable.h"
#include "registertabletr.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <algorithm>

namespace feetech {

namespace {

constexpr std::array<std::pair<TorqueMode, const char *>, 4> kTorqueModeKeys {{
    {TorqueMode::Off, "off"},
    {TorqueMode::On, "on"},
    {TorqueMode::Damping, "damping"},
    {TorqueMode::CalibrateMiddle, "calibrate_middle"},
}};

const Register *findRegister(const QVector<Register> &registers, QStringView key)
{
    const auto found = std::find_if(registers.begin(), registers.end(),
                                    [key](const Register &reg) { return reg.key == key; });
    return found == registers.end() ? nullptr : &*found;
}

bool fail(QString *error, const QString &what)
{
    if (error)
        *error = what;
    return false;
}

bool parseTorqueValues(const QJsonObject &root, const QVector<Register> &registers,
                       TableFacts &facts, QString *error)
{
    const QJsonValue field = root.value(QLatin1String("torque_enable_values"));
    const Register *torque = findRegister(registers, u"torque_enable");
    if (!torque && field.isUndefined())
        return true; // a partial table: nothing to say about torque
    if (!torque)
        return fail(error,
                    RegisterTableTr::tr("torque_enable_values: the table has no torque_enable"));
    if (!field.isObject())
        return fail(error, RegisterTableTr::tr("torque_enable_values must be an object"));
    const QJsonObject values = field.toObject();
    for (auto it = values.begin(); it != values.end(); ++it) {
        const auto mode =
            std::find_if(kTorqueModeKeys.begin(), kTorqueModeKeys.end(), [&](const auto &entry) {
                return it.key() == QLatin1String(entry.second);
            });
        if (mode == kTorqueModeKeys.end())
            return fail(
                error,
                RegisterTableTr::tr("torque_enable_values: unknown mode \"%1\"").arg(it.key()));
        const qint32 value = it.value().toInt(-1);
        const bool listed = std::any_of(torque->choices.begin(), torque->choices.end(),
                                        [value](const Choice &c) { return c.value == value; });
        if (!it.value().isDouble() || !listed)
            return fail(
                error,
                RegisterTableTr::tr("torque_enable_values: \"%1\" is not one of torque_enable's "
                                    "choices")
                    .arg(it.key()));
        facts.torqueValues[std::size_t(mode->first)] = value;
    }
    for (const TorqueMode required : {TorqueMode::Off, TorqueMode::On}) {
        if (!facts.torqueValues[std::size_t(required)])
            return fail(error,
                        RegisterTableTr::tr("torque_enable_values: \"%1\" is missing")
                            .arg(QLatin1String(kTorqueModeKeys[std::size_t(required)].second)));
    }
    return true;
}

bool parseFeedbackBlock(const QJsonObject &root, const QVector<Register> &registers,
                        TableFacts &facts, QString *error)
{
    const Register *first = findRegister(registers, u"present_position");
    if (!first && root.value(QLatin1String("feedback_block")).isUndefined())
        return true; // a partial table: no feedback to read
    const QJsonObject block = root.value(QLatin1String("feedback_block")).toObject();
    facts.feedbackAddress = block.value(QLatin1String("address")).toInt(-1);
    facts.feedbackSize = block.value(QLatin1String("size")).toInt(-1);
    // In 64 bits: the file's numbers may be anywhere in int's range, checked only below.
    const qint64 end = qint64(facts.feedbackAddress) + facts.feedbackSize;
    // The block must start at present position and lie wholly inside the table's registers.
    const bool covered = first && first->address == facts.feedbackAddress && facts.feedbackSize > 0
        && std::any_of(registers.begin(), registers.end(),
                       [end](const Register &reg) { return reg.end() == end; });
    if (!covered)
        return fail(
            error,
            RegisterTableTr::tr("feedback_block must give the address of present_position and "
                                "a size that ends at the end of a register"));
    return true;
}

} // namespace

std::optional<TableFacts> parseTableFacts(const QJsonObject &root,
                                          const QVector<Register> &registers, QString *error)
{
    TableFacts facts;
    if (!parseTorqueValues(root, registers, facts, error)
        || !parseFeedbackBlock(root, registers, facts, error))
        return std::nullopt;
    return facts;
}

std::optional<QVector<qint32>> parseBaudRates(const QJsonObject &root, QString *error)
{
    const QJsonArray rates = root.value(QLatin1String("baud_rates")).toArray();
    QVector<qint32> result;
    for (const QJsonValue &rate : rates) {
        const qint32 baud = rate.toInt(0);
        if (!rate.isDouble() || baud <= 0 || result.contains(baud)) {
            fail(error,
                 RegisterTableTr::tr(
                     "baud_rates: every rate must be a positive number, listed once"));
            return std::nullopt;
        }
        result.append(baud);
    }
    // Address 6 holds a code from 0 to 7 (spec §6).
    if (result.isEmpty() || result.size() > 8) {
        fail(error, RegisterTableTr::tr("baud_rates must list the rates of codes 0 to 7"));
        return std::nullopt;
    }
    return result;
}

} // namespace feetech
