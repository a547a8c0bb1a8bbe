// Waiting for a BusClient operation to end, for the fault soak and the unplug cycles.
#include "operationwait.h"

#include "operationreply.h"

#include <QEventLoop>
#include <QTimer>

namespace soak {

std::optional<feetech::OperationResult>
runOperation(const std::function<feetech::OperationReply *()> &start, int timeoutMs)
{
    feetech::OperationReply *reply = start();
    if (!reply)
        return std::nullopt;
    // The reply finishes through a queued signal: nothing can have been missed yet.
    std::optional<feetech::OperationResult> final;
    QEventLoop loop;
    QObject::connect(reply, &feetech::OperationReply::finished, &loop,
                     [&](const feetech::OperationResult &result) {
                         final = result;
                         loop.quit();
                     });
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    loop.exec();
    return final;
}

} // namespace soak
