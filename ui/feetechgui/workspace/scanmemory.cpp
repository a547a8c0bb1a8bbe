// The scan options last chosen in the scan dialog, kept across runs (QSettings).
#include "scanmemory.h"

#include "modeltable.h"
#include "registertable.h"

#include <QSettings>

namespace scanmemory {

namespace {

constexpr char kScanIdsKey[] = "scan/ids";
constexpr char kScanBaudsKey[] = "scan/bauds";
constexpr char kScanSkipSilentKey[] = "scan/skipSilentRates";

} // namespace

feetech::ScanOptions rememberedScanOptions()
{
    const QSettings settings;
    feetech::ScanOptions options;
    const QList<QVariant> ids = settings.value(QLatin1String(kScanIdsKey)).toList();
    if (ids.size() == 2 && ids.at(0).toInt() >= 0 && ids.at(1).toInt() <= feetech::kMaxServoId
        && ids.at(0).toInt() <= ids.at(1).toInt()) {
        options.firstId = ids.at(0).toInt();
        options.lastId = ids.at(1).toInt();
    }
    QVector<qint32> bauds;
    for (const QVariant &baud : settings.value(QLatin1String(kScanBaudsKey)).toList()) {
        if (feetech::baudRates().contains(baud.toInt()))
            bauds.append(baud.toInt());
    }
    if (!bauds.isEmpty())
        options.bauds = bauds;
    options.skipSilentRates =
        settings.value(QLatin1String(kScanSkipSilentKey), options.skipSilentRates).toBool();
    return options;
}

void rememberScanOptions(const feetech::ScanOptions &options)
{
    QSettings settings;
    settings.setValue(QLatin1String(kScanIdsKey), QVariantList {options.firstId, options.lastId});
    QVariantList bauds;
    for (const qint32 baud : options.bauds)
        bauds.append(baud);
    settings.setValue(QLatin1String(kScanBaudsKey), bauds);
    settings.setValue(QLatin1String(kScanSkipSilentKey), options.skipSilentRates);
}

} // namespace scanmemory
