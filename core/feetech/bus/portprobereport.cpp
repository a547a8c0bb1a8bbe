// A port probe's report: the rates worth a scan, and whether anything answered at all.
#include "portprobereport.h"

namespace feetech {

QVector<qint32> PortProbeReport::answeringBauds() const
{
    QVector<qint32> bauds;
    for (const RateProbe &rate : rates) {
        if (rate.heard != RateHeard::Silence)
            bauds.append(rate.baud);
    }
    return bauds;
}

bool PortProbeReport::silent() const
{
    return !ptk && ptkBytes == 0 && answeringBauds().isEmpty();
}

} // namespace feetech
