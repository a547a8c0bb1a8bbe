// Reads VmRSS and VmHWM from /proc/self/status for the benchmarks' memory figures.
#include "processmemory.h"

#include <QFile>

namespace util {

std::optional<ProcessMemory> processMemory()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QByteArray text = status.readAll();
    // Lines look like "VmRSS:     43104 kB".
    const auto megabytes = [&text](const char *key) -> std::optional<double> {
        const qsizetype at = text.indexOf(key);
        if (at < 0)
            return std::nullopt;
        const qsizetype end = text.indexOf('\n', at);
        const QByteArray fields = text.mid(at, end - at).simplified();
        bool ok = false;
        const double kilobytes = fields.split(' ').value(1).toDouble(&ok);
        return ok ? std::optional<double>(kilobytes / 1024.0) : std::nullopt;
    };
    const auto resident = megabytes("VmRSS:");
    const auto peak = megabytes("VmHWM:");
    if (!resident || !peak)
        return std::nullopt;
    return ProcessMemory {*resident, *peak};
}

} // namespace util
