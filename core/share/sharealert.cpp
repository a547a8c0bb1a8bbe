// A shared bus's alert as the JSON row the share's clients read.
#include "sharealert.h"

namespace share {

QJsonObject ShareAlert::toJson() const
{
    return {{QStringLiteral("alert"), code},
            {QStringLiteral("id"), int(id)},
            {QStringLiteral("message"), message},
            {QStringLiteral("time"), double(timeUs) / 1e6}};
}

} // namespace share
