// servoctl argument helpers: numbers, hex and ID lists with usage errors that say what is wrong.
#include "arguments.h"

#include "hex.h"
#include "servoctltr.h"

namespace cli {

Arguments::Arguments(const QStringList &raw, const QSet<QString> &valueOptions,
                     const QSet<QString> &flagOptions)
{
    for (int i = 0; i < raw.size(); ++i) {
        const QString &token = raw.at(i);
        if (!token.startsWith(QLatin1String("--")) || token == QLatin1String("--")) {
            m_positional.append(token);
            continue;
        }
        QString name = token.mid(2);
        QString value;
        bool hasValue = false;
        if (const int eq = name.indexOf(u'='); eq >= 0) {
            value = name.mid(eq + 1);
            name = name.left(eq);
            hasValue = true;
        }
        if (flagOptions.contains(name)) {
            if (hasValue)
                throw UsageError {ServoctlTr::tr("--%1 takes no value").arg(name)};
            m_flags.insert(name);
        } else if (valueOptions.contains(name)) {
            if (!hasValue) {
                if (i + 1 >= raw.size())
                    throw UsageError {ServoctlTr::tr("--%1 needs a value").arg(name)};
                value = raw.at(++i);
            }
            // "--id 1 --id 2": which one was meant is not for servoctl to guess.
            if (m_values.contains(name))
                throw UsageError {ServoctlTr::tr("--%1 is given twice").arg(name)};
            m_values.insert(name, value);
        } else {
            throw UsageError {ServoctlTr::tr("unknown option --%1").arg(name)};
        }
    }
}

qint64 integerOption(const Arguments &args, const QString &name, qint64 minimum, qint64 maximum)
{
    const auto value = util::parseInteger(args.value(name));
    if (!value)
        throw UsageError {
            ServoctlTr::tr("--%1: \"%2\" is not a number").arg(name, args.value(name))};
    if (*value < minimum || *value > maximum)
        throw UsageError {ServoctlTr::tr("--%1: %2 is out of range (%3 to %4)")
                              .arg(name)
                              .arg(*value)
                              .arg(minimum)
                              .arg(maximum)};
    return *value;
}

QByteArray hexOption(const Arguments &args, const QString &name)
{
    QString error;
    const auto bytes = util::parseHex(args.value(name), &error);
    if (!bytes)
        throw UsageError {QStringLiteral("--%1: %2").arg(name, error)};
    return *bytes;
}

std::optional<double> durationOption(const Arguments &args)
{
    if (!args.has(QStringLiteral("duration")))
        return std::nullopt;
    bool ok = false;
    const double duration = args.value(QStringLiteral("duration")).toDouble(&ok);
    if (!ok || !(duration > 0))
        throw UsageError {ServoctlTr::tr("--duration must be a number of seconds above 0")};
    return duration;
}

QVector<quint8> idList(const QString &text, int maximumId)
{
    QVector<quint8> ids;
    const auto parseId = [&](const QString &part) {
        const auto value = util::parseInteger(part);
        if (!value)
            throw UsageError {ServoctlTr::tr("--ids: \"%1\" is not an ID").arg(part)};
        if (*value < 0 || *value > maximumId)
            throw UsageError {ServoctlTr::tr("--ids: ID %1 is over %2").arg(*value).arg(maximumId)};
        return int(*value);
    };
    const QStringList parts = text.split(u',');
    for (const QString &part : parts) {
        // "1,,2" or a trailing comma is a slip the user should see, not one to guess past.
        if (part.trimmed().isEmpty() && parts.size() > 1)
            throw UsageError {
                ServoctlTr::tr("--ids: \"%1\" has an empty place between commas").arg(text)};
        if (part.trimmed().isEmpty())
            continue;
        const int dash = part.indexOf(u'-', 1);
        if (dash > 0) {
            const int first = parseId(part.left(dash));
            const int last = parseId(part.mid(dash + 1));
            if (last < first)
                throw UsageError {ServoctlTr::tr("--ids: the range %1 runs backwards").arg(part)};
            for (int id = first; id <= last; ++id)
                ids.append(quint8(id));
        } else {
            ids.append(quint8(parseId(part)));
        }
    }
    if (ids.isEmpty())
        throw UsageError {ServoctlTr::tr("--ids needs at least one ID")};
    return ids;
}

} // namespace cli
