// Waiting for a BusClient operation to end, for the fault soak and the unplug cycles.
#include "operationwait.h"

#include "busclient.h"

#include <QEventLoop>
#include <QTimer>

namespace soak {

std::optional<feetech::OperationResult>
runOperation(feetech::BusClient &client, const std::function<bool()> &start, int timeoutMs)
{
    std::optional<feetech::OperationResult> final;
    QEventLoop loop;
    const auto connection = QObject::connect(&client, &feetech::BusClient::operationFinished, &loop,
                                             [&](const feetech::OperationResult &result) {
                                                 if (result.final) {
                                                     final = result;
                                                     loop.quit();
                                                 }
                                             });
    if (start()) {
        QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
        if (!final)
            loop.exec();
    }
    QObject::disconnect(connection);
    return final;
}

} // namespace soak
