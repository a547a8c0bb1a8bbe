// Reading --faults: NAME=VALUE items, each checked.
#include "faultsettings.h"

#include <QStringList>

namespace sim {

std::optional<FaultSettings> FaultSettings::parse(const QString &text, OptionError *error)
{
    using Code = OptionError::Code;
    FaultSettings settings;
    const auto fail = [&](Code code, const QString &what = {}) -> std::optional<FaultSettings> {
        refused(OptionError(code, what), error);
        return std::nullopt;
    };
    for (const QString &item : text.split(u',', Qt::SkipEmptyParts)) {
        const int eq = item.indexOf(u'=');
        if (eq <= 0)
            return fail(Code::FaultNotNameValue, item);
        const QString name = item.left(eq).trimmed();
        bool ok = false;
        const double value = item.mid(eq + 1).toDouble(&ok);
        if (!ok)
            return fail(Code::FaultNotANumber, item.mid(eq + 1));
        if (name == QLatin1String("delay")) {
            if (value < 0 || value > 60000)
                return fail(Code::FaultDelayOutOfRange);
            settings.delayMs = int(value);
            continue;
        }
        if (value < 0 || value > 1)
            return fail(Code::FaultNotAProbability, name);
        if (name == QLatin1String("drop"))
            settings.drop = value;
        else if (name == QLatin1String("corrupt"))
            settings.corrupt = value;
        else if (name == QLatin1String("truncate"))
            settings.truncate = value;
        else if (name == QLatin1String("noise"))
            settings.noise = value;
        else if (name == QLatin1String("lost"))
            settings.lost = value;
        else
            return fail(Code::UnknownFault, name);
    }
    return settings;
}

} // namespace sim
