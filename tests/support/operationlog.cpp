// The results of a BusClient's replies, gathered into one signal for the tests.
#include "operationlog.h"

OperationLog::OperationLog(feetech::BusClient *client, QObject *parent)
    : QObject(parent)
{
    connect(client, &feetech::BusClient::submitted, this, [this](feetech::OperationReply *reply) {
        connect(reply, &feetech::OperationReply::stepFinished, this, &OperationLog::finished);
        connect(reply, &feetech::OperationReply::finished, this, &OperationLog::finished);
    });
}
