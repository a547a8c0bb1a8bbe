// servoctl argument helpers: numbers, hex and ID lists with usage errors that say what is wrong.
#include "cli/arguments.h"

#include "util/hex.h"

namespace cli {

using Tr = ServoctlTr;

qint64 integerOption(const Arguments &args, const QString &name, qint64 minimum, qint64 maximum)
{
    const auto value = util::parseInteger(args.value(name));
    if (!value)
        throw UsageError {Tr::tr("--%1: \"%2\" is not a number").arg(name, args.value(name))};
    if (*value < minimum || *value > maximum)
        throw UsageError {Tr::tr("--%1: %2 is out of range (%3 to %4)")
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

QVector<quint8> idList(const QString &text, int maximumId)
{
    QVector<quint8> ids;
    const auto parseId = [&](const QString &part) {
        const auto value = util::parseInteger(part);
        if (!value)
            throw UsageError {Tr::tr("--ids: \"%1\" is not an ID").arg(part)};
        if (*value < 0 || *value > maximumId)
            throw UsageError {Tr::tr("--ids: ID %1 is over %2").arg(*value).arg(maximumId)};
        return int(*value);
    };
    for (const QString &part : text.split(u',', Qt::SkipEmptyParts)) {
        const int dash = part.indexOf(u'-', 1);
        if (dash > 0) {
            const int first = parseId(part.left(dash));
            const int last = parseId(part.mid(dash + 1));
            if (last < first)
                throw UsageError {Tr::tr("--ids: the range %1 runs backwards").arg(part)};
            for (int id = first; id <= last; ++id)
                ids.append(quint8(id));
        } else {
            ids.append(quint8(parseId(part)));
        }
    }
    if (ids.isEmpty())
        throw UsageError {Tr::tr("--ids needs at least one ID")};
    return ids;
}

} // namespace cli
